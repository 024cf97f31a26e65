#!/bin/sh
# python.sh -- the Python module's pytest suite (python/tests/test_*.py)
# against the library and the program of this build: exact values, errors
# with their locations, the commands' JSON round trip, and a float
# implementation regression-checked against the exact cones.
# SKIP (77) without python3 or pytest (Debian package python3-pytest):
# the first of $PYTHON (configure's), python3, that imports pytest runs
# `-m pytest`, else Debian's pytest-3.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${WRENCHCONE:?}" "${top_srcdir:?}" "${top_builddir:?}"
pytest=
for py in "${PYTHON:-python3}" python3; do
    if [ "$py" != : ] && command -v "$py" > /dev/null 2>&1 \
        && "$py" -c 'import sys, pytest; sys.exit(sys.version_info < (3, 7))' \
           > /dev/null 2>&1; then
        pytest="$py -m pytest"
        break
    fi
done
if [ -z "$pytest" ]; then
    command -v pytest-3 > /dev/null 2>&1 || { echo "python3 with pytest not found: skipped" >&2; exit 77; }
    pytest=pytest-3
fi
lib=$top_builddir/lib/.libs/libwrenchcone.so
[ -f "$lib" ] || { echo "FAIL: $lib was not built" >&2; exit 1; }

# A sanitized library loads into python only after the ASan runtime;
# python's own allocations are not ours to check for leaks.  Only pytest
# gets the preload (detect_leaks=0 last, so that it wins over the
# caller's options): not this script's own commands.
san=
if [ -n "$WC_SAN" ]; then
    san="env LD_PRELOAD=$(${CC:-cc} -print-file-name=libasan.so) ASAN_OPTIONS=${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
fi
tmp=$(mktemp -d "${TMPDIR:-/tmp}/python.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
# Nothing written into the source tree (read-only under distcheck).
WRENCHCONE_LIB=$lib PYTHONPATH=$top_srcdir/python PYTHONDONTWRITEBYTECODE=1 \
    TMPDIR=$tmp
export WRENCHCONE_LIB PYTHONPATH PYTHONDONTWRITEBYTECODE TMPDIR
cd "$tmp" || exit 99
$san $pytest -q -p no:cacheprovider --rootdir="$tmp" --basetemp="$tmp/pytest" \
    "$top_srcdir"/python/tests/test_*.py
