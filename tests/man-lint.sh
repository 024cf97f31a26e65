#!/bin/sh
# man-lint.sh -- every manual page is "mandoc -Tlint" clean: any message
# fails the test.  Reported as SKIP (77) when mandoc is missing.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${top_srcdir:?top_srcdir is not set}"
command -v mandoc > /dev/null 2>&1 || { echo "mandoc not found: skipped" >&2; exit 77; }

out=$(mandoc -Tlint "$top_srcdir"/man/*.[1-9] 2>&1)
if [ -n "$out" ]; then
    echo "mandoc -Tlint reports:" >&2
    echo "$out" >&2
    exit 1
fi
exit 0
