#!/bin/sh
# cli-report.sh -- wrenchcone report: for every data/ problem one HTML
# page, well-formed (xmllint as XML; as HTML, no error but the HTML 4
# parser's unknown-tag complaints about HTML5 and SVG), self-contained
# (no script, nothing fetched), with every section and an inline figure;
# loaded in headless chromium, its screenshot is not blank (SKIP without
# chromium); bad input: exit status, nothing on stdout, no file left.
# SKIP without xmllint or python3.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${top_srcdir:?top_srcdir is not set}" "${WRENCHCONE:=$PWD/src/wrenchcone}"
. "$top_srcdir/tests/clitest.sh"
need xmllint python3
W=$WRENCHCONE
cd "$top_srcdir" || exit 99

for f in data/*.wc; do
    "$W" report "$f" -o "$tmp/r.html" 2>"$tmp/err" \
        || { fail "report $f: $(cat "$tmp/err")"; continue; }
    xmllint --noout "$tmp/r.html" 2>"$tmp/err" || fail "report $f is not well-formed: $(cat "$tmp/err")"
    xmllint --html --noout "$tmp/r.html" 2>&1 | grep 'error' \
        | grep -v 'HTML parser error : Tag [a-zA-Z]* invalid' > "$tmp/err"
    [ -s "$tmp/err" ] && fail "report $f: $(head -n 3 "$tmp/err")"
    for want in '<h2>The problem</h2>' '<h2>Feasible contact modes</h2>' \
                '<h2>Stability</h2>' '<h2>Insertion plan</h2>' '<svg ' \
                'Reproduce: <code>wrenchcone stability '; do
        grep -qF "$want" "$tmp/r.html" || fail "report $f has no $want"
    done
    grep -qiE '<script|src="http|href="http|@import' "$tmp/r.html" \
        && fail "report $f is not self-contained"
done
# The Figure 6 disk: eq. 25 fails, and the goal's arc is given exactly.
"$W" report data/disk-two-fixels-insert.wc > "$tmp/r.html" || fail "report to stdout"
grep -qF '(5, 1) (&#8776; 11.31&#176;)' "$tmp/r.html" || fail "report: no exact end of G_goal's arc"
grep -qF 'exact semantics: no, e.g. g = (-4, -9, 11)' "$tmp/r.html" || fail "report: no eq. 25"

# A real browser: the page renders to something.
browser=
for b in chromium chromium-browser; do
    command -v $b >/dev/null 2>&1 && { browser=$b; break; }
done
if [ -n "$browser" ]; then
    "$W" report data/three-fixels-insert.wc -o "$tmp/page.html" || fail "report"
    HOME=$tmp timeout 120 $browser --headless --no-sandbox --disable-gpu \
        --disable-dev-shm-usage \
        --screenshot="$tmp/shot.png" --window-size=1000,2000 \
        "file://$tmp/page.html" >"$tmp/log" 2>&1
    [ -s "$tmp/shot.png" ] || fail "$browser took no screenshot: $(tail -n 3 "$tmp/log")"
    [ -s "$tmp/shot.png" ] && { python3 tests/png-pixels.py --nonblank 2000 "$tmp/shot.png" \
        || fail "the screenshot is blank"; }
fi

# Bad input and usage.
bad() {
    want=$1 msg=$2; shift 2
    refused "$want" "$msg" report "$@"
    ls "$tmp" | grep -q 'never' && fail "report $*: left a file"
}
bad 1 "data/none.wc" data/none.wc -o "$tmp/never.html"
bad 2 "report needs PROBLEM" -o "$tmp/never.html"
bad 2 "unknown or incomplete option '--figure'" --figure data/section4.wc -o "$tmp/never.html"
bad 3 "cannot write the report" data/section4.wc -o "$tmp/no/such/never.html"

if [ -z "$browser" ]; then
    [ $failures -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
    echo "SKIP: no chromium (the rest passed)" >&2
    exit 77
fi
[ $failures -eq 0 ] || { echo "$failures failure(s)" >&2; exit 1; }
exit 0
