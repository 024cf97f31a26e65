# clitest.sh -- sourced by the command-line tests (cli-*.sh), after they
# check WRENCHCONE and top_srcdir: a temporary directory $tmp, removed on
# exit; fail NAME WHY, counted in $failures; run INPUT ARGS....
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

tmp=$(mktemp -d "${TMPDIR:-/tmp}/$(basename "$0" .sh).XXXXXX") || exit 99
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM
failures=0

fail() {
    printf 'FAIL: %s: %s\n' "$1" "$2"
    failures=$((failures + 1))
}

# run INPUT ARGS...: run the program on ARGS with INPUT as stdin; sets
# $status and leaves stdout and stderr in $tmp/out and $tmp/err.
run() {
    run_input=$1
    shift
    "$WRENCHCONE" "$@" <"$run_input" >"$tmp/out" 2>"$tmp/err"
    status=$?
}
