// `mdcs demo`: its option table and its run (cmd_demo.h and the demo_*.cpp sections). A build configured with
// -DMDCS_CLI_DEMO=OFF (the sanitizer build of the test suite) keeps the option table and leaves the run out.
#include "commands.h"
#ifdef MDCS_CLI_DEMO
#include "cmd_demo.h"
#else
#include "cli_common.h"
#endif

#include <iostream>
#include <stdexcept>

namespace mdcs_cli {

Command_spec demo_spec()
{
  Command_spec s;
  s.name = "demo";
  s.synopsis = "[--output DIR] [--quick] [--quiet]";
  s.description =
    "Runs every capability on default data and writes pictures (SVG, PNG where rsvg-convert exists), CSV files,\n"
    "summary.md and summary.json into DIR:\n"
    "  catenoid          minimal surface of rotation, R = 2, 1600 random lines; exact answer dashed\n"
    "  goldschmidt       R = 1.7: the global optimum drops to the axis; local descent stays on the catenoid\n"
    "  blobs             length weighted by a density of blobs (many local minima), fixed and relaxed ends\n"
    "  regular           the regular grid C_12 (dynamic programming)\n"
    "  convergence       catenoid energy error vs grid size, random lines vs C_n (CSV + plot)\n"
    "  mincut            the catenoid's dual network written as DIMACS and re-solved by all three max-flow engines\n"
    "  geodesics         exact geodesic distances and shortest paths on CGAL's elephant and Chinese dragon (a\n"
    "                    generated torus without CGAL's data), checked against Surface_mesh_shortest_path;\n"
    "                    in geodesics-MESH/ folders\n"
    "  surface           minimal surfaces (BSP plane arrangement + min-cut): saddle, heavy membrane, Scherk (exact\n"
    "                    area), a saddle on an L-shaped polygonal domain, and a blob density with plane selection\n"
    "                    and a histogram of 8 local descents from random starts against it\n"
    "  mwt               minimum weight triangulations by the triangle LP: 1000 uniform and 400 clustered points\n"
    "                    certified, the thesis's 13-wheel (LP 18.7636 fractional, MWT 18.7989 by branch and bound)\n"
    "  silhouettes       loop picking and loop mapping (min cut) on a 20k-face bunny with a 1k-face coarse mesh,\n"
    "                    12-frame rotation\n";
  s.options = {flag_option("quick", "smaller grids and meshes, fewer runs (for a fast smoke run)")};
  add_common_options(s, Common_options{"mdcs-output", true, false});
  s.notes = "Exit code 1 when a consistency check fails (summary.md and summary.json say which).\n";
  return s;
}

int run_demo_command(Invocation& run)
{
#ifndef MDCS_CLI_DEMO
  (void)run;
  throw std::runtime_error("this mdcs was built without the demo (-DMDCS_CLI_DEMO=OFF, as the sanitizer build of the "
                           "test suite is); scripts/run_demo.sh builds and runs it");
#else
  const std::string output = run.options.text("output");
  Json_object checks;
  const bool ok = run_demo(output, run.options.flag("quick"), run.progress, checks);
  const int code = ok ? EXIT_OK : EXIT_FAILURE_RUNTIME;
  Run_summary_json json;
  json.results.add("checks_passed", ok).add("checks", checks).add("summary_md", (std::filesystem::path(output) / "summary.md").string());
  json.write((std::filesystem::path(output) / "summary.json").string(), run, code);
  return code;
#endif
}

} // namespace mdcs_cli
