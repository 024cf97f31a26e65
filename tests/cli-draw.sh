#!/bin/sh
# cli-draw.sh -- wrenchcone draw: every data/ problem with every figure
# kind is well-formed SVG (xmllint); the paper's examples equal their
# golden files (tests/golden/draw-*.svg); rasterised (rsvg-convert), a
# point of each drawn region, line of force, centre or state is dark and
# a point beside it is not (tests/png-pixels.py); bad input: exit status,
# the message, nothing on stdout, no file left behind.  SKIP without
# xmllint, rsvg-convert or python3.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${top_srcdir:?top_srcdir is not set}" "${WRENCHCONE:=$PWD/src/wrenchcone}"
. "$top_srcdir/tests/clitest.sh"
need xmllint rsvg-convert python3
W=$WRENCHCONE
cd "$top_srcdir" || exit 99

# Every problem, every kind (the mode: the problem's first feasible one):
# drawn by one batch of draw requests (whose "svg" is what -o writes:
# tests/schema.sh), checked by one xmllint and rendered by one
# rsvg-convert; a few processes instead of a hundred.
: > "$tmp/draws"
for f in data/*.wc; do
    mode=$("$W" modes "$f" | head -n 1)
    for kind in --modes --stability --plan --sweep=0,1/5,1 --graph \
                "--mode=$mode"; do
        "$W" draw "$kind" "$f" --print-request >> "$tmp/draws" \
            || fail "draw $kind $f --print-request"
    done
done
"$W" batch "$tmp/draws" > "$tmp/answers" 2> "$tmp/err" \
    || fail "batch of draw requests: exit $?: $(cat "$tmp/err")"
python3 -c '
import json, sys
tmp = sys.argv[1]
requests = open(tmp + "/draws").read().splitlines()
answers = open(tmp + "/answers").read().splitlines()
if len(answers) != len(requests):
    sys.exit("%d answers to %d draw requests" % (len(answers), len(requests)))
for i, (q, a) in enumerate(zip(requests, answers)):
    a = json.loads(a)
    if "svg" not in a:
        print("FAIL: %s answers %s" % (q, json.dumps(a)))
        continue
    open("%s/figure-%02d.svg" % (tmp, i), "w").write(a["svg"])
    print(q, file=open("%s/figure-%02d.request" % (tmp, i), "w"))
' "$tmp" > "$tmp/err" 2>&1 || fail "draw answers: $(cat "$tmp/err")"
grep -q FAIL "$tmp/err" && fail "$(cat "$tmp/err")"
set -- "$tmp"/figure-*.svg
[ $# -eq 36 ] || fail "$# figures drawn, want 36"
xmllint --noout "$@" 2> "$tmp/err" || fail "figures not well-formed: $(cat "$tmp/err")"
rsvg-convert -f pdf -o "$tmp/figures.pdf" "$@" 2> "$tmp/err" \
    || fail "figures that do not render: $(cat "$tmp/err")"

# The paper's examples (the issue's command lines), byte for byte.
golden() {
    name=$1; shift
    "$W" draw "$@" -o "$tmp/$name.svg" || { fail "draw $*"; return; }
    cmp -s "$tmp/$name.svg" "tests/golden/$name.svg" \
        || fail "draw $* differs from tests/golden/$name.svg"
}
golden draw-na --mode=na data/section4.wc
golden draw-modes --modes data/disk-two-fixels.wc
golden draw-strong --stability data/disk-two-fixels.wc
golden draw-goal --plan data/disk-two-fixels-insert.wc
golden draw-sweep --sweep=1/100,1/5,2/5,3/5 data/three-fixels-insert.wc
golden draw-graph --graph data/three-fixels-insert.wc

# Pixels: X,Y (plane), DX,DY (pixels), dark or light.
pixels() {
    kind=$1 file=$2; shift 2
    "$W" draw "$kind" "$file" -o "$tmp/p.svg" \
        && rsvg-convert "$tmp/p.svg" -o "$tmp/p.png" \
        && python3 tests/png-pixels.py "$tmp/p.png" "$tmp/p.svg" "$@" \
        || fail "pixels of draw $kind $file"
}
# Figure 5: the strongly stable region is the arc from (0, 1) to (-1, 0).
pixels --stability data/disk-two-fixels.wc \
    -0.70710678,0.70710678,0,0,dark 0.70710678,-0.70710678,0,0,light
# Figure 6: G_goal's arc runs from direction (5, 1) to (1, 5).
pixels --plan data/disk-two-fixels-insert.wc \
    0.70710678,0.70710678,0,0,dark -0.70710678,-0.70710678,0,0,light
# Figure 11, mu = 1/100: edge 2, s in (51210/130013, 8467/11700); s = 0.56
# is in it, s = 0.15 is not.
pixels --sweep=1/100,1/5,2/5,3/5 data/three-fixels-insert.wc \
    2.32,2.12,0,0,dark 3.55,1.3,0,0,light
# W(na): the ray (1, 0, -1) is a force along y = 1.
pixels --mode=na data/section4.wc 0.1,1,0,0,dark 0.5,0.5,0,0,light
# Mode la's witness (1, 0, -2) turns about (0, -1/2).
pixels --modes data/section4.wc 0,-0.5,0,0,dark 0.5,0.5,0,0,light
# The goal state 111 sits at (2/5, 3): its box's top edge, and left of it.
pixels --graph data/three-fixels-insert.wc 0.4,3,0,-12,dark 0.4,3,-80,0,light
# The wrench (-1, -1, 0) seats the Figure 6 disk: 00 -> 11 is admitted,
# a vertical edge from (0, 0) to (0, 2) (aa), and 10 -> 00 is not.
"$W" draw --graph --wrench=-1,-1,0 data/disk-two-fixels-insert.wc -o "$tmp/w.svg" \
    && rsvg-convert "$tmp/w.svg" -o "$tmp/w.png" \
    && python3 tests/png-pixels.py "$tmp/w.png" "$tmp/w.svg" 0,1,0,0,dark \
        -0.4,0.5,0,0,light || fail "pixels of draw --graph --wrench"
"$W" draw --graph --wrench=-1,-1,0 data/disk-two-fixels-insert.wc \
    | grep -q 'Verdict: accepted' || fail "draw --graph --wrench: no verdict"
"$W" draw --graph --wrench=1,1,0 data/disk-two-fixels-insert.wc \
    | grep -q 'Verdict: rejected: the goal state can lose a contact' \
    || fail "draw --graph --wrench=1,1,0: no rejection"

# Bad input and usage: status, message, nothing on stdout, no file.
bad() {
    want=$1 msg=$2; shift 2
    refused "$want" "$msg" draw "$@"
    [ -e "$tmp/never.svg" ] && fail "draw $*: left a file"
    ls "$tmp" | grep -q 'never.svg.tmp' && fail "draw $*: left a temporary file"
}
bad 1 "wrenchcone: <mode>:1:2: " --mode=nx data/section4.wc -o "$tmp/never.svg"
bad 1 "wrenchcone: <mode>:1:3: mode has 3 letters" --mode=nas data/section4.wc -o "$tmp/never.svg"
bad 2 "draw needs a figure" data/section4.wc -o "$tmp/never.svg"
bad 2 "unknown or incomplete option '--figure5'" --figure5 data/section4.wc -o "$tmp/never.svg"
bad 2 "draw takes one figure" --modes --plan data/section4.wc -o "$tmp/never.svg"
bad 1 "<sweep>:1:3: a friction coefficient must not be negative" --sweep=1,-1 data/section4.wc -o "$tmp/never.svg"
"$W" random --fixels=5 > "$tmp/five.wc" || fail "random"
bad 1 "the state-transition graph" --graph "$tmp/five.wc" -o "$tmp/never.svg"
bad 2 "--wrench goes with --graph only" --modes --wrench=1,1,1 data/section4.wc -o "$tmp/never.svg"
bad 1 "<wrench>:1:1: a wrench is three numbers" --graph --wrench=1,1 data/section4.wc -o "$tmp/never.svg"
bad 1 "<wrench>:1:3: " --graph --wrench=1,x,1 data/section4.wc -o "$tmp/never.svg"
bad 3 "cannot write the figure" --modes data/section4.wc -o "$tmp/no/such/dir/never.svg"
bad 1 "data/none.wc" --modes data/none.wc -o "$tmp/never.svg"
# An existing file is replaced only when the figure is whole.
echo old > "$tmp/keep.svg"
"$W" draw --mode=zz data/section4.wc -o "$tmp/keep.svg" 2>/dev/null
[ "$(cat "$tmp/keep.svg")" = old ] || fail "a failed draw changed its output file"
"$W" draw --modes data/section4.wc -o "$tmp/keep.svg" && xmllint --noout "$tmp/keep.svg" \
    || fail "draw did not replace its output file"
# -o FILE, -oFILE, --output=FILE, -o - and stdout give the same bytes.
"$W" draw --modes data/section4.wc > "$tmp/a.svg" \
    && "$W" draw --modes data/section4.wc -o"$tmp/b.svg" \
    && "$W" draw --modes --output="$tmp/c.svg" data/section4.wc \
    && "$W" draw --modes -o - data/section4.wc > "$tmp/d.svg" \
    && cmp -s "$tmp/a.svg" "$tmp/b.svg" && cmp -s "$tmp/a.svg" "$tmp/c.svg" \
    && cmp -s "$tmp/a.svg" "$tmp/d.svg" \
    && cmp -s "$tmp/a.svg" "$tmp/keep.svg" || fail "-o and stdout differ"

[ $failures -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
exit 0
