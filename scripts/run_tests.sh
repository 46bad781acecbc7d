#!/usr/bin/env bash
# Installs the dependencies, builds every test suite and runs it with CTest.
#   scripts/run_tests.sh             every suite: the C++ test cases and the command-line cases with the C++ code
#                                    built under AddressSanitizer + UndefinedBehaviorSanitizer (build-sanitize/),
#                                    and the Python package in Release with its pytest suite (build/)
#   scripts/run_tests.sh --release   the same suites with the C++ code in Release (build/): quicker to build and
#                                    run, without the memory checks
#   scripts/run_tests.sh --long      also the long cases (C++ [.long], Python's long cases)
#   scripts/run_tests.sh --tsan      only the parallel test cases (test/*/test_parallel_*.cpp) under ThreadSanitizer
#                                    (build-tsan/)
# Why the sanitizers by default: the suite is where hostile input is tried (malformed files, absurd options), and
# a memory error there must fail the run, not pass by luck; building it a second time in Release would double the
# build, which CI cannot afford on two cores. (--sanitize is accepted and means the default.)
set -euo pipefail
cd "$(dirname "$0")/.."

release=0; long=0; tsan=0
for arg in "$@"; do
  case "$arg" in
    --release) release=1 ;;
    --sanitize) release=0 ;;
    --long) long=1 ;;
    --tsan) tsan=1 ;;
    *) echo "run_tests.sh: unknown option '$arg' (use --release, --long, --tsan)" >&2; exit 2 ;;
  esac
done

bash scripts/install_dependencies.sh
jobs=$(nproc 2>/dev/null || echo 2)
off="-DMDCS_BUILD_EXAMPLES=OFF -DMDCS_BUILD_BENCHMARKS=OFF -DMDCS_BUILD_DOC=OFF"
labels=(-LE long); [ "$long" = 1 ] && labels=()

if [ "$tsan" = 1 ]; then
  cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMDCS_TSAN=ON -DMDCS_BUILD_TESTS=ON \
    -DMDCS_BUILD_CLI=OFF -DMDCS_BUILD_PYTHON=OFF $off >/dev/null
  cmake --build build-tsan -j "$jobs"
  ctest --test-dir build-tsan --output-on-failure -j "$jobs" -L tsan
  exit 0
fi

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1

if [ "$release" = 1 ]; then
  # Everything in one Release tree.
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DMDCS_SANITIZE=OFF -DMDCS_BUILD_TESTS=ON -DMDCS_BUILD_CLI=ON \
    -DMDCS_BUILD_PYTHON=ON $off >/dev/null
  cmake --build build -j "$jobs"
  ctest --test-dir build --output-on-failure -j "$jobs" "${labels[@]}"
  exit 0
fi

# C++ test cases and the command-line tool under the sanitizers; the tool without its demo, which no test runs
# (10 min of compiler CPU; scripts/run_demo.sh builds and runs it).
cmake -S . -B build-sanitize -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMDCS_SANITIZE=ON -DMDCS_BUILD_TESTS=ON \
  -DMDCS_BUILD_CLI=ON -DMDCS_CLI_DEMO=OFF -DMDCS_BUILD_PYTHON=OFF $off >/dev/null
cmake --build build-sanitize -j "$jobs"
# The Python extension cannot carry the sanitizers (the interpreter is not instrumented): Release, module only.
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DMDCS_SANITIZE=OFF -DMDCS_BUILD_TESTS=OFF -DMDCS_BUILD_CLI=OFF \
  -DMDCS_BUILD_PYTHON=ON $off >/dev/null
cmake --build build -j "$jobs"

status=0
ctest --test-dir build-sanitize --output-on-failure -j "$jobs" "${labels[@]}" || status=1
ctest --test-dir build --output-on-failure -L python "${labels[@]}" || status=1
exit $status
