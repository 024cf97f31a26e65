#!/bin/sh
# cli-double.sh -- wrenchcone cone --method=paper --arith=double: usage
# errors (exit 2, exact stderr), and the float output of the Section 4
# example in every format (keys, flags and headers; the digits are
# checked by tests/t-double.c, to 1e-12).
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.
#
# Run by make check with WRENCHCONE and top_srcdir in the environment.
# Silent on success; prints each failing case and exits 1.

: "${WRENCHCONE:?WRENCHCONE is not set}"
: "${top_srcdir:?top_srcdir is not set}"

s4="$top_srcdir/data/section4.wc"
. "$top_srcdir/tests/clitest.sh"

# usage NAME FIRST-LINE ARGS...: exit 2, nothing on stdout, and stderr the
# given line then the usual hint.
usage() {
    name=$1
    line=$2
    shift 2
    run /dev/null "$@"
    printf '%s\n%s\n' "$line" \
        "Try 'wrenchcone cone --help' for more information." >"$tmp/want"
    [ "$status" -eq 2 ] || fail "$name" "exit status $status, expected 2"
    [ -s "$tmp/out" ] && fail "$name" "stdout is not empty"
    cmp -s "$tmp/want" "$tmp/err" || {
        fail "$name" "stderr differs:"
        sed 's/^/    /' "$tmp/err"
    }
}

# has NAME TEXT: stdout of the last run contains the line TEXT.
has() {
    grep -qxF -- "$2" "$tmp/out" || {
        fail "$1" "no line '$2' in:"
        sed 's/^/    /' "$tmp/out"
    }
}

# contains NAME TEXT: stdout of the last run contains TEXT.
contains() {
    grep -qF -- "$2" "$tmp/out" || {
        fail "$1" "no '$2' in:"
        sed 's/^/    /' "$tmp/out"
    }
}

usage direct "wrenchcone: --arith=double needs --method=paper" \
    cone --arith=double "$s4" na
usage direct2 "wrenchcone: --arith=double needs --method=paper" \
    cone --arith=double --method=direct "$s4" na
usage trace "wrenchcone: --arith=double does not take --trace" \
    cone --method=paper --arith=double --trace "$s4" na
usage unknown "wrenchcone: unknown arithmetic 'float' (exact or double)" \
    cone --method=paper --arith=float "$s4" na
run /dev/null modes --arith=double "$s4"
[ "$status" -eq 2 ] || fail modes "exit status $status, expected 2"

# --arith=exact is the exact route, byte for byte.
run /dev/null cone --method=paper "$s4" na
mv "$tmp/out" "$tmp/exact"
run /dev/null cone --method=paper --arith=exact "$s4" na
cmp -s "$tmp/exact" "$tmp/out" || fail exact "--arith=exact changed the output"

run /dev/null cone --method=paper --arith=double "$s4" na
[ "$status" -eq 0 ] && [ ! -s "$tmp/err" ] || fail text "status $status"
has text "W(na): wrench cone of mode na"
contains text "floating point, not exact"
has text "  dimension 3, lineality 0, not closed (1 of 3 facets strict)"
[ "$(grep -c 'strict (excluded)$' "$tmp/out")" -eq 1 ] \
    || fail text "not exactly one strict facet"
[ "$(grep -c '  excluded$' "$tmp/out")" -eq 2 ] \
    || fail text "not exactly two excluded rays"

run /dev/null cone --method=paper --arith=double --format=json "$s4" na
[ "$status" -eq 0 ] || fail json "status $status"
contains json '{"format": "wrenchcone-json/1", "mode": "na", "cone": {"empty": false, "arith": "double", "eps": '
contains json '"dim": 3, "lineality_dim": 0, "closed": false, "inequalities": [['
contains json '"strict": [true, false, false], "equalities": [], "rays": [['
contains json '"strict_rays": [true, true, false], "lines": []}}'
[ "$(wc -l <"$tmp/out")" -eq 1 ] || fail json "not one line"

run /dev/null cone --method=paper --arith=double --format=cdd "$s4" na
[ "$status" -eq 0 ] || fail cdd "status $status"
has cdd "* wrenchcone: W(na), the wrench cone of mode na"
has cdd "*   strict facet, H row 1"
has cdd " 3 4 real"
has cdd " 4 4 real"
has cdd " 1 0 0 0"
[ "$(grep -c '^[HV]-representation$' "$tmp/out")" -eq 2 ] \
    || fail cdd "not both representations"

run /dev/null cone --method=paper --arith=double --format=ine "$s4" na
[ "$(grep -c '^V-representation$' "$tmp/out")" -eq 0 ] || fail ine "has a V part"
run /dev/null cone --method=paper --arith=double --format=ext "$s4" na
[ "$(grep -c '^H-representation$' "$tmp/out")" -eq 0 ] || fail ext "has an H part"

# An empty cone and an all-free mode.
printf 'fixel 0 0 normal 0 1 near\nfixel 0 1 normal 0 -1 near\n' >"$tmp/p.wc"
run /dev/null cone --method=paper --arith=double --format=json "$tmp/p.wc" uu
contains free '"dim": 3, "lineality_dim": 3, "closed": true, "inequalities": [], "strict": []'
printf 'fixel 0 0 normal 0 1 near\nfixel 0 2 normal 0 -1 near\n' >"$tmp/q.wc"
run /dev/null cone --method=paper --format=json "$tmp/q.wc" aa
grep -qF '{"empty": true}' "$tmp/out" || fail empty "the exact cone of aa is not empty"
run /dev/null cone --method=paper --arith=double --format=json "$tmp/q.wc" aa
has empty '{"format": "wrenchcone-json/1", "mode": "aa", "cone": {"empty": true, "arith": "double", "eps": 1.0000000000000001e-09}}'

# Bad input is exit 1 with the exact route's diagnostic.
run /dev/null cone --method=paper --arith=double "$s4" nx
[ "$status" -eq 1 ] || fail badmode "exit status $status, expected 1"
grep -qxF "wrenchcone: <mode>:1:2: unknown mode letter 'x'" "$tmp/err" \
    || fail badmode "stderr: $(cat "$tmp/err")"

# Data beyond double range: located at the number farthest from 1.
printf 'mass 1\ninertia 1\ncom 0 0\nfriction 1/2\nfixel 1 0 normal 1 1 touching\nfixel 1e308 1e308 normal 1 1e300 touching\n' >"$tmp/big.wc"
run /dev/null cone --method=paper --arith=double "$tmp/big.wc" ss
[ "$status" -eq 1 ] && [ ! -s "$tmp/out" ] || fail overflow "exit status $status, expected 1 and no output"
grep -qxF "wrenchcone: $tmp/big.wc:6:1: numbers this far from 1 overflow double precision in the paper's system (--arith=double); the exact route has no such limit" "$tmp/err" \
    || fail overflow "stderr: $(cat "$tmp/err")"

[ "$failures" -eq 0 ] || exit 1
exit 0
