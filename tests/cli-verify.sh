#!/bin/sh
# cli-verify.sh -- `wrenchcone verify` end to end (wrenchcone(1)): certificates
# worked out by hand hold (exit 0), tampered ones do not (exit 4, the
# reason on stdout), malformed ones are bad input (exit 1, one located
# diagnostic on stderr, nothing on stdout); and every certificate that
# `wrenchcone feasible --certificate` writes for the data files holds, and
# stops holding once tampered with.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.
#
# Run by make check with WRENCHCONE and top_srcdir in the environment.
# Silent on success; prints each failing case and exits 1.
#
# The certificates in tests/certs were derived by hand for the paper's
# Figure 5 disk (com (0, 0); fixel 1 at (0, -1), normal (0, 1); fixel 2 at
# (1, 0), normal (-1, 0); both touching): J_1n = (0, 1, 0),
# J_1t = (-1, 0, -1), J_2n = (-1, 0, 0), J_2t = (0, -1, -1).
#   ss: J_1n > 0, J_2n > 0; witness (-1, 1, 0) gives 1 and 1.
#   ll: J_1n = 0, J_1t > 0, J_2n = 0, J_2t > 0; witness (0, 0, -1) gives
#       0, 1, 0, 1.
#   nn: all four rows = 0; witness 0.
#   ln: J_1n = 0, J_1t > 0, J_2n = 0, J_2t = 0 forces nu = 0, so J_1t . nu
#       > 0 fails; multipliers (-1, 1, -1, -1): -(0,1,0) + (-1,0,-1)
#       - (-1,0,0) - (0,-1,-1) = 0 with the one > multiplier positive.
# and for three fixels with rational data, a near one in the middle (com
# (1/2, 0); (1/3, 1/2) normal (1, 1/2); (3/2, -1) normal (0, 3) near;
# (-2, 5/7) normal (-4, 6)): rows J_1n (12, 6, -7), J_1t (-6, 12, 1),
# J_2n (0, 1, 1), J_3n (-28, 42, -85), J_3t (-21, -14, 50);
#   sss: witness (-1, 1, -1) gives 1 > 0, 0 >= 0, 155 > 0;
#   nan: multipliers (227/8280, 118/1035, 1, -7/552, 0) on the rows
#       J_1n, J_1t, -J_2n, J_3n, J_3t sum to 0, the > one (-J_2n) is 1.

: "${WRENCHCONE:?WRENCHCONE is not set}"
: "${top_srcdir:?top_srcdir is not set}"

certs="$top_srcdir/tests/certs"
data="$top_srcdir/data"
. "$top_srcdir/tests/clitest.sh"

# expect NAME STATUS STDOUT STDERR: the last run exited with STATUS and
# printed exactly STDOUT and STDERR (each one line, or nothing if empty).
expect() {
    if [ "$status" -ne "$2" ]; then
        fail "$1" "exit status $status, expected $2"
    fi
    for stream in out err; do
        if [ "$stream" = out ]; then want=$3; else want=$4; fi
        if [ -z "$want" ]; then
            : >"$tmp/want"
        else
            printf '%s\n' "$want" >"$tmp/want"
        fi
        if ! cmp -s "$tmp/want" "$tmp/$stream"; then
            fail "$1" "std$stream differs"
            sed 's/^/    expected: /' "$tmp/want"
            sed 's/^/    got:      /' "$tmp/$stream"
        fi
    done
}

# holds FILE MODE VERDICT: tests/certs/FILE holds for mode MODE, which it
# says is VERDICT (feasible or infeasible).
holds() {
    run /dev/null verify "$certs/$1"
    expect "$1" 0 "certificate holds: mode $2 is $3" ""
}

# tampered FILE REASON: tests/certs/FILE does not hold, for REASON.
tampered() {
    run /dev/null verify "$certs/$1"
    expect "$1" 4 "certificate does not hold: $2" ""
}

# malformed FILE LINE:COL: MESSAGE -- the diagnostic for tests/certs/FILE
malformed() {
    run /dev/null verify "$certs/$1"
    expect "$1" 1 "" "wrenchcone: $certs/$1:$2"
}

# Certificates worked out by hand.
holds figure5-ss.json ss feasible
holds figure5-ll.json ll feasible
holds figure5-nn.json nn feasible
holds figure5-ln.json ln infeasible
holds figure5-ln-pretty.json ln infeasible
holds rational-sss.json sss feasible
holds rational-nan.json nan infeasible

# The same certificates with one thing changed.
tampered tampered-multiplier.json \
    "the multipliers combine the rows to (-2, 0, 0), not to zero"
tampered tampered-multiplier-sign.json \
    "multiplier 3 is -1, negative on a '>' constraint"
tampered tampered-multiplier-count.json \
    "there are 3 multipliers for 4 constraints"
tampered tampered-no-strict.json \
    "no '>' constraint has a positive multiplier"
tampered tampered-witness.json \
    "the witness (0, 1, 0) violates constraint 2: (-1, 0, 0) . nu = 0, not > 0"
tampered tampered-claim.json \
    "the witness (0, 0, -1) violates constraint 4: (0, -1, -1) . nu = 1, not = 0"
tampered tampered-relation.json \
    "constraint 2 is not the one mode ll implies for fixel 1: expected (-1, 0, -1) . nu > 0, found (-1, 0, -1) . nu >= 0"
tampered tampered-row.json \
    "constraint 3 is not the one mode ln implies for fixel 2: expected (-1, 0, 0) . nu = 0, found (-1, 0, 1) . nu = 0"
tampered tampered-constraint-dropped.json \
    "the certificate lists 3 constraints; mode ln implies 4"
tampered tampered-problem.json \
    "constraint 2 is not the one mode ss implies for fixel 2: expected (-2, 0, -1) . nu > 0, found (-1, 0, 0) . nu > 0"
tampered tampered-mode.json \
    "constraint 2 is not the one mode sl implies for fixel 2: expected (-1, 0, 0) . nu = 0, found (-1, 0, 0) . nu > 0"

# Malformed certificates: exit status 1, located at the offending value.
malformed bad-empty.json "1:1: unexpected end of input"
malformed bad-truncated.json "1:193: unterminated string"
malformed bad-kind.json "1:10: unknown certificate kind 'stability'"
malformed bad-decimal.json "1:80: bad rational '0.5'"
malformed bad-division.json "1:339: division by zero in '1/0'"
malformed bad-letter.json \
    "1:38: letter 'a' not allowed on fixel 1, which is touching"
malformed bad-length.json "1:38: mode has 1 letter; the problem has 2 fixels"
malformed bad-zero-normal.json "1:336: zero normal"
malformed bad-missing-mode.json "1:1: missing key 'mode'"
malformed bad-duplicate-key.json "1:62: duplicate key 'mode'"
malformed bad-state.json "1:358: unknown fixel state 'sliding'"
malformed bad-row-length.json "1:158: 'row' must have 3 entries, not 2"
malformed bad-feasible.json "1:56: 'feasible' must be true or false"
malformed bad-relation.json "1:188: unknown relation '<'"
malformed bad-pretty.json "20:11: mode has 1 letter; the problem has 2 fixels"

# Strong-stability certificates (classify --certificate).
summary() { run /dev/null verify "$certs/$1"; expect "$1" 0 "certificate holds: $2" ""; }
summary figure5-strongly-stable.json "wrench (0, -1, 0) is strongly stable: 9 moving faces excluded"
summary figure5-near-strongly-stable.json "wrench (0, -1, 0) is strongly stable: 5 moving faces excluded"
summary figure5-near-not-weakly-stable.json "wrench (0, 1, 0) is not weakly stable"
summary figure5-kinetic-moves.json "wrench (-1, -1, -1) is weakly stable but moves in mode ls"
tampered tampered-face-missing.json "the faces omit the moving face rr"
tampered tampered-face-repeated.json "face 7 (ss) repeats face 1"
tampered tampered-face-sign.json "face 2 (ln) is not a moving face of the problem"
tampered tampered-face-multiplier.json "face 1 (ss): the multipliers combine the rows to (0, 0, 0, 1), not to zero"
tampered tampered-face-multiplier-count.json "face 4 (sn): there are 8 multipliers for 9 rows"
tampered tampered-rotation-missing.json "the faces omit the moving face nu, rotation -1"
tampered tampered-kinetic-friction.json "the motion's letter l at fixel 1 needs c_1t = -mu_k c_1n = -1, but c_1t = -1/2"
tampered tampered-separator.json "the separator y = (0, 1, 2) has y . (J_1n + mu_s J_1t) = -1, not >= 0"
tampered tampered-static-forces.json "the static force at fixel 1 leaves its friction cone: |c_1t| = 2 > mu_s c_1n = 1"
malformed bad-sign-letter.json "12:13: letter 'u' not allowed on fixel 2, which is touching"
malformed bad-rotation.json "1:435: a rotation face has the sign n..n"
malformed bad-mass.json "1:50: 'mass' must be positive"
malformed bad-missing-faces.json "1:1: missing key 'faces'"

# Inputs no certificate writer makes: a NUL byte, deep nesting, 10 MB of
# repeated garbage, 4 MB of a valid JSON array.
printf '{"mode": "ss"\000}' >"$tmp/nul.json"
run /dev/null verify "$tmp/nul.json"
expect nul-byte 1 "" \
    "wrenchcone: $tmp/nul.json:1:14: expected ',' or '}', found '\\x00'"
awk 'BEGIN { for (i = 0; i < 100000; i++) printf "{\"a\": [" }' \
    >"$tmp/deep.json"
run /dev/null verify "$tmp/deep.json"
expect deep-nesting 1 "" \
    "wrenchcone: $tmp/deep.json:1:225: nesting deeper than 64 levels"
yes '{"kind": [1, 2' | head -c 10485760 >"$tmp/garbage.json"
run /dev/null verify "$tmp/garbage.json"
expect garbage 1 "" \
    "wrenchcone: $tmp/garbage.json:2:1: expected ',' or ']', found '{'"
{ printf '['; yes '0,' | head -n 2000000 | tr -d '\n'; printf '0]'; } \
    >"$tmp/array.json"
run /dev/null verify "$tmp/array.json"
expect big-array 1 "" \
    "wrenchcone: $tmp/array.json:1:1: expected a certificate object, found an array"

# Standard input, JSON output, a missing file, bad usage.
run "$certs/figure5-ln.json" verify -
expect stdin 0 "certificate holds: mode ln is infeasible" ""
run "$certs/bad-letter.json" verify -
expect stdin-malformed 1 "" \
    "wrenchcone: <stdin>:1:38: letter 'a' not allowed on fixel 1, which is touching"
run /dev/null verify --format=json "$certs/figure5-ln.json"
expect json-holds 0 '{"format": "wrenchcone-json/1", "holds": true, "mode": "ln", "feasible": false}' ""
run /dev/null verify --format=json "$certs/tampered-witness.json"
expect json-does-not-hold 4 '{"format": "wrenchcone-json/1", "holds": false, "mode": "ss", "feasible": true, "reason": "the witness (0, 1, 0) violates constraint 2: (-1, 0, 0) . nu = 0, not > 0"}' ""
run /dev/null verify --format=json "$certs/bad-kind.json"
expect json-malformed 1 "" \
    "wrenchcone: $certs/bad-kind.json:1:10: unknown certificate kind 'stability'"
missing="$tmp/no-such-file.json"
run /dev/null verify "$missing"
if [ "$status" -ne 1 ] || [ -s "$tmp/out" ] ||
    [ "$(wc -l <"$tmp/err")" -ne 1 ]; then
    fail missing-file "exit status $status, expected 1 and one line on stderr"
fi
case $(cat "$tmp/err") in
    "wrenchcone: $missing: "?*) ;;
    *) fail missing-file "stderr does not name the file:"
       sed 's/^/    /' "$tmp/err" ;;
esac
# usage NAME ARGS...: verify ARGS is bad usage: exit status 2, a message
# on stderr, nothing on stdout
usage() {
    usage_name=$1
    shift
    run /dev/null verify "$@"
    if [ "$status" -ne 2 ] || [ -s "$tmp/out" ] || [ ! -s "$tmp/err" ]; then
        fail "$usage_name" "exit status $status, expected 2 with a message"
    fi
}
usage usage-no-argument
usage usage-bogus-option --bogus "$certs/figure5-ln.json"
usage usage-two-files "$certs/figure5-ln.json" "$certs/figure5-ln.json"
usage usage-format-cdd --format=cdd "$certs/figure5-ln.json"

# Round trip: `feasible --certificate` for every Table 1 mode of every
# data file, then verify; each certificate tampered with in three ways no
# longer holds.
if ! "$WRENCHCONE" feasible --help >/dev/null 2>&1; then
    printf '%s: SKIP round trip: no feasible command in this build\n' "$0"
else
    # modes STATES: every Table 1 mode for fixels in STATES (t touching,
    # n near; e.g. ttn), one a line
    modes() {
        printf '\n' >"$tmp/modes"
        states=$1
        while [ -n "$states" ]; do
            case $states in
            t*) letters="s l r n" ;;
            *)  letters="s a" ;;
            esac
            states=${states#?}
            while read -r p; do
                for l in $letters; do printf '%s%s\n' "$p" "$l"; done
            done <"$tmp/modes" >"$tmp/modes.next"
            mv "$tmp/modes.next" "$tmp/modes"
        done
        cat "$tmp/modes"
    }
    # tamper HOW IN OUT: a copy of certificate IN changed one way, so that
    # it cannot hold (the writer puts the witness before the rows)
    tamper() {
        case $1 in
        row)        # the first row's first entry p becomes 10p +- 1
            sed 's/"row": \["\([-0-9]*\)"/"row": ["\11"/' "$2" ;;
        relation)   # the first relation changes: >= to >, others to >=
            sed -e 's/"relation": "\([^"]*\)"/"relation": "#\1"/' \
                -e 's/"#>="/">"/; s/"#>"/">="/; s/"#="/">="/' "$2" ;;
        answer)     # the witness becomes minus the first row r, which has
                    # r . nu < 0; the first multiplier p becomes 10p +- 1
            sed -e 's/"witness": \[[^]]*\]\(.*\)"row": \["\([^"]*\)", "\([^"]*\)", "\([^"]*\)"\]/"witness": ["-\2", "-\3", "-\4"]\1"row": ["\2", "\3", "\4"]/' \
                -e 's/"--/"/g' \
                -e 's/"multipliers": \["\([-0-9]*\)"/"multipliers": ["\11"/' \
                "$2" ;;
        esac >"$3"
    }
    # The 32 modes of peg-in-hole: every fourth by default, all when
    # WC_TEST_MULTIPLIER widens the run.
    stride=4
    [ "${WC_TEST_MULTIPLIER:-1}" -gt 1 ] 2>/dev/null && stride=1
    mkdir "$tmp/rt" || exit 99
    : >"$tmp/rt/holds.req"
    : >"$tmp/rt/holds.list"
    : >"$tmp/rt/tampered.req"
    : >"$tmp/rt/tampered.list"
    feasible_modes=
    n=0
    for spec in disk-two-fixels:tt section4:tn peg-in-hole:ttn three-fixels:nnn; do
        problem="$data/${spec%:*}.wc"
        every=1
        [ "${spec%:*}" = peg-in-hole ] && every=$stride
        k=0
        for mode in $(modes "${spec#*:}"); do
            k=$((k + 1))
            [ $((k % every)) -eq 0 ] || continue
            n=$((n + 1))
            cert="$tmp/rt/$n.json"
            "$WRENCHCONE" feasible --certificate="$cert" "$problem" "$mode" \
                >/dev/null 2>"$tmp/err"
            fstatus=$?
            name="round trip ${spec%:*} $mode"
            if [ "$fstatus" -ne 0 ] || [ ! -s "$cert" ]; then
                fail "$name" "feasible: exit status $fstatus"
                sed 's/^/    /' "$tmp/err"
                continue
            fi
            printf '{"command": "verify", "certfile": "%s"}\n' "$cert" >>"$tmp/rt/holds.req"
            printf '%s %s %s\n' "${spec%:*}" "$mode" "$name" >>"$tmp/rt/holds.list"
            for how in row relation answer; do
                tamper "$how" "$cert" "$tmp/rt/$n-$how.json"
                if cmp -s "$cert" "$tmp/rt/$n-$how.json"; then
                    fail "$name" "tampering ($how) changed nothing"
                    continue
                fi
                printf '{"command": "verify", "certfile": "%s"}\n' "$tmp/rt/$n-$how.json" >>"$tmp/rt/tampered.req"
                printf '%s %s (tampered, %s)\n' "$mode" "$name" "$how" >>"$tmp/rt/tampered.list"
            done
        done
    done
    # Each certificate holds, and each tampered one does not: the
    # answers of one `wrenchcone batch` process, each exactly what
    # `verify --format=json` prints for its file.
    "$WRENCHCONE" batch <"$tmp/rt/holds.req" >"$tmp/rt/holds.out" 2>"$tmp/err"
    status=$?
    if [ "$status" -ne 0 ] || [ -s "$tmp/err" ]; then
        fail "round trip" "batch verify: exit status $status, expected 0"
        sed 's/^/    /' "$tmp/err"
    fi
    [ "$(wc -l <"$tmp/rt/holds.out")" -eq "$(wc -l <"$tmp/rt/holds.list")" ] ||
        fail "round trip" "$(wc -l <"$tmp/rt/holds.out") answers to $(wc -l <"$tmp/rt/holds.list") certificates"
    while read -r problem mode name; do
        IFS= read -r answer <&3
        prefix='{"format": "wrenchcone-json/1", "holds": true, "mode": "'$mode'", "feasible": '
        case $answer in
        "${prefix}true}")
            [ "$problem" = disk-two-fixels ] &&
                feasible_modes="$feasible_modes $mode" ;;
        "${prefix}false}") ;;
        *)  fail "$name" "does not hold:"
            printf '    %s\n' "$answer" ;;
        esac
    done <"$tmp/rt/holds.list" 3<"$tmp/rt/holds.out"
    # the paper's reference results: Figure 5's feasible modes
    if [ "$feasible_modes" != " ss sl sr sn ls ll rs rr ns nn" ]; then
        fail "figure 5 modes" "feasible:$feasible_modes"
    fi
    "$WRENCHCONE" batch <"$tmp/rt/tampered.req" >"$tmp/rt/tampered.out" 2>"$tmp/err"
    status=$?
    if [ "$status" -ne 4 ] || [ -s "$tmp/err" ]; then
        fail "round trip" "batch verify of the tampered: exit status $status, expected 4"
        sed 's/^/    /' "$tmp/err"
    fi
    [ "$(wc -l <"$tmp/rt/tampered.out")" -eq "$(wc -l <"$tmp/rt/tampered.list")" ] ||
        fail "round trip" "$(wc -l <"$tmp/rt/tampered.out") answers to $(wc -l <"$tmp/rt/tampered.list") tampered certificates"
    while read -r mode name; do
        IFS= read -r answer <&3
        case $answer in
        '{"format": "wrenchcone-json/1", "holds": false, "mode": "'"$mode"'", "feasible": '*', "reason": "'?*'"}') ;;
        *)  fail "$name" "unexpected answer:"
            printf '    %s\n' "$answer" ;;
        esac
    done <"$tmp/rt/tampered.list" 3<"$tmp/rt/tampered.out"

    # What feasible prints with --format=json is a certificate too.
    run /dev/null feasible --format=json "$data/disk-two-fixels.wc" ln
    cp "$tmp/out" "$tmp/printed.json"
    run /dev/null verify "$tmp/printed.json"
    expect printed-json 0 "certificate holds: mode ln is infeasible" ""
fi

# A certificate that cannot be written is an I/O failure (exit 3), and a
# file that was there before -- here a device -- is never removed.
if [ -c /dev/full ] && [ -w /dev/full ]; then
    "$WRENCHCONE" feasible --certificate=/dev/full \
        "$top_srcdir/data/disk-two-fixels.wc" ln > /dev/null 2>&1
    st=$?
    [ "$st" -eq 3 ] || fail "certificate to /dev/full: exit $st, want 3"
    [ -c /dev/full ] || fail "certificate to /dev/full removed the device"
fi
"$WRENCHCONE" feasible --certificate=/nonexistent-dir/c.json \
    "$top_srcdir/data/disk-two-fixels.wc" ln > /dev/null 2>&1
st=$?
[ "$st" -eq 3 ] || fail "certificate into a missing directory: exit $st, want 3"

if [ "$failures" -ne 0 ]; then
    printf '%s: %d failure(s)\n' "$0" "$failures"
    exit 1
fi
exit 0
