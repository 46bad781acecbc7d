#!/usr/bin/env bash
# Installs every dependency of MDCS from Debian 12 packages. Idempotent: when everything is already
# installed it does nothing; otherwise it runs `apt-get update` and installs what is missing.
set -euo pipefail

packages=(
  build-essential cmake                 # compiler and build system
  libcgal-dev                           # CGAL 5.5 (header-only), the geometric foundation
  libcgal-demo                          # /usr/share/doc/libcgal-dev/data.tar.gz: ~140 real meshes
  libboost-dev libboost-graph-dev       # Boost.Graph max-flow, Boost.Math quadrature
  libeigen3-dev libgmp-dev libmpfr-dev  # linear algebra and exact / multi-precision arithmetic
  catch2                                # test framework (v2)
  libglpk-dev coinor-libclp-dev         # LP solvers (minimum weight triangulation)
  libtbb-dev                            # optional parallelism
  libopenmesh-dev                       # OpenMesh: the tests run the mesh algorithms on its TriMesh too
  doxygen libjs-mathjax                 # offline manual (formulas through the local MathJax)
  librsvg2-bin                          # rsvg-convert: PNG copies of the SVG pictures
  python3                               # the runner of the command-line cases (test/cli)
  python3-dev pybind11-dev python3-pybind11   # the Python package mdcs (python/): headers and pybind11
  python3-numpy python3-scipy           # its arrays and sparse matrices
  python3-pytest                        # its test suite
  python3-dask python3-distributed      # mdcs.dask (LocalCluster in the tests)
  python3-venv python3-pip python3-setuptools python3-wheel   # pip install from the source tree, offline
  python3-tqdm python3-zarr             # optional: progress bars, Zarr output of mdcs.dask
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_dependencies: all ${#packages[@]} packages are installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null 2>&1 || { echo "install_dependencies: run as root (or install sudo)" >&2; exit 1; }
  SUDO="sudo"
fi
echo "install_dependencies: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
echo "install_dependencies: done"
