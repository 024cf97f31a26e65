#!/bin/sh
# dist-files.sh -- the release tarball holds what the README promises:
#   1. every file of the source tree that the README names (a word such
#      as data/section4.wc, doc/design.md, ./man/wrenchcone.1 or
#      quickstart.sh that names a file or a folder of the tree) is in the
#      distribution; src/wrenchcone, which the build makes, is not asked;
#   2. the example problems and the corpus are all listed in data/local.mk
#      (so installed), and everything it lists exists;
#   3. every file of fuzz/ and of the folders of tests/ is in the
#      distribution.
# The distribution is DIST_DIR when set (the distcheck-hook passes the
# unpacked tarball); otherwise `make distdir` makes one in a scratch folder.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${top_srcdir:?}"
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/dist-files.XXXXXX") || exit 99
trap 'chmod -R u+w "$tmp" 2> /dev/null; rm -rf "$tmp"' EXIT

if [ -z "${DIST_DIR:-}" ]; then
    : "${top_builddir:?}"
    command -v "${MAKE:-make}" > /dev/null 2>&1 || { echo "make not found: skipped" >&2; exit 77; }
    DIST_DIR=$tmp/dist
    (cd "$top_builddir" && env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL \
        "${MAKE:-make}" distdir distdir="$DIST_DIR" > "$tmp/log" 2>&1) \
        || { cat "$tmp/log" >&2; echo "FAIL: make distdir" >&2; exit 1; }
fi

# 1. The README's file names.
grep -oE '(\./)?[A-Za-z0-9_][A-Za-z0-9_.-]*(/[A-Za-z0-9_.-]*)*' "$top_srcdir/README" \
    | sed 's|^\./||' | sort -u > "$tmp/words"
named=0
while read -r w; do
    first=${w%%/*}
    # A file of the tree, or a name under one of its folders.
    if [ -e "$top_srcdir/$w" ] || { [ "$first" != "$w" ] && [ -d "$top_srcdir/$first" ]; }; then
        case $w in src/wrenchcone) continue ;; esac
        [ "$first" = "$w" ] && [ -d "$top_srcdir/$w" ] && continue
        named=$((named + 1))
        [ -e "$DIST_DIR/$w" ] || fail "README names $w; the distribution lacks it"
    fi
done < "$tmp/words"
[ "$named" -ge 10 ] || fail "found only $named file names in README"
[ -f "$DIST_DIR/quickstart.sh" ] || fail "the distribution lacks quickstart.sh"

# 2. data/local.mk lists every file of data/ and nothing else.
sed -n 's|^[[:space:]]*\(data/[^[:space:]\\]*\).*|\1|p' "$top_srcdir/data/local.mk" \
    | sort > "$tmp/listed"
(cd "$top_srcdir" && find data -type f ! -name local.mk | sort) > "$tmp/files"
comm -23 "$tmp/files" "$tmp/listed" | sed 's/^/not in data\/local.mk (so neither installed nor distributed): /' > "$tmp/d"
comm -13 "$tmp/files" "$tmp/listed" | sed 's/^/listed in data\/local.mk but missing: /' >> "$tmp/d"
while read -r line; do fail "$line"; done < "$tmp/d"
while read -r f; do
    [ -f "$DIST_DIR/$f" ] || fail "the distribution lacks $f"
done < "$tmp/listed"

# 3. The fuzz targets and their corpora (Makefile.am lists the files), and
# the files of the tests' folders (a folder in EXTRA_DIST whose name is
# also a make target, such as tests/install beside tests/install.sh,
# would be made instead of copied).
(cd "$top_srcdir" && find fuzz tests/*/ -type f ! -path '*/.*') | while read -r f; do
    [ -f "$DIST_DIR/$f" ] || echo "$f"
done > "$tmp/fuzz"
while read -r f; do fail "the distribution lacks $f (EXTRA_DIST)"; done < "$tmp/fuzz"

[ $fails -eq 0 ] || { echo "$fails failure(s)" >&2; exit 1; }
exit 0
