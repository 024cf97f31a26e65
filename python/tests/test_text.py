# test_text.py -- what the module does with text it cannot send as it
# is, and the input the library echoes back: a token cut inside a
# character is cut before it (an InputError, never UnicodeDecodeError);
# control characters come back quoted, the message one line; a NaN or
# infinite float is refused by the library as the command line refuses
# "nan" (an Error, not ValueError or OverflowError); a lone surrogate is
# a located UsageError, not UnicodeEncodeError; a missing or doubled
# input says which.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

import json
import math

import pytest

import wrenchcone as wc
from conftest import run

P = "data/section4.wc"
DISAGREE = ("V-representation\nbegin\n1 4 rational\n0 1 0 -1\nend\n")


def test_token_cut_before_a_character():
    # 1 + 2 * 40 bytes: the first 64 end inside the 32nd character
    with pytest.raises(wc.InputError) as info:
        wc.classify(P, ["a" + "\u00e9" * 40, 0, 0])
    e = info.value
    assert e.message == "bad number 'a" + "\u00e9" * 31 + "...'"
    assert (e.file, e.line, e.column) == ("<wrench>", 1, 1)


def test_control_characters_quoted():
    with pytest.raises(wc.UsageError) as info:
        wc.request({"command": "a\nb\u2028"})
    assert info.value.message.startswith(
        "unknown command 'a\\x0ab\\u2028' (cone, ")
    assert "\n" not in str(info.value)
    with pytest.raises(wc.UsageError) as info:
        wc.request({"command": "modes", "problem": P, "k\x01": 1})
    assert info.value.message == '"k\\x01" is not a key of a modes request'


@pytest.mark.parametrize("x,text", [(math.nan, "nan"), (math.inf, "inf"),
                                    (-math.inf, "-inf")])
def test_non_finite_wrench(x, text):
    with pytest.raises(wc.InputError) as info:
        wc.classify(P, [0, x, 0])
    assert info.value.message == "bad number '%s'" % text
    assert (info.value.file, info.value.line) == ("<wrench>", 1)
    # the command line's words for the same number
    status, out, err = run("classify", P, "0", text, "0") \
        if text != "-inf" else run("classify", P, "--", "0", text, "0")
    assert status == 1
    assert err.rstrip("\n").endswith("bad number '%s'" % text)


@pytest.mark.parametrize("tol", [math.nan, math.inf])
def test_non_finite_tolerance(tol):
    with pytest.raises(wc.UsageError) as info:
        wc.compare(P, "sa", foreign_text=DISAGREE, tol=tol)
    assert "\"tol\" must be an angle" in info.value.message


def test_lone_surrogate():
    # as text: the bytes go as they are, and the library locates them
    status, answer = wc.request_json('{"command": "x\ud800"}')
    assert status == 2
    assert json.loads(answer)["error"] == {
        "message": "invalid UTF-8 in string", "file": "<request>",
        "line": 1, "column": 15, "status": 2}
    status, answer = wc.request_json('{"command": "modes"}\udc80')
    assert status == 2
    assert json.loads(answer)["error"]["message"] \
        == "unexpected '\\xed' after the JSON value"
    # in a value: JSON's own escape, which the library refuses
    with pytest.raises(wc.UsageError) as info:
        wc.cone(wc.Problem.from_text("name \"\ud800\"\n"), "na")
    assert info.value.message == "unpaired surrogate '\\ud800'"


def test_inputs_missing_or_doubled():
    with pytest.raises(TypeError, match=r"^compare needs foreign or "
                       r"foreign_text$"):
        wc.compare(P, "sa")
    with pytest.raises(TypeError, match=r"^compare takes foreign or "
                       r"foreign_text, not both$"):
        wc.compare(P, "sa", "x.ine", foreign_text=DISAGREE)
    with pytest.raises(TypeError, match=r"^cone needs problem or "
                       r"problem_text$"):
        wc.cone(mode="na")
    with pytest.raises(TypeError, match=r"^Problem needs a path or a text$"):
        wc.Problem()
    with pytest.raises(TypeError, match=r"^Problem takes a path or a text, "
                       r"not both$"):
        wc.Problem(path="a.wc", text="mass 1")
    with pytest.raises(TypeError, match=r"missing a required argument: "
                       r"'mode'"):
        wc.compare(P, foreign_text=DISAGREE)


def test_problem_text_by_keyword():
    # the problem as text, the later operands by keyword
    with open(P) as f:
        text = f.read()
    r = wc.compare(problem_text=text, mode="sa", foreign_text=DISAGREE)
    assert r["within_tolerance"] is False
