#!/bin/sh
# cli-plan.sh -- `wrenchcone plan` and `wrenchcone sweep` end to end: the
# paper's Figure 6 disk (eq. 21) and a three-fixel block (Table 5), the
# JSON contract of wrenchcone(1), JSON, a wrench only the complete plan accepts, the
# friction sweep and the critical bracket, and bad input and usage.
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
tmp=$(mktemp -d "${TMPDIR:-/tmp}/cli-plan.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
failed=0
fail() { echo "FAIL: $*"; failed=1; }

command -v python3 > /dev/null 2>&1 || { echo "SKIP: no python3"; exit 77; }

# Figure 6: eq. 21's four strings, G_goal the open wedge of forces
# strictly between the two friction cones, with any torque; eq. 25 fails
# (a large torque spins the seated disk).
"$W" plan --complete --format=json "$D/disk-two-fixels-insert.wc" > "$tmp/p" 2> "$tmp/e" \
    || fail "plan disk: exit $?: $(cat "$tmp/e")"
python3 - "$tmp/p" <<'PY' || fail "plan disk JSON"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["fixels"] == 2, d
assert d["strings"] == ["ms", "sm", "ss", "su", "us"], d["strings"]
assert d["needed"] == ["ms", "sm", "su", "us"], d["needed"]
assert d["needed_exact"] == ["ms", "sm", "us"], d["needed_exact"]
assert d["redundant"] == [{"string": "ss", "in": "us"}], d["redundant"]
assert [s["state"] for s in d["states"]] == ["00", "10", "01", "11"], d["states"]
assert d["states"][3]["strings"] == ["sm", "ms", "ss"], d["states"]
g = d["goal"]
assert g["empty"] is False and g["interior"] is True and len(g["pieces"]) == 1, g
c = g["pieces"][0]
assert c["rays"] == [["-5", "-1", "0"], ["-1", "-5", "0"]], c
assert c["lines"] == [["0", "0", "1"]], c
assert [f["included"] for f in c["faces"]] == [False, False, False, True], c
assert d["goal_in_strong"] is False and d["goal_not_strong"] == ["-4", "-9", "11"], d
assert d["goal_in_strong_paper"] is False, d
assert d["push"]["goal"] == [{"from": ["5", "1"], "to": ["1", "5"],
                              "from_closed": False, "to_closed": False}], d["push"]
assert d["complete"]["accepted"] == g and d["complete"]["outside_goal"] is None, d
PY

# Table 5 for three fixels: the twelve strings.
"$W" plan --format=json "$D/three-fixels.wc" > "$tmp/p" 2> "$tmp/e" \
    || fail "plan three-fixels: exit $?: $(cat "$tmp/e")"
python3 - "$tmp/p" <<'PY' || fail "plan three-fixels JSON"
import json, sys
d = json.load(open(sys.argv[1]))
assert sorted(d["needed"]) == sorted("suu usu uus msu smu mms mus sum msm ums usm smm".split()), d
assert len(d["strings"]) == 19, d
t5 = {"000": "sss", "100": "suu mss", "010": "usu sms", "001": "uus ssm",
      "110": "ssu msu smu mms", "101": "sus mus sum msm",
      "011": "uss ums usm smm", "111": "sss mss sms ssm mms smm msm"}
for s in d["states"]:
    assert sorted(s["strings"]) == sorted(t5[s["state"]].split()), s
assert d["goal_in_strong"] is True and d["goal_in_strong_paper"] is True, d
assert set(d["needed_exact"]) <= set(d["needed"]), d
assert "push" in d and d["push"]["goal"] == [], d
PY

# The man page's wrench: accepted by the complete plan, held by msu.
"$W" plan --complete --format=json "$D/three-fixels-insert.wc" -7 -5 5 > "$tmp/w" 2> "$tmp/e" \
    || fail "plan wrench: exit $?: $(cat "$tmp/e")"
python3 - "$tmp/w" <<'PY' || fail "plan wrench JSON"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["wrench"] == ["-7", "-5", "5"] and d["in_goal"] is False, d
assert d["holding"] == ["msu"], d
c = d["complete"]
assert c["accepted"] is True and c["verdict"] == "accepted" and c["states"] == [], c
e = {(t["from"], t["to"]) for t in c["transitions"]}
assert ("110", "100") in e and ("111", "111") in e, e
assert all(t["from"] != "111" or t["to"] == "111" for t in c["transitions"]), c
PY
# Pulling straight up: a cycle or a stuck state, never accepted.
"$W" plan --complete --format=json "$D/three-fixels-insert.wc" 0 1 0 > "$tmp/w" 2> "$tmp/e" \
    || fail "plan (0, 1, 0): exit $?"
python3 - "$tmp/w" <<'PY' || fail "plan (0, 1, 0) JSON"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["in_goal"] is False and d["complete"]["accepted"] is False, d
# the seated part is pulled off its fixels
assert d["complete"]["verdict"] == "goal_leaves", d
assert d["complete"]["states"] == ["111"], d
PY
# Without --complete, no "complete" key.
"$W" plan --format=json "$D/three-fixels-insert.wc" -7 -5 5 > "$tmp/w" \
    && python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert "complete" not in d' "$tmp/w" \
    || fail "plan wrench without --complete"

# The sweep: nonempty at 1/100 and 1/5, empty at 2/5 and 3/5, pushing on
# the chamfer (edge 2) only, shrinking.
"$W" sweep --format=json --friction=1/100,1/5,2/5,3/5 "$D/three-fixels-insert.wc" > "$tmp/s" 2> "$tmp/e" \
    || fail "sweep: exit $?: $(cat "$tmp/e")"
python3 - "$tmp/s" <<'PY' || fail "sweep JSON"
import json, sys
d = json.load(open(sys.argv[1]))
s = d["sweep"]
assert [v["friction"] for v in s] == ["1/100", "1/5", "2/5", "3/5"], s
assert [v["goal"]["empty"] for v in s] == [False, False, True, True], s
assert all(r["edge"] == 2 for v in s for r in v["push"]["goal"]), s
lens = [v["push_length_approx"] for v in s]
assert lens[0] > lens[1] > 0 and lens[2] == 0 and lens[3] == 0, lens
assert "critical" not in d, d
PY
# The critical bracket: both ends exact and dyadic (the default
# --max-friction is a power of two), width respected.
"$W" sweep --format=json --critical --width=1/100 "$D/three-fixels-insert.wc" > "$tmp/c" 2> "$tmp/e" \
    || fail "sweep --critical: exit $?: $(cat "$tmp/e")"
python3 - "$tmp/c" <<'PY' || fail "sweep --critical JSON"
import json, sys
from fractions import Fraction as F
d = json.load(open(sys.argv[1]))["critical"]
assert d["found"] is True, d
lo, hi = F(d["lo"]), F(d["hi"])
assert 0 < hi - lo <= F(1, 100), d
dyadic = lambda x: x.denominator & (x.denominator - 1) == 0
assert dyadic(lo) and dyadic(hi), d
assert F(1, 5) < lo < hi < F(2, 5), d
assert d["lo_witness"] is not None and len(d["lo_witness"]) == 3, d
assert d["hi_cover"] and set(d["hi_cover"]) <= set("suu usu uus msu smu mms mus sum msm ums usm smm".split()), d
PY
# The witness at lo is in G_goal at lo, by `plan` with that friction.
python3 - "$tmp/c" "$D/three-fixels-insert.wc" "$tmp/lo.wc" > "$tmp/args" <<'PY' || fail "lo problem"
import json, sys
d = json.load(open(sys.argv[1]))["critical"]
src = open(sys.argv[2]).read().replace("friction 1/5", "friction " + d["lo"])
open(sys.argv[3], "w").write(src)
print(" ".join(d["lo_witness"]))
PY
"$W" plan --format=json "$tmp/lo.wc" $(cat "$tmp/args") > "$tmp/w" 2> "$tmp/e" \
    && python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); assert d["in_goal"] is True, d' "$tmp/w" \
    || fail "the witness at lo is not in G_goal ($(cat "$tmp/e"))"
# One fixel: G_goal is never empty (approach it), so the search gives up.
printf 'fixel 0 0 normal 0 1\n' > "$tmp/one.wc"
"$W" sweep --critical --max-friction=8 "$tmp/one.wc" > "$tmp/o" 2> "$tmp/e" \
    && grep -q 'G_goal is not empty at any mu <= 8' "$tmp/o" \
    || fail "one fixel: want 'not empty at any mu <= 8' ($(cat "$tmp/o" "$tmp/e"))"

# Text output names what the JSON has.
"$W" plan "$D/disk-two-fixels-insert.wc" > "$tmp/t" 2> "$tmp/e" || fail "plan text: exit $?"
grep -q '^  11      sm\* ms\* ss$' "$tmp/t" && grep -q 'needed, exactly: ms sm us' "$tmp/t" \
    && grep -q 'exact semantics: no, e.g. g = (-4, -9, 11)' "$tmp/t" \
    || fail "plan text: $(cat "$tmp/t")"

# Bad input: located errors, exit 1, nothing on stdout.
expect() { # expect STATUS PATTERN CMD...
    want=$1 pat=$2; shift 2
    "$@" > "$tmp/o" 2> "$tmp/e"; got=$?
    [ "$got" -eq "$want" ] && [ ! -s "$tmp/o" ] && grep -q -- "$pat" "$tmp/e" \
        || fail "$*: want exit $want and '$pat', got $got: $(cat "$tmp/e")"
}
expect 1 '^wrenchcone: <wrench>:1:3: ' "$W" plan "$D/three-fixels.wc" 1 1/0 0
expect 1 '^wrenchcone: <friction>:1:5: ' "$W" sweep --friction=1/5,x "$D/three-fixels.wc"
expect 1 '^wrenchcone: <friction>:1:1: .*negative' "$W" sweep --friction=-1 "$D/three-fixels.wc"
expect 1 '^wrenchcone: <width>:1:1: ' "$W" sweep --critical --width=0 "$D/three-fixels.wc"
expect 1 '^wrenchcone: <width>:1:1: the width must not be negative' "$W" sweep --critical --width=-1 "$D/three-fixels.wc"
# The search's cost is bounded: every step is a plan (at most 162 of them).
expect 1 '^wrenchcone: <width>:1:1: the width must be at least 2^-96' "$W" sweep --critical --width=1e-30 "$D/three-fixels.wc"
expect 1 "^wrenchcone: <width>:1:1: number too big in '1e-100000'" "$W" sweep --critical --width=1e-100000 "$D/three-fixels.wc"
expect 1 '^wrenchcone: <max-friction>:1:1: the largest friction must be at most 2^32' "$W" sweep --critical --max-friction=4294967297 "$D/three-fixels.wc"
expect 1 '^wrenchcone: <friction>:1:2001: at most 1000 values (each costs a plan)$' "$W" sweep --friction="$(awk 'BEGIN { s = "1"; for (i = 1; i <= 1000; i++) s = s ",1"; print s }')" "$D/three-fixels.wc"
expect 1 "^wrenchcone: <friction>:1:3: number too big in '1e100000'" "$W" sweep --friction=1,1e100000 "$D/three-fixels.wc"
expect 1 "^wrenchcone: <wrench>:1:3: number too big in '1e400'" "$W" plan "$D/three-fixels.wc" 1 1e400 0
# The smallest width allowed is accepted: the bracket ends dyadic.
"$W" sweep --critical --width=1/79228162514264337593543950336 "$D/three-fixels-insert.wc" > "$tmp/o" 2> "$tmp/e" \
    && grep -q '^  hi - lo = 1/79228162514264337593543950336 <= 1/79228162514264337593543950336 (98 plans)$' "$tmp/o" \
    || fail "sweep at the smallest width: $(cat "$tmp/e")"
"$W" random --fixels=7 --seed=1 > "$tmp/seven.wc" || fail "random --fixels=7"
expect 1 'seven.wc:13:1: the complete plan handles at most 6 fixels (this is fixel 7)$' "$W" plan --complete "$tmp/seven.wc"
expect 2 'sweep needs --friction=LIST or --critical' "$W" sweep "$D/three-fixels.wc"
expect 2 'plan takes PROBLEM and optionally FX FY TAU' "$W" plan "$D/three-fixels.wc" 1 2
expect 2 "option '--complete' does not apply here" "$W" sweep --complete "$D/three-fixels.wc"
expect 2 "option '--friction' does not apply here" "$W" plan --friction=1 "$D/three-fixels.wc"
expect 1 'cannot open' "$W" plan "$tmp/missing.wc"
"$W" plan --help > "$tmp/o" 2> "$tmp/e" && grep -q 'Usage: wrenchcone plan' "$tmp/o" \
    || fail "plan --help"
"$W" sweep --help > "$tmp/o" 2> "$tmp/e" && grep -q -- '--critical' "$tmp/o" \
    || fail "sweep --help"
"$W" plan "$D/three-fixels.wc" > /dev/full 2> "$tmp/e"
[ $? -eq 3 ] || fail "plan to /dev/full: want exit 3"


# Kinetic friction above static (issue 13): Figure 6 with mu_s = 1/10 and
# mu_k = 1/2.  A maintained contact may slide, pushing with mu_k, so the
# plans read m with the wider cone: G_goal is the wedge of friction 1/2,
# and (-2, -10, -10), which slides the seated disk off fixel 2, is
# rejected.
sed 's|^friction 1/5$|friction 1/10 1/2|' "$D/disk-two-fixels-insert.wc" > "$tmp/k.wc"
"$W" plan --complete --format=json "$tmp/k.wc" -2 -10 -10 > "$tmp/w" 2> "$tmp/e" \
    || fail "plan mu_k > mu_s wrench: exit $?: $(cat "$tmp/e")"
python3 - "$tmp/w" <<'PY' || fail "plan mu_k > mu_s wrench JSON"
import json, sys
d = json.load(open(sys.argv[1]))
assert d["in_goal"] is False and d["holding"] == ["ms"], d
c = d["complete"]
assert c["accepted"] is False and c["verdict"] == "goal_leaves" and c["states"] == ["11"], c
assert {"from": "11", "to": "10", "via": "ms"} in c["transitions"], c
PY
"$W" plan --complete --format=json "$tmp/k.wc" > "$tmp/p" 2> "$tmp/e" \
    || fail "plan mu_k > mu_s: exit $?: $(cat "$tmp/e")"
python3 - "$tmp/p" <<'PY' || fail "plan mu_k > mu_s JSON"
import json, sys
d = json.load(open(sys.argv[1]))
g = d["goal"]
assert len(g["pieces"]) == 1 and g["pieces"][0]["rays"] == [["-2", "-1", "0"], ["-1", "-2", "0"]], g
assert d["needed_exact"] == ["ms", "sm", "us"], d
assert d["complete"]["accepted"] == g and d["complete"]["outside_goal"] is None, d
assert d["push"]["goal"] == [{"from": ["2", "1"], "to": ["1", "2"],
                              "from_closed": False, "to_closed": False}], d["push"]
PY
"$W" plan --complete "$tmp/k.wc" -2 -10 -10 > "$tmp/t" 2> "$tmp/e" \
    && grep -q '^  not in G_goal: held by ms$' "$tmp/t" \
    && grep -q '^  complete plan: rejected: the goal state can lose a contact$' "$tmp/t" \
    || fail "plan mu_k > mu_s text: $(cat "$tmp/t" "$tmp/e")"

# Certificates of G_goal and of the critical bracket: they hold, the claim
# is the set printed, and a changed end does not hold.
for f in disk-two-fixels-insert three-fixels-insert peg-in-hole; do
    "$W" plan --certificate="$tmp/g.json" "$D/$f.wc" > /dev/null 2> "$tmp/e" \
        || fail "plan --certificate $f: exit $?: $(cat "$tmp/e")"
    "$W" verify "$tmp/g.json" > "$tmp/v" 2>&1 \
        && grep -q '^certificate holds: the goal set is exact: ' "$tmp/v" \
        || fail "verify plan certificate $f: $(cat "$tmp/v")"
done
"$W" plan --format=json "$D/three-fixels-insert.wc" > "$tmp/p"
"$W" plan --certificate="$tmp/g.json" "$D/three-fixels-insert.wc" > /dev/null
python3 - "$tmp/p" "$tmp/g.json" <<'PY' || fail "plan certificate claim"
import json, sys
assert json.load(open(sys.argv[2]))["goal"] == json.load(open(sys.argv[1]))["goal"]
PY
"$W" sweep --critical --certificate="$tmp/c.json" "$D/three-fixels-insert.wc" > /dev/null 2> "$tmp/e" \
    || fail "sweep --certificate: exit $?: $(cat "$tmp/e")"
"$W" verify "$tmp/c.json" > "$tmp/v" 2>&1
[ "$(cat "$tmp/v")" = "certificate holds: the critical friction lies in [187/512, 375/1024]: G_goal is nonempty at mu = lo and empty at mu = hi" ] \
    || fail "verify critical certificate: $(cat "$tmp/v")"
sed 's|"lo": "187/512"|"lo": "3/8"|' "$tmp/c.json" > "$tmp/c2.json"
"$W" verify "$tmp/c2.json" > "$tmp/v" 2>&1
[ $? -eq 4 ] || fail "a critical certificate with lo moved up holds: $(cat "$tmp/v")"
"$W" plan --certificate="$tmp/x.json" "$D/disk-two-fixels-insert.wc" 0 -1 0 > "$tmp/o" 2> "$tmp/e"
[ $? -eq 2 ] && [ ! -s "$tmp/o" ] || fail "plan --certificate with a wrench: not a usage error"
"$W" sweep --friction=1/5 --certificate="$tmp/x.json" "$D/disk-two-fixels-insert.wc" > "$tmp/o" 2> "$tmp/e"
[ $? -eq 2 ] && [ ! -s "$tmp/o" ] || fail "sweep --certificate without --critical: not a usage error"

# Found by review: claims that held with no proof.  An empty goal set at
# zero without a certificate at hi is malformed; a piece that leaves out
# the relative interior of its closure does not hold; more planes than
# verify reads are refused before any work.
python3 - "$tmp/c.json" "$tmp/g.json" "$tmp" <<'PY' || fail "review mutations"
import json, sys
c, g, t = json.load(open(sys.argv[1])), json.load(open(sys.argv[2])), sys.argv[3]
c.update(found=False, empty_at_zero=True, lo="0", hi=None, lower=None, upper=None)
json.dump(c, open(t + "/r1.json", "w"))
assert g["goal"]["pieces"], "three-fixels-insert has a goal set"
g["goal"]["pieces"][0]["faces"][-1]["included"] = False
json.dump(g, open(t + "/r2.json", "w"))
g["planes"] = [[1, 0, k] for k in range(1001)]
json.dump(g, open(t + "/r3.json", "w"))
PY
for r in r1:1 r2:4 r3:1; do
    "$W" verify "$tmp/${r%%:*}.json" > "$tmp/v" 2>&1
    st=$?
    [ $st -eq "${r##*:}" ] || fail "review case ${r%%:*}: exit $st, not ${r##*:}: $(cat "$tmp/v")"
done

exit $failed
