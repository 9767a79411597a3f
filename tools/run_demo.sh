#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds pednav and runs the main job on its built-in default: a simulated
# walk through the foot pipeline, printing its error and writing a plot to
# out/demo/. Installs missing packages first. Extra arguments go to `pednav demo`.
set -euo pipefail
cd "$(dirname "$0")/.."
tools/install_deps.sh
jobs=$(nproc 2>/dev/null || echo 2)
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$jobs"
build/bin/pednav demo --out out/demo "$@"
