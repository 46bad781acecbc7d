// `mdcs curve`: its option table and its run (cmd_curve.h).
#include "cmd_curve.h"
#include "commands.h"

#include <iostream>

namespace mdcs_cli {

Command_spec curve_spec() { return curve_command_spec(); }

int run_curve_command(Invocation& run)
{
  Curve_settings s = parse_curve_settings(run.options);
  s.threads = threads_text(run.threads);
  const Curve_run r = run_curve(s, run.progress);
  const int code = r.curve.is_feasible ? EXIT_OK : EXIT_INFEASIBLE;
  write_curve_json(s, r, run, code);
  std::cout << r.summary;
  return code;
}

} // namespace mdcs_cli
