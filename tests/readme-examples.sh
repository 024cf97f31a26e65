#!/bin/sh
# readme-examples.sh -- every example in the README works as printed.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.
#
# In README, a line "    $ ./src/wrenchcone ARGS..." (four spaces) is a
# command, run by sh from a scratch copy of the top of the tree (data/
# and the program under test as ./src/wrenchcone), so that files the
# examples write stay out of the source tree.  The lines after it that
# are indented by four spaces, up to the next command or the first line
# that is not indented, are its expected standard output, byte for byte
# (blank lines at the end of a block do not count).  Each command must
# exit 0.  The scratch top also has python/ (the module) and lib/ (the
# build's, holding lib/.libs/, where the module finds the library) for
# the Python example, which is skipped, with a note, without python3.
# The examples write their files in /tmp (so that running them leaves the
# tree as it was: dist-files.sh would see their files); here /tmp/ in a
# command stands for a scratch folder, so that runs do not share files.

: "${WRENCHCONE:?WRENCHCONE is not set}"
: "${top_srcdir:?top_srcdir is not set}"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/readme.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/top" "$tmp/top/src" "$tmp/ex" "$tmp/tmp" || exit 99
ln -s "$top_srcdir/data" "$tmp/top/data" || exit 99
ln -s "$WRENCHCONE" "$tmp/top/src/wrenchcone" || exit 99
ln -s "$top_srcdir/python" "$tmp/top/python" || exit 99
ln -s "${top_builddir:-$top_srcdir}/lib" "$tmp/top/lib" || exit 99
# A sanitized library loads into python only after the ASan runtime.
pyenv=
if [ -n "${WC_SAN:-}" ]; then
    pyenv="LD_PRELOAD=$(${CC:-cc} -print-file-name=libasan.so) ASAN_OPTIONS=detect_leaks=0"
fi

# Split the README into ex/N.cmd and ex/N.out.
awk -v dir="$tmp/ex" '
    function close_block() { if (n) { close(dir "/" n ".cmd"); close(dir "/" n ".out") } }
    /^    \$ / { close_block(); n++; cmd = substr($0, 7)
               printf "%s\n", cmd > (dir "/" n ".cmd"); printf "" > (dir "/" n ".out")
               inblock = 1; blanks = 0; next }
    inblock && /^$/ { blanks++; next }
    inblock && /^    / { while (blanks > 0) { print "" > (dir "/" n ".out"); blanks-- }
                        print substr($0, 5) > (dir "/" n ".out"); next }
    { inblock = 0; blanks = 0 }
    END { close_block(); print n + 0 > (dir "/count") }
' "$top_srcdir/README"

count=$(cat "$tmp/ex/count")
[ "$count" -ge 10 ] || { echo "FAIL: README shows $count commands, want at least 10" >&2; exit 1; }
fails=0
i=1
while [ "$i" -le "$count" ]; do
    cmd=$(cat "$tmp/ex/$i.cmd")
    env=
    case $cmd in
    *python3*)
        if ! command -v python3 > /dev/null 2>&1; then
            echo "README: \$ $cmd: skipped, python3 not found" >&2
            i=$((i + 1))
            continue
        fi
        env="PYTHONDONTWRITEBYTECODE=1 $pyenv" ;;
    esac
    run=$(printf '%s\n' "$cmd" | sed "s|/tmp/|$tmp/tmp/|g")
    (cd "$tmp/top" && env $env sh -c "$run") > "$tmp/got" 2> "$tmp/err" < /dev/null
    status=$?
    if [ "$status" -ne 0 ]; then
        echo "FAIL: README: \$ $cmd: exit status $status" >&2
        sed 's/^/    /' "$tmp/err" >&2
        fails=$((fails + 1))
    elif ! cmp -s "$tmp/got" "$tmp/ex/$i.out"; then
        echo "FAIL: README: \$ $cmd: the output differs from the README's:" >&2
        diff "$tmp/ex/$i.out" "$tmp/got" | sed 's/^/    /' >&2
        fails=$((fails + 1))
    fi
    i=$((i + 1))
done
[ $fails -eq 0 ] || { echo "$fails failure(s)" >&2; exit 1; }
exit 0
