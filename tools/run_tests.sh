#!/usr/bin/env bash
# Builds pednav and runs every test (ctest). Installs missing packages first.
#   tools/run_tests.sh              Release build in build/, all tests
#   tools/run_tests.sh --sanitize   ASan+UBSan build in build-asan/, all tests
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
flags=(-DCMAKE_BUILD_TYPE=Release)
if [ "${1:-}" = "--sanitize" ]; then
  build=build-asan
  flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DPEDNAV_SANITIZE=ON)
  tools/install_deps.sh
else
  tools/install_deps.sh
fi
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B "$build" "${flags[@]}"
cmake --build "$build" -j "$jobs"
cd "$build"
ctest --output-on-failure -j "$jobs"
