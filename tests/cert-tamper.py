#!/usr/bin/env python3
"""cert-tamper.py -- systematic tampering with the certificates that
wrenchcone writes, run by tests/cert-tamper.sh.

Usage: cert-tamper.py WRENCHCONE DATA_DIR TMP_DIR

For each kind of certificate (mode-feasibility, strong-stability,
stability-set, plan-goal, critical-friction) the certificates are written by the program for the files
of DATA_DIR; then, one at a time, one leaf or one array or one key of one
certificate is changed, the JSON written again and `wrenchcone verify` run
on it.  The program is started a few times only: the certificates are
written, and the changed ones verified, by `wrenchcone batch` (verify
requests answer as `wrenchcone verify` exits: "holds" true or false, or
an error record); the first few changes of each kind also go through
`wrenchcone verify` itself, which must agree and print as wrenchcone(1)
says.  The changes, by what they touch:

  a rational (a "p/q" string or a JSON integer): +1, negate, 0, times 2;
  a boolean: flipped;
  a string: one letter changed (a sign or mode string: one of s/l/r/n
    swapped for another), and for the strings with a few valid values
    (state, relation, kind, covers) another valid value;
  an array: one element dropped, duplicated, or two unequal ones swapped;
  an object: one key dropped.

A field class is the JSON path with array indices written [*].  The
mutations are sampled class by class (every class and change is tried
before any is tried twice), seeded by WC_TEST_SEED (default 20021212),
their number scaled by WC_TEST_MULTIPLIER.

verify must exit 4 (caught: does not hold), 1 (caught: malformed, one
located message) or 0 (survived); anything else fails at once.  A
survivor fails the test when its class must always be caught (MUST below)
or when its claim is false: a survivor that changed the claim (the
problem, the mode, the wrench, the verdicts, the claimed set) is judged
by the program itself, which computes the claim again for the changed
problem; it is harmless only when the program agrees.

Prints a table per kind on stdout; on failure, the mutation and the
seed.  Standard library only."""

import json
import os
import random
import re
import subprocess
import sys
import time
from fractions import Fraction

RATIONAL = re.compile(r'^-?[0-9]+(/[0-9]+)?$')
ENUMS = {
    'state': ['touching', 'near'],
    'relation': ['>', '>=', '='],
    'kind': ['mode-feasibility', 'strong-stability', 'stability-set',
             'plan-goal', 'critical-friction'],
}
SIGN_KEYS = ('sign', 'mode')
BUDGET = {'mode-feasibility': 80, 'strong-stability': 80,
          'stability-set': 110, 'plan-goal': 24, 'critical-friction': 10}

# (class pattern, changes or None for all, how a survivor is judged):
# 'never' -- it must always be caught; 'claim' -- harmless only when the
# program computes the same claim for the changed certificate.
PROBLEM = (r'^problem(\.|$)', None, 'claim')
MUST = {
    'mode-feasibility': [
        PROBLEM,
        (r'^(mode|feasible)$', None, 'claim'),
        # without kind a certificate is read as mode-feasibility
        (r'^kind$', ('letter', 'enum'), 'never'),
        (r'^constraints($|\[)', None, 'never'),
    ],
    'strong-stability': [
        PROBLEM,
        (r'^(wrench|wrench\[\*\]|weakly_stable|strongly_stable)$', None,
         'claim'),
        (r'^kind$', None, 'never'),
        (r'^faces$', ('drop', 'dup'), 'never'),
        (r'^faces\[\*\]\.(sign|rotation)$', None, 'never'),
    ],
    'stability-set': [
        PROBLEM,
        (r'^strong(\.empty|\.interior|\.pieces(\[\*\]\.(empty|dim|rays.*'
         r'|lines.*|faces.*))?)?$', None, 'claim'),
        (r'^kind$', None, 'never'),
        (r'^covers', None, 'never'),
        (r'^moving_faces$', ('drop', 'dup'), 'never'),
        (r'^moving_faces\[\*\]\.(sign|rotation)$', None, 'never'),
        (r'^tree$', ('drop', 'dup'), 'never'),
        (r'^tree\[\*\]\.in$', None, 'never'),
    ],
    'plan-goal': [
        PROBLEM,
        (r'^goal(\.empty|\.interior|\.pieces(\[\*\]\.(empty|dim|rays.*'
         r'|lines.*|faces.*))?)?$', None, 'claim'),
        (r'^kind$', None, 'never'),
        (r'^covers', None, 'never'),
        (r'^strings$', ('drop', 'dup'), 'never'),
        (r'^strings\[\*\]\.string$', None, 'never'),
        (r'^tree$', ('drop', 'dup'), 'never'),
        (r'^tree\[\*\]\.in$', None, 'never'),
    ],
    'critical-friction': [
        (r'^kind$', None, 'never'),
        (r'^(lo|hi|found|empty_at_zero)$', None, 'never'),
        (r'^lower\.strings$', ('drop', 'dup'), 'never'),
        (r'^upper\.(kind|covers|goal.*)$', None, 'never'),
        (r'^upper\.problem\.(mass|inertia|com|fixels\[\*\]\.(point|normal|mu_s|mu_k))', None,
         'never'),
        (r'^upper\.tree$', ('drop', 'dup'), 'never'),
    ],
}


class Failure(Exception):
    pass


def must_rule(kind, cls, op):
    for pat, ops, how in MUST[kind]:
        if re.search(pat, cls) and (ops is None or op in ops):
            return how
    return None


def run(argv, path=None):
    try:
        p = subprocess.run(argv + ([path] if path else []),
                           capture_output=True, timeout=120)
    except subprocess.TimeoutExpired:
        return None, b'', b'timeout'
    return p.returncode, p.stdout, p.stderr


def batch(W, requests, tmp):
    """The answers of `wrenchcone batch` to the requests (dicts), as
    parsed JSON objects, one per request."""
    path = os.path.join(tmp, 'requests.jsonl')
    with open(path, 'w') as f:
        for r in requests:
            f.write(json.dumps(r) + '\n')
    rc, o, e = run([W, 'batch', path])
    lines = o.decode().splitlines()
    if rc is None or len(lines) != len(requests):
        raise Failure('batch of %d requests: exit %s, %d answers: %s'
                      % (len(requests), rc, len(lines),
                         e.decode(errors='replace')))
    return [json.loads(x) for x in lines]


# ---------------------------------------------------------------------
# Writing the certificates.

def all_modes(states):
    modes = ['']
    for s in states:
        modes = [m + c for m in modes for c in ('slrn' if s == 'touching'
                                                 else 'sa')]
    return modes


def gen_certs(W, data, tmp, rng):
    """The certificates of each kind: {kind: [(name, text)]}."""
    files = sorted(f for f in os.listdir(data) if f.endswith('.wc'))
    out = {'mode-feasibility': [], 'strong-stability': [],
           'stability-set': [], 'plan-goal': [], 'critical-friction': []}
    probs = [(f[:-3], os.path.join(data, f)) for f in files]
    # Figure 5 with kinetic friction 1/2: weakly but not strongly stable
    # wrenches (wrenchcone-certificate(5)).
    src = open(os.path.join(data, 'disk-two-fixels.wc')).read()
    mk = os.path.join(tmp, 'disk-two-fixels-mu-k.wc')
    open(mk, 'w').write(src.replace('friction 1\n', 'friction 1 1/2\n'))
    probs.append(('disk-two-fixels-mu-k', mk))
    # The certificates come in batch answers, under "certificate".
    def written(requests):
        for r in requests:
            r['certificate'] = True
        got = batch(W, requests, tmp)
        for r, a in zip(requests, got):
            if 'certificate' not in a:
                raise Failure('%s: no certificate: %s'
                              % (json.dumps(r), json.dumps(a)))
        return [a['certificate'] for a in got]

    sets = written([{'command': 'stability', 'problem': f}
                    for name, f in probs])
    modes = batch(W, [{'command': 'modes', 'problem': f}
                      for name, f in probs], tmp)
    named, requests = [], []
    for (name, f), d, m in zip(probs, sets, modes):
        out['stability-set'].append((name, json.dumps(d)))
        states = [x['state'] for x in d['problem']['fixels']]
        feasible = m['modes']
        infeasible = [x for x in all_modes(states) if x not in feasible]
        picked = rng.sample(feasible, min(2, len(feasible))) \
            + rng.sample(infeasible, min(2, len(infeasible)))
        for x in picked:
            named.append(('mode-feasibility', '%s %s' % (name, x)))
            requests.append({'command': 'feasible', 'problem': f,
                             'mode': x})
        wrenches = [('-1', '-1', '-1'), ('0', '-1', '0'), ('0', '1', '0')]
        wrenches.append(tuple(str(rng.randint(-3, 3)) for _ in range(3)))
        for g in wrenches:
            named.append(('strong-stability', '%s %s' % (name, ' '.join(g))))
            requests.append({'command': 'classify', 'problem': f,
                             'wrench': list(g)})
    # the sets of a plan, on the two smallest problems
    for name in ('disk-two-fixels', 'disk-two-fixels-insert'):
        named.append(('plan-goal', name))
        requests.append({'command': 'plan',
                         'problem': os.path.join(data, name + '.wc')})
    named.append(('critical-friction', 'disk-two-fixels-insert'))
    requests.append({'command': 'sweep', 'critical': True, 'width': '1/4',
                     'problem': os.path.join(data,
                                             'disk-two-fixels-insert.wc')})
    for (kind, name), d in zip(named, written(requests)):
        out[kind].append((name, json.dumps(d)))

    # Each certificate holds, and the command line writes the same one.
    every = [(k, n, t) for k in out for n, t in out[k]]
    paths = []
    for i, (k, n, t) in enumerate(every):
        paths.append(os.path.join(tmp, 'cert-%d.json' % i))
        open(paths[-1], 'w').write(t)
    for (k, n, t), a in zip(every, batch(W, [{'command': 'verify',
                                             'certfile': x}
                                            for x in paths], tmp)):
        if a.get('holds') is not True:
            raise Failure('%s certificate of %s does not verify: %s'
                          % (k, n, json.dumps(a)))
    cert = os.path.join(tmp, 'cert.json')
    f = probs[0][1]
    for argv, text in ((['stability', f], out['stability-set'][0][1]),
                       (['plan', os.path.join(data, 'disk-two-fixels.wc')],
                        out['plan-goal'][0][1])):
        rc, o, e = run([W, argv[0], '--certificate=' + cert] + argv[1:])
        if rc != 0 or json.load(open(cert)) != json.loads(text):
            raise Failure('%s --certificate: exit %s, or another certificate'
                          ' than the request\'s' % (' '.join(argv), rc))
    verdicts = set()
    for name, text in out['strong-stability']:
        d = json.loads(text)
        verdicts.add((d['weakly_stable'], d['strongly_stable']))
    if len(verdicts) != 3:
        raise Failure('the strong-stability certificates cover only %s'
                      % sorted(verdicts))
    if sorted(set(json.loads(t)['feasible'] for n, t in
                  out['mode-feasibility'])) != [False, True]:
        raise Failure('the mode-feasibility certificates lack a verdict')
    return out


# ---------------------------------------------------------------------
# The changes.

def is_rational(v):
    return (isinstance(v, str) and RATIONAL.match(v) is not None) or \
        (isinstance(v, int) and not isinstance(v, bool))


def enumerate_units(node, path, cls, units, key=None):
    """Every (class, change) applicable in node, with its path: units is
    {(class, change): [path]}."""
    def add(c, op, p):
        units.setdefault((c, op), []).append(p)

    if isinstance(node, dict):
        for k, v in node.items():
            ck = cls + '.' + k if cls else k
            add(ck, 'delete', path + (k,))
            enumerate_units(v, path + (k,), ck, units, k)
    elif isinstance(node, list):
        if node:
            add(cls, 'drop', path)
            add(cls, 'dup', path)
        if any(x != node[0] for x in node):
            add(cls, 'swap', path)
        for i, v in enumerate(node):
            enumerate_units(v, path + (i,), cls + '[*]', units, key)
    elif isinstance(node, bool):
        add(cls, 'flip', path)
    elif is_rational(node):
        zero = Fraction(node) == 0
        for op in ('+1', 'negate', 'zero', 'x2'):
            if op == '+1' or not zero:
                add(cls, op, path)
    elif isinstance(node, str):
        add(cls, 'letter', path)
        if key in ENUMS or cls.startswith('covers'):
            add(cls, 'enum', path)


def get(doc, path):
    for p in path:
        doc = doc[p]
    return doc


def new_rational(v, op):
    q = Fraction(v)
    q = {'+1': q + 1, 'negate': -q, 'zero': Fraction(0), 'x2': 2 * q}[op]
    if isinstance(v, int):
        return int(q)
    return str(q)


def new_string(v, op, key, cls, rng):
    if op == 'enum':
        vals = ENUMS.get(key, ['strong', 'weak', 'both'])
        return rng.choice([x for x in vals if x != v])
    if not v:
        return 'x'
    i = rng.randrange(len(v))
    if key in SIGN_KEYS:
        pool = {'a': 's', 'u': 'slrn'}.get(v[i], 'slrn')
    else:
        pool = 'abcdefghijklmnopqrstuvwxyz'
    pool = [c for c in pool if c != v[i]]
    return v[:i] + rng.choice(pool) + v[i + 1:]


def mutate(doc, path, op, rng):
    """Apply the change in place; returns its description, or None when it
    would change nothing."""
    parent = get(doc, path[:-1]) if path else None
    last = path[-1] if path else None
    where = ''.join('[%d]' % p if isinstance(p, int) else '.' + p
                    for p in path).lstrip('.')
    if op == 'delete':
        del parent[last]
        return 'delete %s' % where
    node = get(doc, path)
    if op in ('drop', 'dup', 'swap'):
        i = rng.randrange(len(node))
        if op == 'drop':
            del node[i]
            return 'drop %s[%d]' % (where, i)
        if op == 'dup':
            node.insert(i + 1, json.loads(json.dumps(node[i])))
            return 'duplicate %s[%d]' % (where, i)
        j = rng.randrange(len(node))
        if node[i] == node[j]:
            return None
        node[i], node[j] = node[j], node[i]
        return 'swap %s[%d] and [%d]' % (where, min(i, j), max(i, j))
    if op == 'flip':
        new = not node
    elif op in ('+1', 'negate', 'zero', 'x2'):
        new = new_rational(node, op)
        if Fraction(new) == Fraction(node):
            return None
    else:
        key = last if isinstance(last, str) else \
            next((p for p in reversed(path) if isinstance(p, str)), None)
        new = new_string(node, op, key, where, rng)
    parent[last] = new
    return '%s %s: %s -> %s' % (op, where, json.dumps(node), json.dumps(new))


# ---------------------------------------------------------------------
# Judging a survivor: the claim computed again by the program.

def dedup(doc):
    """The problem without the exact copies of a fixel (a .wc file cannot
    hold two, and a copy changes no claim: the forces of two copies add up
    to forces of one), and the mode without their letters; False when the
    copies have different letters."""
    fx = doc['problem']['fixels']
    mode = doc.get('mode')
    keep = []
    for i, f in enumerate(fx):
        j = next((j for j in keep if fx[j] == f), None)
        if j is None:
            keep.append(i)
        elif isinstance(mode, str) and len(mode) == len(fx) and \
                mode[i] != mode[j]:
            return False
    doc['problem']['fixels'] = [fx[i] for i in keep]
    if isinstance(mode, str) and len(mode) == len(fx):
        doc['mode'] = ''.join(mode[i] for i in keep)
    return True


def write_problem(pr, path):
    """The certificate's problem as a .wc file; False when it has no such
    file (a key missing, a value of the wrong type)."""
    try:
        lines = []
        for k in ('mass', 'inertia'):
            if k in pr:
                lines.append('%s %s' % (k, str(Fraction(pr[k]))))
        lines.append('com %s %s' % tuple(str(Fraction(x))
                                         for x in pr['com']))
        if len(pr['com']) != 2:
            return False
        for f in pr['fixels']:
            if len(f['point']) != 2 or len(f['normal']) != 2 or \
                    f['state'] not in ('touching', 'near'):
                return False
            s = 'fixel %s %s normal %s %s %s' % (
                tuple(str(Fraction(x)) for x in f['point'] + f['normal'])
                + (f['state'],))
            if 'mu_s' in f:
                s += ' friction %s %s' % (Fraction(f['mu_s']),
                                          Fraction(f['mu_k']))
            lines.append(s)
    except (KeyError, TypeError, ValueError, ZeroDivisionError):
        return False
    open(path, 'w').write('\n'.join(lines) + '\n')
    return True


def rref(rows):
    rows = [list(r) for r in rows]
    out, col = [], 0
    while rows and col < 3:
        piv = next((r for r in rows if r[col] != 0), None)
        if piv is None:
            col += 1
            continue
        rows.remove(piv)
        piv = [x / piv[col] for x in piv]
        out = [[a - r[col] * b for a, b in zip(r, piv)] for r in out]
        rows = [[a - r[col] * b for a, b in zip(r, piv)] for r in rows]
        out.append(piv)
        col += 1
    return tuple(sorted(tuple(r) for r in out))


def direction(v):
    m = max(abs(x) for x in v)
    return tuple(x / m for x in v) if m else tuple(v)


def canonical_set(strong):
    """The claimed set as the set of its included relatively open faces,
    each as (the span of the lines, the directions of its rays)."""
    faces = set()
    for pc in strong['pieces']:
        lines = rref([[Fraction(x) for x in l] for l in pc['lines']])
        rays = [[Fraction(x) for x in r] for r in pc['rays']]
        for f in pc['faces']:
            if f['included']:
                faces.add((lines, frozenset(direction(rays[i])
                                            for i in f['rays'])))
    return (strong['empty'], strong['interior'], frozenset(faces))


def claim_holds(W, kind, doc, tmp):
    """Whether the program finds the changed certificate's claim true:
    True, or a string saying why not."""
    wc = os.path.join(tmp, 'oracle.wc')
    try:
        doc = json.loads(json.dumps(doc))
        if not dedup(doc):
            return 'copies of one fixel with different letters'
        if not write_problem(doc['problem'], wc):
            return 'its problem is not a problem'
        if kind == 'mode-feasibility':
            rc, o, e = run([W, 'feasible', '--format=json', wc,
                            str(doc['mode'])])
            if rc != 0:
                return 'feasible: exit %s: %s' % (rc, e.decode().strip())
            if json.loads(o)['feasible'] != doc['feasible']:
                return 'the program says feasible is %s' % \
                    json.dumps(json.loads(o)['feasible'])
            return True
        if kind == 'strong-stability':
            rc, o, e = run([W, 'classify', '--format=json', wc, '--']
                           + [str(Fraction(x)) for x in doc['wrench']])
            if rc != 0:
                return 'classify: exit %s: %s' % (rc, e.decode().strip())
            d = json.loads(o)
            for k in ('weakly_stable', 'strongly_stable'):
                if d[k] != doc[k]:
                    return 'the program says %s is %s' % (k, json.dumps(d[k]))
            return True
        cert = os.path.join(tmp, 'oracle.json')
        cmd, key = ('plan', 'goal') if kind == 'plan-goal' \
            else ('stability', 'strong')
        rc, o, e = run([W, cmd, '--certificate=' + cert, wc])
        if rc != 0:
            return '%s: exit %s: %s' % (cmd, rc, e.decode().strip())
        if canonical_set(json.load(open(cert))[key]) != \
                canonical_set(doc[key]):
            return 'the program finds another set'
        return True
    except (KeyError, TypeError, ValueError, IndexError,
            AttributeError) as x:
        return 'its claim cannot be read (%s)' % x


# ---------------------------------------------------------------------
# The run.

def verify(W, path):
    """`wrenchcone verify PATH`: its status, after checking that it
    printed what wrenchcone(1) says for that status."""
    rc, o, e = run([W, 'verify'], path)
    o, e = o.decode(errors='replace'), e.decode(errors='replace')
    good = {0: o.startswith('certificate holds: ') and not e,
            4: o.startswith('certificate does not hold: ') and not e,
            1: not o and re.match(r'^wrenchcone: [^\n]*:[0-9]+:[0-9]+: '
                                  r'[^\n]+\n$', e) is not None}
    if rc not in good:
        raise Failure('verify exited %s\n  stdout: %s\n  stderr: %s'
                      % (rc, o.strip(), e.strip()))
    if not good[rc]:
        raise Failure('verify exited %s with stdout %r and stderr %r'
                      % (rc, o, e))
    return rc


def answer_status(a):
    """The status `wrenchcone verify` exits with, from its batch answer."""
    if a.get('holds') is True:
        return 0
    if a.get('holds') is False:
        return 4
    err = a.get('error', {})
    if err.get('status') == 1 and err.get('line') is not None:
        return 1
    raise Failure('verify answered %s' % json.dumps(a))


# Changes of each kind that also go through `wrenchcone verify`.
CLI_SAMPLE = 4


def tamper_kind(kind, certs, rng, budget):
    """The changed certificates: [(what, doc, cls, op)]."""
    units = {}
    parsed = [json.loads(t) for n, t in certs]
    for c, d in enumerate(parsed):
        u = {}
        enumerate_units(d, (), '', u)
        for k, paths in u.items():
            units.setdefault(k, []).extend((c, p) for p in paths)
    keys = sorted(units)
    rng.shuffle(keys)
    # a class that must be caught gets two turns in each round
    order = keys + [k for k in keys if must_rule(kind, *k)]
    changed = []
    misses = 0
    while len(changed) < budget and misses < 1000:
        cls, op = order[(len(changed) + misses) % len(order)]
        c, p = rng.choice(units[(cls, op)])
        doc = json.loads(certs[c][1])
        what = mutate(doc, p, op, rng)
        if what is None:
            misses += 1
            continue
        what = '%s certificate of %s: %s' % (kind, certs[c][0], what)
        changed.append((what, doc, cls, op))
    return changed


def judge(W, kind, changed, tmp, stats):
    """Verify every changed certificate (one batch; the first few also
    by the command line) and judge the survivors."""
    paths = []
    for i, (what, doc, cls, op) in enumerate(changed):
        paths.append(os.path.join(tmp, 'tampered-%d.json' % i))
        open(paths[-1], 'w').write(json.dumps(doc))
    answers = batch(W, [{'command': 'verify', 'certfile': x}
                        for x in paths], tmp)
    for i, ((what, doc, cls, op), a) in enumerate(zip(changed, answers)):
        try:
            rc = answer_status(a)
            if i < CLI_SAMPLE and verify(W, paths[i]) != rc:
                raise Failure('verify exits otherwise than its batch '
                              'answer %s' % json.dumps(a))
        except Failure as x:
            raise Failure('%s\n  %s' % (what, x))
        row = stats.setdefault((kind, cls), {0: 0, 1: 0, 4: 0,
                                             'survivors': []})
        row[rc] += 1
        if rc != 0:
            continue
        rule = must_rule(kind, cls, op)
        verdict = None
        if rule == 'never':
            verdict = 'FAIL: this class must always be caught'
        elif rule == 'claim':
            holds = claim_holds(W, kind, doc, tmp)
            verdict = 'harmless: the program agrees with the changed claim' \
                if holds is True else 'FAIL: %s' % holds
        row['survivors'].append((what, verdict))


def report(stats, kinds, elapsed):
    bad = []
    for kind in kinds:
        rows = {c: r for (k, c), r in stats.items() if k == kind}
        tot = {x: sum(r[x] for r in rows.values()) for x in (0, 1, 4)}
        print('%s: %d mutations, %d caught (4), %d malformed (1), '
              '%d survived (0)' % (kind, sum(tot.values()), tot[4], tot[1],
                                   tot[0]))
        for cls in sorted(rows):
            r = rows[cls]
            if not r['survivors']:
                continue
            n = r[0] + r[1] + r[4]
            print('  %-44s survived %d/%d' % (cls, r[0], n))
            shown = set()
            for what, verdict in r['survivors']:
                if verdict and verdict.startswith('FAIL'):
                    bad.append('%s\n    %s' % (what, verdict))
                key = verdict or ''
                if key not in shown:
                    shown.add(key)
                    print('      e.g. %s%s' % (what.split(': ', 1)[1],
                                               '\n        ' + verdict
                                               if verdict else ''))
    print('%.1f s' % elapsed)
    return bad


def main():
    W, data, tmp = sys.argv[1:4]
    seed = int(os.environ.get('WC_TEST_SEED', '20021212'))
    mult = int(os.environ.get('WC_TEST_MULTIPLIER', '1'))
    rng = random.Random(seed)
    start = time.time()
    stats = {}
    try:
        certs = gen_certs(W, data, tmp, rng)
        for kind in certs:
            judge(W, kind, tamper_kind(kind, certs[kind], rng,
                                       BUDGET[kind] * mult), tmp, stats)
    except Failure as x:
        print('FAIL: %s' % x)
        print('replay with: WC_TEST_SEED=%d WC_TEST_MULTIPLIER=%d'
              % (seed, mult))
        return 1
    bad = report(stats, list(certs), time.time() - start)
    if bad:
        print('FAIL: %d survivor(s) that must have been caught:' % len(bad))
        for b in bad:
            print('  ' + b)
        print('replay with: WC_TEST_SEED=%d WC_TEST_MULTIPLIER=%d'
              % (seed, mult))
        return 1
    return 0


if __name__ == '__main__':
    sys.exit(main())
