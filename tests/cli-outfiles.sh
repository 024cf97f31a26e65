#!/bin/sh
# cli-outfiles.sh -- the files the program writes, -o FILE and
# --certificate=FILE (wrenchcone(1), FILES), all in a private folder: a
# FIFO and a character device are written through and stay what they
# were; a regular file is replaced whole, keeping its permissions (0600,
# 0640); a read-only one is refused and kept; a write that fails (EFBIG
# under ulimit -f) keeps the old file and says so in one line; a
# directory and a symbolic link to nothing are refused; SIGTERM while the
# temporary file exists removes it (a preloaded library, tests/
# stall-open.c, stops the program there, so the signal comes at that
# point every time).  No temporary file is ever left.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${top_srcdir:?top_srcdir is not set}" "${WRENCHCONE:=$PWD/src/wrenchcone}"
. "$top_srcdir/tests/clitest.sh"
need mkfifo timeout cmp
W=$WRENCHCONE
cd "$top_srcdir" || exit 99
d=$tmp/w
mkdir "$d" || exit 99

# The bytes each writer writes, on standard output (draw) or into a new
# file (certificate), to compare with.
"$W" draw --modes data/section4.wc >"$tmp/fig.svg" || exit 99
"$W" stability data/section4.wc --certificate="$tmp/cert.json" >/dev/null \
    || exit 99

# no_temporary WHAT: nothing but the files the test made in $d.
no_temporary() {
    for f in "$d"/*.tmp-* "$d"/.*.tmp-*; do
        [ -e "$f" ] && fail "$1" "left $f behind"
    done
}

# one_line NAME MESSAGE: $tmp/err is exactly the line MESSAGE.
one_line() {
    printf '%s\n' "$2" >"$tmp/want"
    cmp -s "$tmp/want" "$tmp/err" || fail "$1" "stderr '$(cat "$tmp/err")'"
}

# A FIFO with a reader gets the figure, and stays a FIFO.
mkfifo "$d/fifo"
timeout 20 cat "$d/fifo" >"$tmp/got" &
reader=$!
timeout 20 "$W" draw --modes data/section4.wc -o "$d/fifo" 2>"$tmp/err"
st=$?
wait "$reader"
[ "$st" -eq 0 ] || fail "fifo" "exit $st: $(cat "$tmp/err")"
[ -p "$d/fifo" ] || fail "fifo" "is no longer a FIFO"
cmp -s "$tmp/got" "$tmp/fig.svg" || fail "fifo" "the reader did not get the figure"
# The same for a certificate.
timeout 20 cat "$d/fifo" >"$tmp/got" &
reader=$!
timeout 20 "$W" stability data/section4.wc --certificate="$d/fifo" \
    >/dev/null 2>"$tmp/err"
st=$?
wait "$reader"
[ "$st" -eq 0 ] || fail "fifo certificate" "exit $st: $(cat "$tmp/err")"
[ -p "$d/fifo" ] || fail "fifo certificate" "is no longer a FIFO"
cmp -s "$tmp/got" "$tmp/cert.json" \
    || fail "fifo certificate" "the reader did not get the certificate"
rm -f "$d/fifo"

# A character device (a null device of our own, where mknod is allowed)
# stays one.
if mknod "$d/null" c 1 3 2>/dev/null && [ -c "$d/null" ]; then
    "$W" draw --modes data/section4.wc -o "$d/null" 2>"$tmp/err" \
        || fail "device" "exit $?: $(cat "$tmp/err")"
    [ -c "$d/null" ] || fail "device" "is no longer a character device"
    "$W" stability data/section4.wc --certificate="$d/null" >/dev/null \
        2>"$tmp/err" || fail "device certificate" "exit $?: $(cat "$tmp/err")"
    [ -c "$d/null" ] || fail "device certificate" "is no longer a character device"
    rm -f "$d/null"
fi

# -o - is standard output.
"$W" draw --modes data/section4.wc -o - >"$tmp/got" 2>"$tmp/err" \
    || fail "-o -" "exit $?"
cmp -s "$tmp/got" "$tmp/fig.svg" || fail "-o -" "differs from standard output"
[ -e ./- ] && fail "-o -" "made a file named -"

# A regular file is replaced whole and keeps its permissions.
for mode in 600 640; do
    echo old >"$d/p$mode"
    chmod "$mode" "$d/p$mode"
    "$W" draw --modes data/section4.wc -o "$d/p$mode" 2>"$tmp/err" \
        || fail "mode $mode" "exit $?: $(cat "$tmp/err")"
    cmp -s "$d/p$mode" "$tmp/fig.svg" || fail "mode $mode" "not the figure"
    got=$(stat -c %a "$d/p$mode")
    [ "$got" = "$mode" ] || fail "mode $mode" "became $got"
    echo old >"$d/c$mode"
    chmod "$mode" "$d/c$mode"
    "$W" stability data/section4.wc --certificate="$d/c$mode" >/dev/null \
        2>"$tmp/err" || fail "certificate mode $mode" "exit $?: $(cat "$tmp/err")"
    cmp -s "$d/c$mode" "$tmp/cert.json" || fail "certificate mode $mode" "not the certificate"
    got=$(stat -c %a "$d/c$mode")
    [ "$got" = "$mode" ] || fail "certificate mode $mode" "became $got"
done
# A new file is made as the umask says.
(umask 027 && "$W" draw --modes data/section4.wc -o "$d/new.svg") \
    || fail "new file" "exit $?"
got=$(stat -c %a "$d/new.svg")
[ "$got" = 640 ] || fail "new file" "mode $got under umask 027, not 640"

# A read-only file (even for root, who may write anything) is refused and
# kept.
echo old >"$d/ro"
chmod 444 "$d/ro"
"$W" draw --modes data/section4.wc -o "$d/ro" >"$tmp/out" 2>"$tmp/err"
st=$?
[ "$st" -eq 3 ] || fail "read-only" "exit $st, not 3"
[ -s "$tmp/out" ] && fail "read-only" "wrote on stdout"
one_line "read-only" "wrenchcone: $d/ro: cannot write the figure: Permission denied"
[ "$(cat "$d/ro")" = old ] || fail "read-only" "the file changed"
"$W" stability data/section4.wc --certificate="$d/ro" >"$tmp/out" 2>"$tmp/err"
st=$?
[ "$st" -eq 3 ] || fail "read-only certificate" "exit $st, not 3"
[ -s "$tmp/out" ] && fail "read-only certificate" "wrote on stdout"
one_line "read-only certificate" \
    "wrenchcone: $d/ro: cannot write the certificate: Permission denied"
[ "$(cat "$d/ro")" = old ] || fail "read-only certificate" "the file changed"
chmod 644 "$d/ro"

# A write that fails: the file size limit (ulimit -f, in blocks of 512
# or 1024 bytes: 4 blocks are under the certificate's 7517 bytes and the
# figure's 7483).  The old file stays, one line says why, exit 3.
echo old >"$d/old.json"
st=$( (ulimit -f 4 && "$W" stability data/section4.wc \
       --certificate="$d/old.json" >"$tmp/out" 2>"$tmp/err"); echo $?)
[ "$st" -eq 3 ] || fail "EFBIG certificate" "exit $st, not 3"
one_line "EFBIG certificate" \
    "wrenchcone: $d/old.json: cannot write the certificate: File too large"
[ "$(cat "$d/old.json")" = old ] || fail "EFBIG certificate" "the old certificate changed"
[ -s "$tmp/out" ] && fail "EFBIG certificate" "wrote on stdout"
echo old >"$d/old.svg"
st=$( (ulimit -f 4 && "$W" draw --modes data/section4.wc -o "$d/old.svg" \
       >"$tmp/out" 2>"$tmp/err"); echo $?)
[ "$st" -eq 3 ] || fail "EFBIG figure" "exit $st, not 3"
one_line "EFBIG figure" \
    "wrenchcone: $d/old.svg: cannot write the figure: File too large"
[ "$(cat "$d/old.svg")" = old ] || fail "EFBIG figure" "the old figure changed"

# Refused: a directory, a symbolic link to nothing (it would make a file
# wherever the link points).
mkdir "$d/dir"
"$W" draw --modes data/section4.wc -o "$d/dir" 2>"$tmp/err"
st=$?
[ "$st" -eq 3 ] || fail "directory" "exit $st, not 3"
one_line "directory" "wrenchcone: $d/dir: cannot write the figure: Is a directory"
ln -s "$d/nothing" "$d/dangling"
"$W" stability data/section4.wc --certificate="$d/dangling" >/dev/null \
    2>"$tmp/err"
st=$?
[ "$st" -eq 3 ] || fail "dangling link" "exit $st, not 3"
one_line "dangling link" \
    "wrenchcone: $d/dangling: cannot write the certificate: a symbolic link to no file"
[ -e "$d/nothing" ] && fail "dangling link" "made the file it points to"
rmdir "$d/dir"
rm -f "$d/dangling"
no_temporary "after the writes"

# SIGTERM while the temporary file exists: it is removed, the old file is
# kept, and the program ends by the signal (exit 128 + 15).
if "${CC:-cc}" -shared -fPIC -o "$tmp/stall.so" "$top_srcdir/tests/stall-open.c" \
    -ldl 2>"$tmp/err"; then
    preload=$tmp/stall.so
    # A sanitizer's runtime must come first.
    [ -n "${WC_SAN:-}" ] \
        && preload="$(${CC:-cc} -print-file-name=libasan.so) $preload"
    echo old >"$d/sig.svg"
    LD_PRELOAD=$preload WC_STALL_MARK=$tmp/mark \
        ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0 \
        timeout 20 "$W" draw --modes data/section4.wc -o "$d/sig.svg" \
        2>"$tmp/err" &
    pid=$!
    i=0
    while [ ! -e "$tmp/mark" ] && [ $i -lt 200 ] && kill -0 $pid 2>/dev/null; do
        sleep 0.1
        i=$((i + 1))
    done
    if [ -e "$tmp/mark" ]; then
        # timeout passes the signal on and exits as its child did.
        kill -TERM $pid
        wait $pid
        st=$?
        [ "$st" -eq 143 ] || fail "SIGTERM" "exit $st, not 143: $(cat "$tmp/err")"
        [ "$(cat "$d/sig.svg")" = old ] || fail "SIGTERM" "the old file changed"
        no_temporary "SIGTERM"
    else
        wait $pid
        fail "SIGTERM" "the program never opened its temporary file: $(cat "$tmp/err")"
    fi
else
    fail "SIGTERM" "cannot build the preloaded library: $(cat "$tmp/err")"
fi

if [ "$failures" -ne 0 ]; then
    printf '%s: %d failure(s)\n' "$0" "$failures"
    exit 1
fi
exit 0
