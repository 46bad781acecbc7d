#!/usr/bin/env bash
# Installs the dependencies, builds the command-line tool and runs `mdcs demo`, which runs every capability
# on default data and writes pictures (SVG, and PNG where rsvg-convert exists) and a summary.
#   scripts/run_demo.sh [OUTPUT_FOLDER]      (default: mdcs-output)
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-mdcs-output}"
bash scripts/install_dependencies.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release -DMDCS_BUILD_EXAMPLES=ON >/dev/null
cmake --build build --target mdcs -j "$jobs"
./build/examples/mdcs/mdcs demo --output "$out"
