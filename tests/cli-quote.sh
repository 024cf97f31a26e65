#!/bin/sh
# cli-quote.sh -- input the program echoes is quoted and bounded: every
# line `batch` writes is valid UTF-8 JSON whatever its request held (raw
# bytes after a backslash, in a key, a command, a number, a path), and a
# few of them are exact bytes; messages on stderr quote raw bytes and
# control characters as \xNN and cut a long token on a character
# boundary; a path that is not UTF-8 is quoted in --print-request's JSON,
# in the SVG of draw and the HTML of report (well-formed XML, UTF-8); the
# mode a cone file claims is quoted in compare's text; a problem's name
# that is not UTF-8 is refused; batch's exit status ranks an internal
# failure above every other error and every error above a comparison
# beyond its tolerance (wrenchcone(1), batch).
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.
#
# Run by make check with WRENCHCONE and top_srcdir in the environment.
# Silent on success; prints each failing case and exits 1.

: "${WRENCHCONE:?WRENCHCONE is not set}"
: "${top_srcdir:?top_srcdir is not set}"

. "$top_srcdir/tests/clitest.sh"
need python3
W=$WRENCHCONE
VERIFY=$(dirname "$W")/wrenchcone-verify
cd "$top_srcdir" || exit 99

# json_lines NAME FILE: every line of FILE is one JSON value in valid
# UTF-8, and the file ends with a newline.
cat > "$tmp/lines.py" <<'EOF'
import json, sys
data = open(sys.argv[1], "rb").read()
if data and not data.endswith(b"\n"):
    sys.exit("no newline at the end")
for i, line in enumerate(data.split(b"\n")[:-1], 1):
    try:
        json.loads(line.decode("utf-8"))
    except ValueError as e:
        sys.exit("line %d: %s: %r" % (i, e, line[:100]))
EOF
json_lines() {
    python3 "$tmp/lines.py" "$2" > "$tmp/why" 2>&1 \
        || fail "$1" "not valid UTF-8 JSON lines: $(cat "$tmp/why")"
}

# same NAME WANT-FILE GOT-FILE
same() {
    cmp -s "$2" "$3" || { fail "$1" "differs:"; diff "$2" "$3" | head -n 6; }
}

# --- batch: hostile requests, one answer line each ------------------------
# A backslash before a raw byte, before a 2-byte character, \u0 and raw
# bytes; raw bytes in a key, after a value, in a number; control
# characters in a command and a key; a number of 81 bytes of 2-byte
# characters; raw bytes in a problem's text and in a path.
{
    printf '{"command": "x\\\377"}\n'
    printf '{"command": "x\\\303\251"}\n'
    printf '{"command": "\\u0\303\251\200"}\n'
    printf '{"command": "cone", "\376": 1}\n'
    printf '{"command": "cone"\376}\n'
    printf '{"command": "a\\nb\\u0085"}\n'
    printf '{"command": "modes", "problem": "data/section4.wc", "\\t": 1}\n'
    printf '{"command": "classify", "problem": "data/section4.wc", "wrench": ["a'
    i=0
    while [ $i -lt 40 ]; do printf '\303\251'; i=$((i + 1)); done
    printf '", 0, 0]}\n'
    printf '{"command": "modes", "problem_text": "name \\"a\377\\"\\nmass 1"}\n'
    printf '{"command": "modes", "problem": "\377/\001.wc"}\n'
    printf '\377\n'
} > "$tmp/hostile.jsonl"
"$W" batch "$tmp/hostile.jsonl" > "$tmp/got" 2> "$tmp/err"
st=$?
[ $st -eq 2 ] || fail "hostile batch" "exit status $st, want 2"
[ -s "$tmp/err" ] && fail "hostile batch" "wrote on stderr: $(head -c 200 "$tmp/err")"
json_lines "hostile batch" "$tmp/got"
B=$tmp/hostile.jsonl
E='{"format": "wrenchcone-json/1", "error": {"message": '
{
    printf '%s"invalid escape '"'"'\\\\\\\\xff'"'"'", "file": "%s", "line": 1, "column": 15, "status": 2}}\n' "$E" "$B"
    printf '%s"invalid escape '"'"'\\\\\303\251'"'"'", "file": "%s", "line": 2, "column": 15, "status": 2}}\n' "$E" "$B"
    printf '%s"invalid escape '"'"'\\\\u0\303\251\\\\x80'"'"'", "file": "%s", "line": 3, "column": 14, "status": 2}}\n' "$E" "$B"
    printf '%s"invalid UTF-8 in string", "file": "%s", "line": 4, "column": 22, "status": 2}}\n' "$E" "$B"
    printf '%s"expected '"','"' or '"'}'"', found '"'"'\\\\xfe'"'"'", "file": "%s", "line": 5, "column": 19, "status": 2}}\n' "$E" "$B"
    printf '%s"unknown command '"'"'a\\\\x0ab\\\\u0085'"'"' (cone, modes, feasible, classify, stability, plan, sweep, verify, compare, random, draw or report)", "file": "%s", "line": 6, "column": 13, "status": 2}}\n' "$E" "$B"
    printf '%s"\\"\\\\x09\\" is not a key of a modes request", "file": "%s", "line": 7, "column": 53, "status": 2}}\n' "$E" "$B"
    printf '%s"bad number '"'"'a' "$E"
    i=0
    while [ $i -lt 31 ]; do printf '\303\251'; i=$((i + 1)); done
    printf '...'"'"'", "file": "<wrench>", "line": 1, "column": 1, "status": 1}}\n'
    printf '%s"invalid UTF-8 in string", "file": "%s", "line": 9, "column": 47, "status": 2}}\n' "$E" "$B"
    printf '%s"invalid UTF-8 in string", "file": "%s", "line": 10, "column": 34, "status": 2}}\n' "$E" "$B"
    printf '%s"expected a value, found '"'"'\\\\xff'"'"'", "file": "%s", "line": 11, "column": 1, "status": 2}}\n' "$E" "$B"
} > "$tmp/want"
same "hostile batch" "$tmp/want" "$tmp/got"

# A path of 100,000 bytes: the record names its first 1024 and "...".
python3 -c 'print("{\"command\": \"modes\", \"problem\": \"" + "d" * 100000 + "\"}")' \
    > "$tmp/long.jsonl"
"$W" batch "$tmp/long.jsonl" > "$tmp/got" 2> "$tmp/err"
python3 -c 'print("{\"format\": \"wrenchcone-json/1\", \"error\": {\"message\": \"cannot open: File name too long\", \"file\": \"" + "d" * 1024 + "...\", \"line\": null, \"column\": null, \"status\": 1}}")' \
    > "$tmp/want"
same "100,000-byte path" "$tmp/want" "$tmp/got"

# --- messages on stderr ---------------------------------------------------
# expect_err NAME STATUS: the last run's exit status and stderr ($tmp/want).
expect_err() {
    [ "$status" -eq "$2" ] || fail "$1" "exit status $status, want $2"
    same "$1" "$tmp/want" "$tmp/err"
}
run /dev/null "$(printf 'co\377\001')" data/section4.wc na
printf "wrenchcone: unknown command 'co\\\\xff\\\\x01'\nTry 'wrenchcone --help' for more information.\n" > "$tmp/want"
expect_err "unknown command" 2
run /dev/null cone --method="$(printf '\351\n!')" data/section4.wc na
printf "wrenchcone: unknown method '\\\\xe9\\\\x0a!' (direct or paper)\nTry 'wrenchcone cone --help' for more information.\n" > "$tmp/want"
expect_err "unknown method" 2
long=$(i=0; while [ $i -lt 40 ]; do printf '\303\251'; i=$((i + 1)); done)
run /dev/null random "x$long"
printf "wrenchcone: random takes no operands, not 'x" > "$tmp/want"
i=0; while [ $i -lt 31 ]; do printf '\303\251'; i=$((i + 1)); done >> "$tmp/want"
printf "...'\nTry 'wrenchcone random --help' for more information.\n" >> "$tmp/want"
expect_err "long operand" 2
run /dev/null modes "--x$(printf '\376')"
printf "wrenchcone: unknown or incomplete option '--x\\\\xfe'\nTry 'wrenchcone modes --help' for more information.\n" > "$tmp/want"
expect_err "unknown option" 2
run /dev/null modes "$(printf 'no\377such.wc')"
printf "wrenchcone: no\\\\xffsuch.wc: cannot open: No such file or directory\n" > "$tmp/want"
expect_err "missing file" 1
run /dev/null batch "$(printf 'no\377such.jsonl')"
printf "wrenchcone: no\\\\xffsuch.jsonl: cannot open: No such file or directory\n" > "$tmp/want"
expect_err "missing batch file" 1
"$VERIFY" --format="$(printf 'x\033')" c.json > "$tmp/out" 2> "$tmp/err"
status=$?
printf "wrenchcone: unknown format 'x\\\\x1b' (text or json)\nTry 'wrenchcone-verify --help' for more information.\n" > "$tmp/want"
expect_err "wrenchcone-verify --format" 2

# --- outputs that name a path ---------------------------------------------
q=$tmp/$(printf 'q\377')
grep -v '^name' data/section4.wc > "$q.wc"
"$W" cone --print-request "$q.wc" na > "$tmp/got" 2> "$tmp/err"
json_lines "--print-request" "$tmp/got"
printf '{"command": "cone", "problem": "%s/q\\\\xff.wc", "mode": "na"}\n' "$tmp" > "$tmp/want"
same "--print-request" "$tmp/want" "$tmp/got"
cat > "$tmp/check_xml.py" <<'EOF'
import sys, xml.dom.minidom
data = open(sys.argv[1], "rb").read()
text = data.decode("utf-8")
if sys.argv[2] not in text:
    sys.exit("no %r" % sys.argv[2])
xml.dom.minidom.parseString(data)
EOF
"$W" draw --mode=na -o "$tmp/d.svg" "$q.wc" 2> "$tmp/err" \
    || fail "draw" "status $?: $(cat "$tmp/err")"
python3 "$tmp/check_xml.py" "$tmp/d.svg" 'q\xff.wc' > "$tmp/why" 2>&1 \
    || fail "draw" "the SVG: $(cat "$tmp/why")"
"$W" report -o "$tmp/r.html" "$q.wc" 2> "$tmp/err" \
    || fail "report" "status $?: $(cat "$tmp/err")"
python3 "$tmp/check_xml.py" "$tmp/r.html" 'q\xff.wc' > "$tmp/why" 2>&1 \
    || fail "report" "the HTML: $(cat "$tmp/why")"

# The mode a cone file claims, with a newline: one line in the text.
"$W" cone --format=json data/section4.wc na \
    | sed 's/"mode": "na"/"mode": "x\\ny"/' > "$tmp/c.json"
run /dev/null compare data/section4.wc na "$tmp/c.json"
grep -qx 'the file is for mode x\\x0ay, not na' "$tmp/out" \
    || fail "compare" "the file's mode not quoted: $(grep -a 'for mode' "$tmp/out" | head -n 2)"
grep -qx 'verdict: outside tolerance: the file is for mode x\\x0ay, not na' "$tmp/out" \
    || fail "compare" "the verdict does not quote the file's mode"

# A problem's name that is not UTF-8, or holds a control character.
printf 'name "a\377"\n' > "$tmp/n1.wc"
grep -v '^name' data/section4.wc >> "$tmp/n1.wc"
run /dev/null modes "$tmp/n1.wc"
printf 'wrenchcone: %s/n1.wc:1:8: invalid UTF-8 in string\n' "$tmp" > "$tmp/want"
expect_err "name not UTF-8" 1
printf 'name "a\033b"\n' > "$tmp/n2.wc"
run /dev/null modes "$tmp/n2.wc"
printf "wrenchcone: %s/n2.wc:1:8: control character '\\\\x1b' in string\n" "$tmp" > "$tmp/want"
expect_err "name with an escape character" 1

# --- batch's exit status --------------------------------------------------
disagree='{"command": "compare", "problem": "data/section4.wc", "mode": "sa", "foreign_text": "V-representation\nbegin\n1 4 rational\n0 1 0 -1\nend\n"}'
badinput='{"command": "cone", "problem": "data/section4.wc", "mode": "nx"}'
badusage='{"command": "cone"}'
internal='{"command": "modes", "problem": "/proc/self/mem"}'
# batch_status NAME WANT LINE...
batch_status() {
    bs_name=$1 bs_want=$2
    shift 2
    printf '%s\n' "$@" > "$tmp/status.jsonl"
    "$W" batch "$tmp/status.jsonl" > "$tmp/out" 2> "$tmp/err"
    bs=$?
    [ $bs -eq "$bs_want" ] || fail "batch status: $bs_name" "exit $bs, want $bs_want"
    [ "$(wc -l < "$tmp/out")" -eq $# ] || fail "batch status: $bs_name" "not $# answers"
}
batch_status "a disagreement alone" 4 "$disagree"
batch_status "bad input and a disagreement" 1 "$disagree" "$badinput"
batch_status "bad usage, bad input and a disagreement" 2 "$badinput" "$badusage" "$disagree"
# /proc/self/mem fails when read (Linux): an internal failure.
"$W" modes /proc/self/mem > /dev/null 2>&1
if [ $? -eq 3 ]; then
    batch_status "an internal failure and a disagreement" 3 "$disagree" "$internal"
    batch_status "an internal failure after bad usage" 3 "$badusage" "$internal" "$disagree"
else
    echo "note: /proc/self/mem reads without an I/O error here: no internal failure to test"
fi

[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
exit 0
