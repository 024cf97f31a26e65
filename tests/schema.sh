#!/bin/sh
# schema.sh -- the command table (lib/api/schema.c, printed by
# `wrenchcone --schema`) against what is written from it or about it:
#   - wrenchcone(1) names every option of every command in that command's
#     entry of COMMANDS or in OPTIONS, and names no option that no command
#     has;
#   - REQUESTS names every request key of every request command;
#   - each command's --help lists each of its options, and the main
#     --help each command;
#   - --print-request of a command line, fed to batch, answers what the
#     command line prints with --format=json.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${WRENCHCONE:?}" "${top_srcdir:?}"
. "$top_srcdir/tests/clitest.sh"
need python3
W=$WRENCHCONE
D=$top_srcdir/data

"$W" --schema > "$tmp/schema.json" || fail schema "exit $?"
for c in $(python3 -c 'import json,sys
for c in json.load(open(sys.argv[1]))["commands"]: print(c["name"])' "$tmp/schema.json"); do
    "$W" "$c" --help > "$tmp/help-$c" || fail "$c --help" "exit $?"
done
"$W" --help > "$tmp/help" || fail "--help" "exit $?"

python3 - "$tmp" "$top_srcdir/man/wrenchcone.1" <<'PY' || failures=$((failures + 1))
import json, re, sys
tmp, man = sys.argv[1], sys.argv[2]
schema = json.load(open(tmp + "/schema.json"))
text = open(man).read()
bad = []

def section(name):
    m = re.search(r'^\.SH ' + name + r'\n(.*?)(?=^\.SH )', text, re.S | re.M)
    return m.group(1) if m else ""

def options_in(s):
    return set(m.replace('\\-', '-')
               for m in re.findall(r'\\-\\-((?:[a-z]|\\-)+)', s))

commands, general = section("COMMANDS"), section("OPTIONS")
# A command's entry: from ".TP\n.B NAME" to the next entry of another
# command at the top level.
names = [c["name"] for c in schema["commands"]]
starts = [(m.start(), m.group(1)) for m in
          re.finditer(r'^\.TP\n\.B ([a-z]+)\b', commands, re.M) if m.group(1) in names]
entries = {}
for k, (pos, name) in enumerate(starts):
    end = starts[k + 1][0] if k + 1 < len(starts) else len(commands)
    entries[name] = entries.get(name, "") + commands[pos:end]
every = {"help", "version", "progress", "decimals", "print-request", "schema"}
known = set(every)
for c in schema["commands"]:
    if c["name"] not in entries:
        bad.append("wrenchcone(1) COMMANDS has no entry for %s" % c["name"])
        continue
    have = options_in(entries[c["name"]]) | options_in(general)
    for o in c["options"]:
        known.add(o["option"])
        if o["option"] not in have:
            bad.append("wrenchcone(1) does not name --%s of %s" % (o["option"], c["name"]))
    h = open(tmp + "/help-" + c["name"]).read()
    for o in c["options"]:
        if not re.search(r'^  (-[a-z], )?--' + re.escape(o["option"]) + r'\b', h, re.M):
            bad.append("%s --help does not list --%s" % (c["name"], o["option"]))
    if not re.search(r'^  ' + re.escape(c["synopsis"]), open(tmp + "/help").read(), re.M):
        bad.append("--help does not list %s" % c["name"])
for o in sorted(options_in(text) - known):
    bad.append("wrenchcone(1) names --%s, which no command has" % o)
for o in sorted(every - options_in(text)):
    bad.append("wrenchcone(1) does not name --%s" % o)
requests = section("REQUESTS")
words = set(re.findall(r'^\.BR? (\S+)', requests, re.M)) | \
    set(re.findall(r'" (\S+?)(?: |$)', requests, re.M)) | \
    set(re.findall(r'\.BR? \S+ ", " (\S+)', requests, re.M))
for c in schema["commands"]:
    if not c["request"]:
        continue
    for a in c["operands"] + c["options"]:
        if a["request"] and a["key"] not in requests:
            bad.append("REQUESTS does not name key %s of %s" % (a["key"], c["name"]))
for b in bad:
    print("FAIL: " + b)
sys.exit(1 if bad else 0)
PY

# --print-request, then batch: the same answer as --format=json.
same_answer() { # NAME ARGS...
    name=$1; shift
    "$W" "$@" --print-request > "$tmp/req" 2> "$tmp/err" \
        || { fail "$name" "--print-request: exit $?: $(cat "$tmp/err")"; return; }
    "$W" batch "$tmp/req" > "$tmp/got" 2> "$tmp/err"
    st=$?
    "$W" "$@" --format=json > "$tmp/want" 2> "$tmp/err"
    [ $? = $st ] || fail "$name" "exit status $st from batch"
    cmp -s "$tmp/got" "$tmp/want" || fail "$name" "batch answers $(head -c 200 "$tmp/got")"
}
same_answer cone cone "$D/section4.wc" na
same_answer cone-paper cone --method=paper --trace "$D/section4.wc" sa
same_answer modes modes --witness "$D/three-fixels.wc"
same_answer feasible feasible "$D/three-fixels.wc" asa
same_answer classify classify "$D/section4.wc" 0 -1 0
same_answer classify-max classify --max-modes=2 "$D/three-fixels.wc" 0 -1 0
same_answer stability stability --bias 0 -1 0 --length=1/2 "$D/section4.wc"
same_answer plan plan "$D/three-fixels.wc"
same_answer plan-wrench plan --complete "$D/three-fixels.wc" 0 -1 0
same_answer compare compare --tol=1e-6 "$D/section4.wc" na "$top_srcdir/tests/golden/section4-na.json"
same_answer sweep sweep --critical --friction=0,1/10 "$D/three-fixels.wc"
same_answer random random --seed=7 --fixels=4 --shape=polygon --degenerate
"$W" classify --certificate="$tmp/cert.json" "$D/section4.wc" 0 -1 0 > /dev/null \
    || fail certificate "classify --certificate: exit $?"
same_answer verify verify "$tmp/cert.json"

# draw and report: the answer's document is what -o writes.
same_document() { # NAME KEY ARGS... (-o FILE appended)
    name=$1; key=$2; shift 2
    "$W" "$@" -o "$tmp/doc" --print-request > "$tmp/req" 2> "$tmp/err" \
        || { fail "$name" "--print-request: exit $?: $(cat "$tmp/err")"; return; }
    "$W" "$@" -o "$tmp/doc" || { fail "$name" "exit $?"; return; }
    "$W" batch "$tmp/req" | python3 -c 'import json, sys
sys.stdout.write(json.loads(sys.stdin.readline())[sys.argv[1]])' "$key" > "$tmp/got" \
        || { fail "$name" "no $key in the answer"; return; }
    cmp -s "$tmp/got" "$tmp/doc" || fail "$name" "the answer's $key differs from -o's file"
}
same_document draw-mode svg draw --mode=na "$D/section4.wc"
same_document draw-sweep svg draw --sweep=0,1/5 "$D/three-fixels.wc"
same_document draw-graph svg draw --graph --wrench=0,-1,0 "$D/three-fixels.wc"
same_document report html report "$D/section4.wc"

# "certificate": true: the answer carries what --certificate writes, on
# one line, and it holds.
for req in '"command": "classify", "problem": "'"$D"'/section4.wc", "wrench": [0, -1, 0]' \
           '"command": "feasible", "problem": "'"$D"'/section4.wc", "mode": "na"' \
           '"command": "plan", "problem": "'"$D"'/three-fixels.wc"'; do
    printf '{%s, "certificate": true}\n' "$req" | "$W" batch > "$tmp/ans" \
        || { fail certificate "$req: exit $?"; continue; }
    python3 -c 'import json, sys
json.dump(json.loads(open(sys.argv[1]).readline())["certificate"], sys.stdout)' "$tmp/ans" > "$tmp/c.json" \
        && "$W" verify "$tmp/c.json" > /dev/null \
        || fail certificate "$req: the certificate in the answer does not verify"
done

# batch is not a request.
"$W" batch --print-request /dev/null > "$tmp/out" 2> /dev/null
[ $? = 2 ] && [ ! -s "$tmp/out" ] || fail batch "--print-request is not refused"

# Standard input becomes problem_text.
"$W" cone --print-request - na < "$D/section4.wc" > "$tmp/req" \
    && "$W" batch "$tmp/req" > "$tmp/got" \
    && "$W" cone --format=json "$D/section4.wc" na > "$tmp/want" \
    && cmp -s "$tmp/got" "$tmp/want" || fail stdin "$(cat "$tmp/req")"
[ $failures -eq 0 ]
