// mdcs: the command-line tool of MDCS (Minimal Discrete Curves and Surfaces).
//   mdcs --help | mdcs --version | mdcs <command> --help
// Every sub-command lives in its own translation unit (cmd_<name>.cpp); this file dispatches and turns errors
// into the documented exit codes.
#include "commands.h"

#include <CGAL/MDCS/progress.h>

#include <exception>
#include <iostream>
#include <new>
#include <string>

namespace {

using namespace mdcs_cli;

const Command_entry commands[] = {
  {"demo", "run every capability on default data; pictures and summary.md in an output folder", demo_spec, run_demo_command},
  {"curve", "globally minimal curve for a univariate variational problem (catenoid, arc length, blobs)", curve_spec,
   run_curve_command},
  {"geodesics", "geodesic distances (exact or approximate) and shortest paths on a triangle mesh", geodesics_spec,
   run_geodesics_command},
  {"mincut", "max-flow / min-cut of a DIMACS file with the Min_cut component", mincut_spec, run_mincut_command},
  {"mwt", "minimum weight triangulation of a point set, certified (triangle LP, pruning)", mwt_spec, run_mwt_command},
  {"surface", "globally minimal surface for a bivariate variational problem (random-plane BSP complex)", surface_spec,
   run_surface_command},
  {"silhouette", "simplified silhouette loops of a triangle mesh for a view (loop picking, loop mapping)", silhouette_spec,
   run_silhouette_command},
};

std::string main_usage()
{
  std::string s =
    "usage: mdcs <command> [options]        (mdcs <command> --help for its options; mdcs --version)\n"
    "MDCS - Minimal Discrete Curves and Surfaces: globally minimal discrete curves and surfaces by min-cut, exact\n"
    "geodesics, certified minimum weight triangulations, simplified silhouettes.\n"
    "commands:\n";
  for(const Command_entry& c : commands) {
    std::string name = c.name;
    s += "  " + name + std::string(name.size() < 11 ? 11 - name.size() : 1, ' ') + c.summary + "\n";
  }
  s += "options of every command: --threads N (0: all), --quiet, --heartbeat S, --help, --version; most also\n"
       "--output DIR (with summary.json, the run as data) and --no-picture.\n"
       "exit codes: 0 success, 1 runtime error (a failed write or a result that failed its check included),\n"
       "2 wrong command line, 3 bad input data, 4 infeasible problem\n";
  return s;
}

} // namespace

int main(int argc, char** argv)
{
  install_signal_handlers();
  const std::string first = argc > 1 ? argv[1] : "";
  if(argc < 2 || first == "--help" || first == "-h" || first == "help") {
    (argc < 2 ? std::cerr : std::cout) << main_usage();
    return argc < 2 ? EXIT_USAGE : EXIT_OK;
  }
  if(first == "--version") {
    std::cout << "mdcs " << mdcs_version() << "\n";
    return EXIT_OK;
  }
  const Command_entry* command = nullptr;
  for(const Command_entry& c : commands)
    if(first == c.name) command = &c;
  if(!command) {
    std::cerr << "mdcs: unknown command '" << first << "'\n" << main_usage();
    return EXIT_USAGE;
  }
  const std::string name = command->name;
  try {
    const Command_spec spec = command->spec();
    if(command_line_asks(argc, argv, 2, "help")) {
      std::cout << help_text(spec);
      return EXIT_OK;
    }
    if(command_line_asks(argc, argv, 2, "version")) {
      std::cout << "mdcs " << mdcs_version() << "\n";
      return EXIT_OK;
    }
    Invocation run(spec, argc, argv, 2);
    return command->run(run);
  } catch(const Usage_error& e) {
    std::cerr << "mdcs " << name << ": " << e.what() << "\n(mdcs " << name << " --help lists the options)\n";
    return EXIT_USAGE;
  } catch(const Input_error& e) {
    std::cerr << "mdcs " << name << ": bad input: " << e.what() << "\n";
    return EXIT_BAD_INPUT;
  } catch(const std::invalid_argument& e) {
    std::cerr << "mdcs " << name << ": invalid input: " << e.what() << "\n";
    return EXIT_BAD_INPUT;
  } catch(const std::domain_error& e) {
    std::cerr << "mdcs " << name << ": invalid input: " << e.what() << "\n";
    return EXIT_BAD_INPUT;
  } catch(const CGAL::MDCS::Operation_cancelled& e) {
    std::cerr << "mdcs " << name << ": " << (interrupted() ? "interrupted; " : "") << e.what() << "\n";
    return EXIT_FAILURE_RUNTIME;
  } catch(const Result_error& e) {
    std::cerr << "mdcs " << name << ": result refused: " << e.what() << "\n";
    return EXIT_FAILURE_RUNTIME;
  } catch(const std::bad_alloc&) {
    std::cerr << "mdcs " << name << ": error: out of memory\n";
    return EXIT_FAILURE_RUNTIME;
  } catch(const std::exception& e) {
    std::cerr << "mdcs " << name << ": error: " << e.what() << "\n";
    return EXIT_FAILURE_RUNTIME;
  }
}
