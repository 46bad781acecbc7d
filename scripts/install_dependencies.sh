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
