#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Builds pednav and runs its tests (ctest). Installs missing packages first,
# including the JDK and JUnit 5 for the Java binding's tests.
#   tools/run_tests.sh              every test: the Release build in build/ with its tests, then
#                                   --fuzz, then --tsan, each phase timed (what .ci/run runs)
#   tools/run_tests.sh --release    only the Release build in build/ and its tests
#   tools/run_tests.sh --sanitize   clang ASan+UBSan build (preset asan-ubsan) in build-asan/: every
#                                   test but those labelled ${PEDNAV_SANITIZE_SKIP_LABELS:-slow}, and
#                                   the bounded run of every libFuzzer target (label fuzz)
#   tools/run_tests.sh --tsan       ThreadSanitizer build (preset tsan) in build-tsan/: the tests
#                                   labelled threads
#   tools/run_tests.sh --fuzz       the same ASan+UBSan build, only the fuzz targets and their bounded
#                                   runs (label fuzz, about 50 s on 2 cores)
#   (the whole suite under ASan+UBSan, --sanitize, does not fit CI's 20 minutes on 2 cores:
#   README "Reliability")
#   PEDNAV_BUILD_JAVA=OFF tools/run_tests.sh   without the Java binding
set -euo pipefail
cd "$(dirname "$0")/.."
mode="${1:-}"
case "$mode" in
  ""|--release|--sanitize|--fuzz|--tsan) ;;
  *) echo "usage: tools/run_tests.sh [--release|--sanitize|--fuzz|--tsan]" >&2; exit 2 ;;
esac
jobs=$(nproc 2>/dev/null || echo 2)
java="${PEDNAV_BUILD_JAVA:-ON}"

deps() {
  local extra=()
  [ "$java" = "OFF" ] || extra+=(--java)
  if [ "$mode" != "--release" ]; then extra+=(clang-14 libclang-rt-14-dev); fi
  tools/install_deps.sh "${extra[@]}"
}

phase_release() {
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release "-DPEDNAV_BUILD_JAVA=$java"
  cmake --build build -j "$jobs"
  ctest --test-dir build --output-on-failure -j "$jobs"
}

# The Java binding's tests need GCC's ASan runtime (bindings/java): not in this clang build;
# the Python tests are not built in sanitizer builds (bindings/python).
phase_sanitize() {
  cmake --preset asan-ubsan
  cmake --build build-asan -j "$jobs"
  local skip="${PEDNAV_SANITIZE_SKIP_LABELS:-slow}"
  ASAN_OPTIONS="detect_leaks=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}" \
  UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}" \
    ctest --test-dir build-asan --output-on-failure -j "$jobs" ${skip:+-LE "$skip"}
}

phase_fuzz() {
  cmake --preset asan-ubsan
  cmake --build build-asan -j "$jobs" --target pednav_fuzzers
  ctest --test-dir build-asan --output-on-failure -j "$jobs" -L '^fuzz$'
}

phase_tsan() {
  cmake --preset tsan
  cmake --build build-tsan -j "$jobs" --target pednav_threads_tests
  TSAN_OPTIONS="halt_on_error=1:second_deadlock_stack=1${TSAN_OPTIONS:+:$TSAN_OPTIONS}" \
    ctest --test-dir build-tsan --output-on-failure -j "$jobs" -L '^threads$'
}

timed() {
  local start=$SECONDS
  "$@"
  echo "run_tests: $1 took $((SECONDS - start)) s"
}

deps
case "$mode" in
  "")
    timed phase_release
    timed phase_fuzz
    timed phase_tsan ;;
  --release) phase_release ;;
  --sanitize) timed phase_sanitize ;;
  --fuzz) timed phase_fuzz ;;
  --tsan) timed phase_tsan ;;
esac
