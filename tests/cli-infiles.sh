#!/bin/sh
# cli-infiles.sh -- the files the program reads (wrenchcone(1), FILES):
# a request reads regular files only, so that a batch answers every line
# -- a request naming /dev/stdin or /proc/self/fd/0 (the batch's own
# input), the batch's own file, a FIFO without a writer (which must not
# block: under timeout 20, a hang fails), /dev/zero or a directory gets
# its error line at once, and the other requests their answers; a batch
# whose input is its output (batch F >> F) is refused; the
# command line still reads a FIFO, /dev/stdin and a shell's <(...); an
# input over the size limit is refused from its size, unread, or, for a
# device, after at most the limit (checked by memory: ulimit -v).
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${top_srcdir:?top_srcdir is not set}" "${WRENCHCONE:=$PWD/src/wrenchcone}"
. "$top_srcdir/tests/clitest.sh"
need mkfifo timeout cmp
W=$WRENCHCONE
cd "$top_srcdir" || exit 99

# answer_error NAME LINE MESSAGE FILE: line LINE of $tmp/out is the error
# record of MESSAGE about FILE (bad input, status 1).
answer_error() {
    want="{\"format\": \"wrenchcone-json/1\", \"error\": {\"message\": \"$3\", \"file\": \"$4\", \"line\": null, \"column\": null, \"status\": 1}}"
    got=$(sed -n "$2p" "$tmp/out")
    [ "$got" = "$want" ] || fail "$1" "line $2 is '$got'"
}

modes='{"command": "modes", "problem": "data/section4.wc"}'
"$W" modes --format=json data/section4.wc >"$tmp/modes.json" || exit 99

# 1,001 requests through a pipe, the first naming the batch's own input:
# 1,001 answers, the first an error, the 1,000 others the modes.
for own in /dev/stdin /proc/self/fd/0; do
    for jobs in 1 2; do
        { printf '{"command": "cone", "problem": "%s", "mode": "na"}\n' "$own"
          i=0
          while [ $i -lt 1000 ]; do echo "$modes"; i=$((i + 1)); done
        } | timeout 60 "$W" batch --jobs=$jobs >"$tmp/out" 2>"$tmp/err"
        st=$?
        name="$own, --jobs=$jobs"
        [ "$st" -eq 1 ] || fail "$name" "exit $st, not 1: $(cat "$tmp/err")"
        n=$(wc -l <"$tmp/out")
        [ "$n" -eq 1001 ] || fail "$name" "$n answers to 1001 requests"
        answer_error "$name" 1 "the batch's own input: a request cannot read it" "$own"
        [ "$(sed 1d "$tmp/out" | sort -u)" = "$(cat "$tmp/modes.json")" ] \
            || fail "$name" "the other answers are not the modes"
    done
done

# A batch from a regular file that names itself, on standard input and
# as its FILE.
printf '{"command": "modes", "problem": "%s"}\n%s\n' "$tmp/self.jsonl" \
    "$modes" >"$tmp/self.jsonl"
for how in stdin file; do
    if [ $how = stdin ]; then
        timeout 60 "$W" batch <"$tmp/self.jsonl" >"$tmp/out" 2>"$tmp/err"
    else
        timeout 60 "$W" batch "$tmp/self.jsonl" >"$tmp/out" 2>"$tmp/err"
    fi
    st=$?
    [ "$st" -eq 1 ] || fail "itself ($how)" "exit $st, not 1"
    [ "$(wc -l <"$tmp/out")" -eq 2 ] || fail "itself ($how)" "not 2 answers"
    answer_error "itself ($how)" 1 "the batch's own input: a request cannot read it" "$tmp/self.jsonl"
    [ "$(sed -n 2p "$tmp/out")" = "$(cat "$tmp/modes.json")" ] \
        || fail "itself ($how)" "the second answer is not the modes"
done

# A batch whose input is its output would answer its answers without
# end: refused, unread.
cp "$tmp/self.jsonl" "$tmp/loop.jsonl"
timeout 20 "$W" batch "$tmp/loop.jsonl" >>"$tmp/loop.jsonl" 2>"$tmp/err"
st=$?
[ "$st" -eq 1 ] || fail "input is output" "exit $st, not 1"
printf 'wrenchcone: %s: the batch'"'"'s input is also its output\n' \
    "$tmp/loop.jsonl" >"$tmp/want"
cmp -s "$tmp/want" "$tmp/err" || fail "input is output" "stderr '$(cat "$tmp/err")'"
cmp -s "$tmp/self.jsonl" "$tmp/loop.jsonl" || fail "input is output" "the file changed"

# Not regular files: a FIFO nobody writes (nothing may wait for it), a
# device without end, a directory; each line answered, in order.
mkfifo "$tmp/fifo"
mkdir "$tmp/dir"
for f in "$tmp/fifo" /dev/zero "$tmp/dir"; do
    printf '{"command": "modes", "problem": "%s"}\n' "$f"
    printf '{"command": "compare", "problem": "data/section4.wc", "mode": "na", "foreign": "%s"}\n' "$f"
    printf '{"command": "verify", "certfile": "%s"}\n' "$f"
done >"$tmp/odd.jsonl"
echo "$modes" >>"$tmp/odd.jsonl"
timeout 20 "$W" batch "$tmp/odd.jsonl" >"$tmp/out" 2>"$tmp/err"
st=$?
[ "$st" -eq 1 ] || fail "not regular" "exit $st, not 1: $(cat "$tmp/err")"
[ "$(wc -l <"$tmp/out")" -eq 10 ] || fail "not regular" "$(wc -l <"$tmp/out") answers to 10 requests"
k=0
for f in "$tmp/fifo" /dev/zero "$tmp/dir"; do
    msg="not a regular file (a request reads regular files only)"
    [ "$f" = "$tmp/dir" ] && msg="read error: Is a directory"
    for c in modes compare verify; do
        k=$((k + 1))
        answer_error "$c $f" $k "$msg" "$f"
    done
done
[ "$(sed -n 10p "$tmp/out")" = "$(cat "$tmp/modes.json")" ] \
    || fail "not regular" "the last answer is not the modes"

# The command line reads what its user names: a FIFO with a writer,
# /dev/stdin, a shell's <(...) (a pipe under /dev/fd).
"$W" cone data/section4.wc na >"$tmp/cone.txt" || exit 99
timeout 20 sh -c 'cat data/section4.wc >"$1"' sh "$tmp/fifo" &
timeout 20 "$W" cone "$tmp/fifo" na >"$tmp/out" 2>"$tmp/err" \
    || fail "command-line FIFO" "exit $?: $(cat "$tmp/err")"
wait
cmp -s "$tmp/out" "$tmp/cone.txt" || fail "command-line FIFO" "another cone"
"$W" cone /dev/stdin na <data/section4.wc >"$tmp/out" 2>"$tmp/err" \
    || fail "command-line /dev/stdin" "exit $?: $(cat "$tmp/err")"
cmp -s "$tmp/out" "$tmp/cone.txt" || fail "command-line /dev/stdin" "another cone"
cat data/section4.wc | "$W" cone /dev/fd/0 na >"$tmp/out" 2>"$tmp/err" \
    || fail "command-line pipe" "exit $?: $(cat "$tmp/err")"
cmp -s "$tmp/out" "$tmp/cone.txt" || fail "command-line pipe" "another cone"

# Over the limit (256 MB): a file is refused from its size, unread, in
# little memory; a device without end after 256 MB and one byte, in not
# much more memory than that (the reader used to hold 512 MB).
# Sanitizers reserve terabytes of address space: no ulimit -v there.
if [ -z "${WC_SAN:-}" ]; then
    : >"$tmp/huge"
    if truncate -s 268435457 "$tmp/huge" 2>/dev/null; then
        st=$( (ulimit -v 100000 && "$W" modes "$tmp/huge" >"$tmp/out" 2>"$tmp/err"); echo $?)
        [ "$st" -eq 1 ] || fail "huge file" "exit $st, not 1: $(cat "$tmp/err")"
        grep -qxF "wrenchcone: $tmp/huge: file too large (over 268435456 bytes)" "$tmp/err" \
            || fail "huge file" "stderr '$(cat "$tmp/err")'"
        printf '{"command": "modes", "problem": "%s"}\n' "$tmp/huge" >"$tmp/huge.jsonl"
        st=$( (ulimit -v 100000 && "$W" batch "$tmp/huge.jsonl" >"$tmp/out" 2>"$tmp/err"); echo $?)
        [ "$st" -eq 1 ] || fail "huge file request" "exit $st, not 1: $(cat "$tmp/err")"
        answer_error "huge file request" 1 "file too large (over 268435456 bytes)" "$tmp/huge"
    fi
    rm -f "$tmp/huge"
    st=$( (ulimit -v 400000 && "$W" modes /dev/zero >"$tmp/out" 2>"$tmp/err"); echo $?)
    [ "$st" -eq 1 ] || fail "/dev/zero" "exit $st, not 1: $(cat "$tmp/err")"
    grep -qxF "wrenchcone: /dev/zero: file too large (over 268435456 bytes)" "$tmp/err" \
        || fail "/dev/zero" "stderr '$(cat "$tmp/err")'"
fi

if [ "$failures" -ne 0 ]; then
    printf '%s: %d failure(s)\n' "$0" "$failures"
    exit 1
fi
exit 0
