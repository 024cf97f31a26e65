# clitest.sh -- sourced by the command-line tests (cli-*.sh), after they
# check WRENCHCONE and top_srcdir: a temporary directory $tmp, removed on
# exit; fail NAME WHY (or fail WHAT), counted in $failures; need TOOL...;
# run INPUT ARGS...; refused STATUS MESSAGE ARGS....
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

tmp=$(mktemp -d "${TMPDIR:-/tmp}/$(basename "$0" .sh).XXXXXX") || exit 99
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM
failures=0

fail() {
    if [ $# -ge 2 ]; then
        printf 'FAIL: %s: %s\n' "$1" "$2"
    else
        printf 'FAIL: %s\n' "$1"
    fi
    failures=$((failures + 1))
}

# need TOOL...: SKIP (exit 77) unless every TOOL is on the PATH.
need() {
    for need_tool in "$@"; do
        command -v "$need_tool" >/dev/null 2>&1 \
            || { echo "SKIP: no $need_tool" >&2; exit 77; }
    done
}

# run INPUT ARGS...: run the program on ARGS with INPUT as stdin; sets
# $status and leaves stdout and stderr in $tmp/out and $tmp/err.
run() {
    run_input=$1
    shift
    "$WRENCHCONE" "$@" <"$run_input" >"$tmp/out" 2>"$tmp/err"
    status=$?
}

# refused STATUS MESSAGE ARGS...: the program on ARGS exits STATUS, with
# MESSAGE in what it writes on stderr and nothing on stdout.
refused() {
    refused_status=$1 refused_message=$2
    shift 2
    run /dev/null "$@"
    [ "$status" -eq "$refused_status" ] \
        || fail "$*" "exit $status, not $refused_status"
    [ -s "$tmp/out" ] && fail "$*" "wrote on stdout"
    grep -qF -- "$refused_message" "$tmp/err" \
        || fail "$*" "message '$(cat "$tmp/err")'"
}
