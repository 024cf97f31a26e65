#!/usr/bin/env python3
"""Regenerate the expected outputs the tests compare against, after a
deliberate change of output format: tests/golden/* (see cli-cone.sh for
the command behind each file) and the output lines under each
"$ wrenchcone ..." example in man/*.1 and man/*.5.  Review the diff before
committing: the tests exist to catch changes nobody meant.

Usage: tests/update-golden.py PATH/TO/wrenchcone   (from the source top)"""
import re, shlex, subprocess, sys

prog = sys.argv[1]
golden = {
    'section4-na.txt': 'cone data/section4.wc na',
    'section4-na.json': 'cone --format=json data/section4.wc na',
    'section4-na.cdd': 'cone --format=cdd data/section4.wc na',
    'section4-na-paper-trace.txt': 'cone --method=paper --trace data/section4.wc na',
    'figure5-ln.json': 'cone --format=json data/disk-two-fixels.wc ln',
}
# tests/cli-draw.sh: the paper's figures.
golden.update({
    'draw-na.svg': 'draw --mode=na data/section4.wc',
    'draw-modes.svg': 'draw --modes data/disk-two-fixels.wc',
    'draw-strong.svg': 'draw --stability data/disk-two-fixels.wc',
    'draw-goal.svg': 'draw --plan data/disk-two-fixels-insert.wc',
    'draw-sweep.svg': 'draw --sweep=1/100,1/5,2/5,3/5 data/three-fixels-insert.wc',
    'draw-graph.svg': 'draw --graph data/three-fixels-insert.wc',
})
for name, args in golden.items():
    out = subprocess.run([prog] + args.split(), capture_output=True, check=True).stdout
    open('tests/golden/' + name, 'wb').write(out)

def unroff(s):
    return s.replace('\\-', '-').replace('\\&', '').replace('\\e', '\\').replace('\\(aq', "'")

def roff(s):
    s = s.replace('\\', '\\e').replace('-', '\\-')
    return '\\&' + s if s.startswith(('.', "'")) else s

for page in ('man/wrenchcone.1', 'man/wrenchcone.5'):
    lines = open(page).read().split('\n')
    out, i, in_ex = [], 0, False
    while i < len(lines):
        l = lines[i]
        out.append(l)
        i += 1
        if l.startswith('.EX'):
            in_ex = True
        elif l.startswith('.EE'):
            in_ex = False
        elif in_ex and l.startswith('$ wrenchcone'):
            cmd = unroff(l[2:])
            r = subprocess.run('wrenchcone() { "%s" "$@"; }; %s' % (prog, cmd),
                               shell=True, capture_output=True, text=True)
            start = i
            while i < len(lines) and not lines[i].startswith(('.EE', '$ ')):
                i += 1
            if i > start:       # an example shown without output stays so
                out.extend(roff(x) for x in r.stdout.rstrip('\n').split('\n'))
    open(page, 'w').write('\n'.join(out))
