# test_roundtrip.py -- the module returns the program's --format=json
# answer, shape kept: for every computing command (cone, modes, feasible,
# classify, stability, plan, compare) on the example problems of data/
# and a few corpus problems, the module's answer, each Fraction written
# back as its string, equals the program's JSON; every rational string
# outside the labels became a Fraction, and the labels (modes, states,
# strings) stayed strings.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

import glob
import itertools
import os
import re
from fractions import Fraction

import pytest

import wrenchcone as wc
from conftest import TOP, run, run_json

DATA = sorted(os.path.relpath(p, TOP)
              for p in glob.glob(os.path.join(TOP, "data", "*.wc")))
CORPUS = ["data/corpus/r1-s3.wc", "data/corpus/r2-s1-disk.wc",
          "data/corpus/r2-s2-degenerate.wc",
          "data/corpus/r3-s7-degenerate.wc"]
INSERT = [p for p in DATA if p.endswith("-insert.wc")]
RATIONAL = re.compile(r"-?[0-9]+(/[0-9]+)?\Z")
# label keys: their strings are names, never numbers (wc._LABELS)
LABELS = {"mode", "modes", "holding", "strings", "needed", "needed_exact",
          "string", "in", "state", "states", "from", "to", "via", "file",
          "problem"}


def back(v):
    """v with each Fraction written as the program writes a rational."""
    if isinstance(v, dict):
        return {k: back(x) for k, x in v.items()}
    if isinstance(v, list):
        return [back(x) for x in v]
    if isinstance(v, Fraction):
        return str(v)
    return v


def check_kinds(v, key=None, label=False):
    """No rational string left outside labels, no Fraction inside."""
    label = label or key in LABELS
    if isinstance(v, dict):
        for k, x in v.items():
            check_kinds(x, k, label)
    elif isinstance(v, list):
        for x in v:
            check_kinds(x, None, label)
    elif isinstance(v, Fraction):
        assert not label, "a Fraction under a label key"
    elif isinstance(v, str) and not label:
        assert not RATIONAL.match(v), "rational string %r left" % v


def same(py, cli):
    assert back(py) == cli
    check_kinds(py)


def all_modes(path):
    return run_json("modes", path)[0]["modes"]


@pytest.mark.parametrize("path", DATA + CORPUS)
def test_cones_modes_feasible(path):
    M, _ = run_json("modes", "--witness", path)
    same(wc.modes(path, witness=True), M)
    modes = M["modes"][:6]
    for mode in modes:
        J, _ = run_json("cone", path, mode)
        same(wc.request({"command": "cone", "problem": path, "mode": mode}),
             J)
        same(wc.cone(wc.Problem.read(path), mode), J["cone"])
    for mode in modes[:3]:
        same(wc.feasible(path, mode), run_json("feasible", path, mode)[0])
    # an infeasible mode: letters of the right kinds, not in the list
    for letters in itertools.product("lrns", repeat=M["fixels"]):
        mode = "".join(letters)
        try:
            C = wc.feasible(path, mode)
        except wc.InputError:  # a letter of the wrong kind
            continue
        assert C["feasible"] is (mode in M["modes"])
        if not C["feasible"]:
            same(C, run_json("feasible", path, mode)[0])
            break
    J, _ = run_json("cone", "--trace", "--method=paper", path, modes[0])
    same(wc.request({"command": "cone", "problem": path, "mode": modes[0],
                     "method": "paper", "trace": True}), J)


@pytest.mark.parametrize("path", DATA + CORPUS)
def test_classify(path):
    for g in (["0", "-1", "0"], ["1/3", "-2", "5/7"], ["0", "0", "0"]):
        J, _ = run_json("classify", path, *g)
        same(wc.classify(path, [Fraction(x) for x in g]), J)


@pytest.mark.parametrize("path", DATA)
def test_stability(path):
    same(wc.stability(path), run_json("stability", path)[0])


@pytest.mark.parametrize("path", INSERT)
def test_plan(path):
    P = wc.plan(path)
    same(P, run_json("plan", path)[0])
    assert all(isinstance(s["state"], str) for s in P["states"])
    same(wc.plan(path, complete=True), run_json("plan", "--complete", path)[0])
    same(wc.plan(path, wrench=[-1, -1, 0]),
         run_json("plan", path, "-1", "-1", "0")[0])


@pytest.mark.parametrize("path", ["data/section4.wc",
                                  "data/disk-two-fixels.wc"])
def test_compare(path, tmp_path):
    mode = all_modes(path)[2]
    status, ext, err = run("cone", "--method=paper", "--arith=double",
                           "--format=ext", path, mode)
    assert status == 0, err
    f = tmp_path / "foreign.ext"
    f.write_text(ext)
    J, st = run_json("compare", path, mode, str(f))
    assert st == 0
    same(wc.compare(path, mode, foreign=f), J)
    assert J["file"] == str(f)
    J["file"] = "<foreign_text>"
    same(wc.compare(path, mode, foreign_text=ext), J)
    # a cone that is not W(mode): a disagreement is an answer
    other = all_modes(path)[0]
    J, st = run_json("compare", "--tol=1e-6", path, other, str(f))
    assert st == 4
    same(wc.compare(path, other, foreign=str(f), tol=1e-6), J)
