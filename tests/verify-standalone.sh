#!/bin/sh
# verify-standalone.sh -- the standalone checker wrenchcone-verify(1):
#   1. for every certificate in tests/certs and every certificate that
#      `wrenchcone feasible --certificate` (every Table 1 mode) and
#      `wrenchcone classify --certificate` (a few wrenches) write for the
#      data files (the bulk of them written by one `wrenchcone batch`
#      process, with "certificate": true), as text and as JSON, and for standard input, a missing
#      file, a directory, an empty file and usage errors, it prints the
#      same bytes on stdout and stderr and exits with the same status as
#      `wrenchcone verify` (a usage error's last line names the program
#      run, "Try 'wrenchcone-verify --help'": compared with that one
#      change);
#   2. it links GMP and the C library only: neither the program nor the
#      check library lib/.libs/libwccheck.a defines or refers to a FLINT,
#      MPFR or cddlib symbol (nm), and ldd lists no library but GMP, the
#      C library and, in a sanitizer build, the sanitizers' own.
# The build already makes a FLINT or cddlib call in lib/check a link
# error (src/local.mk); this test says so again, by name.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${WRENCHCONE:?}" "${top_srcdir:?}" "${top_builddir:?}"
V=$top_builddir/src/wrenchcone-verify
[ -x "$V" ] || { echo "verify-standalone.sh: $V is not an executable" >&2; exit 99; }
certs=$top_srcdir/tests/certs
data=$top_srcdir/data
tmp=$(mktemp -d "${TMPDIR:-/tmp}/vstand.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
failed=0
compared=0
fail() { echo "FAIL: $*" >&2; failed=1; }

# same NAME STDIN ARGS...: `wrenchcone verify ARGS` and `wrenchcone-verify
# ARGS` with standard input from STDIN agree byte for byte.  Each run's
# stdout and stderr are appended to one file per program and stream,
# between lines naming the case and (stdout) the exit status, and
# check_same compares the files once: a cmp per case cost more CPU than
# the case.
same() {
    name=$1 in=$2
    shift 2
    for f in o1 e1 o2 e2.raw; do
        printf '== %s\n' "$name" >> "$tmp/$f"
    done
    "$WRENCHCONE" verify "$@" < "$in" >> "$tmp/o1" 2>> "$tmp/e1"
    s1=$?
    "$V" "$@" < "$in" >> "$tmp/o2" 2>> "$tmp/e2.raw"
    s2=$?
    printf '\n== exit %s\n' "$s1" >> "$tmp/o1"
    printf '\n== exit %s\n' "$s2" >> "$tmp/o2"
    printf '\n==\n' >> "$tmp/e1"
    printf '\n==\n' >> "$tmp/e2.raw"
    compared=$((compared + 1))
}

# check_same: every case so far agreed (the status, stdout, stderr).
check_same() {
    sed "s/^Try 'wrenchcone-verify --help'/Try 'wrenchcone verify --help'/" \
        "$tmp/e2.raw" > "$tmp/e2"
    cmp -s "$tmp/o1" "$tmp/o2" || { fail "stdout or exit status differs"; diff -u "$tmp/o1" "$tmp/o2" >&2; }
    cmp -s "$tmp/e1" "$tmp/e2" || { fail "stderr differs"; diff -u "$tmp/e1" "$tmp/e2" >&2; }
    : > "$tmp/o1"; : > "$tmp/o2"; : > "$tmp/e1"; : > "$tmp/e2.raw"
}

# both NAME FILE: as text and as JSON.
both() {
    same "$1" /dev/null "$2"
    same "$1 (json)" /dev/null --format=json "$2"
}

# 1. The same verdicts.
for c in "$certs"/*.json; do
    both "$(basename "$c")" "$c"
done

# modes PROBLEM: every Table 1 mode of PROBLEM, feasible or not, one a
# line.  A fixel is touching when some feasible mode has l, r or n there.
modes() {
    "$WRENCHCONE" modes "$1" | awk '
        { for (i = 1; i <= length($0); i++)
              if (substr($0, i, 1) ~ /[lrn]/) touching[i] = 1
          n = length($0) }
        END {
            k = 1; m[1] = ""
            for (i = 1; i <= n; i++) {
                letters = touching[i] ? "slrn" : "sa"; k2 = 0
                for (j = 1; j <= k; j++)
                    for (l = 1; l <= length(letters); l++)
                        m2[++k2] = m[j] substr(letters, l, 1)
                k = k2
                for (j = 1; j <= k; j++) m[j] = m2[j]
            }
            for (j = 1; j <= k; j++) print m[j]
        }'
}

# The certificates: the first mode and the first wrench of each problem
# by `--certificate=FILE` command lines, the rest by one `wrenchcone
# batch` process, whose answers end with the document --certificate
# writes, on one line.  $tmp/list names each certificate and its file.
: > "$tmp/requests"
: > "$tmp/list"
for problem in "$data"/*.wc; do
    p=$(basename "$problem" .wc)
    P=$(printf '"%s"' "$problem")
    first=1
    for mode in $(modes "$problem"); do
        cert=$tmp/$p-$mode.json
        if [ "$first" -eq 1 ]; then
            first=0
            "$WRENCHCONE" feasible --certificate="$cert" "$problem" "$mode" \
                > /dev/null 2> "$tmp/err" \
                || { fail "feasible --certificate $p $mode: $(cat "$tmp/err")"; continue; }
        else
            printf '{"command": "feasible", "problem": %s, "mode": "%s", "certificate": true}\n' \
                "$P" "$mode" >> "$tmp/requests"
        fi
        printf '%s %s\n' "$cert" "feasible $p $mode" >> "$tmp/list"
    done
    k=0
    for g in "0 -1 0" "1 1 0" "1 -1 0" "-1 -1 -1" "0 1 0"; do
        k=$((k + 1))
        cert=$tmp/$p-classify-$k.json
        if [ "$k" -eq 1 ]; then
            # shellcheck disable=SC2086
            "$WRENCHCONE" classify --certificate="$cert" "$problem" $g \
                > /dev/null 2> "$tmp/err" \
                || { fail "classify --certificate $p $g: $(cat "$tmp/err")"; continue; }
        else
            # shellcheck disable=SC2086
            set -- $g
            printf '{"command": "classify", "problem": %s, "wrench": ["%s", "%s", "%s"], "certificate": true}\n' \
                "$P" "$1" "$2" "$3" >> "$tmp/requests"
        fi
        printf '%s %s\n' "$cert" "classify $p $g" >> "$tmp/list"
    done
done
"$WRENCHCONE" batch < "$tmp/requests" > "$tmp/answers" 2> "$tmp/err" \
    || fail "batch: exit status $?: $(cat "$tmp/err")"
[ "$(wc -l < "$tmp/requests")" -eq "$(wc -l < "$tmp/answers")" ] \
    || fail "batch: $(wc -l < "$tmp/answers") answers to $(wc -l < "$tmp/requests") requests"
# Each answer's last member is the certificate; write it to its file (the
# files listed without a command line of their own, in order).
while read -r cert name; do
    [ -f "$cert" ] || printf '%s\n' "$cert"
done < "$tmp/list" > "$tmp/batch-files"
awk -v files="$tmp/batch-files" '
    { if ((getline f < files) <= 0) { print "no file for answer " NR > "/dev/stderr"; exit 1 }
      i = index($0, ", \"certificate\": {")
      if (i == 0 || substr($0, length($0)) != "}") {
          print "answer " NR " has no certificate: " $0 > "/dev/stderr"; exit 1 }
      print substr($0, i + 17, length($0) - i - 17) > f; close(f) }' \
    "$tmp/answers" || fail "batch answers without certificates"
while read -r cert name; do
    [ -s "$cert" ] || { fail "$name: no certificate"; continue; }
    both "$name" "$cert"
done < "$tmp/list"
check_same
[ "$compared" -ge 300 ] || fail "only $compared comparisons"

# Standard input, files that are not certificates, usage.
same "stdin" "$certs/figure5-ln.json" -
same "stdin (json)" "$certs/tampered-witness.json" --format=json -
same "stdin, malformed" "$certs/bad-truncated.json" -
same "missing file" /dev/null "$tmp/no-such-file.json"
same "directory" /dev/null "$tmp"
: > "$tmp/empty.json"
same "empty file" /dev/null "$tmp/empty.json"
same "no operand" /dev/null
same "two operands" /dev/null "$certs/figure5-ln.json" "$certs/figure5-ln.json"
same "unknown format" /dev/null --format=cdd "$certs/figure5-ln.json"
same "missing format" /dev/null "$certs/figure5-ln.json" --format
same "unknown option" /dev/null --bogus "$certs/figure5-ln.json"
same "options after the operand" /dev/null "$certs/figure5-ln.json" --format=json
check_same

# The program's own help and version.
"$V" --help > "$tmp/o" 2> "$tmp/e" && [ ! -s "$tmp/e" ] \
    && grep -q "^Usage: wrenchcone-verify " "$tmp/o" || fail "--help"
"$V" -V > "$tmp/o" 2> "$tmp/e" && [ ! -s "$tmp/e" ] \
    && grep -q "^GMP [0-9]" "$tmp/o" && ! grep -qi "flint\|cdd" "$tmp/o" \
    || fail "--version: $(cat "$tmp/o" "$tmp/e")"

# 2. GMP and the C library only.  Names of FLINT (fmpz_, fmpq_, flint_,
# nmod_, n_...), MPFR and cddlib (dd_, ddf_, set_ of setoper.h), with or
# without leading underscores.
foreign='^_*(fmpz|fmpq|fmpzi|flint|nmod|mpfr|dd|ddf|set)_'
if command -v nm > /dev/null 2>&1; then
    for f in "$V" "$top_builddir/lib/.libs/libwccheck.a"; do
        [ -f "$f" ] || { fail "no $f"; continue; }
        bad=$(nm "$f" 2> /dev/null | awk '{print $NF}' | grep -E "$foreign" | sort -u)
        [ -z "$bad" ] || fail "$f names FLINT, MPFR or cddlib symbols:" $bad
        # ... and the test sees symbols at all
        nm "$f" 2> /dev/null | grep -q "wc_verify_fprint" || fail "nm $f: no wc_verify_fprint"
    done
else
    echo "nm not found: symbol check skipped" >&2
fi
if command -v ldd > /dev/null 2>&1; then
    ldd "$V" > "$tmp/ldd" 2>&1 || fail "ldd $V: $(cat "$tmp/ldd")"
    grep -q libgmp "$tmp/ldd" || fail "ldd $V lists no libgmp: $(cat "$tmp/ldd")"
    bad=$(awk '{print $1}' "$tmp/ldd" | sed 's,.*/,,' | grep -vE \
        '^(linux-vdso|linux-gate|ld-linux[-a-z0-9_.]*|libc|libgmp|libasan|libubsan|libstdc\+\+|libm|libgcc_s|libpthread|libdl|librt)(\.so.*)?$')
    [ -z "$bad" ] || fail "ldd $V lists more than GMP and the C library:" $bad
fi

exit $failed
