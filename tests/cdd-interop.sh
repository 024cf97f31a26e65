#!/bin/sh
# cdd-interop.sh -- cddlib's own program (scdd_gmp, Debian package
# libcdd-tools) reads the cdd files we write and finds the same numbers of
# rays and facets.  Reported as SKIP (77) when scdd_gmp is missing.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${WRENCHCONE:?WRENCHCONE is not set}"
: "${top_srcdir:?top_srcdir is not set}"
command -v scdd_gmp > /dev/null 2>&1 || { echo "scdd_gmp not found: skipped" >&2; exit 77; }

W=$WRENCHCONE
D=$top_srcdir/data
tmp=$(mktemp -d "${TMPDIR:-/tmp}/cdd-interop.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

"$W" cone --format=ine "$D/section4.wc" na > "$tmp/s4.ine" || fail "cone --format=ine"
"$W" cone --format=ext "$D/section4.wc" na > "$tmp/s4b.ext" || fail "cone --format=ext"
(cd "$tmp" && scdd_gmp s4.ine > /dev/null 2>&1 && scdd_gmp s4b.ext > /dev/null 2>&1) \
    || fail "scdd_gmp rejects our cdd output"
rays=$(sed -n '/^begin/{n;p;q}' "$tmp/s4.ext" | awk '{print $1}')
facets=$(sed -n '/^begin/{n;p;q}' "$tmp/s4b.ine" | awk '{print $1}')
[ "$rays" = 3 ] || fail "cdd finds $rays rays, want 3"
[ "$facets" = 4 ] || fail "cdd finds $facets rows, want 3 facets + 1 >= 0"

[ $fails -eq 0 ] || { echo "$fails failure(s)" >&2; exit 1; }
exit 0
