#!/bin/sh
# cli-batch.sh -- `wrenchcone batch` and `cone --all-modes` end to end
# (wrenchcone(1), REQUESTS): on every data/*.wc problem and every corpus
# problem, one batch of requests (cones of the feasible modes, by both
# routes, with a trace and in doubles; modes with and without witnesses;
# feasible; classify; compare against a cone file, agreeing and not; and
# on the data/ problems and a sample of the corpus stability, with a bias,
# and plan, with a wrench) answers line for line exactly what the single
# commands print with --format=json, errors included; --all-modes prints
# the same lines as one cone per mode, and refuses a problem of over
# 10000 modes; malformed lines, unknown or ill-typed keys and missing
# files give the located error line and the batch goes on; the exit
# status is the worst line's, an error outranking a disagreement; an
# empty input gives nothing and status 0;
# --jobs=2 and 5 answer the same bytes as one thread, a bad --jobs is a
# usage error.
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
tmp=$(mktemp -d "${TMPDIR:-/tmp}/cli-batch.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM
failures=0

fail() {
    printf 'FAIL: %s\n' "$*"
    failures=$((failures + 1))
}

# The problems are named relative to the source tree, as a user would.
cd "$top_srcdir" || exit 99

# JSON string literal of $1 (quotes and backslashes escaped).
jstr() {
    printf '"%s"' "$(printf '%s' "$1" | sed 's/[\\"]/\\&/g')"
}

# The error record of the CLI's diagnostic in $tmp/err with status $1:
# "wrenchcone: FILE:LINE:COL: MSG", "wrenchcone: FILE: MSG" (FILE without
# spaces) or "wrenchcone: MSG".
record() {
    line=$(head -n 1 "$tmp/err")
    line=${line#wrenchcone: }
    file=null l=null c=null msg=$line
    case $line in
    *:[0-9]*:[0-9]*:\ *)
        file=$(printf '%s' "$line" | sed 's/^\([^ :]*\):\([0-9]*\):\([0-9]*\): .*/\1/')
        l=$(printf '%s' "$line" | sed 's/^\([^ :]*\):\([0-9]*\):\([0-9]*\): .*/\2/')
        c=$(printf '%s' "$line" | sed 's/^\([^ :]*\):\([0-9]*\):\([0-9]*\): .*/\3/')
        msg=$(printf '%s' "$line" | sed 's/^[^ :]*:[0-9]*:[0-9]*: //')
        file=$(jstr "$file") ;;
    [!\ ]*:\ *)
        file=$(jstr "${line%%: *}")
        msg=${line#*: } ;;
    esac
    printf '{"format": "wrenchcone-json/1", "error": {"message": %s, "file": %s, "line": %s, "column": %s, "status": %s}}\n' \
        "$(jstr "$msg")" "$file" "$l" "$c" "$1"
}

# req JSON ARGS...: the request JSON goes to the batch; what `wrenchcone
# ARGS --format=json` prints (or its error record) to the expected answers;
# its status to the expected worst.
worst=0
req() {
    printf '%s\n' "$1" >> "$tmp/requests"
    shift
    "$W" "$@" --format=json > "$tmp/out" 2> "$tmp/err"
    st=$?
    case $st in
    0|4) cat "$tmp/out" >> "$tmp/want" ;;
    *) record $st >> "$tmp/want" ;;
    esac
    # errors rank above a disagreement (4), the larger error first
    [ $(rank $st) -gt $(rank $worst) ] && worst=$st
}

# rank STATUS: 0, 4 (a disagreement, an answer), 1, 2, 3 in this order.
rank() {
    case $1 in 0) echo 0 ;; 4) echo 1 ;; *) echo $(($1 + 1)) ;; esac
}

: > "$tmp/requests"
: > "$tmp/want"
sample=0
for p in data/*.wc data/corpus/*.wc; do
    P=$(jstr "$p")
    modes=$("$W" modes "$p") || { fail "modes $p"; continue; }
    first=$(printf '%s\n' $modes | head -n 1)
    last=$(printf '%s\n' $modes | tail -n 1)
    req "{\"command\": \"modes\", \"problem\": $P}" modes "$p"
    req "{\"command\": \"modes\", \"problem\": $P, \"witness\": true}" modes --witness "$p"
    # Every mode's cone on data/, the first and last on the corpus (whose
    # every cone corpus.sh checks), and feasible on the first and last
    # (t-request and python.sh compare more), to keep the test to seconds.
    case $p in data/corpus/*) some="$first $last" ;; *) some=$modes ;; esac
    for m in $some; do
        req "{\"command\": \"cone\", \"problem\": $P, \"mode\": \"$m\"}" cone "$p" "$m"
    done
    for m in $first $last; do
        req "{\"command\": \"feasible\", \"problem\": $P, \"mode\": \"$m\"}" feasible "$p" "$m"
    done
    req "{\"command\": \"cone\", \"problem\": $P, \"mode\": \"$first\", \"method\": \"paper\", \"trace\": true}" \
        cone --method=paper --trace "$p" "$first"
    req "{\"command\": \"cone\", \"problem\": $P, \"mode\": \"$last\", \"method\": \"paper\", \"arith\": \"double\"}" \
        cone --method=paper --arith=double "$p" "$last"
    req "{\"command\": \"classify\", \"problem\": $P, \"wrench\": [\"0\", \"-1\", \"0\"]}" classify "$p" 0 -1 0
    req "{\"command\": \"classify\", \"problem\": $P, \"wrench\": [1, \"-1/2\", 0.25], \"max_modes\": 2}" \
        classify --max-modes=2 "$p" 1 -1/2 0.25
    "$W" cone --format=json "$p" "$first" > "$tmp/cone-$sample.json"
    F=$(jstr "$tmp/cone-$sample.json")
    req "{\"command\": \"compare\", \"problem\": $P, \"mode\": \"$first\", \"foreign\": $F}" \
        compare "$p" "$first" "$tmp/cone-$sample.json"
    req "{\"command\": \"compare\", \"problem\": $P, \"mode\": \"$last\", \"foreign\": $F, \"tol\": 1e-6}" \
        compare --tol=1e-6 "$p" "$last" "$tmp/cone-$sample.json"
    case $p in data/corpus/r[34]*) sample=$((sample + 1)); continue ;; esac
    req "{\"command\": \"stability\", \"problem\": $P}" stability "$p"
    req "{\"command\": \"stability\", \"problem\": $P, \"bias\": [\"0\", \"-1\", \"0\"], \"length\": \"2\"}" \
        stability --bias=0,-1,0 --length=2 "$p"
    req "{\"command\": \"plan\", \"problem\": $P}" plan "$p"
    req "{\"command\": \"plan\", \"problem\": $P, \"wrench\": [\"0\", \"-1\", \"0\"]}" plan "$p" 0 -1 0
    sample=$((sample + 1))
done
# Errors the command line reports from the problem, the mode, a number.
for b in tests/bad/bad-number.wc tests/bad/duplicate-fixel.wc \
    tests/bad/no-fixel.wc tests/bad/point-off-boundary.wc \
    tests/bad/unterminated-name.wc tests/bad/modes.wc; do
    req "{\"command\": \"modes\", \"problem\": $(jstr "$b")}" modes "$b"
done
req '{"command": "cone", "problem": "data/section4.wc", "mode": "nx"}' cone data/section4.wc nx
req '{"command": "cone", "problem": "data/no-such-file.wc", "mode": "na"}' cone data/no-such-file.wc na
req '{"command": "classify", "problem": "data/section4.wc", "wrench": ["0", "1/0", "0"]}' \
    classify data/section4.wc 0 1/0 0
req '{"command": "stability", "problem": "data/section4.wc", "length": "-1"}' stability --length=-1 data/section4.wc

"$W" batch "$tmp/requests" > "$tmp/got" 2> "$tmp/err"
st=$?
[ $st -eq $worst ] || fail "batch exit status $st, want $worst (the worst line's)"
[ -s "$tmp/err" ] && fail "batch wrote on stderr: $(head -n 3 "$tmp/err")"
if ! cmp -s "$tmp/want" "$tmp/got"; then
    fail "batch differs from the single commands:"
    diff "$tmp/want" "$tmp/got" | head -n 10 | cut -c 1-300
fi
want=$(wc -l < "$tmp/requests")
got=$(wc -l < "$tmp/got")
[ "$want" -eq "$got" ] || fail "$want requests, $got answer lines"
# The same from standard input, and with "-".
"$W" batch < "$tmp/requests" > "$tmp/got2" 2>/dev/null
cmp -s "$tmp/got" "$tmp/got2" || fail "batch < FILE differs from batch FILE"
"$W" batch - < "$tmp/requests" > "$tmp/got2" 2>/dev/null
cmp -s "$tmp/got" "$tmp/got2" || fail "batch - < FILE differs from batch FILE"
# With threads: the same bytes, in the same order, the same status.
for j in 2 5; do
    "$W" batch --jobs=$j "$tmp/requests" > "$tmp/got2" 2> "$tmp/err"
    st=$?
    [ $st -eq $worst ] || fail "batch --jobs=$j exit status $st, want $worst"
    [ -s "$tmp/err" ] && fail "batch --jobs=$j wrote on stderr: $(head -n 3 "$tmp/err")"
    cmp -s "$tmp/got" "$tmp/got2" || fail "batch --jobs=$j differs from batch"
done

# --all-modes: one cone line per mode of `modes`, in its order, as the
# batch (equal to the single commands above) answers a cone request each.
for p in data/*.wc data/corpus/r1-s3.wc data/corpus/r4-s7-degenerate.wc; do
    : > "$tmp/cones"
    for m in $("$W" modes "$p"); do
        printf '{"command": "cone", "problem": %s, "mode": "%s"}\n' "$(jstr "$p")" "$m" >> "$tmp/cones"
    done
    "$W" batch "$tmp/cones" > "$tmp/want"
    "$W" cone --all-modes "$p" > "$tmp/got" 2> "$tmp/err" || fail "cone --all-modes $p: status $?"
    cmp -s "$tmp/want" "$tmp/got" || fail "cone --all-modes $p differs from one cone per mode"
done
"$W" cone --all-modes --method=paper --format=json data/section4.wc > "$tmp/got" || fail "--all-modes --method=paper"
"$W" cone --all-modes data/section4.wc | cmp -s - "$tmp/got" || fail "--all-modes: the routes differ"
"$W" cone --all-modes --format=text data/section4.wc > "$tmp/out" 2> "$tmp/err"
[ $? -eq 2 ] && [ ! -s "$tmp/out" ] || fail "--all-modes --format=text: not a usage error"
"$W" cone --all-modes data/section4.wc na > "$tmp/out" 2> "$tmp/err"
[ $? -eq 2 ] && [ ! -s "$tmp/out" ] || fail "--all-modes with a MODE: not a usage error"
"$W" cone --all-modes tests/bad/bad-number.wc > "$tmp/out" 2> "$tmp/err"
[ $? -eq 1 ] && [ ! -s "$tmp/out" ] || fail "--all-modes on a bad problem: not status 1 with nothing on stdout"

# More modes than --all-modes computes: refused before any cone, with
# the count (120 near fixels in general enough position: 13732 modes).
awk 'BEGIN { print "mass 1\ninertia 1\ncom 0 0\nfriction 1/5"
    for (k = 1; k <= 120; k++)
        printf "fixel %d %d normal %d %d near\n", k, k * k + 3, k % 7 - 3, k % 5 + 1 }' > "$tmp/many.wc"
"$W" cone --all-modes "$tmp/many.wc" > "$tmp/out" 2> "$tmp/err"
st=$?
[ $st -eq 1 ] && [ ! -s "$tmp/out" ] || fail "--all-modes over the limit: status $st"
[ "$(cat "$tmp/err")" = "wrenchcone: $tmp/many.wc: 13732 modes, over the 10000 that --all-modes computes: list them with 'modes' and give them to 'batch'" ] \
    || fail "--all-modes over the limit: $(cat "$tmp/err")"

# Malformed lines: an error line each, located in the batch file, and
# the batch goes on.
cat > "$tmp/bad.jsonl" <<'EOF'
{"command": "cone", "problem": "data/section4.wc", "mode": "na"

[1, 2]
{"command": "batch", "problem": "data/section4.wc"}
{"command": "cone", "problem": "data/section4.wc", "mode": "na", "witness": true}
{"command": "cone", "problem": "data/section4.wc"}
{"command": "cone", "problem": "data/section4.wc", "mode": 3}
{"command": "cone", "mode": "na"}
{"command": "cone", "problem": "-", "mode": "na"}
{"command": "classify", "problem": "data/section4.wc", "wrench": ["0", "-1"]}
{"command": "cone", "problem": "data/section4.wc", "mode": "na", "method": "fast"}
{"command": "modes", "problem_text": "mass 1\ninertia 1\ncom 0 0\nfriction 1/5\nfixel 0 -1 normal 0 1 touching\nfixel 1 0 normal -1 0 near\n"}
{"command": "modes", "problem_text": "mass 1\nbogus 2\n"}
{"command": "modes", "problem": "data/section4.wc"} trailing
EOF
"$W" batch "$tmp/bad.jsonl" > "$tmp/got" 2> "$tmp/err"
st=$?
[ $st -eq 2 ] || fail "malformed lines: exit status $st, want 2"
B=$tmp/bad.jsonl
cat > "$tmp/want" <<EOF
{"format": "wrenchcone-json/1", "error": {"message": "unexpected end of input", "file": "$B", "line": 1, "column": 64, "status": 2}}
{"format": "wrenchcone-json/1", "error": {"message": "a request is a JSON object, not an array", "file": "$B", "line": 3, "column": 1, "status": 2}}
{"format": "wrenchcone-json/1", "error": {"message": "unknown command 'batch' (cone, modes, feasible, classify, stability, plan, sweep, verify, compare, random, draw or report)", "file": "$B", "line": 4, "column": 13, "status": 2}}
{"format": "wrenchcone-json/1", "error": {"message": "\"witness\" is not a key of a cone request", "file": "$B", "line": 5, "column": 66, "status": 2}}
{"format": "wrenchcone-json/1", "error": {"message": "a cone request needs \"mode\"", "file": "$B", "line": 6, "column": 1, "status": 2}}
{"format": "wrenchcone-json/1", "error": {"message": "\"mode\" takes a string", "file": "$B", "line": 7, "column": 60, "status": 2}}
{"format": "wrenchcone-json/1", "error": {"message": "the request needs \"problem\" (a file) or \"problem_text\"", "file": "$B", "line": 8, "column": 1, "status": 2}}
{"format": "wrenchcone-json/1", "error": {"message": "a request reads no standard input: give \"problem_text\"", "file": "$B", "line": 9, "column": 32, "status": 2}}
{"format": "wrenchcone-json/1", "error": {"message": "\"wrench\" takes three numbers [FX, FY, TAU]", "file": "$B", "line": 10, "column": 66, "status": 2}}
{"format": "wrenchcone-json/1", "error": {"message": "unknown method 'fast' (direct or paper)", "file": "$B", "line": 11, "column": 76, "status": 2}}
{"format": "wrenchcone-json/1", "fixels": 2, "modes": ["la", "ls", "na", "ns", "ra", "rs", "sa", "ss"], "count": 8}
{"format": "wrenchcone-json/1", "error": {"message": "unknown keyword 'bogus'", "file": "<problem_text>", "line": 2, "column": 1, "status": 1}}
{"format": "wrenchcone-json/1", "error": {"message": "unexpected 't' after the JSON value", "file": "$B", "line": 14, "column": 53, "status": 2}}
EOF
if ! cmp -s "$tmp/want" "$tmp/got"; then
    fail "malformed lines:"
    diff "$tmp/want" "$tmp/got" | cut -c 1-300
fi

# Empty input: nothing out, status 0; blank lines only: the same.
: | "$W" batch > "$tmp/got" 2> "$tmp/err"
st=$?
[ $st -eq 0 ] && [ ! -s "$tmp/got" ] && [ ! -s "$tmp/err" ] || fail "empty input: status $st, output $(head -c 80 "$tmp/got")"
printf '\n  \n\t\n' | "$W" batch > "$tmp/got" 2> "$tmp/err"
[ $? -eq 0 ] && [ ! -s "$tmp/got" ] || fail "blank lines: not skipped"

# A batch file that cannot be opened; bad usage.
"$W" batch "$tmp/no-such.jsonl" > "$tmp/out" 2> "$tmp/err"
[ $? -eq 1 ] && [ ! -s "$tmp/out" ] || fail "missing batch file: not status 1"
grep -q "^wrenchcone: $tmp/no-such.jsonl: cannot open: " "$tmp/err" || fail "missing batch file: $(cat "$tmp/err")"
"$W" batch a b > "$tmp/out" 2> "$tmp/err"
[ $? -eq 2 ] || fail "batch with two files: not a usage error"
"$W" batch --format=json < /dev/null > "$tmp/out" 2> "$tmp/err"
[ $? -eq 2 ] || fail "batch --format: not a usage error"
for j in 0 257 x ''; do
    "$W" batch --jobs=$j < /dev/null > "$tmp/out" 2> "$tmp/err"
    st=$?
    printf "wrenchcone: --jobs takes a count from 1 to 256, not '%s'\nTry 'wrenchcone batch --help' for more information.\n" "$j" > "$tmp/want"
    [ $st -eq 2 ] && [ ! -s "$tmp/out" ] && cmp -s "$tmp/want" "$tmp/err" \
        || fail "batch --jobs=$j: status $st, $(cat "$tmp/err")"
done

[ $failures -eq 0 ] || { echo "$failures failure(s)"; exit 1; }
exit 0
