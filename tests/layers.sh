#!/bin/sh
# layers.sh -- the library's layering (lib/README) holds in the sources:
#   - a file in lib/L/ includes only headers of L and of the layers below
#     it, named "layer/name.h"; lib/check/ uses lib/core/ alone;
#   - no file inside a layer includes the umbrella header "wrenchcone.h";
#   - every file in lib/ and src/ is under 1,000 lines, and no function
#     (a body from a "{" in column 1 to the next "}" in column 1) is over
#     150 lines.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${top_srcdir:?top_srcdir is not set}"
cd "$top_srcdir" || exit 99
fails=0
fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

# One awk pass over every file: the include rules, file and function
# sizes.  Each violation is a line of output.
problems=$(awk '
    function rank(l) {
        if (l == "core" || l == "check") return 0
        if (l == "exact") return 1
        if (l == "model") return 2
        if (l == "analysis") return 3
        if (l == "float") return 4
        if (l == "io") return 5
        if (l == "draw") return 6
        if (l == "api") return 7
        return 99
    }
    FNR == 1 {
        if (prev != "" && lines >= 1000)
            printf "%s has %d lines (the limit is 1,000)\n", prev, lines
        prev = FILENAME; lines = 0; start = 0
        split(FILENAME, part, "/")
        layer = (part[1] == "lib" && part[3] != "") ? part[2] : ""
        if (layer != "" && rank(layer) == 99)
            printf "%s: lib/%s is not a layer of lib/README\n", FILENAME, layer
    }
    { lines++ }
    layer != "" && /^[ \t]*#[ \t]*include[ \t]*"/ {
        inc = $0; sub(/^[^"]*"/, "", inc); sub(/".*/, "", inc)
        if (inc == "wrenchcone.h")
            printf "%s includes the umbrella header\n", FILENAME
        else if (inc !~ /\//)
            printf "%s includes \"%s\": name its layer\n", FILENAME, inc
        else {
            l = inc; sub(/\/.*/, "", l)
            if (layer == "check" && l != "check" && l != "core")
                printf "%s includes %s: lib/check uses lib/core alone\n", FILENAME, inc
            else if (rank(l) > rank(layer))
                printf "%s (%s) includes %s, a higher layer\n", FILENAME, layer, inc
        }
    }
    /^[A-Za-z_].*\(/ { name = $0 }
    /^\{/ { start = FNR }
    /^\}/ && start {
        if (FNR - start - 1 > 150)
            printf "%s: %s is %d lines (the limit is 150)\n", FILENAME, name, FNR - start - 1
        start = 0
    }
    END {
        if (prev != "" && lines >= 1000)
            printf "%s has %d lines (the limit is 1,000)\n", prev, lines
    }' lib/*.[ch] lib/*/*.[ch] lib/*/*.inc src/*.[ch])
if [ -n "$problems" ]; then
    echo "$problems" | sed 's/^/FAIL: /' >&2
    fails=$(echo "$problems" | wc -l)
fi

[ $fails -eq 0 ] || { echo "$fails failure(s)" >&2; exit 1; }
exit 0
