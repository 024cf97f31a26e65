#!/bin/sh
# cert-tamper.sh -- systematic tampering with every kind of certificate
# (mode-feasibility, strong-stability, stability-set): the certificates the
# program writes for data/, changed one leaf, array or key at a time, must
# each be caught by `verify` (exit 4, or 1 when malformed) unless the change
# is harmless; verify never crashes.  The work is done by cert-tamper.py
# (python3, standard library only), which says what is changed and how a
# survivor is judged.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.
#
# Run by make check with WRENCHCONE and top_srcdir in the environment;
# WC_TEST_SEED and WC_TEST_MULTIPLIER as for the C tests.  Prints the
# table of outcomes per kind (into the test's log); on failure, the
# mutation and the seed, and exits 1.

: "${WRENCHCONE:?WRENCHCONE is not set}"
: "${top_srcdir:?top_srcdir is not set}"

command -v python3 > /dev/null 2>&1 || { echo "SKIP: no python3"; exit 77; }

tmp=$(mktemp -d "${TMPDIR:-/tmp}/cert-tamper.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT

python3 "$top_srcdir/tests/cert-tamper.py" "$WRENCHCONE" "$top_srcdir/data" "$tmp"
