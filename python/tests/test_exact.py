# test_exact.py -- the module's answers are the exact values: the paper's
# Section 4 cone, the modes of its Figure 5 disk, a feasibility
# certificate and a classification, checked against the values the
# program prints (README, wrenchcone(1)), every rational a Fraction.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

from fractions import Fraction

import pytest

import wrenchcone as wc

F = Fraction


def vecs(rows):
    return [[F(x) for x in r] for r in rows]


def test_readme_example():
    # exactly as the issue and the README write it
    W = wc.cone(wc.Problem.read("data/section4.wc"), "na")
    assert W["rays"][0] == [Fraction(-1), Fraction(-5), Fraction(-1)]


SECTION4_NA = {
    "empty": False, "dim": 3, "lineality_dim": 0,
    "inequalities": vecs([[-5, 2, -5], [-1, 0, 1], [5, 2, 5]]),
    "equalities": [],
    "rays": vecs([[-1, -5, -1], [1, -5, 1], [1, 0, -1]]),
    "lines": [],
    "faces": [
        {"dim": 0, "rays": [], "included": False},
        {"dim": 1, "rays": [0], "included": False},
        {"dim": 1, "rays": [1], "included": False},
        {"dim": 1, "rays": [2], "included": True},
        {"dim": 2, "rays": [0, 1], "included": False},
        {"dim": 2, "rays": [0, 2], "included": True},
        {"dim": 2, "rays": [1, 2], "included": True},
        {"dim": 3, "rays": [0, 1, 2], "included": True},
    ],
}


def test_section4_cone():
    W = wc.cone(wc.Problem.read("data/section4.wc"), "na")
    assert W == SECTION4_NA
    for v in W["rays"] + W["inequalities"]:
        assert all(type(x) is Fraction for x in v)
    assert type(W["dim"]) is int and type(W["empty"]) is bool
    # face indices stay indices
    assert all(type(i) is int for f in W["faces"] for i in f["rays"])


def test_section4_both_routes_and_inline_text():
    with open("data/section4.wc") as f:
        text = f.read()
    assert wc.cone(wc.Problem.from_text(text), "na") == SECTION4_NA
    assert wc.cone("data/section4.wc", "na", method="paper") == SECTION4_NA
    # the paper's route in doubles is the closure's approximation
    D = wc.cone("data/section4.wc", "na", method="paper", arith="double")
    assert D["dim"] == 3 and D["arith"] == "double"
    assert all(type(x) in (int, float) for r in D["rays"] for x in r)
    assert D["strict_rays"] == [True, True, False]


def test_section4_trace():
    # the trace is beside the cone: the whole answer by request
    T = wc.request({"command": "cone", "problem": "data/section4.wc",
                    "mode": "na", "trace": True})
    assert T["method"] == "direct" and T["mode"] == "na"
    assert T["cone"] == SECTION4_NA
    assert T["trace"][0]["name"] == "J"
    assert T["trace"][0]["matrix"] == vecs([[0, -1, -1, 0], [1, 0, 0, -1],
                                            [0, 0, -1, -1]])
    for step in T["trace"]:
        assert isinstance(step["name"], str)
        assert len(step["matrix"]) == step["rows"]
        assert all(type(x) is Fraction for row in step["matrix"] for x in row)


def test_section4_modes():
    M = wc.modes(wc.Problem.read("data/section4.wc"))
    assert M == {"format": "wrenchcone-json/1", "fixels": 2, "count": 8,
                 "modes": ["la", "ls", "na", "ns", "ra", "rs", "sa", "ss"]}


FIGURE5_MODES = ["ll", "ls", "nn", "ns", "rr", "rs", "sl", "sn", "sr", "ss"]


def test_figure5_modes():
    M = wc.modes(wc.Problem.read("data/disk-two-fixels.wc"))
    assert M == {"format": "wrenchcone-json/1", "fixels": 2,
                 "modes": FIGURE5_MODES, "count": 10}


def test_figure5_witnesses():
    M = wc.modes("data/disk-two-fixels.wc", witness=True)
    assert M["modes"] == FIGURE5_MODES
    assert len(M["witnesses"]) == 10
    for w in M["witnesses"]:
        assert len(w) == 3 and all(type(x) is Fraction for x in w)
    # ss: the disk lifts off both fixels; nn: it does not move
    assert M["witnesses"][FIGURE5_MODES.index("nn")] == [0, 0, 0]
    assert M["witnesses"][FIGURE5_MODES.index("ss")] != [0, 0, 0]


def test_figure5_cones():
    # W(nn) of the disk on two fixels: the wrenches the fixels can hold
    W = wc.cone("data/disk-two-fixels.wc", "nn")
    assert not W["empty"] and W["dim"] >= 1
    # an infeasible mode's cone is empty, not an error
    assert wc.cone("data/disk-two-fixels.wc", "ln") == {"empty": True}


def test_figure5_infeasible_certificate():
    C = wc.feasible("data/disk-two-fixels.wc", "ln")
    assert C["kind"] == "mode-feasibility" and C["mode"] == "ln"
    assert C["feasible"] is False
    assert C["multipliers"] == [F(-1), F(1), F(-1), F(-1)]
    assert [c["row"] for c in C["constraints"]] == vecs(
        [[0, 1, 0], [-1, 0, -1], [-1, 0, 0], [0, -1, -1]])
    assert [c["relation"] for c in C["constraints"]] == ["=", ">", "=", "="]
    # Motzkin: sum of y_k row_k is 0
    rows = [c["row"] for c in C["constraints"]]
    y = C["multipliers"]
    assert [sum(y[k] * rows[k][i] for k in range(4)) for i in range(3)] \
        == [0, 0, 0]


@pytest.mark.parametrize("wrench", [
    [0, -1, 0], ["0", "-1", "0"], [F(0), F(-1), F(0)], [0.0, -1.0, 0.0],
    (0, "-2/2", 0)])
def test_figure5_classify(wrench):
    C = wc.classify("data/disk-two-fixels.wc", wrench)
    assert C["wrench"] == [0, -1, 0]
    assert C["modes"] == ["nn", "ns"]
    assert C["weakly_stable"] is True and C["strongly_stable"] is True
    assert C["strongly_stable_paper"] is False
    assert C["static_c"] == [F(1), F(0), F(0), F(0)]
    assert C["paper_witness"] == {"mode": "ns", "nudot": [0, 0, 0],
                                  "c": [1, 0, 0, 0]}


def test_rationals_are_fractions():
    # a float argument is its exact binary value: 0.1 is not 1/10
    C = wc.classify("data/disk-two-fixels.wc", [0, 0.1, 0])
    assert C["wrench"] == [0, F(0.1), 0] and C["wrench"][1] != F(1, 10)
    C = wc.classify("data/disk-two-fixels.wc", [F(1, 3), -1, 0])
    assert C["wrench"] == [F(1, 3), -1, 0]
