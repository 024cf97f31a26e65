#!/bin/sh
# install.sh -- the installed tree works on its own: `make install
# DESTDIR=TMP` (the configured prefix, staged under TMP), then
#   0. the programs, the example problems and the corpus are installed:
#      every file of data/ is in $(pkgdatadir), byte for byte; so is the
#      bash completion;
#   1. the installed wrenchcone runs an example from the installed
#      $(pkgdatadir) (the README's "Installing" example) and prints what
#      the tree's program prints, and the standalone checker
#      bin/wrenchcone-verify runs;
#   2. the installed manual pages' examples, which name the installed
#      problem files, run with the installed program (tests/man-examples.sh);
#   3. the shared library exports exactly the wc_ functions that the
#      installed headers declare (nm -D), nothing internal;
#   4. tests/install/one-cone.c, which includes <wrenchcone/wrenchcone.h>,
#      compiles and links with `pkg-config --cflags --libs wrenchcone`
#      alone (PKG_CONFIG_SYSROOT_DIR=TMP) and prints the same cone as
#      `wrenchcone cone`; so it does against the static library with
#      `pkg-config --static`;
#   5. when configure found a Python 3, the Python module is installed in
#      its pythondir naming the installed library's directory, and,
#      imported from there (PYTHONPATH into the staged tree, the staged
#      library by WRENCHCONE_LIB), computes the cone of step 1.
# SKIP (77) without pkg-config, a C compiler, nm or perl.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${WRENCHCONE:?}" "${top_srcdir:?}" "${top_builddir:?}"
for t in pkg-config nm perl "${MAKE:-make}" "${CC:-cc}"; do
    command -v "$t" > /dev/null 2>&1 || { echo "$t not found: skipped" >&2; exit 77; }
done
tmp=$(mktemp -d "${TMPDIR:-/tmp}/install.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
dest=$tmp/dest
fail() { echo "FAIL: $*" >&2; exit 1; }

# A make of its own: not the harness's jobserver or flags.
(cd "$top_builddir" && env -u MAKEFLAGS -u MFLAGS -u MAKELEVEL \
    "${MAKE:-make}" install DESTDIR="$dest" > "$tmp/log" 2>&1) \
    || { cat "$tmp/log" >&2; fail "make install DESTDIR=$dest"; }

# Where things went: the configured directories, under $dest.
find_one() {
    f=$(find "$dest" -path "$1" | head -n 1)
    [ -n "$f" ] || fail "nothing installed matches $1"
    echo "$f"
}
bin=$(dirname "$(find_one '*/bin/wrenchcone')")
data=$(dirname "$(find_one '*/share/wrenchcone/section4.wc')")
pkgdatadir=${data#"$dest"}
pc=$(find_one '*/pkgconfig/wrenchcone.pc')
so=$(find_one '*/libwrenchcone.so')
mandir=$(dirname "$(dirname "$(find_one '*/man1/wrenchcone.1')")")

# 0. Every file of data/ is installed, the corpus in corpus/.
for f in "$top_srcdir"/data/*.wc "$top_srcdir"/data/corpus/*; do
    case $f in */corpus/*) to=$data/corpus/${f##*/} ;; *) to=$data/${f##*/} ;; esac
    cmp -s "$f" "$to" || fail "data/${f#"$top_srcdir"/data/} is not installed as $to"
done

# The bash completion, unless configured --without-bash-completion-dir.
if grep -q '^bashcompletion_DATA = completion/wrenchcone' "$top_builddir/Makefile"; then
    c=$(find "$dest" -path '*/completions/wrenchcone' | head -n 1)
    [ -n "$c" ] && cmp -s "$c" "$top_builddir/completion/wrenchcone" \
        || fail "the bash completion is not installed (completions/wrenchcone)"
    [ -n "$c" ] && cmp -s "$c-verify" "$top_builddir/completion/wrenchcone" \
        || fail "the bash completion is not installed as completions/wrenchcone-verify"
fi

# 1. The installed program (it links the library statically: no
# LD_LIBRARY_PATH) runs the README's first example from $(pkgdatadir).
"$bin/wrenchcone" cone "$data/section4.wc" na > "$tmp/inst" 2> "$tmp/err" \
    || { cat "$tmp/err" >&2; fail "installed wrenchcone cone $data/section4.wc na"; }
(cd "$top_srcdir" && "$WRENCHCONE" cone data/section4.wc na) > "$tmp/cli" || exit 1
cmp -s "$tmp/inst" "$tmp/cli" \
    || { diff "$tmp/cli" "$tmp/inst" >&2; fail "the installed program prints another cone"; }
# The README's "Installing" example, its /usr/local read as the
# configured prefix (PREFIX/share/wrenchcone is $(pkgdatadir)).
rp=$(sed -n 's|^    wrenchcone cone \(/usr/local/share/wrenchcone/section4.wc\) na$|\1|p' \
    "$top_srcdir/README")
[ -n "$rp" ] || fail "README has no line '    wrenchcone cone /usr/local/share/wrenchcone/section4.wc na'"
case $pkgdatadir in
*/share/wrenchcone)
    prefix=${pkgdatadir%/share/wrenchcone}
    "$bin/wrenchcone" cone "$dest$prefix${rp#/usr/local}" na | cmp -s - "$tmp/cli" \
        || fail "README: wrenchcone cone $rp na, installed in $prefix" ;;
esac
out=$("$bin/wrenchcone-verify" "$top_srcdir/tests/certs/figure5-ln.json") \
    && [ "$out" = "certificate holds: mode ln is infeasible" ] \
    || fail "installed wrenchcone-verify: $out"

# 2. The installed pages name $(pkgdatadir); staged, it is under $dest.
mkdir "$tmp/man" "$tmp/run" || exit 99
roff=$(printf '%s\n' "$pkgdatadir" | sed 's/-/\\-/g')
grep -qxF "\$ wrenchcone cone $roff/section4.wc na" "$mandir/man1/wrenchcone.1" \
    || fail "the installed wrenchcone(1) does not run $pkgdatadir/section4.wc"
for p in "$mandir"/man1/wrenchcone.1 "$mandir"/man5/wrenchcone.5 \
         "$mandir"/man5/wrenchcone-certificate.5; do
    # a sed replacement: \ & | escaped; - is written \- in the pages
    d=$(printf '%s\n' "$pkgdatadir" | sed -e 's/[\\&|]/\\&/g' -e 's/-/\\\\-/g')
    e=$(printf '%s\n' "$dest$pkgdatadir" | sed -e 's/[\\&|]/\\&/g' -e 's/-/\\\\-/g')
    # the pages' scratch files /tmp/wrenchcone-*, which man-examples.sh
    # may be writing at the same time, go to $tmp/run
    r=$(printf '%s\n' "$tmp/run" | sed -e 's/[\\&|]/\\&/g' -e 's/-/\\\\-/g')
    sed -e "s|$d/|$e/|g" -e "s|/tmp/wrenchcone|$r/wrenchcone|g" "$p" > "$tmp/man/${p##*/}" \
        || exit 99
done
WRENCHCONE=$bin/wrenchcone WC_MAN_DIR=$tmp/man WC_MAN_RUN_DIR=$tmp/run \
    sh "$top_srcdir/tests/man-examples.sh" \
    || fail "the installed manual pages' examples"

# 3. Exports against declarations.
nm -D --defined-only "$so" | awk '$2 ~ /^[TDBRW]$/ {print $3}' | sort -u > "$tmp/exported"
# Declarations: the headers without their comments, read as one line.
cat $(find "$dest" -path '*/include/wrenchcone/*' -name '*.h') | perl -0pe 's{/\*.*?\*/}{ }gs' \
    | tr -s ' \t\n' ' ' | grep -oE '\bwc_[A-Za-z0-9_]+ *\(' | tr -d ' (' | sort -u > "$tmp/declared"
bad=$(comm -23 "$tmp/exported" "$tmp/declared")
[ -z "$bad" ] || fail "exported but not declared in an installed header:" $bad
missing=$(comm -13 "$tmp/exported" "$tmp/declared")
[ -z "$missing" ] || fail "declared but not exported:" $missing

# 4. An outside program, built with pkg-config alone: the sysroot puts
# the .pc file's -I and -L under $dest; system directories stay in.
PKG_CONFIG_PATH=$(dirname "$pc") PKG_CONFIG_LIBDIR=$(dirname "$pc") \
PKG_CONFIG_SYSROOT_DIR=$dest PKG_CONFIG_ALLOW_SYSTEM_CFLAGS=1 PKG_CONFIG_ALLOW_SYSTEM_LIBS=1
export PKG_CONFIG_PATH PKG_CONFIG_LIBDIR PKG_CONFIG_SYSROOT_DIR \
    PKG_CONFIG_ALLOW_SYSTEM_CFLAGS PKG_CONFIG_ALLOW_SYSTEM_LIBS
flags=$(pkg-config --cflags --libs wrenchcone) || fail "pkg-config --cflags --libs wrenchcone"
${CC:-cc} $WC_SAN -o "$tmp/one-cone" "$top_srcdir/tests/install/one-cone.c" $flags \
    2> "$tmp/cc" || { cat "$tmp/cc" >&2; fail "cc one-cone.c $flags"; }
LD_LIBRARY_PATH=$(dirname "$so")${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH} "$tmp/one-cone" > "$tmp/got" \
    || fail "one-cone exits $?"
# The program prints a header line naming the problem first; the cone
# text follows and must match.
tail -n "$(wc -l < "$tmp/got")" "$tmp/cli" | cmp -s - "$tmp/got" \
    || { diff "$tmp/got" "$tmp/cli" >&2; fail "the outside program's cone differs from wrenchcone cone"; }

# The static library: --static adds Libs.private (cddlib, MPFR).  FLINT
# and cddlib stay shared (Debian ships no archives of them).
a=$(dirname "$so")/libwrenchcone.a
if [ -f "$a" ]; then
    sflags=$(pkg-config --static --cflags --libs wrenchcone | sed "s|-lwrenchcone|$a|") \
        || fail "pkg-config --static"
    ${CC:-cc} $WC_SAN -o "$tmp/one-cone-static" "$top_srcdir/tests/install/one-cone.c" $sflags \
        2> "$tmp/cc" || { cat "$tmp/cc" >&2; fail "cc one-cone.c $sflags"; }
    "$tmp/one-cone-static" | cmp -s - "$tmp/got" \
        || fail "one-cone linked with libwrenchcone.a prints another cone"
fi

# 5. The Python module, installed when configure found a Python 3.
py=$(sed -n 's/^PYTHON = //p' "$top_builddir/Makefile")
if [ -n "$py" ] && [ "$py" != : ]; then
    init=$(find_one '*/wrenchcone/__init__.py')
    libdir=$(dirname "$so")
    grep -qxF "_INSTALLED_LIBDIR = '${libdir#"$dest"}'" "$init" \
        || fail "the installed module does not name the library's directory ${libdir#"$dest"}"
    # Only python gets the ASan runtime (see python.sh).
    san=
    if [ -n "$WC_SAN" ]; then
        san="env LD_PRELOAD=$(${CC:-cc} -print-file-name=libasan.so) ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
    fi
    pypath=$(dirname "$(dirname "$init")")
    (cd "$tmp" && PYTHONPATH=$pypath WRENCHCONE_LIB=$so \
        PYTHONDONTWRITEBYTECODE=1 $san "$py" -c '
import sys, wrenchcone as wc
if not wc.__file__.startswith(sys.argv[2]):
    sys.exit("imported %s, not the installed module" % wc.__file__)
W = wc.cone(wc.Problem.read(sys.argv[1]), "na")
print(" ".join(" ".join(str(x) for x in r) for r in W["rays"]))
' "$data/section4.wc" "$dest") > "$tmp/py" 2>&1 \
        || { cat "$tmp/py" >&2; fail "the installed Python module"; }
    echo "-1 -5 -1 1 -5 1 1 0 -1" | cmp -s - "$tmp/py" \
        || { cat "$tmp/py" >&2; fail "the installed Python module computes another cone"; }
fi
exit 0
