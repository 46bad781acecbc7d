// `mdcs geodesics`: its option table (geodesics_options.h) and its run (cmd_geodesics.h).
#include "cmd_geodesics.h"
#include "commands.h"
#include "geodesic_matrix.h"

#include <iostream>

namespace mdcs_cli {

// The run on meshes (see the extern declarations in cmd_geodesics.h).
template Geodesics_run run_geodesics_on<Geo_mesh>(const Geo_mesh&, const std::string&, const std::vector<std::string>&,
                                                  double, const Geodesics_settings&, const Progress_bar&,
                                                  const Geodesics_run*, bool);

Command_spec geodesics_spec() { return geodesics_command_spec(); }

int run_geodesics_command(Invocation& run)
{
  Geodesics_settings s = parse_geodesics_settings(run.options);
  s.threads = threads_text(run.threads);
  s.thread_count = run.threads.used();
  if(run.options.given("matrix")) return run_geodesic_matrix(run, s);
  Geodesics_run r = run_geodesics(s, run.progress);
  Run_summary_json json = geodesics_summary_json(s, r);
  json.write((std::filesystem::path(s.output) / "summary.json").string(), run, EXIT_OK);
  std::cout << r.summary;
  return EXIT_OK;
}

} // namespace mdcs_cli
