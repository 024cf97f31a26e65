#!/bin/sh
# completion.sh -- the bash completion (completion/wrenchcone, made by
# completion/gen.sh from the program's --help) completes commands,
# options, option values and file arguments: it is sourced in bash, the
# words of a command line are set as bash sets them for <TAB> ('='
# breaks words), and COMPREPLY, sorted, must be exactly the expected
# words.  The MODE of cone, feasible and compare is asked of the built
# program (`modes`); wrenchcone-verify completes as `wrenchcone verify`.
# SKIP (77) without bash.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

: "${top_builddir:?}"
command -v bash > /dev/null 2>&1 || { echo "bash not found: skipped" >&2; exit 77; }
comp=$top_builddir/completion/wrenchcone
[ -f "$comp" ] || { echo "FAIL: $comp was not built" >&2; exit 1; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/completion.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
mkdir "$tmp/sub" && : > "$tmp/a.wc" && : > "$tmp/b.json" && : > "$tmp/c.ext" \
    && : > "$tmp/d.txt" || exit 99
cp "$top_srcdir/data/disk-two-fixels.wc" "$tmp/sub/two.wc" \
    && cp "$top_srcdir/data/section4.wc" "$tmp/sub/s4.wc" || exit 99
case $top_builddir in
/*) prog=$top_builddir/src/wrenchcone ;;
*) prog=$(pwd)/$top_builddir/src/wrenchcone ;;
esac

cd "$tmp" && bash --norc --noprofile -s "$comp" "$prog" <<'EOF'
source "$1" || exit 1
prog=$2
fails=0
# t 'WORDS...' 'EXPECTED...': complete the last word of WORDS (words
# separated by '|', so that a word may be empty) and compare; with a
# third argument, the completion function to call (default _wrenchcone).
t() {
    local IFS='|'
    COMP_WORDS=($1)
    [[ $1 == *'|' ]] && COMP_WORDS+=('')
    COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
    COMP_LINE=${COMP_WORDS[*]}
    COMP_POINT=${#COMP_LINE}
    COMPREPLY=()
    ${3:-_wrenchcone} wrenchcone "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD-1]}"
    IFS=' '
    local got
    got=$(printf '%s\n' "${COMPREPLY[@]}" | LC_ALL=C sort | tr '\n' ' ')
    got=${got% }
    if [[ $got != "$2" ]]; then
        echo "FAIL: wrenchcone ${1//|/ }<TAB>: got '$got', want '$2'" >&2
        fails=$((fails + 1))
    fi
}
# contains 'WORDS' WORD...: the completions include every WORD.
contains() {
    local IFS='|' w
    COMP_WORDS=($1)
    [[ $1 == *'|' ]] && COMP_WORDS+=('')
    COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
    COMPREPLY=()
    IFS=' '
    _wrenchcone
    shift
    for w in "$@"; do
        [[ " ${COMPREPLY[*]} " == *" $w "* ]] && continue
        echo "FAIL: wrenchcone ${COMP_WORDS[*]}<TAB>: no $w in '${COMPREPLY[*]}'" >&2
        fails=$((fails + 1))
    done
}

t 'wrenchcone|co' 'compare cone'
t 'wrenchcone|' 'batch classify compare cone draw feasible modes plan random report stability sweep verify'
t 'wrenchcone|--' '--help --version'
contains 'wrenchcone|draw|--' --mode= --modes --stability --plan --sweep= --graph
contains 'wrenchcone|stability|--' --certificate= --bias= --length= --format= --progress --help
t 'wrenchcone|cone|--m' '--method='
t 'wrenchcone|modes|--w' '--witness'
t 'wrenchcone|sweep|--cr' '--critical'
t 'wrenchcone|cone|--format|=|' 'cdd ext ine json text'
t 'wrenchcone|cone|--format|=|j' 'json'
t 'wrenchcone|modes|--format|=|' 'json text'
t 'wrenchcone|cone|--method|=|' 'direct paper'
t 'wrenchcone|random|--shape|=|p' 'polygon'
t 'wrenchcone|cone|' 'a.wc sub/'
t 'wrenchcone|cone|--trace|' 'a.wc sub/'
t 'wrenchcone|cone|a.wc|' ''
t 'wrenchcone|verify|' 'b.json sub/'
t 'wrenchcone|compare|a.wc|na|' 'b.json c.ext sub/'
t 'wrenchcone|feasible|--certificate|=|' 'b.json sub/'
t 'wrenchcone|feasible|--certificate|=|b.json|' 'a.wc sub/'
t 'wrenchcone|random|' ''
# MODE: the feasible modes of the problem, from the program's `modes`.
t "$prog|cone|sub/two.wc|" 'll ls nn ns rr rs sl sn sr ss'
t "$prog|cone|sub/two.wc|s" 'sl sn sr ss'
t "$prog|feasible|--format=json|sub/two.wc|l" 'll ls'
t "$prog|compare|sub/s4.wc|" 'la ls na ns ra rs sa ss'
t "$prog|cone|sub/s4.wc|na|" ''
t "$prog|cone|missing.wc|" ''
t "$prog|cone|a.wc|" ''
# wrenchcone-verify: as wrenchcone verify.
t 'wrenchcone-verify|' 'b.json sub/' _wrenchcone_verify
t 'wrenchcone-verify|--f' '--format=' _wrenchcone_verify
t 'wrenchcone-verify|--format|=|' 'json text' _wrenchcone_verify
[ "$(complete -p wrenchcone)" = 'complete -F _wrenchcone wrenchcone' ] \
    || { echo "FAIL: complete -p wrenchcone: $(complete -p wrenchcone)" >&2; fails=$((fails + 1)); }
[ "$(complete -p wrenchcone-verify)" = 'complete -F _wrenchcone_verify wrenchcone-verify' ] \
    || { echo "FAIL: complete -p wrenchcone-verify: $(complete -p wrenchcone-verify)" >&2; fails=$((fails + 1)); }
exit $((fails > 0))
EOF
