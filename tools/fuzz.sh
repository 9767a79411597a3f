#!/usr/bin/env bash
# SPDX-License-Identifier: Apache-2.0
# Runs every libFuzzer target of fuzz/ for SECONDS each (default 600) and
# prints, per target, the executions, the rate, the corpus size and the
# findings (crash, leak, timeout and out-of-memory inputs, saved under
# <build>/fuzz/findings/). Exits 1 when any target found something.
#   tools/fuzz.sh [SECONDS] [TARGET...]     e.g. tools/fuzz.sh 60 push_records map_geojson
# Builds the clang ASan+UBSan fuzz build (preset "fuzz", in build-fuzz/) first
# when it is not there. PEDNAV_FUZZ_JOBS (default 2) targets run at once; the
# corpus each target grows is kept in <build>/fuzz/work/<target> and reused.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-600}"
shift || true
build="${PEDNAV_FUZZ_BUILD:-build-fuzz}"
jobs="${PEDNAV_FUZZ_JOBS:-2}"
case "$seconds" in ''|*[!0-9]*) echo "usage: tools/fuzz.sh [SECONDS] [TARGET...]" >&2; exit 2 ;; esac
if [ ! -f "$build/CMakeCache.txt" ]; then
  cmake --preset fuzz
fi
cmake --build "$build" -j "$jobs" --target pednav_fuzzers >/dev/null
targets=("$@")
if [ ${#targets[@]} -eq 0 ]; then
  mapfile -t targets < <(ctest --test-dir "$build" -N -L '^fuzz$' | sed -n 's/.*Test *#[0-9]*: fuzz\.\(.*\)$/\1/p')
fi
logs="$build/fuzz/logs"
mkdir -p "$logs" "$build/fuzz/findings"
run_one() {
  local name="$1"
  local args
  # The arguments of its ctest entry, with this run's time.
  args=$(ctest --test-dir "$build" -N -V -R "^fuzz\.${name}\$" | sed -n 's/.*Test command: //p' | head -n 1)
  [ -n "$args" ] || { echo "$name: no such fuzz target" >&2; return 1; }
  # shellcheck disable=SC2086
  eval set -- $args
  local exe="$1"
  shift
  local rest=()
  for a in "$@"; do
    case "$a" in -max_total_time=*) rest+=("-max_total_time=$seconds") ;; *) rest+=("$a") ;; esac
  done
  ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 "$exe" "${rest[@]}" >"$logs/$name.log" 2>&1 || true
}
running=0
for t in "${targets[@]}"; do
  run_one "$t" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then wait -n || true; running=$((running - 1)); fi
done
wait || true
found=0
printf '%-36s %14s %10s %8s  %s\n' target executions exec/s corpus findings
for t in "${targets[@]}"; do
  log="$logs/$t.log"
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log" | tail -n 1)
  corpus=$(find "$build/fuzz/work/$t" -type f 2>/dev/null | wc -l)
  findings=$(grep -E '^(==[0-9]+==ERROR|SUMMARY: |.*runtime error:|==[0-9]+== ERROR: libFuzzer)' "$log" | head -n 1 || true)
  artifact=$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | head -n 1)
  if [ -n "$findings" ] || [ -n "$artifact" ]; then found=1; fi
  printf '%-36s %14s %10s %8s  %s\n' "$t" "${execs:-?}" "${rate:-?}" "$corpus" \
    "${findings:+$findings }${artifact:-none}"
done
echo "logs: $logs"
exit "$found"
