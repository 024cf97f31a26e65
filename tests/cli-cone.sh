#!/bin/sh
# cli-cone.sh -- `wrenchcone cone` end to end: exact golden outputs for the
# paper's Section 4 example in every format, both routes byte-equal on
# every data file and mode, an infeasible mode printed as empty, help and
# version, and cddlib's own tools reading our .ine and .ext.
#
# Environment (exported by the test harness): WRENCHCONE, top_srcdir.

: "${WRENCHCONE:?}" "${top_srcdir:?}"
W=$WRENCHCONE
D=$top_srcdir/data
G=$top_srcdir/tests/golden
tmp=${TMPDIR:-/tmp}/wc-cli-cone.$$
mkdir -p "$tmp" || exit 99
trap 'rm -rf "$tmp"' EXIT
fails=0

fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

# golden NAME ARGS...: stdout must equal tests/golden/NAME, stderr empty.
golden() {
    name=$1; shift
    if ! (cd "$top_srcdir" && "$W" "$@") > "$tmp/out" 2> "$tmp/err"; then
        fail "$name: exit status $?"; return
    fi
    [ -s "$tmp/err" ] && fail "$name: stderr: $(cat "$tmp/err")"
    cmp -s "$tmp/out" "$G/$name" || {
        fail "$name: output differs from tests/golden/$name"
        diff "$G/$name" "$tmp/out" | head -20 >&2
    }
}

golden section4-na.txt cone data/section4.wc na
golden section4-na.json cone --format=json data/section4.wc na
golden section4-na.cdd cone --format=cdd data/section4.wc na
golden section4-na-paper-trace.txt cone --method=paper --trace data/section4.wc na
golden figure5-ln.json cone --format=json data/disk-two-fixels.wc ln
# Options may follow the arguments; stdin reads as '-'.
golden section4-na.json cone data/section4.wc na --format=json
(cd "$top_srcdir" && "$W" cone --format=json - na < data/section4.wc) > "$tmp/out" 2>&1
cmp -s "$tmp/out" "$G/section4-na.json" || fail "stdin input differs"

# Both routes print the same bytes, in every format, for every mode below.
check_routes() {
    file=$1; shift
    for mode in "$@"; do
        for fmt in text json cdd; do
            "$W" cone --format=$fmt --method=direct "$D/$file" "$mode" > "$tmp/d" 2>&1 \
                || fail "$file $mode: direct exit $?"
            "$W" cone --format=$fmt --method=paper "$D/$file" "$mode" > "$tmp/p" 2>&1 \
                || fail "$file $mode: paper exit $?"
            cmp -s "$tmp/d" "$tmp/p" || fail "$file $mode $fmt: routes differ"
        done
    done
}
check_routes section4.wc na ns nu sa ss la ra ma mu
check_routes disk-two-fixels.wc ss sl sr sn ls rs ns ll rr nn ln mm mn nm lr
check_routes peg-in-hole.wc lra nna nns mms sss rla
check_routes three-fixels.wc sss aaa saa uua aus

# Trace: every matrix of Section 5, in text and JSON.
"$W" cone --method=paper --trace --format=json "$D/section4.wc" na > "$tmp/t" \
    || fail "json trace exit $?"
for m in '"J"' '"C"' '"E"' '"N"' '"R"' '"S"' '"V"' '"K"' '"P"' '"K^F"' '"F"'; do
    grep -q "\"name\": $m" "$tmp/t" || fail "json trace lacks $m"
done

# Help and version go to stdout and exit 0; the version names the libraries.
"$W" --help > "$tmp/h" 2>&1 && grep -q '^Usage: wrenchcone' "$tmp/h" || fail "--help"
"$W" cone --help > "$tmp/h" 2>&1 && grep -q -- '--method' "$tmp/h" || fail "cone --help"
"$W" --version > "$tmp/v" 2>&1 || fail "--version exit"
for lib in GMP FLINT cddlib; do grep -q "$lib" "$tmp/v" || fail "--version lacks $lib"; done
"$W" cone --version > /dev/null 2>&1 || fail "cone --version exit"

# Unimplemented commands: exit 2, nothing on stdout.
"$W" draw "$D/disk-two-fixels.wc" > "$tmp/o" 2> /dev/null
[ $? -eq 2 ] && [ ! -s "$tmp/o" ] || fail "planned command: want exit 2, empty stdout"

# A write error is an I/O failure: exit 3.
if [ -w /dev/full ]; then
    "$W" cone "$D/section4.wc" na > /dev/full 2> /dev/null
    [ $? -eq 3 ] || fail "write to /dev/full: want exit 3"
fi

[ $fails -eq 0 ] || { echo "$fails failure(s)" >&2; exit 1; }
exit 0
