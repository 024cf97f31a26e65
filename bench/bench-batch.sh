#!/bin/sh
# bench-batch.sh PROGRAM DATADIR [CONES] [PROCESSES] -- small cones
# through one `batch` process against one process per cone.
#
# CONES requests (default 10000) cycle over every feasible mode of the
# Section 4 example and of the two-fixel disk (2 fixels each) and go to
# one `PROGRAM batch`; then PROCESSES runs (default 1000) of `PROGRAM cone
# --format=json` on the same requests, one process each, are timed and
# scaled to CONES (10,000 processes take minutes on a loaded machine; the
# per-process cost does not depend on the count).  Prints the time per
# cone of each and their ratio.  Wall-clock times (date +%s%N, GNU).
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

W=${1:?usage: bench-batch.sh PROGRAM DATADIR [CONES] [PROCESSES]}
D=${2:?usage: bench-batch.sh PROGRAM DATADIR [CONES] [PROCESSES]}
cones=${3:-10000}
procs=${4:-1000}
tmp=$(mktemp -d "${TMPDIR:-/tmp}/bench-batch.XXXXXX") || exit 1
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM

: > "$tmp/pairs"
for p in "$D/section4.wc" "$D/disk-two-fixels.wc"; do
    for m in $("$W" modes "$p"); do
        printf '%s %s\n' "$p" "$m" >> "$tmp/pairs"
    done
done
npairs=$(wc -l < "$tmp/pairs")
# The requests, cycling over the pairs.
awk -v n="$cones" '{ p[NR] = $1; m[NR] = $2 }
    END { for (i = 0; i < n; i++) { k = i % NR + 1
          printf "{\"command\": \"cone\", \"problem\": \"%s\", \"mode\": \"%s\"}\n", p[k], m[k] } }' \
    "$tmp/pairs" > "$tmp/requests"

now() { date +%s%N; }

t0=$(now)
"$W" batch "$tmp/requests" > "$tmp/batch.out" || { echo "bench-batch: batch failed" >&2; exit 1; }
t1=$(now)
[ "$(wc -l < "$tmp/batch.out")" -eq "$cones" ] || { echo "bench-batch: short answer" >&2; exit 1; }

head -n "$procs" "$tmp/requests" | sed 's/.*"problem": "\([^"]*\)", "mode": "\([^"]*\)".*/\1 \2/' > "$tmp/args"
t2=$(now)
while read -r p m; do
    "$W" cone --format=json "$p" "$m"
done < "$tmp/args" > "$tmp/procs.out"
t3=$(now)
# The first PROCESSES answers must be the batch's, byte for byte.
head -n "$procs" "$tmp/batch.out" | cmp -s - "$tmp/procs.out" || { echo "bench-batch: answers differ" >&2; exit 1; }

awk -v c="$cones" -v p="$procs" -v b="$((t1 - t0))" -v s="$((t3 - t2))" -v k="$npairs" 'BEGIN {
    bc = b / c / 1e6; pc = s / p / 1e6
    printf "bench-batch: %d small cones (%d problem/mode pairs, 2 fixels)\n", c, k
    printf "  %-34s %10s %12s\n", "", "total s", "ms per cone"
    printf "  %-34s %10.2f %12.3f\n", "one batch process, " c " requests", b / 1e9, bc
    printf "  %-34s %10.2f %12.3f\n", p " processes, scaled to " c, s / 1e9 * c / p, pc
    printf "  one process per cone / batch: %.1f x\n", pc / bc
}'
