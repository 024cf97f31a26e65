#!/bin/sh
# cli-stability.sh -- `wrenchcone classify` and `wrenchcone stability` end
# to end: the paper's Figure 5 disk, exact verdicts and sets, negative
# numbers as operands, located errors for bad numbers, exit statuses, the
# certificate round trip through `verify`, and the robustness report.
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
tmp=$(mktemp -d "${TMPDIR:-/tmp}/cli-stability.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

command -v python3 > /dev/null 2>&1 || { echo "SKIP: no python3"; exit 77; }

# Figure 5, pushing straight down into fixel 1: held by fixel 1 alone, no
# solution moves (strongly stable by the definition), but W(ns) holds it,
# so eq. 19 excludes it.
"$W" classify --format=json "$D/disk-two-fixels.wc" 0 -1 0 > "$tmp/c" 2> "$tmp/e" \
    || fail "classify figure 5: exit $?: $(cat "$tmp/e")"
python3 - "$tmp/c" <<'PY' || fail "classify figure 5 JSON"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["wrench"] == ["0", "-1", "0"], d
assert d["weakly_stable"] is True and d["strongly_stable"] is True, d
assert d["strongly_stable_paper"] is False, d
assert d["modes"] == ["nn", "ns"] and d["modes_complete"] is True, d
assert d["motions"] == [], d
assert d["static_c"] == ["1", "0", "0", "0"], d
assert d["paper_witness"]["mode"] == "ns", d
PY

# Pulling up, away from fixel 1: not weakly stable; the disk rolls on
# fixel 2 (mode sn) with an exact witness.
"$W" classify --format=json "$D/disk-two-fixels.wc" 1 1 0 > "$tmp/c" 2> "$tmp/e" \
    || fail "classify (1, 1, 0): exit $?"
python3 - "$tmp/c" <<'PY' || fail "classify (1, 1, 0) JSON"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["weakly_stable"] is False and d["strongly_stable"] is False, d
assert d["strongly_stable_paper"] is False, d
assert [m["sign"] for m in d["motions"]] == ["sn"], d
assert d["motions"][0]["nudot"] == ["0", "1/2", "-1/2"], d
PY

# Bad operands: a located error, nothing on stdout.
"$W" classify "$D/disk-two-fixels.wc" 0 -1 1/0 > "$tmp/o" 2> "$tmp/e"
[ $? -eq 1 ] && [ ! -s "$tmp/o" ] && grep -q '^wrenchcone: <wrench>:1:6: ' "$tmp/e" \
    || fail "bad wrench number: want exit 1 and <wrench>:1:6 ($(cat "$tmp/e"))"
"$W" classify "$D/disk-two-fixels.wc" 0 -1 > "$tmp/o" 2> /dev/null
[ $? -eq 2 ] && [ ! -s "$tmp/o" ] || fail "classify arity: want exit 2"
"$W" stability --bias=1,2 "$D/disk-two-fixels.wc" > "$tmp/o" 2> /dev/null
[ $? -eq 2 ] && [ ! -s "$tmp/o" ] || fail "--bias with two numbers: want exit 2"
"$W" stability --length=-1 --bias 1 -1 0 "$D/disk-two-fixels.wc" > "$tmp/o" 2> "$tmp/e"
[ $? -eq 1 ] && [ ! -s "$tmp/o" ] && grep -q '<length>' "$tmp/e" \
    || fail "negative length: want exit 1"
# Command-line numbers obey the problem file's bound (1024 bits).
"$W" classify "$D/disk-two-fixels.wc" 0 1e-400 0 > "$tmp/o" 2> "$tmp/e"
[ $? -eq 1 ] && [ ! -s "$tmp/o" ] \
    && grep -q "^wrenchcone: <wrench>:1:3: number too big in '1e-400'" "$tmp/e" \
    || fail "huge wrench number: want exit 1 ($(cat "$tmp/e"))"
"$W" stability --bias=1,1e999,0 "$D/disk-two-fixels.wc" > "$tmp/o" 2> "$tmp/e"
[ $? -eq 1 ] && [ ! -s "$tmp/o" ] \
    && grep -q "^wrenchcone: <bias>:1:3: number too big in '1e999'" "$tmp/e" \
    || fail "huge bias number: want exit 1 ($(cat "$tmp/e"))"
"$W" classify --bias=1,2,3 "$D/disk-two-fixels.wc" 0 0 0 > "$tmp/o" 2> /dev/null
[ $? -eq 2 ] && [ ! -s "$tmp/o" ] || fail "--bias on classify: want exit 2"

# stability: the sets, both semantics, the push regions, the bias.
"$W" stability --format=json --bias 1 -1 0 "$D/disk-two-fixels.wc" > "$tmp/s" 2> "$tmp/e" \
    || fail "stability figure 5: exit $?: $(cat "$tmp/e")"
python3 - "$tmp/s" <<'PY' || fail "stability figure 5 JSON"
import json, sys
d = json.load(open(sys.argv[1]))
# mu = 1 puts each fixel exactly on the edge of the other's friction cone:
# Nguyen's condition holds only for mu > 1, so the weak set is a wedge
# around the squeezing line (1, 1, 1), not all of R^3.
w = d["weak"]
assert w["dim"] == 3 and w["lineality_dim"] == 1, w
assert w["lines"] == [["1", "1", "1"]], w
assert w["inequalities"] == [["-1", "0", "1"], ["0", "1", "-1"]], w
for k in ("strong", "strong_paper"):
    s = d[k]
    assert s["empty"] is False and s["interior"] is True, s
assert d["semantics_differ"] is True
# The witness is a nonzero wrench: the origin is in every set of the
# definition and in every W(x), so it would show nothing.
assert d["differ_only_at_origin"] is False and d["paper_vacuous"] is False, d
assert d["difference_witness"] == {"wrench": ["-1", "-1", "-1"],
                                   "strong": True, "strong_paper": False}, d
assert d["push"]["strong"] == [{"from": ["0", "1"], "to": ["-1", "0"],
                                "from_closed": True, "to_closed": True}], d["push"]
assert d["push"]["strong_paper"] == [{"from": ["0", "1"], "to": ["-1", "0"],
                                      "from_closed": False, "to_closed": False}], d["push"]
b = d["bias"]
assert b["strong"] == {"in_set": True, "rho": "1/2", "closed": True}, b
assert b["strong_paper"] == {"in_set": True, "rho": "1/2", "closed": False}, b
PY

# With mu = 11/10 Nguyen's condition holds: the weak set is R^3.
sed 's|^friction 1$|friction 11/10|' "$D/disk-two-fixels.wc" > "$tmp/f.wc"
"$W" stability --format=json "$tmp/f.wc" > "$tmp/s" 2> /dev/null || fail "mu 11/10: exit $?"
python3 - "$tmp/s" <<'PY' || fail "mu 11/10: the weak set should be R^3"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["weak"]["dim"] == 3 and d["weak"]["lineality_dim"] == 3, d["weak"]
assert d["push"]["weak"][0].get("full") is True, d["push"]
PY

# The text output says how the semantics differ.
"$W" stability "$D/disk-two-fixels.wc" > "$tmp/t" 2> /dev/null || fail "stability text"
grep -q '^the semantics differ' "$tmp/t" || fail "text lacks the semantics line"
grep -q '^the semantics differ: e.g. g = (-1, -1, -1) is strongly stable under the definition (exact) only' "$tmp/t" \
    || fail "the text witness is not the nonzero (-1, -1, -1)"
# A second route: classify decides that witness by LPs alone.
"$W" classify "$D/disk-two-fixels.wc" -1 -1 -1 > "$tmp/t" 2> /dev/null || fail "classify witness"
grep -q '^strongly stable (exact semantics, Pang and Trinkle): yes$' "$tmp/t" \
    && grep -q '^strongly stable (paper semantics, eq. 19): no$' "$tmp/t" \
    || fail "classify disagrees with the stability witness"

# --progress: reports on stderr (one per line when it is not a terminal),
# the first and last of each stage always; stdout unchanged.
"$W" stability "$D/peg-in-hole.wc" > "$tmp/quiet" 2> "$tmp/e" && [ ! -s "$tmp/e" ] \
    || fail "stability writes on stderr without --progress"
"$W" stability --progress "$D/peg-in-hole.wc" > "$tmp/loud" 2> "$tmp/e" \
    || fail "stability --progress: exit $?"
cmp -s "$tmp/quiet" "$tmp/loud" || fail "--progress changes stdout"
grep -v -x 'wrenchcone: [a-z ]*: [0-9]*/[0-9]* ([0-9]*%)' "$tmp/e" && fail "--progress: a line out of format"
for want in 'moving faces: 0/9 (0%)' 'moving faces: 9/9 (100%)' \
            'cells of the sets: 0/1687 (0%)' 'cells of the sets: 1687/1687 (100%)'; do
    grep -q -x "wrenchcone: $want" "$tmp/e" || fail "--progress: no line '$want'"
done

# No touching fixel: eq. 19 holds vacuously, and both outputs say so.
"$W" stability "$D/three-fixels.wc" > "$tmp/t" 2> /dev/null || fail "stability three-fixels"
grep -q '^note: no fixel touches, so eq. 19 is vacuous' "$tmp/t" || fail "no vacuity note (stability)"
"$W" stability --format=json "$D/three-fixels.wc" | grep -q '"paper_vacuous": true' \
    || fail "no vacuity flag (stability JSON)"
"$W" classify "$D/three-fixels.wc" 0 -1 0 > "$tmp/t" 2> /dev/null || fail "classify three-fixels"
grep -q '^  vacuously: no fixel touches' "$tmp/t" || fail "no vacuity note (classify)"
"$W" classify --format=json "$D/three-fixels.wc" 0 -1 0 | grep -q '"paper_vacuous": true' \
    || fail "no vacuity flag (classify JSON)"
"$W" classify --format=json "$D/disk-two-fixels.wc" 0 -1 0 | grep -q '"paper_vacuous": false' \
    || fail "vacuity flag set with touching fixels (classify JSON)"

# Certificates: written, and checked by verify with GMP alone.
if "$W" verify --help 2>/dev/null | grep -q strong-stability; then
    for g in "0 -1 0" "1 1 0" "1 -1 0"; do
        # shellcheck disable=SC2086
        "$W" classify --certificate="$tmp/cert.json" "$D/disk-two-fixels.wc" $g > /dev/null 2>&1 \
            || fail "classify --certificate ($g)"
        "$W" verify "$tmp/cert.json" > "$tmp/o" 2>&1 || fail "verify certificate of ($g): $(cat "$tmp/o")"
    done
fi

# stability --certificate: holds for every example, claims the set printed,
# and with the weak cone claimed instead (the Figure 5 disk with kinetic
# friction 1/2, where they differ) is never accepted.
for f in "$D"/*.wc; do
    "$W" stability --certificate="$tmp/s.json" "$f" > /dev/null 2> "$tmp/e" \
        || fail "stability --certificate $f: exit $?: $(cat "$tmp/e")"
    "$W" verify "$tmp/s.json" > "$tmp/v" 2>&1 \
        && grep -q '^certificate holds: the strongly stable set is exact: ' "$tmp/v" \
        || fail "verify stability certificate $f: $(cat "$tmp/v")"
done
sed 's|^friction 1$|friction 1 1/2|' "$D/disk-two-fixels.wc" > "$tmp/k.wc"
"$W" stability --format=json "$tmp/k.wc" > "$tmp/j"
"$W" stability --certificate="$tmp/s.json" "$tmp/k.wc" > /dev/null
python3 - "$tmp/j" "$tmp/s.json" "$tmp/w.json" <<'PY' || fail "stability certificate claim"
import json, sys
out, cert = json.load(open(sys.argv[1])), json.load(open(sys.argv[2]))
assert cert["strong"] == out["strong"], "the claim is not the set printed"
weak = out["weak"]
assert out["strong"]["pieces"] != [weak]
cert["strong"] = {"empty": False, "interior": weak["dim"] == 3, "pieces": [weak]}
json.dump(cert, open(sys.argv[3], "w"))
PY
"$W" verify "$tmp/w.json" > "$tmp/v" 2>&1
st=$?
# 4, or 1 when the proofs no longer fit the claim's faces: never accepted
[ $st -eq 4 ] || [ $st -eq 1 ] \
    || fail "the weak cone claimed as the strong set: exit $st: $(cat "$tmp/v")"

# The tree of three-fixels (nothing holds the part: the origin and 26
# regions off the weak cone).  Its first region cut by a basis plane, which
# leaves it on one side: exit 4, named; a region that is not empty given
# null, or a region given two nodes: exit 4.
"$W" stability --certificate="$tmp/t.json" "$D/three-fixels.wc" > /dev/null
python3 - "$tmp/t.json" "$tmp" <<'PY' || fail "tree tampering setup"
import json, sys
cert = json.load(open(sys.argv[1]))
tree = cert["tree"]
b = tree[0]["basis"]
def put(name, t):
    c = dict(cert); c["tree"] = t
    json.dump(c, open(sys.argv[2] + "/" + name, "w"))
put("nocut.json", [tree[0], {"split": b[0]}, None, None, tree[1]] + tree[2:])
put("null.json", [tree[0], None] + tree[2:])
put("extra.json", tree + [tree[-1]])
put("short.json", tree[:-1])
PY
for t in nocut null extra short; do
    "$W" verify "$tmp/$t.json" > "$tmp/v" 2>&1
    st=$?
    [ $st -eq 4 ] || fail "tree $t: exit $st: $(cat "$tmp/v")"
done
"$W" verify "$tmp/nocut.json" 2>&1 | grep -q "does not cut the region" \
    || fail "a cut that misses its region is not named"
"$W" verify "$tmp/null.json" 2>&1 | grep -q "the tree has null for this region" \
    || fail "a missing region is not named"

# A piece whose inequalities describe a 3-D cone around its 2-D rays (two
# opposite corners of a quadrilateral), every incidence check passing but
# the dimension: a leaf would place by the inequalities a region outside
# the rays' cone, and a false claim (an open ray of strongly stable
# wrenches dropped) would hold.  The equalities' rank must catch it.
"$W" stability --certificate="$tmp/p.json" "$D/peg-in-hole.wc" > /dev/null
python3 - "$tmp/p.json" "$tmp/fat.json" <<'PY' || fail "fat piece setup"
import json, sys
def cross(u, v): return [u[1]*v[2]-u[2]*v[1], u[2]*v[0]-u[0]*v[2], u[0]*v[1]-u[1]*v[0]]
def dot(u, v): return sum(a*b for a, b in zip(u, v))
d = json.load(open(sys.argv[1]))
P = d["strong"]["pieces"]
r1, r2 = ([int(x) for x in r] for r in P[1]["rays"])
b = [5, -2, 3]
c = [x + y for x, y in zip(r1, r2)]
p = [10*x - y for x, y in zip(b, c)]
q = [1000*x - y for x, y in zip(c, p)]
V = [r1, p, r2, q]
H = []
for i in range(4):
    n = cross(V[i], V[(i+1) % 4])
    n = [-x for x in n] if dot(n, V[(i+2) % 4]) > 0 else n
    H.append([str(x) for x in n])
P[1]["inequalities"] = H
P[1]["equalities"] = []
P[2]["faces"][2]["included"] = False
d["tree"][25] = {"in": True, "piece": 1, "piece_face": 3}
json.dump(d, open(sys.argv[2], "w"))
PY
"$W" verify "$tmp/fat.json" > "$tmp/v" 2>&1
st=$?
[ $st -eq 4 ] && grep -q "has dim 2, but its equalities have rank 0" "$tmp/v" \
    || fail "a piece with a 3-D constraint cone around 2-D rays: exit $st: $(cat "$tmp/v")"

exit $failed
