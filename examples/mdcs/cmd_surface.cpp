// `mdcs surface`: its option table and its run (cmd_surface.h).
#include "cmd_surface.h"
#include "commands.h"

#include <iostream>

namespace mdcs_cli {

Command_spec surface_spec() { return surface_command_spec(); }

int run_surface_command(Invocation& run)
{
  Surface_settings s = parse_surface_settings(run.options);
  s.threads = threads_text(run.threads);
  const Surface_run r = run_surface(s, run.progress);
  const int code = r.surface.is_feasible ? EXIT_OK : EXIT_INFEASIBLE;
  write_surface_json(s, r, run, code);
  std::cout << r.summary;
  return code;
}

} // namespace mdcs_cli
