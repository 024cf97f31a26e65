# conftest.py -- what the tests of the Python module share: the top of
# the source tree as the working directory (the problems are named
# data/NAME, as a user of the tree names them), the program under test
# for comparisons, and the seed of the randomized tests.
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.
#
# tests/python.sh runs them inside make check, with top_srcdir,
# WRENCHCONE (the program) and WRENCHCONE_LIB (the library built with
# it) in the environment; by hand, from the top of a tree built in
# place or in _build/:  PYTHONPATH=python python3 -m pytest python/tests

import json
import os
import subprocess

import pytest

TOP = os.environ.get("top_srcdir") or os.path.dirname(
    os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def _program():
    if os.environ.get("WRENCHCONE"):
        return os.environ["WRENCHCONE"]
    for p in ("src/wrenchcone", "_build/src/wrenchcone"):
        if os.path.exists(os.path.join(TOP, p)):
            return os.path.join(TOP, p)
    raise RuntimeError("set WRENCHCONE to the program under test")


PROGRAM = _program()
SEED = int(os.environ.get("WC_TEST_SEED", "20021212"))
MULTIPLIER = max(1, int(os.environ.get("WC_TEST_MULTIPLIER", "1")))


@pytest.fixture(autouse=True)
def at_top(monkeypatch):
    monkeypatch.chdir(TOP)


def run(*args):
    """The program's (status, stdout, stderr) for args, from the top."""
    p = subprocess.run([PROGRAM] + list(args), cwd=TOP,
                       stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       universal_newlines=True)
    return p.returncode, p.stdout, p.stderr


def run_json(*args):
    """The program's --format=json answer to args, parsed (plain JSON:
    numbers still strings), and its exit status."""
    status, out, err = run(args[0], "--format=json", *args[1:])
    assert status in (0, 4), "%s: status %d: %s" % (args, status, err)
    return json.loads(out), status
