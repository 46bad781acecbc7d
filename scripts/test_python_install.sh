#!/usr/bin/env bash
# Checks the README's install commands for the Python package mdcs: a venv made from Debian's /usr/bin/python3 with
# --system-site-packages, "pip install --no-build-isolation ./python" offline (--no-index: nothing is downloaded),
# then the pytest suite against the installed package (default run; --long adds the long cases).
# A few minutes: pip compiles the extension (MDCS_BUILD_JOBS=N compile jobs, default 2; MDCS_CMAKE_ARGS passes more
# CMake arguments, e.g. "-DCMAKE_CXX_COMPILER_LAUNCHER=ccache").
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
long=()
for arg in "$@"; do
  case "$arg" in
    --long) long=(--run-long) ;;
    *) echo "test_python_install.sh: unknown option '$arg' (use --long)" >&2; exit 2 ;;
  esac
done
bash scripts/install_dependencies.sh
tmp=$(mktemp -d)
# pip builds in the source tree (python/build, python/mdcs.egg-info): removed afterwards unless they were there before.
leftovers=()
for d in "$root/python/build" "$root/python/mdcs.egg-info"; do [ -e "$d" ] || leftovers+=("$d"); done
trap 'rm -rf "$tmp" "${leftovers[@]}"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$tmp/venv"
"$tmp/venv/bin/pip" install --no-index --no-build-isolation "$root/python"
# From an empty folder, so that "import mdcs" finds the installed package, not python/mdcs of the source tree.
cd "$tmp"
"$tmp/venv/bin/python" -c "import mdcs, mdcs._mdcs; print('installed mdcs', mdcs.__version__, 'at', mdcs.__file__)"
"$tmp/venv/bin/python" -m pytest -q -p no:cacheprovider "${long[@]}" "$root/python/tests"
echo "test_python_install: pip install from the source tree and the pytest suite passed"
