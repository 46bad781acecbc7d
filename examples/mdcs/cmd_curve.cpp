// `mdcs curve`: its option table and its run (cmd_curve.h).
#include "cmd_curve.h"
#include "commands.h"

#include <iostream>

namespace mdcs_cli {

Curve_run run_curve(const Curve_settings& s, const Progress_bar& progress)
{
  if(s.functional == "catenoid") {
    const VM::Curve_problem_2 problem{CGAL::Bbox_2(-1, 0, 1, s.radius), s.left.value_or(VM::End_condition::fixed(s.radius)),
                                      s.right.value_or(VM::End_condition::fixed(s.radius))};
    return run_curve_with(s, problem, VM::Surface_of_rotation_functional(), progress);
  }
  const VM::Curve_problem_2 problem{s.box, s.left.value_or(VM::End_condition::fixed(0.5)), s.right.value_or(VM::End_condition::fixed(0.5))};
  if(s.functional == "arc-length") return run_curve_with(s, problem, VM::Arc_length_functional(), progress);
  return run_curve_with(s, problem, VM::make_density_weighted_length_functional(Blob_density(s.box, unsigned(s.seed))), progress);
}

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
