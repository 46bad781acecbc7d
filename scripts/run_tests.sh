#!/usr/bin/env bash
# Installs the dependencies, builds the whole test suite and runs it with CTest.
#   scripts/run_tests.sh              default run (Release, long cases excluded)
#   scripts/run_tests.sh --sanitize   the same under AddressSanitizer + UndefinedBehaviorSanitizer
#   scripts/run_tests.sh --long       also run the cases tagged [.long]
#   scripts/run_tests.sh --tsan       only the parallel test cases (test/*/test_parallel_*.cpp) under ThreadSanitizer
# Build folders: build/ (or build-sanitize/, build-tsan/) at the repository root.
set -euo pipefail
cd "$(dirname "$0")/.."

sanitize=OFF; long=0; tsan=0
for arg in "$@"; do
  case "$arg" in
    --sanitize) sanitize=ON ;;
    --long) long=1 ;;
    --tsan) tsan=1 ;;
    *) echo "run_tests.sh: unknown option '$arg' (use --sanitize, --long, --tsan)" >&2; exit 2 ;;
  esac
done

bash scripts/install_dependencies.sh

if [ "$tsan" = 1 ]; then
  jobs=$(nproc 2>/dev/null || echo 2)
  cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DMDCS_TSAN=ON -DMDCS_BUILD_TESTS=ON \
    -DMDCS_BUILD_EXAMPLES=OFF -DMDCS_BUILD_CLI=OFF -DMDCS_BUILD_BENCHMARKS=OFF -DMDCS_BUILD_DOC=OFF >/dev/null
  cmake --build build-tsan -j "$jobs"
  ctest --test-dir build-tsan --output-on-failure -L tsan
  exit 0
fi

if [ "$sanitize" = ON ]; then build=build-sanitize; type=RelWithDebInfo; else build=build; type=Release; fi
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=$type -DMDCS_SANITIZE=$sanitize \
  -DMDCS_BUILD_TESTS=ON -DMDCS_BUILD_EXAMPLES=OFF -DMDCS_BUILD_CLI=ON -DMDCS_BUILD_BENCHMARKS=OFF -DMDCS_BUILD_DOC=OFF >/dev/null
cmake --build "$build" -j "$jobs"

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=0
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
if [ "$long" = 1 ]; then
  ctest --test-dir "$build" --output-on-failure -j "$jobs"
else
  ctest --test-dir "$build" --output-on-failure -j "$jobs" -LE long
fi
