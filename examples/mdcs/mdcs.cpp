// mdcs: the command-line tool of MDCS (Minimal Discrete Curves and Surfaces).
//   mdcs --help | mdcs <command> --help
#include "cli_common.h"
#include "cmd_curve.h"
#include "cmd_demo.h"
#include "cmd_geodesics.h"
#include "cmd_mincut.h"
#include "cmd_mwt.h"
#include "cmd_silhouette.h"
#include "cmd_surface.h"

#include <CGAL/MDCS/progress.h>

#include <exception>
#include <iostream>
#include <string>

namespace {

const char* main_usage()
{
  return
    "usage: mdcs <command> [options]        (mdcs <command> --help for its options)\n"
    "MDCS - Minimal Discrete Curves and Surfaces: globally minimal discrete curves by min-cut, exact geodesics.\n"
    "commands:\n"
    "  demo      run every capability on default data; pictures and summary.md in an output folder\n"
    "  curve     globally minimal curve for a univariate variational problem (catenoid, arc length, blobs)\n"
    "  geodesics geodesic distances (exact or approximate) and shortest paths on a triangle mesh (OFF, PLY, OBJ, STL)\n"
    "  mincut    max-flow / min-cut of a DIMACS file with the Min_cut component\n"
    "  mwt       minimum weight triangulation of a point set, certified (triangle LP, pruning)\n"
    "  surface   globally minimal surface for a bivariate variational problem (random-plane BSP complex)\n"
    "  silhouette simplified silhouette loops of a triangle mesh for a view (loop picking, loop mapping)\n"
    "exit codes: 0 success, 1 runtime error, 2 wrong command line, 3 bad input data, 4 infeasible problem\n";
}

} // namespace

int main(int argc, char** argv)
{
  using namespace mdcs_cli;
  if(argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h" || std::string(argv[1]) == "help") {
    std::cout << main_usage();
    return argc < 2 ? EXIT_USAGE : EXIT_OK;
  }
  const std::string command = argv[1];
  const char* usage = command == "curve" ? curve_usage() : command == "demo" ? demo_usage()
                    : command == "geodesics" ? geodesics_usage() : command == "mincut" ? mincut_usage()
                    : command == "mwt" ? mwt_usage() : command == "surface" ? surface_usage()
                    : command == "silhouette" ? silhouette_usage() : main_usage();
  try {
    if(command == "curve") return command_curve(Options(argc, argv, 2, {"no-local", "quiet", "help"}));
    if(command == "demo") return command_demo(Options(argc, argv, 2, {"quick", "quiet", "help"}));
    if(command == "geodesics") return command_geodesics(Options(argc, argv, 2, {"stop-at-targets", "compare-exact", "compare-cgal", "quiet", "repair", "help"}));
    if(command == "mincut") return command_mincut(Options(argc, argv, 2, {"help"}));
    if(command == "mwt") return command_mwt(Options(argc, argv, 2, mwt_flags()));
    if(command == "surface") return command_surface(Options(argc, argv, 2, surface_flags()));
    if(command == "silhouette") return command_silhouette(Options(argc, argv, 2, silhouette_flags()));
    std::cerr << "mdcs: unknown command '" << command << "'\n" << main_usage();
    return EXIT_USAGE;
  } catch(const Usage_error& e) {
    std::cerr << "mdcs " << command << ": " << e.what() << "\n\n" << usage;
    return EXIT_USAGE;
  } catch(const Input_error& e) {
    std::cerr << "mdcs " << command << ": bad input: " << e.what() << "\n";
    return EXIT_BAD_INPUT;
  } catch(const std::invalid_argument& e) {
    std::cerr << "mdcs " << command << ": invalid input: " << e.what() << "\n";
    return EXIT_BAD_INPUT;
  } catch(const std::domain_error& e) {
    std::cerr << "mdcs " << command << ": invalid input: " << e.what() << "\n";
    return EXIT_BAD_INPUT;
  } catch(const CGAL::MDCS::Operation_cancelled& e) {
    std::cerr << "mdcs " << command << ": " << e.what() << "\n";
    return EXIT_FAILURE_RUNTIME;
  } catch(const std::exception& e) {
    std::cerr << "mdcs " << command << ": error: " << e.what() << "\n";
    return EXIT_FAILURE_RUNTIME;
  }
}
