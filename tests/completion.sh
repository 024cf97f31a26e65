#!/bin/sh
# completion.sh -- the bash completion (completion/wrenchcone, made by
# completion/gen.sh from the program's --help) completes commands,
# options, option values and file arguments: it is sourced in bash, the
# words of a command line are set as bash sets them for <TAB> ('='
# breaks words), and COMPREPLY, sorted, must be exactly the expected
# words.  SKIP (77) without bash.
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

cd "$tmp" && bash --norc --noprofile -s "$comp" <<'EOF'
source "$1" || exit 1
fails=0
# t 'WORDS...' 'EXPECTED...': complete the last word of WORDS (words
# separated by '|', so that a word may be empty) and compare.
t() {
    local IFS='|'
    COMP_WORDS=($1)
    [[ $1 == *'|' ]] && COMP_WORDS+=('')
    COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
    COMP_LINE=${COMP_WORDS[*]}
    COMP_POINT=${#COMP_LINE}
    COMPREPLY=()
    _wrenchcone wrenchcone "${COMP_WORDS[COMP_CWORD]}" "${COMP_WORDS[COMP_CWORD-1]}"
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
[ "$(complete -p wrenchcone)" = 'complete -F _wrenchcone wrenchcone' ] \
    || { echo "FAIL: complete -p wrenchcone: $(complete -p wrenchcone)" >&2; fails=$((fails + 1)); }
exit $((fails > 0))
EOF
