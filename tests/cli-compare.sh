#!/bin/sh
# cli-compare.sh -- `wrenchcone compare` end to end (wrenchcone(1)): the exact
# cone of the paper's Section 4 example, written by `wrenchcone cone` as
# cdd .ext and .ine and converted to decimals (each row divided by its
# length, printed with %.17g: no longer exact), is within the default
# tolerance; with one ray dropped, one ray rotated by 1e-3 rad, one facet
# removed, or the dimension wrong (a 2-D cone given a ray out of its
# plane), it is not (exit 4) and the report names what differs; our own
# outputs (JSON, cdd, empty cones) pass; malformed files are bad input
# (exit 1, one located diagnostic, nothing on stdout); bad options are bad
# usage (exit 2).
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.
#
# Run by make check with WRENCHCONE and top_srcdir in the environment.
# Silent on success; prints each failing case and exits 1.

: "${WRENCHCONE:?WRENCHCONE is not set}"
: "${top_srcdir:?top_srcdir is not set}"

W=$WRENCHCONE
D=$top_srcdir/data
. "$top_srcdir/tests/clitest.sh"

# run NAME WANT ARGS...: `wrenchcone compare ARGS` must exit WANT; its
# stdout and stderr are left in $tmp/out and $tmp/err (not clitest.sh's).
run() {
    run_name=$1
    run_want=$2
    shift 2
    "$W" compare "$@" <"$tmp/stdin" >"$tmp/out" 2>"$tmp/err"
    status=$?
    if [ "$status" -ne "$run_want" ]; then
        fail "$run_name" "exit status $status, expected $run_want"
        sed 's/^/    /' "$tmp/err" | head -5
        tail -3 "$tmp/out" | sed 's/^/    /'
    fi
}
: >"$tmp/stdin"

# has NAME REGEX: some line of the report matches the extended REGEX.
has() {
    if ! grep -E -q -- "$2" "$tmp/out"; then
        fail "$1" "no line of the report matches /$2/"
        sed 's/^/    /' "$tmp/out" | tail -12
    fi
}

# count NAME REGEX N: exactly N lines of the report match REGEX.
count() {
    count_n=$(grep -E -c -- "$2" "$tmp/out")
    if [ "$count_n" -ne "$3" ]; then
        fail "$1" "$count_n lines match /$2/, expected $3"
    fi
}

# The rows of a cdd block as decimals: each row's three coordinates
# divided by their length and printed with %.17g; the number type becomes
# real.
cat >"$tmp/dec.awk" <<'EOF'
/^begin/ { inb = 1; hdr = 1; print; next }
/^end/ { inb = 0; print; next }
inb && hdr { hdr = 0; sub(/rational/, "real"); print; next }
inb && NF == 4 {
    n = sqrt($2 * $2 + $3 * $3 + $4 * $4)
    if (n == 0) { print; next }
    printf " %s %.17g %.17g %.17g\n", $1, $2 / n, $3 / n, $4 / n
    next
}
{ print }
EOF

# drop.awk K: the block without its K-th data row, the count one less.
cat >"$tmp/drop.awk" <<'EOF'
/^begin/ { inb = 1; print; getline; $1 = $1 - 1; print " " $0; next }
/^end/ { inb = 0 }
inb && NF == 4 { k++; if (k == K) next }
{ print }
EOF

# add.awk ROW: the block with one more data row (ROW) before 'end'.
cat >"$tmp/add.awk" <<'EOF'
/^begin/ { print; getline; $1 = $1 + 1; print " " $0; next }
/^end/ { print " " ROW }
{ print }
EOF

s4=$D/section4.wc
"$W" cone --format=ext "$s4" na >"$tmp/exact.ext" || fail ext "cone failed"
"$W" cone --format=ine "$s4" na >"$tmp/exact.ine" || fail ine "cone failed"
awk -f "$tmp/dec.awk" "$tmp/exact.ext" >"$tmp/s4.ext"
awk -f "$tmp/dec.awk" "$tmp/exact.ine" >"$tmp/s4.ine"
# The conversion is not exact: 1/sqrt(27) is not a decimal.
grep -q ' 0 -0.19245008972987526 -0.96225044864937626 -0.19245008972987526$' \
    "$tmp/s4.ext" || fail decimals "unexpected decimal .ext"

# --- Decimals of the exact cone pass, and the report has every part.
run ext-decimals 0 "$s4" na "$tmp/s4.ext"
if [ "$(sed -n 1p "$tmp/out")" != "exact (GMP) against $tmp/s4.ext; distances are floating-point angles in radians" ]; then
    fail ext-decimals "header line: $(sed -n 1p "$tmp/out")"
fi
has ext-decimals '^exact cone W\(na\) of .*section4.wc: nonempty, dimension 3, lineality 0, 3 extreme rays, 3 facets$'
has ext-decimals '^float cone: .*s4.ext, V-representation \(generators\) at line 9$'
has ext-decimals '^  emptiness: exact nonempty, float nonempty$'
has ext-decimals '^  dimension: exact 3, float 3; lineality: exact 0, float 0$'
# every float ray with its angle to the exact closure and every exact ray
# with its angle to the float closure
count ext-decimals '^    fr[0-2] +\(.*\)  line 1[345]  angle [0-9.e-]+  nearest r[0-2] at [0-9.e-]+$' 3
count ext-decimals '^    r[0-2] +\(.*\)  angle [0-9.e-]+  nearest fr[0-2] at [0-9.e-]+$' 3
has ext-decimals '^    fr[0-2] +\(0\.707107, 0, -0\.707107\)  line 15  angle 0  nearest r2 at 0$'
has ext-decimals '^  Hausdorff distance [0-9.e-]+ \(exact to float [0-9.e-]+, float to exact [0-9.e-]+\)$'
has ext-decimals '^  missing rays: none$'
has ext-decimals '^  extra rays: none$'
has ext-decimals '^  missing facets: none$'
has ext-decimals '^  extra facets: none$'
has ext-decimals '^strictness cannot be read from a float cone; check your handling of strict inequalities:$'
has ext-decimals '^  the exact cone excludes 4 of the 8 faces of its closure: dim 0 \(the apex\); dim 1 \{r0\}; dim 1 \{r1\}; dim 2 \{r0 r1\}$'
has ext-decimals '^verdict: within tolerance$'

run ine-decimals 0 "$s4" na "$tmp/s4.ine"
has ine-decimals '^float cone: .*s4.ine, H-representation \(inequalities\) at line 9$'
count ine-decimals '^    fh[0-2] +\(.*\)  line 1[234]  nearest h[0-2] at [0-9.e-]+$' 3
has ine-decimals '^verdict: within tolerance$'

# Rows inside the cone change nothing, and are named.
awk -v ROW='0 0 -1 0' -f "$tmp/add.awk" "$tmp/s4.ext" >"$tmp/in1.ext"
awk -v ROW='0 0 -2 0' -f "$tmp/add.awk" "$tmp/in1.ext" >"$tmp/in2.ext"
run redundant 0 "$s4" na "$tmp/in2.ext"
has redundant '^  redundant input rows \(on no extreme ray of the float cone\): lines 16, 17$'

# At tolerance 0 the decimals are too far (about 1e-17): exit 4.
run tol-zero 4 --tol=0 "$s4" na "$tmp/s4.ext"
has tol-zero '^verdict: outside tolerance: Hausdorff distance [0-9.e-]+ > tol 0; '

# --- Our own outputs pass, exactly (distance 0, even at --tol=0).
for fmt in json cdd ext ine; do
    "$W" cone --format=$fmt "$s4" na >"$tmp/own.$fmt"
    run "own-$fmt" 0 --tol=0 "$s4" na "$tmp/own.$fmt"
    has "own-$fmt" '^  Hausdorff distance 0 \(exact to float 0, float to exact 0\)$'
done
# JSON and cdd give both representations: each is compared.
run own-json-both 0 "$s4" na "$tmp/own.json"
has own-json-both "^float cone: .*own.json, generators \('rays', 'lines'\) at line 1$"
has own-json-both "^float cone: .*own.json, inequalities \('inequalities', 'equalities'\) at line 1$"
# Every mode of the data files, as decimals: within tolerance.
for mode in na ns nu sa ss la ra ma mu; do
    "$W" cone --format=ext "$s4" $mode | awk -f "$tmp/dec.awk" >"$tmp/m.ext"
    run "mode-$mode" 0 "$s4" $mode "$tmp/m.ext"
done
for mode in ss sl sr sn ls rs ns ll rr nn mm mn lr; do
    "$W" cone --format=ine "$D/disk-two-fixels.wc" $mode \
        | awk -f "$tmp/dec.awk" >"$tmp/m.ine"
    run "disk-$mode" 0 "$D/disk-two-fixels.wc" $mode "$tmp/m.ine"
done

# --- One ray dropped: the (1, 0, -1) ray, the fourth row (after the apex).
awk -v K=4 -f "$tmp/drop.awk" "$tmp/s4.ext" >"$tmp/drop.ext"
run drop-ray 4 "$s4" na "$tmp/drop.ext"
has drop-ray '^  dimension: exact 3, float 2; lineality: exact 0, float 0$'
has drop-ray '^  missing rays: r2$'
has drop-ray '^  extra rays: none$'
has drop-ray '^verdict: outside tolerance: dimension differs \(exact 3, float 2\); Hausdorff distance [0-9.e-]+ > tol 1e-09; 1 missing ray \(r2\); 1 missing facet \(h1\)$'

# --- One ray rotated by 1e-3 rad, about the y axis (orthogonal to it).
awk 'BEGIN { t = 0.001 }
     NF == 4 && $1 == "0" && $3 == "0" {
         x = $2; z = $4
         printf " 0 %.17g 0 %.17g\n", x * cos(t) + z * sin(t), z * cos(t) - x * sin(t)
         next
     }
     { print }' "$tmp/s4.ext" >"$tmp/rot.ext"
run rotate-ray 4 "$s4" na "$tmp/rot.ext"
has rotate-ray '^    r2 +\(0\.707107, 0, -0\.707107\)  angle [0-9.e-]+  nearest fr[0-2] at 0\.001$'
has rotate-ray '^  missing rays: r2$'
has rotate-ray '^  extra rays: fr[0-2] \(line 15\)$'
has rotate-ray '^verdict: outside tolerance: Hausdorff distance 0\.000[0-9]+ > tol 1e-09; 1 missing ray \(r2\); 1 extra ray \(fr[0-2]\); '
# ... and within a tolerance of 0.01 rad.
run rotate-ray-tol 0 --tol=0.01 "$s4" na "$tmp/rot.ext"

# --- One facet removed: the second row of the .ine, h1 = (-1, 0, 1).
awk -v K=2 -f "$tmp/drop.awk" "$tmp/s4.ine" >"$tmp/nofacet.ine"
run drop-facet 4 "$s4" na "$tmp/nofacet.ine"
has drop-facet '^  dimension: exact 3, float 3; lineality: exact 0, float 1$'
has drop-facet '^  missing facets: h1$'
has drop-facet '^verdict: outside tolerance: lineality differs \(exact 0, float 1\); .*1 missing facet \(h1\)$'

# --- The dimension wrong: the 2-D half-plane W(sss) of the peg, given a
# ray out of its plane.
peg=$D/peg-in-hole.wc
"$W" cone --format=ext "$peg" sss | awk -f "$tmp/dec.awk" >"$tmp/peg.ext"
run peg 0 "$peg" sss "$tmp/peg.ext"
awk -v ROW='0 0 0 1' -f "$tmp/add.awk" "$tmp/peg.ext" >"$tmp/peg3.ext"
run peg-dimension 4 "$peg" sss "$tmp/peg3.ext"
has peg-dimension '^  dimension: exact 2, float 3; lineality: exact 1, float 1$'
has peg-dimension '^  extra rays: fr[01] \(line 1[01]\)$'
has peg-dimension '^verdict: outside tolerance: dimension differs \(exact 2, float 3\); '

# --- The report as JSON.
run json-pass 0 --format=json "$s4" na "$tmp/s4.ext"
has json-pass '"within_tolerance": true, "differences": \[\]\}$'
has json-pass '^\{"format": "wrenchcone-json/1", "exact": \{"arith": "gmp", "problem": ".*section4.wc", "mode": "na", "empty": false, "dim": 3, "lineality_dim": 0, '
has json-pass '"strictness": "strictness cannot be read from a float cone; check your handling of strict inequalities"'
has json-pass '"excluded_faces": \[\{"dim": 0, "rays": \[\]\}, \{"dim": 1, "rays": \[0\]\}, \{"dim": 1, "rays": \[1\]\}, \{"dim": 2, "rays": \[0, 1\]\}\]'
run json-drop 4 --format=json "$s4" na "$tmp/drop.ext"
has json-drop '"float": \[\{"representation": "generators", "line": 9, "empty": false, "dim": 2, "lineality_dim": 0, '
has json-drop '"within_tolerance": false, "differences": \["dimension", "distance", "rays", "facets"\]\}$'

# --- Empty cones: W(ln) of the Figure 5 disk is empty.
disk=$D/disk-two-fixels.wc
"$W" cone --format=cdd "$disk" ln >"$tmp/empty.cdd"
run empty-both 0 "$disk" ln "$tmp/empty.cdd"
has empty-both '^  emptiness: exact empty, float empty$'
run empty-one 4 "$disk" ss "$tmp/empty.cdd"
has empty-one '^verdict: outside tolerance: inequalities: emptiness differs \(exact nonempty, float empty\); generators: emptiness differs \(exact nonempty, float empty\)$'
printf '{"empty": true}\n' >"$tmp/empty.json"
run empty-json 4 "$s4" na "$tmp/empty.json"
has empty-json "^float cone: .*empty.json, 'empty': true at line 1$"

# --- A float cone in the JSON of `wrenchcone cone --arith=double`
# (numbers as JSON numbers; "strict" marks are not read), and a mode
# mismatch.
cat >"$tmp/float.json" <<'EOF'
{"mode": "na", "cone": {"empty": false, "arith": "double", "eps": 1e-09, "dim": 3, "lineality_dim": 0, "closed": false,
 "inequalities": [[-0.70710678118654757, 0, 0.70710678118654757], [-0.6804138174397717, 0.27216552697590868, -0.6804138174397717], [0.6804138174397717, 0.27216552697590868, 0.6804138174397717]],
 "strict": [true, false, false], "equalities": [],
 "rays": [[-0.19245008972987526, -0.96225044864937626, -0.19245008972987526], [0.19245008972987526, -0.96225044864937626, 0.19245008972987526], [0.70710678118654757, 0, -0.70710678118654757]],
 "strict_rays": [true, true, false], "lines": []}}
EOF
run float-json 0 "$s4" na "$tmp/float.json"
has float-json "^float cone: .*float.json, generators \('rays', 'lines'\) at line 4$"
has float-json "^float cone: .*float.json, inequalities \('inequalities', 'equalities'\) at line 2$"
run float-json-mode 4 "$s4" ns "$tmp/float.json"
has float-json-mode '^verdict: outside tolerance: the file is for mode na, not ns; '

# FILE '-' is standard input.
cp "$tmp/s4.ine" "$tmp/stdin"
run stdin 0 "$s4" na -
has stdin '^exact \(GMP\) against <stdin>; '
: >"$tmp/stdin"

# --- Malformed files: exit 1, one exact located diagnostic, no stdout.
# bad NAME 'LINE:COL: MESSAGE' FORMAT: the file written by printf FORMAT.
bad() {
    printf "$3" >"$tmp/$1"
    run "bad-$1" 1 "$s4" na "$tmp/$1"
    if [ -s "$tmp/out" ]; then
        fail "bad-$1" "stdout is not empty"
    fi
    printf 'wrenchcone: %s:%s\n' "$tmp/$1" "$2" >"$tmp/want"
    if ! cmp -s "$tmp/want" "$tmp/err"; then
        fail "bad-$1" "stderr differs"
        sed 's/^/    expected: /' "$tmp/want"
        sed 's/^/    got:      /' "$tmp/err"
    fi
}
bad empty "1:1: no cone here: expected a cdd file (H- or V-representation, 'begin' .. 'end') or a JSON cone" ''
bad number "5:6: bad number 'x'" \
    'V-representation\nbegin\n 2 4 real\n 0 1 2 3\n 0 1 x 3\nend\n'
bad short-row "4:7: a row has 4 numbers, found 3" \
    'V-representation\nbegin\n 1 4 real\n 0 1 2\nend\n'
bad few-rows "5:1: found 1 row before 'end', but the header (line 3) announces 2" \
    'V-representation\nbegin\n 2 4 real\n 0 1 2 3\nend\n'
bad no-end "5:1: end of file before 'end'" \
    'V-representation\nbegin\n 1 4 real\n 0 1 2 3\n'
bad columns "3:4: a cone in R^3 has 4 columns (1 homogenizing + 3 coordinates), not 5" \
    'V-representation\nbegin\n 1 5 real\n'
bad vertex "4:4: not a cone: a point other than the origin (a cone's one point is its apex, '1 0 0 0')" \
    'V-representation\nbegin\n 1 4 real\n 1 1 0 0\nend\n'
bad constant "4:2: not a cone: the constant term b is 1/2; the rows 'b -A' (b - A g >= 0) of a cone have b = 0" \
    'H-representation\nbegin\n 1 4 real\n 1/2 1 0 0\nend\n'
bad linearity "2:13: linearity row 3 is beyond the last row of the block (1)" \
    'V-representation\nlinearity 1 3\nbegin\n 1 4 real\n 0 1 0 0\nend\n'
bad exponent "4:4: exponent out of range in '1e2000' (at most 1000 here)" \
    'V-representation\nbegin\n 1 4 real\n 0 1e2000 0 0\nend\n'
bad second "6:1: a second V-representation" \
    'V-representation\nbegin\n 1 4 real\n 0 1 0 0\nend\nV-representation\n'
# At most one H- and one V-representation: a block with no keyword is H
# (cdd's default), so a third block always repeats a kind.
bad blocks-default "10:1: a second H-representation (a block with no representation keyword is an H-representation, as in cdd; the first is line 1)" \
    'begin\n 1 4 real\n 0 1 0 0\nend\nV-representation\nbegin\n 1 4 real\n 0 1 0 0\nend\nbegin\n 1 4 real\n 0 1 0 0\nend\n'
bad blocks-three "11:1: a second H-representation (a block with no representation keyword is an H-representation, as in cdd; the first is line 6)" \
    'V-representation\nbegin\n 1 4 real\n 0 1 0 0\nend\nH-representation\nbegin\n 1 4 real\n 0 1 0 0\nend\nbegin\n 1 4 real\n 0 1 0 0\nend\nbegin\n 1 4 real\n 0 1 0 0\nend\n'
bad blocks-v "10:1: a second V-representation" \
    'begin\n 1 4 real\n 0 1 0 0\nend\nV-representation\nbegin\n 1 4 real\n 0 1 0 0\nend\nV-representation\nbegin\n 1 4 real\n 0 1 0 0\nend\n'
bad json-short "1:50: each entry of 'rays' must be an array of 3 numbers" \
    '{"mode": "na", "cone": {"empty": false, "rays": [[1, 2]]}}\n'
bad json-empty "1:11: 'empty' must be true or false" '{"empty": "no"}\n'
bad json-syntax "2:1: unexpected end of input" \
    '{"empty": false, "rays": [[1, 2, 3]]\n'
# "dim", "lineality_dim" and "faces" are not read, but must be well formed.
bad json-dim-fraction "1:25: 'dim' must be an integer from 0 to 3, not 3.5" \
    '{"empty": false, "dim": 3.5, "rays": [[1, 0, 0]]}\n'
bad json-dim-negative "2:9: 'dim' must be an integer from 0 to 3, not -1" \
    '{"empty": false,\n "dim": -1, "rays": [[1, 0, 0]]}\n'
bad json-face-ray "2:35: face ray index 3 is out of range: 'rays' has 3 rows (0 to 2)" \
    '{"empty": false, "rays": [[1, 0, 0], [0, 1, 0], [0, 0, 1]],\n "faces": [{"dim": 2, "rays": [0, 3], "included": true}]}\n'

# --- Bad usage: exit 2, nothing on stdout.
usage() {
    run "usage-$1" 2 "$@"
    if [ -s "$tmp/out" ]; then
        fail "usage-$1" "stdout is not empty"
    fi
}
usage --tol=abc "$s4" na "$tmp/s4.ext"
printf '%s\n' "wrenchcone: --tol must be an angle in radians, at least 0 and below pi/2 (such as 1e-9), not 'abc'" \
    "Try 'wrenchcone compare --help' for more information." >"$tmp/want"
cmp -s "$tmp/want" "$tmp/err" || fail usage-tol-message "$(cat "$tmp/err")"
usage --tol=-1 "$s4" na "$tmp/s4.ext"
usage --tol=2 "$s4" na "$tmp/s4.ext"
usage --tol= "$s4" na "$tmp/s4.ext"
usage --format=cdd "$s4" na "$tmp/s4.ext"
usage "$s4" na
usage "$s4" na "$tmp/s4.ext" extra
usage - na -

# A bad problem or mode is bad input, reported before FILE is read.
run bad-mode 1 "$s4" xx "$tmp/nonexistent"
grep -q '^wrenchcone: <mode>:1:' "$tmp/err" || fail bad-mode "$(cat "$tmp/err")"
run no-file 1 "$s4" na "$tmp/nonexistent"

# Help.
"$W" compare --help >"$tmp/out" 2>&1 || fail help "exit $?"
has help '^Usage: wrenchcone compare \[OPTIONS\] PROBLEM MODE FILE$'
has help 'default 1e-9'
"$W" --help >"$tmp/out" 2>&1
has help-top '^  compare PROBLEM MODE FILE$'

# The double route on well-conditioned problems, round trip: its .ext,
# .ine and JSON each compare within the default tolerance (exit 0).
for pm in section4.wc:na section4.wc:ns section4.wc:sa section4.wc:ma \
          disk-two-fixels.wc:nn disk-two-fixels.wc:ss disk-two-fixels.wc:mm \
          three-fixels.wc:aaa three-fixels.wc:saa; do
    p=${pm%%:*}; m=${pm#*:}
    for fmt in ext ine json; do
        "$W" cone --method=paper --arith=double --format=$fmt \
            "$top_srcdir/data/$p" "$m" > "$tmp/dbl.$fmt" 2>/dev/null \
            || fail "double-$p-$m-$fmt" "cone exit $?"
        "$W" compare "$top_srcdir/data/$p" "$m" "$tmp/dbl.$fmt" > "$tmp/out" 2>&1
        st=$?
        [ "$st" -eq 0 ] || fail "double-$p-$m-$fmt" "compare exit $st"
    done
done

# Large cones of every kind take the near-linear conversion: a wedge
# times a line (lineality 1) of 1001 rows is read exactly -- its two
# extreme rays are rows 1 and 998 of the wedge (file lines 6 and 1003) --
# and compared as usual; so are 1001 rays of a pointed cone.
big() {
    awk -v n="$1" -v line="$2" 'BEGIN {
        print "V-representation"
        if (line) print "linearity 1 1"
        print "begin"; print n " 4 rational"
        if (line) { print "0 0 0 1"; n-- }
        for (i = 1; i <= n; i++) print 0, i - 500, 1000 + (i * i) % 997, (line ? 0 : 1)
        print "end" }'
}
big 1001 1 > "$tmp/wedge1001.ext"
big 1001 0 > "$tmp/fan1001.ext"
run wedge-1001 4 "$D/section4.wc" na "$tmp/wedge1001.ext"
if [ -s "$tmp/err" ] \
    || ! grep -q "^  read exactly: nonempty, dimension 3, lineality 1, 2 extreme rays, 2 facets\$" "$tmp/out" \
    || ! grep -q "^    fr0   (-0.44614, 0.894963, 0)  line 6  " "$tmp/out" \
    || ! grep -q "^    fr1   (0.445424, 0.89532, 0)  line 1003  " "$tmp/out" \
    || ! grep -q "^verdict: outside tolerance: lineality differs (exact 0, float 1);" "$tmp/out"; then
    fail wedge-1001 "expected the exact wedge times a line and its verdict"
    cat "$tmp/err"
fi
run fan-1001 4 "$D/section4.wc" na "$tmp/fan1001.ext"

[ "$failures" -eq 0 ]
