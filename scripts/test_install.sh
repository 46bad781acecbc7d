#!/usr/bin/env bash
# Installs MDCS into a temporary prefix and builds a tiny consumer project with find_package(MDCS).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_dependencies.sh
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cmake -S . -B "$tmp/build" -DMDCS_BUILD_TESTS=OFF -DMDCS_BUILD_EXAMPLES=OFF -DMDCS_BUILD_DOC=OFF \
  -DCMAKE_INSTALL_PREFIX="$tmp/prefix" >/dev/null
cmake --install "$tmp/build" >/dev/null
cmake -S test/install_consumer -B "$tmp/consumer" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$tmp/prefix" >/dev/null
cmake --build "$tmp/consumer" -j 2 >/dev/null
"$tmp/consumer/consumer"
echo "test_install: find_package(MDCS) consumer built and ran"
