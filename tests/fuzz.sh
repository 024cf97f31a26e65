#!/bin/sh
# fuzz.sh -- build the libFuzzer targets of fuzz/ with clang, AddressSanitizer
# and UndefinedBehaviorSanitizer, and run each for a while on a copy of its
# seed corpus (doc/fuzzing.md).  Not part of make check: run it as
# `make fuzz` or `sh tests/fuzz.sh`.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.
#
# Environment:
#   FUZZ_SECONDS  seconds per target (default 60)
#   FUZZ_TARGETS  targets to run (default: parse verify compare cone
#                 request)
#   FUZZ_DIR      scratch folder (default ./_fuzz): the sanitized build,
#                 the corpora, the logs and any reproducer; an earlier
#                 build there is reused
#   FUZZ_CC       the compiler (default clang)
#   FUZZ_ARGS     more libFuzzer options for every target
# Prints one line per target: PASS or FAIL, executions, and the final
# coverage (libFuzzer's cov: edges and ft: features).  Exits 0 when every
# target passed, 1 when one crashed, leaked, timed out or failed a
# property (the reproducer's path is printed), 77 (skip) when clang or
# libFuzzer is missing, 99 when the build fails.

srcdir=${top_srcdir:-$(dirname "$0")/..}
srcdir=$(cd "$srcdir" && pwd) || exit 99
FUZZ_SECONDS=${FUZZ_SECONDS:-60}
FUZZ_TARGETS=${FUZZ_TARGETS:-parse verify compare cone request}
FUZZ_DIR=${FUZZ_DIR:-_fuzz}
FUZZ_CC=${FUZZ_CC:-clang}
SAN="-fsanitize=address,undefined -fno-sanitize-recover=undefined"
CFLAGS_FUZZ="-g -O1 -fno-omit-frame-pointer -fsanitize=fuzzer-no-link $SAN"

mkdir -p "$FUZZ_DIR" || exit 99
work=$(cd "$FUZZ_DIR" && pwd) || exit 99

# clang and libFuzzer: link a trivial target.
printf 'int LLVMFuzzerTestOneInput(const char *d, unsigned long n)\n{ return d == 0 && n > 0; }\n' \
    >"$work/probe.c"
if ! command -v "$FUZZ_CC" >/dev/null 2>&1 \
    || ! "$FUZZ_CC" -fsanitize=fuzzer $SAN -o "$work/probe" "$work/probe.c" \
        >"$work/probe.log" 2>&1; then
    echo "SKIP: fuzz: $FUZZ_CC with libFuzzer is not available (clang, libclang-rt-dev)"
    exit 77
fi

# The source to build: this tree, or a copy of it when it is configured
# in place (configure then refuses an out-of-tree build).
src=$srcdir
if [ -f "$srcdir/config.status" ]; then
    if ! git -C "$srcdir" rev-parse --git-dir >/dev/null 2>&1; then
        echo "fuzz: $srcdir is configured in place; run make distclean there"
        exit 99
    fi
    src=$work/src
    rm -rf "$src" && mkdir -p "$src" || exit 99
    git -C "$srcdir" ls-files -z | tar -C "$srcdir" --null -T - -cf - \
        | tar -C "$src" -xf - || exit 99
fi
if [ ! -x "$src/configure" ]; then
    ( cd "$src" && autoreconf -fi ) >"$work/autoreconf.log" 2>&1 \
        || { echo "fuzz: autoreconf failed (see $work/autoreconf.log)"; exit 99; }
fi

# The sanitized library and program (the program writes seeds).
build=$work/build
mkdir -p "$build" || exit 99
if [ ! -f "$build/Makefile" ] || [ "$(cat "$build/src.path" 2>/dev/null)" != "$src" ]; then
    rm -rf "$build" && mkdir -p "$build" || exit 99
    echo "$src" >"$build/src.path"
    ( cd "$build" && "$src/configure" CC="$FUZZ_CC" CFLAGS="$CFLAGS_FUZZ" \
        --disable-shared ) >"$work/configure.log" 2>&1 \
        || { echo "fuzz: configure failed (see $work/configure.log)"; exit 99; }
fi
( cd "$build" && make -j2 lib/libwc.la src/wrenchcone ) >"$work/make.log" 2>&1 \
    || { echo "fuzz: building the library failed (see $work/make.log)"; exit 99; }
# The libraries: LIBS and the per-library variables configure sets
# (each program names what it links; the fuzz targets need them all).
libs=$(sed -n 's/^\(CDD_LIBS\|FLINT_LIBS\|GMP_LIBS\|LIBS\) = //p' "$build/Makefile" | tr '\n' ' ')
W=$build/src/wrenchcone

# seed TARGET FILE...: copy files into the target's corpus.
seed() {
    seed_t=$1
    shift
    [ -d "$work/corpus/$seed_t" ] || return 0
    for f in "$@"; do
        [ -f "$f" ] && cp "$f" "$work/corpus/$seed_t/"
    done
}

# The corpora: committed seeds, the data and test inputs, and files the
# program writes for the data (certificates, cones in every format).
rm -rf "$work/corpus" "$work/gen"
mkdir -p "$work/gen" || exit 99
for t in $FUZZ_TARGETS; do
    mkdir -p "$work/corpus/$t" || exit 99
    seed "$t" "$srcdir"/fuzz/corpus/"$t"/* "$srcdir"/fuzz/regressions/"$t"/*
done
seed parse "$srcdir"/data/*.wc "$srcdir"/data/corpus/*.wc "$srcdir"/tests/bad/*.wc
seed verify "$srcdir"/tests/certs/*.json "$srcdir"/tests/golden/*.json
seed compare "$srcdir"/tests/golden/*.cdd "$srcdir"/tests/golden/section4-na.json
i=0
for p in "$srcdir"/data/*.wc "$srcdir"/data/corpus/*.wc; do
    i=$((i + 1))
    g=$work/gen/$i
    "$W" modes "$p" 2>/dev/null | head -4 >"$g.modes"
    while read -r m; do
        "$W" feasible --format=json "$p" "$m" >"$g-$m.cert" 2>/dev/null
        seed verify "$g-$m.cert"
    done <"$g.modes"
    case $p in
    */data/corpus/*) ;;
    *) j=0
        for w in "0 -1 0" "-1 -1 -1" "0 1 0" "1 -2 1/2"; do
            j=$((j + 1))
            "$W" classify --certificate="$g-stab$j.json" "$p" $w >/dev/null 2>&1 \
                && seed verify "$g-stab$j.json"
        done
        # the certificates of sets, where they are small
        "$W" stability --certificate="$g-set.json" "$p" >/dev/null 2>&1 \
            && [ "$(wc -c <"$g-set.json")" -le 120000 ] && seed verify "$g-set.json"
        "$W" plan --certificate="$g-goal.json" "$p" >/dev/null 2>&1 \
            && [ "$(wc -c <"$g-goal.json")" -le 120000 ] && seed verify "$g-goal.json" ;;
    esac
    case $p in
    */data/corpus/*) awk -v g="$g" 'NR <= 3 { print > (g "-cone" NR ".json") }' \
        "${p%.wc}.cones.json" 2>/dev/null
        seed compare "$g"-cone*.json ;;
    *) m=$(head -1 "$g.modes")
        [ -n "$m" ] || continue
        for f in json cdd ine ext; do
            "$W" cone --format=$f "$p" "$m" >"$g.$f" 2>/dev/null && seed compare "$g.$f"
        done ;;
    esac
done

status=0
for t in $FUZZ_TARGETS; do
    exe=$work/fuzz-$t
    if ! $FUZZ_CC $CFLAGS_FUZZ -fsanitize=fuzzer -std=c11 -I"$src/lib" \
        -I"$srcdir/fuzz" -I"$build" -I"$build/lib" -DGMPRATIONAL \
        -o "$exe" "$srcdir/fuzz/fuzz-$t.c" "$build/lib/.libs/libwc.a" $libs -lm \
        >"$work/$t.build.log" 2>&1; then
        echo "FAIL: fuzz-$t: does not build (see $work/$t.build.log)"
        status=1
        continue
    fi
    case $t in
    verify) max_len=16384 ;;
    compare) max_len=8192 ;;
    cone) max_len=64 ;;
    *) max_len=4096 ;;
    esac
    dict=
    [ -f "$srcdir/fuzz/$t.dict" ] && dict=-dict=$srcdir/fuzz/$t.dict
    mkdir -p "$work/crash" || exit 99
    rm -f "$work/crash/$t-"*
    LSAN_OPTIONS="suppressions=$srcdir/tests/lsan.supp:print_suppressions=0" \
    ASAN_OPTIONS=${ASAN_OPTIONS:-quarantine_size_mb=32:malloc_context_size=10} \
    UBSAN_OPTIONS=print_stacktrace=1 \
        nice "$exe" -max_total_time="$FUZZ_SECONDS" -print_final_stats=1 \
        -timeout=25 -rss_limit_mb=2048 -max_len=$max_len \
        -artifact_prefix="$work/crash/$t-" $dict $FUZZ_ARGS \
        "$work/corpus/$t" >"$work/$t.log" 2>&1
    rc=$?
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$work/$t.log" | tail -1)
    cov=$(grep -E '^#[0-9]+' "$work/$t.log" | grep -o 'cov: [0-9]*' | tail -1)
    ft=$(grep -E '^#[0-9]+' "$work/$t.log" | grep -o 'ft: [0-9]*' | tail -1)
    if [ "$rc" -eq 0 ]; then
        echo "PASS: fuzz-$t: ${execs:-?} execs in ${FUZZ_SECONDS}s, ${cov:-cov: ?}, ${ft:-ft: ?}"
    else
        status=1
        echo "FAIL: fuzz-$t: exit $rc after ${execs:-?} execs, ${cov:-cov: ?}, ${ft:-ft: ?}"
        grep -E '^(==[0-9]+==ERROR|SUMMARY|.*property failed)' "$work/$t.log" | head -3 \
            | sed 's/^/    /'
        for r in "$work/crash/$t-"*; do
            [ -f "$r" ] && echo "    reproducer: $r (run: $exe $r)"
        done
        echo "    log: $work/$t.log"
    fi
done
exit $status
