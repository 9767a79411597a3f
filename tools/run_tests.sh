#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds pednav and runs every test (ctest). Installs missing packages first,
# including the JDK and JUnit 5 for the Java binding's tests.
#   tools/run_tests.sh              Release build in build/, all tests
#   tools/run_tests.sh --sanitize   ASan+UBSan build in build-asan/, all tests
#   PEDNAV_BUILD_JAVA=OFF tools/run_tests.sh   without the Java binding
set -euo pipefail
cd "$(dirname "$0")/.."
build=build
flags=(-DCMAKE_BUILD_TYPE=Release)
case "${1:-}" in
  "") ;;
  --sanitize)
    build=build-asan
    flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DPEDNAV_SANITIZE=ON) ;;
  *) echo "usage: tools/run_tests.sh [--sanitize]" >&2; exit 2 ;;
esac
java="${PEDNAV_BUILD_JAVA:-ON}"
flags+=("-DPEDNAV_BUILD_JAVA=$java")
if [ "$java" = "OFF" ]; then
  tools/install_deps.sh
else
  tools/install_deps.sh --java
fi
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B "$build" "${flags[@]}"
cmake --build "$build" -j "$jobs"
cd "$build"
ctest --output-on-failure -j "$jobs"
