#!/bin/sh
# cli-errors.sh -- bad input gives exit status 1, nothing on stdout and one
# exact diagnostic on stderr; bad usage gives exit status 2 (wrenchcone(1), wrenchcone(5)).
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.
#
# Run by make check with WRENCHCONE and top_srcdir in the environment.
# Silent on success; prints each failing case and exits 1.

: "${WRENCHCONE:?WRENCHCONE is not set}"
: "${top_srcdir:?top_srcdir is not set}"

bad="$top_srcdir/tests/bad"
. "$top_srcdir/tests/clitest.sh"

# expect_status NAME WANT: the last run's status is WANT and its stdout
# is empty.
expect_status() {
    if [ "$status" -ne "$2" ]; then
        fail "$1" "exit status $status, expected $2"
    fi
    if [ -s "$tmp/out" ]; then
        fail "$1" "stdout is not empty:"
        sed 's/^/    /' "$tmp/out"
    fi
}

# expect_stderr NAME LINE: stderr is exactly LINE and a newline.
expect_stderr() {
    printf '%s\n' "$2" >"$tmp/want"
    if ! cmp -s "$tmp/want" "$tmp/err"; then
        fail "$1" "stderr differs"
        printf '    expected: %s\n' "$2"
        sed 's/^/    got:      /' "$tmp/err"
    fi
}

# bad_file NAME MODE LINE:COL: MESSAGE -- the diagnostic for tests/bad/NAME.wc
bad_file() {
    file="$bad/$1.wc"
    run /dev/null cone "$file" "$2"
    expect_status "$1" 1
    expect_stderr "$1" "wrenchcone: $file:$3"
}

# bad_mode NAME MODE COL: MESSAGE -- a mode rejected for tests/bad/modes.wc
bad_mode() {
    run /dev/null cone "$bad/modes.wc" "$2"
    expect_status "$1" 1
    expect_stderr "$1" "wrenchcone: <mode>:1:$3"
}

# usage_error NAME ARGS...: exit status 2, a message, nothing on stdout
usage_error() {
    usage_name=$1
    shift
    run /dev/null "$@"
    expect_status "$usage_name" 2
    if [ ! -s "$tmp/err" ]; then
        fail "$usage_name" "no message on stderr"
    fi
}

# Every error class of wrenchcone(5).
bad_file unknown-keyword n "3:1: unknown keyword 'mas'"
bad_file bad-number nn "4:7: bad number 'x1'"
bad_file division-by-zero n "2:10: division by zero in '1/0'"
bad_file zero-normal nn "3:18: zero normal"
bad_file mass-nonpositive n "2:6: mass must be positive"
bad_file inertia-nonpositive n "3:9: inertia must be positive"
bad_file friction-negative n "3:32: friction must be non-negative"
bad_file polygon-degenerate n \
    "2:3: degenerate polygon: vertices 0, 1 and 2 are collinear"
bad_file polygon-self-intersecting n \
    "3:1: self-intersecting polygon: edges 0 and 2 cross"
bad_file point-off-boundary ns \
    "4:8: point (2, 0) is not on the shape's boundary; give its normal"
bad_file point-at-vertex nn \
    "4:7: point (2, 2) is a polygon vertex; give its normal"
bad_file duplicate-fixel nns \
    "4:7: fixel 3 has the same point and normal as fixel 1"
bad_file duplicate-keyword n "4:1: duplicate 'mass'"
bad_file missing-argument n "2:8: 'com' needs 2 numbers"
bad_file trailing-token n "3:18: unexpected token '1'"
bad_file no-fixel n "3:17: no fixel in the problem"
bad_file unterminated-name n "2:6: unterminated string"

# The file is read before the mode: a bad file and a bad mode report the
# file.
bad_file unknown-keyword xyz "3:1: unknown keyword 'mas'"

# Bad modes (fixel 1 touching, fixel 2 near; Table 2).
bad_mode mode-too-long nas "3: mode has 3 letters; the problem has 2 fixels"
bad_mode mode-too-short n "2: mode has 1 letter; the problem has 2 fixels"
bad_mode mode-empty "" "1: mode has 0 letters; the problem has 2 fixels"
bad_mode mode-unknown-letter nx "2: unknown mode letter 'x'"
bad_mode mode-uppercase Na "1: unknown mode letter 'N'"
bad_mode mode-a-on-touching aa \
    "1: letter 'a' not allowed on fixel 1, which is touching"
bad_mode mode-u-on-touching us \
    "1: letter 'u' not allowed on fixel 1, which is touching"
bad_mode mode-n-on-near nn "2: letter 'n' not allowed on fixel 2, which is near"
bad_mode mode-m-on-near mm "2: letter 'm' not allowed on fixel 2, which is near"

# The good modes of the same problem are answers, not errors.
for mode in na nu ns mu la ra su; do
    run /dev/null cone "$bad/modes.wc" "$mode"
    if [ "$status" -ne 0 ]; then
        fail "good-mode-$mode" "exit status $status, expected 0"
        sed 's/^/    /' "$tmp/err"
    fi
done

# Standard input is named <stdin>.
run "$bad/unknown-keyword.wc" cone - n
expect_status stdin 1
expect_stderr stdin "wrenchcone: <stdin>:3:1: unknown keyword 'mas'"
run "$bad/modes.wc" cone - n
expect_status stdin-mode 1
expect_stderr stdin-mode \
    "wrenchcone: <mode>:1:2: mode has 1 letter; the problem has 2 fixels"

# A file that cannot be read is bad input, reported with its name.
missing="$tmp/no-such-file.wc"
run /dev/null cone "$missing" n
expect_status missing-file 1
case $(cat "$tmp/err") in
    "wrenchcone: $missing: "?*) ;;
    *) fail missing-file "stderr does not name the file:"
       sed 's/^/    /' "$tmp/err" ;;
esac
if [ "$(wc -l <"$tmp/err")" -ne 1 ]; then
    fail missing-file "stderr is not one line"
fi

# Bad usage.
usage_error no-arguments
usage_error random-fixels-zero random --fixels=0
usage_error random-fixels-big random --fixels=1001
usage_error random-seed-overflow random --seed=18446744073709551616
usage_error random-shape random --shape=square
usage_error random-friction random --friction=1/5,-1
usage_error random-format random --format=cdd
usage_error random-operand random extra
usage_error bogus-option --bogus
usage_error cone-bogus-option cone --bogus "$bad/modes.wc" na
usage_error cone-no-arguments cone
usage_error cone-missing-mode cone "$bad/modes.wc"
usage_error cone-extra-argument cone "$bad/modes.wc" na na

# The reader's limits (wrenchcone(5)): numbers of at most 1024 bits and
# polygons of at most 1000 vertices, refused at the offending token; a
# long number quoted in a message is cut.
bad_file number-too-big nn \
    "3:7: number too big in '1e100000' (numerator or denominator over 1024 bits)"
bad_file polygon-too-many-vertices n \
    "2:10442: polygon has more than 1000 vertices"
bad_file point-long ns \
    "4:7: point (1000000000000000000000000000000000000000000000000000000000000000..., 0) is not on the shape's boundary; give its normal"

# Every command's size limit (wrenchcone(1), LIMITS): a located error at
# the first fixel beyond it, exit 1, nothing on stdout.
# floor N STATE: N fixels on a line, each on its own line 4 + i.
floor() {
    printf 'mass 1\ninertia 1\ncom 0 1\nfriction 1/2\n'
    awk -v n="$1" -v s="$2" 'BEGIN { for (i = 1; i <= n; i++) print "fixel " i " 0 normal 0 1 " s }'
}
floor 101 touching >"$tmp/t101.wc"
floor 151 near >"$tmp/n151.wc"
floor 1001 touching >"$tmp/t1001.wc"
floor 2001 near >"$tmp/n2001.wc"
floor 10001 near >"$tmp/n10001.wc"
limit() { # limit NAME LINE:COL: MESSAGE -- ARGS...
    name=$1 want=$2
    shift 2
    run /dev/null "$@"
    expect_status "limit-$name" 1
    expect_stderr "limit-$name" "wrenchcone: $want"
}
limit classify "$tmp/t101.wc:105:1: classify handles at most 100 touching fixels (this is touching fixel 101)" \
    classify "$tmp/t101.wc" 0 -1 0
limit stability "$tmp/t101.wc:105:1: stability handles at most 100 touching fixels (this is touching fixel 101)" \
    stability "$tmp/t101.wc"
limit modes "$tmp/t1001.wc:1005:1: mode enumeration handles at most 1000 fixels (this is fixel 1001)" \
    modes "$tmp/t1001.wc"
limit modes-near "$tmp/n151.wc:155:1: mode enumeration handles at most 150 near fixels (this is near fixel 151)" \
    modes "$tmp/n151.wc"
limit cone "$tmp/n2001.wc:2005:1: a wrench cone handles at most 2000 fixels (this is fixel 2001)" \
    cone "$tmp/n2001.wc" u
limit compare "$tmp/n2001.wc:2005:1: a wrench cone handles at most 2000 fixels (this is fixel 2001)" \
    compare "$tmp/n2001.wc" u "$tmp/n2001.wc"
limit file "$tmp/n10001.wc:10005:1: a problem holds at most 10000 fixels" \
    feasible "$tmp/n10001.wc" s
floor 11 near >"$tmp/n11.wc"
limit plan "$tmp/n11.wc:15:1: an insertion plan handles at most 10 fixels (this is fixel 11)" \
    plan "$tmp/n11.wc"
limit sweep "$tmp/n11.wc:15:1: an insertion plan handles at most 10 fixels (this is fixel 11)" \
    sweep --critical "$tmp/n11.wc"
floor 7 near >"$tmp/n7.wc"
limit complete "$tmp/n7.wc:11:1: the complete plan handles at most 6 fixels (this is fixel 7)" \
    plan --complete "$tmp/n7.wc"
floor 8 near >"$tmp/n8.wc"
limit plancert "$tmp/n8.wc:12:1: a plan certificate handles at most 7 fixels (this is fixel 8)" \
    plan --certificate="$tmp/never.json" "$tmp/n8.wc"
limit sweepcert "$tmp/n8.wc:12:1: a plan certificate handles at most 7 fixels (this is fixel 8)" \
    sweep --critical --certificate="$tmp/never.json" "$tmp/n8.wc"
[ ! -e "$tmp/never.json" ] || fail "a refused certificate left a file"
# A read that fails (EIO; reading /proc/self/mem from offset 0 gives it
# on Linux) is an I/O failure, exit 3; a directory is a wrong argument.
if [ -r /proc/self/mem ]; then
    run /dev/null cone /proc/self/mem u
    expect_status read-eio 3
    expect_stderr read-eio "wrenchcone: /proc/self/mem: read error: Input/output error"
fi
# An input over the size limit, named <stdin> when it is standard input.
head -c 67108865 /dev/zero >"$tmp/huge"
run "$tmp/huge" verify -
expect_status too-large-stdin 1
expect_stderr too-large-stdin "wrenchcone: <stdin>: file too large (over 67108864 bytes)"
run /dev/null verify "$tmp/huge"
expect_status too-large-file 1
expect_stderr too-large-file "wrenchcone: $tmp/huge: file too large (over 67108864 bytes)"
rm -f "$tmp/huge"
run /dev/null cone "$tmp" u
expect_status read-directory 1
expect_stderr read-directory "wrenchcone: $tmp: read error: Is a directory"

# Out of memory: one line on stderr, exit 3, nothing on stdout -- never
# FLINT's abort with its message on stdout.  Every limit keeps a command's
# memory in the megabytes, except the list of modes that classify gives
# on request: with --max-modes=0, a wrench that 40 fixels on a floor
# hold is held by exponentially many strings, far more than 50 MB.
# (Sanitizers reserve terabytes of address space: no ulimit -v there.)
if [ -z "${WC_SAN:-}" ]; then
    floor 40 touching >"$tmp/t40.wc"
    status=$( (ulimit -v 50000 && "$WRENCHCONE" classify --max-modes=0 "$tmp/t40.wc" 0 -1 -10 >"$tmp/out" 2>"$tmp/err"); echo $?)
    expect_status out-of-memory 3
    expect_stderr out-of-memory "wrenchcone: out of memory"
fi

# At the limits themselves the same layouts run: 150 near fixels, 1000
# fixels, 100 touching fixels.
floor 150 near >"$tmp/n150.wc"
run /dev/null modes "$tmp/n150.wc"
[ "$status" -eq 0 ] && [ -s "$tmp/out" ] || fail limit-modes-near "exit status $status at 150 near fixels"
floor 1000 touching >"$tmp/t1000.wc"
run /dev/null modes "$tmp/t1000.wc"
[ "$status" -eq 0 ] && [ -s "$tmp/out" ] || fail limit-modes-1000 "exit status $status at 1000 fixels"
floor 100 touching >"$tmp/t100.wc"
run /dev/null classify "$tmp/t100.wc" 0 -1 -10
[ "$status" -eq 0 ] && [ -s "$tmp/out" ] || fail limit-classify-100 "exit status $status at 100 touching fixels"

if [ "$failures" -ne 0 ]; then
    printf '%s: %d failure(s)\n' "$0" "$failures"
    exit 1
fi
exit 0
