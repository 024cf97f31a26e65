#!/bin/sh
# install.sh -- the installed library works for a program outside the
# tree: `make install` into a temporary prefix, then
#   0. the standalone checker bin/wrenchcone-verify is installed and runs;
#   1. the shared library exports exactly the wc_ functions that the
#      installed headers declare (nm -D), nothing internal;
#   2. tests/install/one-cone.c, which includes <wrenchcone/wrenchcone.h>,
#      compiles and links with `pkg-config --cflags --libs wrenchcone`
#      alone and prints the same cone as `wrenchcone cone`.
# SKIP (77) without pkg-config or nm.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${WRENCHCONE:?}" "${top_srcdir:?}" "${top_builddir:?}"
for t in pkg-config nm perl "${MAKE:-make}"; do
    command -v "$t" > /dev/null 2>&1 || { echo "$t not found: skipped" >&2; exit 77; }
done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/install.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
prefix=$tmp/prefix

# A make of its own: not the harness's jobserver or flags.
(cd "$top_builddir" && env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL \
    "${MAKE:-make}" install prefix="$prefix" > "$tmp/log" 2>&1) \
    || { cat "$tmp/log" >&2; echo "FAIL: make install" >&2; exit 1; }

# The standalone checker is installed, runs, and agrees with the program.
v=$prefix/bin/wrenchcone-verify
[ -x "$v" ] || { echo "FAIL: no bin/wrenchcone-verify installed" >&2; exit 1; }
out=$("$v" "$top_srcdir/tests/certs/figure5-ln.json") \
    && [ "$out" = "certificate holds: mode ln is infeasible" ] \
    || { echo "FAIL: installed wrenchcone-verify: $out" >&2; exit 1; }

so=$(ls "$prefix"/lib/libwrenchcone.so 2> /dev/null)
[ -n "$so" ] || { echo "FAIL: no libwrenchcone.so installed" >&2; exit 1; }

# 1. Exports against declarations.
nm -D --defined-only "$so" | awk '$2 ~ /^[TDBRW]$/ {print $3}' | sort -u > "$tmp/exported"
# Declarations: the headers without their comments, read as one line.
cat $(find "$prefix/include/wrenchcone" -name '*.h') | perl -0pe 's{/\*.*?\*/}{ }gs' \
    | tr -s ' \t\n' ' ' | grep -oE '\bwc_[A-Za-z0-9_]+ *\(' | tr -d ' (' | sort -u > "$tmp/declared"
bad=$(comm -23 "$tmp/exported" "$tmp/declared")
[ -z "$bad" ] || { echo "FAIL: exported but not declared in an installed header:" $bad >&2; exit 1; }
missing=$(comm -13 "$tmp/exported" "$tmp/declared")
[ -z "$missing" ] || { echo "FAIL: declared but not exported:" $missing >&2; exit 1; }

# 2. An outside program, built with pkg-config alone.
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
# The .pc file was made for the configured prefix; point it at ours.
flags=$(pkg-config --define-variable=prefix="$prefix" --cflags --libs wrenchcone) || { echo "FAIL: pkg-config" >&2; exit 1; }
${CC:-cc} $WC_SAN -o "$tmp/one-cone" "$top_srcdir/tests/install/one-cone.c" $flags \
    -Wl,-rpath,"$prefix/lib" 2> "$tmp/cc" \
    || { cat "$tmp/cc" >&2; echo "FAIL: cc one-cone.c $flags" >&2; exit 1; }
"$tmp/one-cone" > "$tmp/got" || { echo "FAIL: one-cone exits $?" >&2; exit 1; }
"$WRENCHCONE" cone "$top_srcdir/data/section4.wc" na > "$tmp/cli" || exit 1
# The program prints a header line naming the problem first; the cone
# text follows and must match.
tail -n "$(wc -l < "$tmp/got")" "$tmp/cli" | cmp -s - "$tmp/got" \
    || { echo "FAIL: the outside program's cone differs from wrenchcone cone:" >&2;
         diff "$tmp/got" "$tmp/cli" >&2; exit 1; }
exit 0
