// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Constants and the relative difference used by many test files (one definition: the test files of a package are
// compiled together in the unity build, where a second definition of the same name is an error).

#ifndef MDCS_TEST_TEST_NUMBERS_H
#define MDCS_TEST_TEST_NUMBERS_H

#include <algorithm>
#include <cmath>
#include <limits>

namespace MDCS_test {

const double inf = std::numeric_limits<double>::infinity();
const double pi = 3.14159265358979323846;

// |a - b| relative to the larger magnitude; 0 when a == b (infinities of the same sign included).
inline double relative_difference(double a, double b)
{
  return a == b ? 0 : std::abs(a - b) / std::max(std::abs(a), std::abs(b));
}

} // namespace MDCS_test

#endif // MDCS_TEST_TEST_NUMBERS_H
