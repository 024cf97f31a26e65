#!/bin/sh
# contract.sh -- run the project's contract check (../shared/contract/check
# beside the source tree) against the built program.  Skipped (77) when the
# shared folder is not there, e.g. in a release tarball.
: "${WRENCHCONE:?}" "${top_srcdir:?}"
check=$top_srcdir/../shared/contract/check
if [ ! -x "$check" ] && [ ! -f "$check" ]; then
    echo "contract check not found at $check: skipped" >&2
    exit 77
fi
command -v python3 > /dev/null 2>&1 || { echo "python3 missing: skipped" >&2; exit 77; }
bash "$check" "$WRENCHCONE"
