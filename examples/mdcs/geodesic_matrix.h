// `mdcs geodesics --matrix npy|mtx`: the matrix mode of the geodesics command (geodesic_matrix.cpp).
#ifndef MDCS_CLI_GEODESIC_MATRIX_H
#define MDCS_CLI_GEODESIC_MATRIX_H

#include "cli_common.h"
#include "geodesics_options.h"

namespace mdcs_cli {

// Runs the matrix mode (`--matrix` given) with the parsed settings; returns the exit code.
int run_geodesic_matrix(Invocation& run, const Geodesics_settings& s);

} // namespace mdcs_cli

#endif // MDCS_CLI_GEODESIC_MATRIX_H
