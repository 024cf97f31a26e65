#!/bin/sh
# cli-text.sh -- text output for people: --decimals (exact rounding,
# labelled, text only, refused outside 0..50), pushing regions on a
# polygon with their ends as points (x, y), the marks of excluded rays
# and strict facets with named columns, and the format key that opens
# every JSON document.
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
D="$top_srcdir/data"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/cli-text.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

# has NAME FILE LINE: FILE has the line LINE, exactly.
has() {
    grep -qxF -- "$3" "$2" || { fail "$1: no line '$3' in:"; sed 's/^/    /' "$2"; }
}

# The square of paper Figure 10 with its three fixels touching: pushing
# regions whose ends are rationals.
sed 's/ near$/ touching/' "$D/three-fixels.wc" > "$tmp/touch.wc" || exit 99

"$W" stability "$tmp/touch.wc" > "$tmp/plain" 2> "$tmp/e" || fail "stability: $(cat "$tmp/e")"
has points "$tmp/plain" '    edge 1: s in [35/78, 2/3], (x, y) from (4, 35/26) to (4, 2)'
has points "$tmp/plain" '    edge 2: s in [1/4, 89/104], (x, y) from (3, 3) to (15/26, 3)'
grep -q approx "$tmp/plain" && fail "approximations without --decimals"

"$W" stability --decimals=3 "$tmp/touch.wc" > "$tmp/dec" 2> "$tmp/e" || fail "stability --decimals: $(cat "$tmp/e")"
has decimals "$tmp/dec" '    edge 1: s in [35/78 (approx. 0.449), 2/3 (approx. 0.667)], (x, y) from (4, 35/26) (approx. (4.000, 1.346)) to (4, 2)'
has decimals "$tmp/dec" '    edge 2: s in [1/4 (approx. 0.250), 89/104 (approx. 0.856)], (x, y) from (3, 3) to (15/26, 3) (approx. (0.577, 3.000))'
# Only approximations are added: without them the text is the same.
sed 's/ (approx\. [^()]*)//g; s/ (approx\. ([^()]*))//g' "$tmp/dec" | cmp -s - "$tmp/plain" \
    || fail "--decimals changes more than it adds"

# Halves round away from zero; --decimals as two words with operands
# that are negative numbers.
"$W" classify --decimals 2 "$D/section4.wc" 1/8 -1/8 5/3 > "$tmp/c" 2> "$tmp/e" || fail "classify: $(cat "$tmp/e")"
has classify "$tmp/c" 'wrench g = (1/8, -1/8, 5/3) (approx. (0.13, -0.13, 1.67))  (fx, fy, torque)'
"$W" classify --decimals=0 "$D/section4.wc" 1/2 -1/2 5/3 > "$tmp/c" 2> "$tmp/e" || fail "classify: $(cat "$tmp/e")"
has classify-0 "$tmp/c" 'wrench g = (1/2, -1/2, 5/3) (approx. (1, -1, 2))  (fx, fy, torque)'

# JSON stays exact and unchanged.
"$W" stability --format=json "$tmp/touch.wc" > "$tmp/j1" || fail "stability json"
"$W" stability --format=json --decimals=7 "$tmp/touch.wc" > "$tmp/j2" || fail "stability json --decimals"
cmp -s "$tmp/j1" "$tmp/j2" || fail "--decimals changes JSON"

# K outside 0..50, or not a whole number: a usage error, nothing on stdout.
for k in 51 -1 x 1.5 '' 0050x 99999999999; do
    "$W" cone --decimals="$k" "$D/section4.wc" na > "$tmp/o" 2> "$tmp/e"
    st=$?
    [ "$st" = 2 ] || fail "--decimals=$k: exit $st, want 2"
    [ -s "$tmp/o" ] && fail "--decimals=$k: output on stdout"
    grep -q "^wrenchcone: --decimals wants a whole number from 0 to 50" "$tmp/e" \
        || fail "--decimals=$k: message '$(cat "$tmp/e")'"
done
"$W" cone --decimals=50 "$D/section4.wc" na > /dev/null || fail "--decimals=50 refused"

# A cone that is not closed: named columns, excluded rays, strict facets.
"$W" cone "$D/section4.wc" na > "$tmp/cone" || fail "cone"
has marks "$tmp/cone" '          fx  fy  torque'
has marks "$tmp/cone" '    r0    -1  -5      -1   excluded'
has marks "$tmp/cone" '    r2     1   0      -1   included'
has marks "$tmp/cone" '    h1    -1   0       1   strict (excluded)'
has marks "$tmp/cone" '    h0    -5   2      -5   included'
# In doubles too, the columns are named.
"$W" cone --arith=double --method=paper "$D/section4.wc" na > "$tmp/dbl" || fail "cone in doubles"
has double-columns "$tmp/dbl" '                               fx                       fy                   torque'
# A closed cone: no marks.
"$W" cone "$D/disk-two-fixels.wc" ss > "$tmp/closed" || fail "cone ss"
grep -Eq 'excluded$|included$' "$tmp/closed" && grep -v 'dim ' "$tmp/closed" | grep -Eq 'excluded$|included$' \
    && fail "marks on a closed cone"

# Every JSON document opens with the format key.
key='{"format": "wrenchcone-json/1", '
for args in "cone --format=json $D/section4.wc na" "modes --format=json $D/section4.wc" \
        "feasible --format=json $D/section4.wc na" "classify --format=json $D/section4.wc 0 -1 0" \
        "stability --format=json $D/section4.wc" "plan --format=json $D/disk-two-fixels-insert.wc" \
        "sweep --format=json --friction=1/5 $D/disk-two-fixels-insert.wc" "cone --all-modes $D/section4.wc"; do
    # shellcheck disable=SC2086
    "$W" $args > "$tmp/o" 2> "$tmp/e" || fail "$args: $(cat "$tmp/e")"
    n=$(grep -cvF "$key" "$tmp/o")
    [ "$n" = 0 ] && [ -s "$tmp/o" ] || fail "$args: a line without the format key"
done
"$W" feasible --format=json "$D/section4.wc" na | "$W" verify --format=json - > "$tmp/o" \
    || fail "verify of feasible's JSON"
grep -q "^{\"format\": \"wrenchcone-json/1\", \"holds\": true" "$tmp/o" || fail "verify: $(cat "$tmp/o")"
printf '{"command": "cone"}\n' | "$W" batch > "$tmp/o" 2> /dev/null
grep -q "^{\"format\": \"wrenchcone-json/1\", \"error\": " "$tmp/o" || fail "batch error: $(cat "$tmp/o")"

exit $failed
