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

rank() {
    case $1 in
        core) echo 0 ;; exact) echo 1 ;; model) echo 2 ;; analysis) echo 3 ;;
        float) echo 4 ;; io) echo 5 ;; check) echo 0 ;; *) echo 99 ;;
    esac
}

for f in lib/*/*.[ch] lib/*/*.inc; do
    [ -f "$f" ] || continue
    layer=${f#lib/}; layer=${layer%%/*}
    r=$(rank "$layer")
    [ "$r" = 99 ] && { fail "$f: lib/$layer is not a layer of lib/README"; continue; }
    for inc in $(sed -n 's/^[ \t]*#[ \t]*include[ \t]*"\([^"]*\)".*/\1/p' "$f"); do
        case $inc in
            wrenchcone.h) fail "$f includes the umbrella header" ;;
            */*) l=${inc%%/*}; ri=$(rank "$l")
                 if [ "$layer" = check ] && [ "$l" != check ] && [ "$l" != core ]; then
                     fail "$f includes $inc: lib/check uses lib/core alone"
                 elif [ "$ri" -gt "$r" ]; then
                     fail "$f ($layer) includes $inc, a higher layer"
                 fi ;;
            *) fail "$f includes \"$inc\": name its layer" ;;
        esac
    done
done

for f in lib/*.[ch] lib/*/*.[ch] src/*.[ch]; do
    [ -f "$f" ] || continue
    n=$(wc -l < "$f")
    [ "$n" -lt 1000 ] || fail "$f has $n lines (the limit is 1,000)"
    long=$(awk '/^[A-Za-z_].*\(/ { name = $0 }
                /^\{/ { start = FNR }
                /^\}/ && start { if (FNR - start - 1 > 150)
                                    printf "%s (%d lines) ", name, FNR - start - 1
                                start = 0 }' "$f")
    [ -z "$long" ] || fail "$f: functions over 150 lines: $long"
done

[ $fails -eq 0 ] || { echo "$fails failure(s)" >&2; exit 1; }
exit 0
