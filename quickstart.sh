#!/bin/sh
# quickstart.sh -- the README's first command: install the Debian packages
# wrenchcone needs (when missing), generate the build system, configure,
# build, and print a real example: the paper's Section 4 wrench cone.
# The packages include every tool `make check` uses (the README's second
# command), so that no test is skipped: python3 and pytest, mandoc,
# cddlib's scdd_gmp, xmllint, rsvg-convert and chromium.
set -e
cd "$(dirname "$0")"

pkgs="build-essential autoconf automake libtool pkg-config libgmp-dev libmpfr-dev libflint-dev libcdd-dev"
# what the tests need besides (tests/*.sh: grep 'exit 77\|need ')
pkgs="$pkgs python3 python3-pytest mandoc libcdd-tools libxml2-utils librsvg2-bin chromium"
missing=
if command -v dpkg-query > /dev/null 2>&1; then
    for p in $pkgs; do
        dpkg-query -W -f='${Status}' "$p" 2> /dev/null | grep -q 'ok installed' || missing="$missing $p"
    done
else
    echo "quickstart: not Debian (no dpkg-query): install GMP, MPFR, FLINT and cddlib yourself"
fi
if [ -n "$missing" ]; then
    echo "quickstart: installing$missing"
    if [ "$(id -u)" = 0 ]; then SUDO=; else SUDO=sudo; fi
    $SUDO apt-get update -qq
    $SUDO env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $missing
fi

[ -x configure ] || autoreconf -fi
[ -f Makefile ] || ./configure ${CONFIGURE_FLAGS:-}
make -j"$(nproc 2> /dev/null || echo 2)"

echo
echo "\$ ./src/wrenchcone cone data/section4.wc na"
./src/wrenchcone cone data/section4.wc na
