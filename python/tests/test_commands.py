# test_commands.py -- a function per command, made from the library's
# schema: each answers what its command line prints with --format=json
# (for draw and report, what -o writes).
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

import inspect
import json
import os
import tempfile

import pytest

import wrenchcone as wc
from conftest import run, run_json

S4 = "data/section4.wc"
T3 = "data/three-fixels.wc"


def test_a_function_for_every_request_command():
    names = [c["name"] for c in wc.schema()["commands"] if c["request"]]
    assert names == ["cone", "modes", "feasible", "classify", "stability",
                     "plan", "sweep", "verify", "compare", "random", "draw",
                     "report"]
    for name in names:
        f = getattr(wc, name)
        assert callable(f) and f.__name__ == name
        assert name in dir(wc)
    with pytest.raises(AttributeError):
        wc.batch


def test_signatures_follow_the_schema():
    sig = inspect.signature(wc.classify)
    assert list(sig.parameters)[:2] == ["problem", "wrench"]
    assert "max_modes" in sig.parameters and "certificate" in sig.parameters
    assert "max_modes" in wc.classify.__doc__
    assert "bias" in inspect.signature(wc.stability).parameters
    assert "certificate" not in inspect.signature(wc.modes).parameters


CASES = [
    ("cone", (S4, "na"), {"method": "paper"}, ["cone", "--method=paper", S4, "na"]),
    ("modes", (T3,), {"witness": True}, ["modes", "--witness", T3]),
    ("feasible", (S4, "na"), {}, ["feasible", S4, "na"]),
    ("classify", (S4, [0, -1, 0]), {"max_modes": 3},
     ["classify", "--max-modes=3", S4, "0", "-1", "0"]),
    ("stability", (S4,), {"bias": [0, -1, 0], "length": "1/2"},
     ["stability", "--bias=0,-1,0", "--length=1/2", S4]),
    ("plan", (T3, [0, -1, 0]), {"complete": True},
     ["plan", "--complete", T3, "0", "-1", "0"]),
    ("sweep", (T3,), {"friction": ["0", "1/10"], "critical": True},
     ["sweep", "--friction=0,1/10", "--critical", T3]),
    ("compare", (S4, "na", "tests/golden/section4-na.json"), {"tol": 1e-6},
     ["compare", "--tol=1e-06", S4, "na", "tests/golden/section4-na.json"]),
    ("random", (), {"seed": 9, "fixels": 4, "shape": "disk"},
     ["random", "--seed=9", "--fixels=4", "--shape=disk"]),
]


@pytest.mark.parametrize("name,args,kwargs,argv", CASES,
                         ids=[c[0] for c in CASES])
def test_each_function_answers_as_the_command_line(name, args, kwargs, argv):
    got = wc.request_json(json.dumps(_request(name, args, kwargs)))
    want, status = run_json(*argv)
    assert got[0] == status
    assert json.loads(got[1]) == want


def _request(name, args, kwargs):
    # what the function sends: read back from its own call
    sent = {}
    real = wc.request

    def spy(req):
        sent.update(req)
        return real(req)
    wc.request = spy
    try:
        getattr(wc, name)(*args, **kwargs)
    finally:
        wc.request = real
    return sent


def test_cone_random_draw_report_return_their_documents():
    assert wc.cone(S4, "na") == wc.request(
        {"command": "cone", "problem": S4, "mode": "na"})["cone"]
    p = wc.random(seed=2, fixels=3)
    assert isinstance(p, wc.Problem) and p.text.startswith("# wrenchcone random")
    assert wc.modes(p)["modes"] == wc.modes(wc.Problem.from_text(p.text))["modes"]
    with tempfile.TemporaryDirectory() as d:
        for name, argv, kwargs in (
                ("draw", ["draw", "--plan", T3], {"plan": True}),
                ("report", ["report", S4], {})):
            out = os.path.join(d, name)
            status, _, err = run(*(argv + ["-o", out]))
            assert status == 0, err
            doc = getattr(wc, name)(argv[-1], **kwargs)
            with open(out, encoding="utf-8") as f:
                assert doc == f.read()


def test_verify_and_certificates():
    # the certificate in the answer, its exact values written back as
    # strings, is what verify checks
    for name, args in (("classify", (S4, [0, -1, 0])), ("plan", (T3,))):
        ans = getattr(wc, name)(*args, certificate=True)
        text = json.dumps(ans["certificate"], default=str)
        assert wc.verify(certfile_text=text)["holds"] is True
    with pytest.raises(TypeError):
        wc.verify()
    with pytest.raises(wc.UsageError):
        wc.request({"command": "modes", "problem": S4, "certificate": True})
