#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Peak resident memory of `pednav run --mount foot` (track CSV written) and of
# `pednav inspect` on canonical CSVs of about SIZE_MB megabytes each (default
# 30, 200 and 1000), and of the refusal of /dev/zero.
#   bench/large_input_rss.sh build/bin/pednav [SIZE_MB ...]
# The CSVs are the simulated 9-minute building tour at 400 Hz with magnetometer
# and barometer (`pednav sim --route building_tour --mount foot --rate 400
# --seed 2`, 29 MB), repeated with its times shifted until the size is reached,
# written under $TMPDIR (else /tmp) and removed at the end. Prints, per size:
# the file, the IMU samples, the peak RSS (GNU time's "Maximum resident set
# size") of each command, and the run's wall time and samples per second. Not a
# test: the figures depend on the allocator, the disk cache and the machine.
set -eu
PEDNAV=${1:?usage: large_input_rss.sh PEDNAV [SIZE_MB ...]}
shift
SIZES=${*:-30 200 1000}
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT

"$PEDNAV" sim --route building_tour --mount foot --rate 400 --seed 2 --out "$DIR/sim" >/dev/null

# Runs the command given under GNU time; sets PEAK_MIB (peak RSS) and SECONDS_TAKEN (wall time).
measure() {
    /usr/bin/time -v -o "$DIR/time.txt" "$@" >"$DIR/stdout.txt" 2>/dev/null || true
    PEAK_MIB=$(awk -F: '/Maximum resident/ {gsub(/ /, "", $2); printf "%.0f", $2 / 1024}' "$DIR/time.txt")
    SECONDS_TAKEN=$(awk '/Elapsed \(wall clock\)/ {n = split($NF, p, ":"); s = 0; for (i = 1; i <= n; i++) s = s * 60 + p[i]; printf "%.1f", s}' "$DIR/time.txt")
}

for size_mb in $SIZES; do
    /usr/bin/python3 - "$DIR/sim/input.csv" "$DIR/large.csv" "$size_mb" <<'PY'
import sys
src, dst, size_mb = sys.argv[1], sys.argv[2], int(sys.argv[3])
with open(src) as f:
    lines = [line for line in f if line.strip() and not line.startswith("#")]
header, rows = lines[0], [line.split(",", 1) for line in lines[1:]]
times = [float(t) for t, _ in rows]
period = times[-1] - times[0] + (times[1] - times[0])
target = size_mb * 1000000
with open(dst, "w") as out:
    out.write(header)
    written, copy = len(header), 0
    while written < target:
        shift = copy * period
        block = []
        for t, (_, rest) in zip(times, rows):
            line = "%.6f,%s" % (t + shift, rest)
            block.append(line)
            written += len(line)
            if written >= target:
                break
        out.write("".join(block))
        copy += 1
PY
    bytes=$(stat -c %s "$DIR/large.csv")
    measure "$PEDNAV" run --mount foot --input "$DIR/large.csv" --output "$DIR/track.csv"
    run_mib=$PEAK_MIB
    run_s=$SECONDS_TAKEN
    samples=$(sed -n 's/^samples \([0-9]*\),.*/\1/p' "$DIR/stdout.txt")
    measure "$PEDNAV" inspect "$DIR/large.csv"
    echo "file $((bytes / 1000000)) MB, $samples IMU samples: run peak RSS $run_mib MiB, $run_s s" \
         "($(awk "BEGIN {printf \"%.2f\", $samples / $run_s / 1e6}") M samples/s); inspect peak RSS $PEAK_MIB MiB"
    rm -f "$DIR/large.csv" "$DIR/track.csv"
done
measure "$PEDNAV" inspect /dev/zero
echo "/dev/zero: refused, peak RSS $PEAK_MIB MiB"
