# test_errors.py -- a failed request raises the Error subclass of its exit
# status, carrying the file, line, column and message that the program
# prints as "wrenchcone: FILE:LINE:COL: MESSAGE" for the same input: every
# bad problem file of tests/bad (as a file and as inline text), a bad
# mode, a bad wrench, a missing file, files that are not regular (a
# FIFO, a device, a directory), and bad requests.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

import glob
import os
import pickle
import re
import signal

import pytest

import wrenchcone as wc
from conftest import TOP, run

# tests/bad/modes.wc is a good problem, for bad modes
BAD = sorted(os.path.relpath(p, TOP)
             for p in glob.glob(os.path.join(TOP, "tests", "bad", "*.wc"))
             if not p.endswith("/modes.wc"))
CLASSES = {1: wc.InputError, 2: wc.UsageError, 3: wc.InternalError}


def diagnostic(err):
    """(file, line, column, message) of the program's first stderr line."""
    line = err.splitlines()[0]
    assert line.startswith("wrenchcone: ")
    line = line[len("wrenchcone: "):]
    m = re.match(r"([^ :]+):([0-9]+):([0-9]+): (.*)\Z", line)
    if m:
        return m.group(1), int(m.group(2)), int(m.group(3)), m.group(4)
    m = re.match(r"([^ ]+): (.*)\Z", line)
    if m:
        return m.group(1), None, None, m.group(2)
    return None, None, None, line


def same_as_program(e, args):
    status, out, err = run(*args)
    assert status in CLASSES and out == ""
    assert type(e) is CLASSES[status] and e.status == status
    assert (e.file, e.line, e.column, e.message) == diagnostic(err)
    assert "wrenchcone: " + str(e) == err.splitlines()[0]


def test_bad_files_exist():
    assert len(BAD) >= 10


@pytest.mark.parametrize("path", BAD)
def test_bad_problem_file(path):
    with pytest.raises(wc.Error) as info:
        wc.modes(wc.Problem.read(path))
    same_as_program(info.value, ["modes", path])
    assert info.value.file == path and info.value.line >= 1


@pytest.mark.parametrize("path", BAD)
def test_bad_problem_text(path):
    with open(path) as f:
        text = f.read()
    with pytest.raises(wc.InputError) as info:
        wc.cone(wc.Problem.from_text(text), "nn")
    e = info.value
    status, out, err = run("modes", path)
    f, line, col, msg = diagnostic(err)
    assert (e.file, e.line, e.column) == ("<problem_text>", line, col)
    # the message names the file where the program's does
    assert e.message == msg.replace(path, "<problem_text>")


def test_bad_mode():
    with pytest.raises(wc.InputError) as info:
        wc.cone("data/section4.wc", "nx")
    same_as_program(info.value, ["cone", "data/section4.wc", "nx"])


def test_bad_wrench():
    with pytest.raises(wc.InputError) as info:
        wc.classify("data/section4.wc", ["1/0", 0, 0])
    same_as_program(info.value,
                    ["classify", "data/section4.wc", "1/0", "0", "0"])


def test_missing_file():
    with pytest.raises(wc.InputError) as info:
        wc.modes("data/no-such-problem.wc")
    same_as_program(info.value, ["modes", "data/no-such-problem.wc"])
    assert info.value.line is None


def test_not_regular_files(tmp_path):
    # A request reads regular files only: a FIFO nobody writes is refused
    # at once (the alarm fails the test instead of hanging it), and so
    # are a device without end and a directory.
    fifo = tmp_path / "fifo"
    os.mkfifo(fifo)
    signal.alarm(20)
    try:
        for path, why in ((str(fifo), "not a regular file (a request "
                           "reads regular files only)"),
                          ("/dev/zero", "not a regular file (a request "
                           "reads regular files only)"),
                          (str(tmp_path), "read error: Is a directory")):
            with pytest.raises(wc.InputError) as info:
                wc.modes(path)
            assert (info.value.file, info.value.line, info.value.message) \
                == (path, None, why)
    finally:
        signal.alarm(0)


def test_bad_requests():
    with pytest.raises(wc.UsageError) as info:
        wc.request({"command": "cone", "problem": "data/section4.wc",
                    "mode": "na", "colour": "red"})
    e = info.value
    assert (e.file, e.line, e.status) == ("<request>", 1, 2)
    assert e.message == "\"colour\" is not a key of a cone request"
    assert e.column > 1
    with pytest.raises(wc.UsageError) as info:
        wc.request({"command": "cone", "problem": "data/section4.wc",
                    "mode": "na", "arith": "double"})
    assert "needs \"method\": \"paper\"" in info.value.message
    status, answer = wc.request_json("[1, 2")
    assert status == 2 and answer.startswith(
        '{"format": "wrenchcone-json/1", "error": ')
    with pytest.raises(TypeError):
        wc.Problem(path="a.wc", text="mass 1")
    with pytest.raises(TypeError):
        wc.classify("data/section4.wc", [True, 0, 0])


def test_errors_are_exceptions():
    assert issubclass(wc.InputError, wc.Error)
    assert issubclass(wc.Error, Exception)
    e = wc.InputError("bad", "f.wc", 3, 7)
    assert str(e) == "f.wc:3:7: bad" and e.status == 1
    c = pickle.loads(pickle.dumps(e))
    assert type(c) is wc.InputError
    assert (c.message, c.file, c.line, c.column, c.status, str(c)) \
        == ("bad", "f.wc", 3, 7, 1, str(e))
    assert str(wc.Error("m", "f.wc")) == "f.wc: m"
    assert str(wc.Error("m")) == "m"


def test_non_ascii_text():
    with open("data/section4.wc") as f:
        text = "# caf\u00e9 \u2713\n" + f.read()
    assert wc.cone(wc.Problem.from_text(text), "na")["rays"][0] == [-1, -5, -1]
    with pytest.raises(wc.InputError) as info:
        wc.modes(wc.Problem.from_text("# caf\u00e9\nmass -1\n"))
    assert (info.value.line, info.value.column) == (2, 6)
