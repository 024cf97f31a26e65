#!/bin/sh
# corpus.sh -- the program still reproduces data/corpus/ byte for byte:
#   1. every problem NAME.wc is what the `wrenchcone random` command on
#      its first line prints;
#   2. NAME.cones.json holds one line per Table 2 mode of the problem, in
#      ASCII order, each what `wrenchcone cone --format=json NAME.wc MODE`
#      prints -- checked for every mode and both routes in one process by
#      tests/corpus-check (which builds each line as the program does);
#   3. the program itself prints the first line, the last, and every 16th
#      (every line with WC_CORPUS_FULL=1, or when corpus-check is missing).
#
# Environment (exported by the test harness): WRENCHCONE, top_srcdir;
# CORPUS_CHECK may name the helper (default: tests/corpus-check beside the
# program's build directory).

: "${WRENCHCONE:?}" "${top_srcdir:?}"
W=$WRENCHCONE
C=$top_srcdir/data/corpus
CHECK=${CORPUS_CHECK:-$(dirname "$W")/../tests/corpus-check}
tmp=${TMPDIR:-/tmp}/wc-corpus.$$
mkdir -p "$tmp" || exit 99
trap 'rm -rf "$tmp"' EXIT
fails=0
problems=0

fail() { echo "FAIL: $*" >&2; fails=$((fails + 1)); }

full=${WC_CORPUS_FULL:-0}
if [ ! -x "$CHECK" ]; then
    echo "corpus.sh: $CHECK not found: running the program on every mode" >&2
    full=1
fi

for p in "$C"/*.wc; do
    [ -f "$p" ] || continue
    problems=$((problems + 1))
    name=$(basename "$p" .wc)
    cones=$C/$name.cones.json
    if [ ! -f "$cones" ]; then
        fail "$name: $name.cones.json is missing"
        continue
    fi

    # 1. the problem is reproduced by its random command
    first=$(sed -n 1p "$p")
    case $first in
        "# wrenchcone random "*)
            args=${first#"# wrenchcone random "}
            # the options are single words; split them, but expand no glob
            set -f
            # shellcheck disable=SC2086
            set -- $args
            set +f
            if "$W" random "$@" > "$tmp/problem" 2> "$tmp/err"; then
                if ! cmp -s "$tmp/problem" "$p"; then
                    fail "$name: 'wrenchcone random $args' no longer prints $name.wc"
                    diff "$p" "$tmp/problem" | head -10 >&2
                fi
            else
                fail "$name: 'wrenchcone random $args' failed: $(cat "$tmp/err")"
            fi
            ;;
        *)
            fail "$name: the first line is not '# wrenchcone random ...'"
            ;;
    esac

    # 2. every mode, both routes, in one process
    if [ -x "$CHECK" ] && ! "$CHECK" "$p" "$cones"; then
        fail "$name: $name.cones.json is not reproduced (the mode is named above)"
    fi

    # 3. the program itself
    total=$(wc -l < "$cones")
    if [ "$full" = 1 ]; then
        cp "$cones" "$tmp/lines"
    else
        awk -v last="$total" 'NR == 1 || NR % 16 == 0 || NR == last' \
            "$cones" > "$tmp/lines"
    fi
    while IFS= read -r line; do
        mode=${line#*'"mode": "'}
        mode=${mode%%'"'*}
        if ! "$W" cone --format=json "$p" "$mode" > "$tmp/out" 2> "$tmp/err"; then
            fail "$name: mode $mode: wrenchcone cone failed: $(cat "$tmp/err")"
        elif ! printf '%s\n' "$line" | cmp -s - "$tmp/out"; then
            fail "$name: mode $mode: wrenchcone cone prints another line"
            printf 'corpus: %s\nprints: %s\n' "$line" "$(cat "$tmp/out")" >&2
        fi
    done < "$tmp/lines"
done

for j in "$C"/*.cones.json; do
    [ -f "$j" ] || continue
    [ -f "${j%.cones.json}.wc" ] || fail "$(basename "$j"): no problem file beside it"
done
[ "$problems" -gt 0 ] || fail "no problem found in $C"
[ "$fails" -eq 0 ] || { echo "$fails failure(s)" >&2; exit 1; }
exit 0
