// Copyright (c) 2026 MDCS contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The thread counts every parallel test case runs with, against the sequential run.

#ifndef MDCS_TEST_THREAD_COUNTS_H
#define MDCS_TEST_THREAD_COUNTS_H

#include <cstddef>

namespace MDCS_test {

#ifdef MDCS_TEST_TSAN
// Under ThreadSanitizer: the reference and one run with three threads. TSan finds a race from the order of memory
// accesses and synchronisations in one run with several threads, not from timing, so more runs add no findings;
// they only multiply a build that is 5-15x slower (2 and 8 threads are checked for equal results in the other
// builds). Three threads: blocks that do not divide evenly among the workers.
constexpr std::size_t thread_counts[] = {1, 3};
#else
// 1: the reference; 2 and 3: even and uneven shares of the blocks; 8: more threads than the machine has cores.
constexpr std::size_t thread_counts[] = {1, 2, 3, 8};
#endif

} // namespace MDCS_test

#endif // MDCS_TEST_THREAD_COUNTS_H
