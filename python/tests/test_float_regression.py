# test_float_regression.py -- how to regression-check a floating-point
# implementation against the exact cones: the use our users named.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.
#
# float_member below stands for "your" floating-point code: it decides
# whether a wrench g is in the wrench cone of a mode by writing g in the
# basis of the cone's three generators (Cramer's rule in plain floats,
# and numpy's solver too when numpy is importable) and accepting non-negative coefficients
# up to a tolerance.  The exact reference is the cone the library
# computes: g is in the closure when h . g <= 0 for every facet h, and in
# the cone itself when the smallest face of the closure holding g is one
# the cone includes (the faces list says which).  On seeded random
# wrenches the two must agree wherever g is off the boundary; on the
# boundary (some h . g == 0, decided exactly) floats cannot decide, and
# the test shows what the float code gets wrong there: it accepts the
# apex and the friction-cone edges, which the exact cone excludes.
# WC_TEST_SEED sets the seed, WC_TEST_MULTIPLIER widens the run; a
# failure prints the seed and the wrench.

import random
from fractions import Fraction

import pytest

import wrenchcone as wc
from conftest import MULTIPLIER, SEED

try:
    import numpy
except ImportError:  # plain floats then
    numpy = None


IMPLS = ["plain"] + (["numpy"] if numpy is not None else [])


def float_member(rays, g, eps=1e-12, impl="plain"):
    """The floating-point code under test: g in cone(rays), rays three
    independent 3-vectors of floats."""
    if impl == "numpy":
        lam = numpy.linalg.solve(numpy.array(rays, dtype=float).T,
                                 numpy.array(g, dtype=float))
        return bool((lam >= -eps).all())
    a = [[rays[j][i] for j in range(3)] for i in range(3)]  # columns: rays

    def det(m):
        return (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]))
    d = det(a)
    for j in range(3):
        m = [row[:] for row in a]
        for i in range(3):
            m[i][j] = g[i]
        if det(m) / d < -eps:
            return False
    return True


def dot(u, v):
    return sum(x * y for x, y in zip(u, v))


def exact_member(W, g):
    """(in the cone, on the boundary of the closure): exact, from W."""
    if W["empty"]:
        return False, False
    hs = W["inequalities"]
    if any(dot(h, g) > 0 for h in hs):
        return False, False
    tight = [h for h in hs if dot(h, g) == 0]
    # the smallest face holding g: the rays on every facet tight at g
    face = [i for i, r in enumerate(W["rays"])
            if all(dot(h, r) == 0 for h in tight)]
    included = {tuple(f["rays"]): f["included"] for f in W["faces"]}
    return included[tuple(face)], bool(tight)


def random_wrench(rng, rays):
    """Mostly uniform small rationals; sometimes a point on a face of the
    closure (a non-negative combination of a subset of the rays)."""
    if rng.random() < 0.3:
        sub = [r for r in rays if rng.random() < 0.5]
        return [sum((Fraction(rng.randint(0, 3)) * r[i] for r in sub),
                    Fraction(0)) for i in range(3)]
    return [Fraction(rng.randint(-60, 60), rng.randint(1, 12))
            for _ in range(3)]


@pytest.mark.parametrize("impl", IMPLS)
@pytest.mark.parametrize("path,mode", [
    ("data/section4.wc", "na"), ("data/section4.wc", "la"),
    ("data/section4.wc", "ns"), ("data/disk-two-fixels.wc", "ns")])
def test_float_membership_against_exact(path, mode, impl):
    W = wc.cone(wc.Problem.read(path), mode)
    if W["empty"] or W["dim"] != 3 or len(W["rays"]) != 3:
        pytest.skip("the float code handles simplicial cones only")
    rays = [[float(x) for x in r] for r in W["rays"]]
    rng = random.Random("%d %s %s" % (SEED, path, mode))
    inner = boundary = 0
    for k in range(400 * MULTIPLIER):
        g = random_wrench(rng, W["rays"])
        inside, on_boundary = exact_member(W, g)
        got = float_member(rays, [float(x) for x in g], impl=impl)
        where = "seed %d, %s %s (%s), wrench %d %s" % (
            SEED, path, mode, impl, k, [str(x) for x in g])
        if on_boundary:
            boundary += 1
            # floats cannot tell strictness: the closure is all they see
            assert got, "closure point rejected: " + where
        else:
            inner += 1
            assert got == inside, "float and exact disagree: " + where
    assert inner > 0 and boundary > 0


@pytest.mark.parametrize("impl", IMPLS)
def test_float_code_misses_strictness(impl):
    # Section 4: W(na) excludes the apex and the friction edges r0, r1,
    # and the float code accepts them; the exact cone says so.
    W = wc.cone("data/section4.wc", "na")
    rays = [[float(x) for x in r] for r in W["rays"]]
    for g, inside in (([0, 0, 0], False), (W["rays"][0], False),
                      (W["rays"][1], False), (W["rays"][2], True),
                      ([a + b for a, b in zip(W["rays"][0], W["rays"][2])],
                       True)):
        assert exact_member(W, [Fraction(x) for x in g])[0] is inside
        assert float_member(rays, [float(x) for x in g], impl=impl) is True
    # classify agrees with the cone: the apex is held by W(ns), not W(na)
    assert "na" not in wc.classify("data/section4.wc", [0, 0, 0])["modes"]
