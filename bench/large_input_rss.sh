#!/bin/sh
# SPDX-License-Identifier: Apache-2.0
# Peak resident memory of `pednav inspect` on a generated canonical CSV of
# SIZE_MB megabytes (default 200), and of the refusal of /dev/zero.
#   bench/large_input_rss.sh build/bin/pednav [SIZE_MB]
# Prints the file size, the peak RSS (GNU time's "Maximum resident set size")
# and their ratio. Not a test: the figure depends on the allocator.
set -eu
PEDNAV=${1:?usage: large_input_rss.sh PEDNAV [SIZE_MB]}
SIZE_MB=${2:-200}
DIR=$(mktemp -d)
trap 'rm -rf "$DIR"' EXIT
/usr/bin/python3 - "$DIR/large.csv" "$SIZE_MB" <<'PY'
import sys
path, size_mb = sys.argv[1], int(sys.argv[2])
row = "%.2f,0.05123,-0.03456,9.81234,0.001234,-0.002345,0.000567\n"
with open(path, "w") as f:
    f.write("t,ax,ay,az,gx,gy,gz\n")
    i, written = 0, 0
    block = []
    while written < size_mb * 1000000:
        line = row % (i * 0.01)
        block.append(line)
        written += len(line)
        i += 1
        if len(block) == 100000:
            f.write("".join(block))
            block = []
    f.write("".join(block))
PY
bytes=$(stat -c %s "$DIR/large.csv")
peak_kb=$(/usr/bin/time -v "$PEDNAV" inspect "$DIR/large.csv" 2>&1 >/dev/null | awk -F: '/Maximum resident/ {gsub(/ /, "", $2); print $2}')
echo "file $bytes bytes, peak RSS $((peak_kb / 1024)) MiB, ratio $(awk "BEGIN {printf \"%.2f\", $peak_kb * 1024 / $bytes}")"
zero_kb=$(/usr/bin/time -v "$PEDNAV" inspect /dev/zero 2>&1 >/dev/null | awk -F: '/Maximum resident/ {gsub(/ /, "", $2); print $2}')
echo "/dev/zero: refused, peak RSS $((zero_kb / 1024)) MiB"
