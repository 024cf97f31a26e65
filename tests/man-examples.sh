#!/bin/sh
# man-examples.sh -- run the examples of the manual pages.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.
#
# The convention, stated again at the top of man/wrenchcone.1: in the
# EXAMPLES section of a page, inside an .EX/.EE block, a line
#
#     $ wrenchcone ARGS...
#
# is a command.  It is run from $top_srcdir as a shell command line, with
# "wrenchcone" meaning the program under test ($WRENCHCONE), standard input
# from /dev/null unless the line redirects it.  It must exit with status 0
# and print something on standard output.  The lines after it, up to the
# next "$ " line or the end of the block, are its expected standard output:
# when there are any, the output must equal them byte for byte, so the
# page cannot drift from the program.  Only the roff escapes \- \& \e and
# \(aq may appear in those blocks; anything else is an error here rather
# than a silent mismatch.  man/wrenchcone.1 must hold at least 4 commands.
# The pages run: wrenchcone.1, wrenchcone.5 and wrenchcone-certificate.5.
# WC_MAN_DIR names another folder of these pages and WC_MAN_RUN_DIR the
# folder to run them from (tests/install.sh runs the installed pages so).
#
# tests/man-lint.sh checks that the pages are "mandoc -Tlint" clean.
#
# Exit status: 0 pass, 1 fail, 99 the harness did not set WRENCHCONE and
# top_srcdir (both are exported by AM_TESTS_ENVIRONMENT).

if [ -z "${WRENCHCONE:-}" ] || [ -z "${top_srcdir:-}" ]; then
    echo "man-examples.sh: WRENCHCONE and top_srcdir must be set" >&2
    exit 99
fi
if [ ! -x "$WRENCHCONE" ]; then
    echo "man-examples.sh: $WRENCHCONE is not an executable" >&2
    exit 99
fi

mandir=${WC_MAN_DIR:-$top_srcdir/man}
rundir=${WC_MAN_RUN_DIR:-$top_srcdir}
page1=$mandir/wrenchcone.1
page5=$mandir/wrenchcone.5
page5c=$mandir/wrenchcone-certificate.5
min_examples=4

tmp=$(mktemp -d "${TMPDIR:-/tmp}/man-examples.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' 0
trap 'exit 1' HUP INT TERM

fail=0
failed() {
    echo "FAIL: $*" >&2
    fail=1
}

# The program under test, for the command lines of the pages.
wrenchcone() {
    "$WRENCHCONE" "$@"
}

# extract PAGE PREFIX: write each example of PAGE's EXAMPLES section as
# PREFIX.N.cmd (the command line, without "$ ") and PREFIX.N.out (its
# expected output, possibly empty), N = 1, 2, ...; print the count.
# Returns non-zero, with a message on stderr, on a malformed block.
extract() {
    awk -v prefix="$2" -v page="$1" '
    function unescape(s,    r, c, i) {
        r = ""
        while ((i = index(s, "\\")) > 0) {
            r = r substr(s, 1, i - 1)
            c = substr(s, i + 1, 1)
            if (c == "-") {
                r = r "-"
                s = substr(s, i + 2)
            } else if (c == "&") {
                s = substr(s, i + 2)
            } else if (c == "e") {
                r = r "\\"
                s = substr(s, i + 2)
            } else if (substr(s, i + 1, 3) == "(aq") {
                r = r "\047"
                s = substr(s, i + 4)
            } else {
                complain("unsupported roff escape " substr(s, i, 4))
                s = substr(s, i + 1)
            }
        }
        return r s
    }
    function complain(what) {
        printf "%s:%d: %s\n", page, FNR, what > "/dev/stderr"
        bad = 1
    }
    # Close the current example; nothing more is written to it.
    function finish() {
        if (cur != "") {
            close(cur ".cmd")
            close(cur ".out")
        }
        cur = ""
    }
    /^\.SH/ {
        finish()
        if (block)
            complain(".EX block not closed by .EE")
        block = 0
        inside = ($0 ~ /^\.SH[ \t]+"?EXAMPLES"?[ \t]*$/)
        next
    }
    !inside { next }
    /^\.EX([ \t]|$)/ { finish(); block = 1; next }
    /^\.EE([ \t]|$)/ { finish(); block = 0; next }
    !block { next }
    /^\$ / {
        finish()
        if ($0 !~ /^\$ wrenchcone /) {
            complain("an example command must start with \"$ wrenchcone \"")
            next
        }
        n++
        cur = prefix "." n
        print unescape(substr($0, 3)) > (cur ".cmd")
        printf "" > (cur ".out")
        next
    }
    /^[.\047]/ { complain("roff request inside an example block"); next }
    cur != "" { print unescape($0) > (cur ".out") }
    END {
        finish()
        if (block)
            complain(".EX block not closed by .EE")
        print n + 0
        exit bad
    }' "$1"
}

# run_examples PREFIX COUNT
run_examples() {
    i=1
    while [ "$i" -le "$2" ]; do
        base=$1.$i
        cmd=$(cat "$base.cmd")
        (cd "$rundir" && eval "$cmd") </dev/null >"$base.stdout" 2>"$base.stderr"
        status=$?
        if [ "$status" -ne 0 ]; then
            failed "exit status $status: $cmd"
            cat "$base.stderr" >&2
        elif [ ! -s "$base.stdout" ]; then
            failed "no output on stdout: $cmd"
            cat "$base.stderr" >&2
        elif [ -s "$base.out" ] && ! cmp -s "$base.out" "$base.stdout"; then
            failed "output differs from the page (- page, + program): $cmd"
            # status 2: no -u here; fall back on the plain POSIX form
            diff -u "$base.out" "$base.stdout" >&2
            [ $? -gt 1 ] && diff "$base.out" "$base.stdout" >&2
        fi
        i=$((i + 1))
    done
}

for page in "$page1" "$page5" "$page5c"; do
    if [ ! -f "$page" ]; then
        failed "missing manual page $page"
    fi
done

if [ -f "$page1" ]; then
    if n1=$(extract "$page1" "$tmp/ex1"); then :; else
        failed "malformed EXAMPLES in $page1"
    fi
    if [ "${n1:-0}" -lt "$min_examples" ]; then
        failed "$page1 has ${n1:-0} example commands; at least $min_examples expected"
    fi
    run_examples "$tmp/ex1" "${n1:-0}"
fi
j=5
for page in "$page5" "$page5c"; do
    if [ -f "$page" ]; then
        if n5=$(extract "$page" "$tmp/ex$j"); then :; else
            failed "malformed EXAMPLES in $page"
        fi
        run_examples "$tmp/ex$j" "${n5:-0}"
    fi
    j=$((j + 1))
done

exit "$fail"
