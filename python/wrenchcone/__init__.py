# wrenchcone -- exact wrench cones from Python, over the shared library
# libwrenchcone through ctypes (standard library only).
#
# Copyright (C) 2026 the wrenchcone authors.
# This file is part of wrenchcone, free software under the GNU General
# Public License, version 2 or (at your option) any later version.

"""Exact wrench cones for planar rigid-body contact tasks.

Every function sends one request to the library's wc_request_json and
returns what the command prints with --format=json, as plain Python
values: objects as dicts, arrays as lists, the exact rationals (JSON
strings such as "-5" or "1/3") as fractions.Fraction, counts as int,
flags as bool, labels (modes, states, strings) as str, and the few
decimal approximations the output marks as such as float.

    >>> import wrenchcone as wc
    >>> from fractions import Fraction
    >>> W = wc.cone(wc.Problem.read("data/section4.wc"), "na")
    >>> W["rays"][0] == [Fraction(-1), Fraction(-5), Fraction(-1)]
    True

A bad problem, mode or number raises InputError, a bad request
UsageError, an internal failure InternalError; all are Error, which
carries the message, file, line and column the command line prints.

The library is found, in this order: the file named by the environment
variable WRENCHCONE_LIB; in the source tree, the build holding this
package (lib/.libs/ or _build/lib/.libs/ at the top of the tree), or,
installed, the installed library (make install writes its directory
below); then the system's search (ctypes.util.find_library).  The library is thread-safe,
and ctypes lets go of the interpreter lock during a call, so threads may
call the functions at once.  See doc/python.md.
"""

import ctypes
import ctypes.util
import inspect
import json
import math
import numbers
import os
import re
import threading
from fractions import Fraction

# The commands' functions (cone, modes, ..., report) are made from the
# library's schema when first used (__getattr__ below): each takes its
# command's operands in order, then its options as keywords.
__all__ = [
    "Problem", "Error", "InputError", "UsageError", "InternalError",
    "request", "request_json", "library_path", "exact", "schema",
]

# The installed library's directory; make install replaces this line
# (python/local.mk).  None in the source tree.
_INSTALLED_LIBDIR = None

_NAMES = ("libwrenchcone.so", "libwrenchcone.so.0", "libwrenchcone.dylib")


class Error(Exception):
    """A failed request: what the command line prints as
    "wrenchcone: FILE:LINE:COL: MESSAGE" and its exit status.

    file, line and column are None where the message has none (as the
    command line's "FILE: MESSAGE" and "MESSAGE")."""

    status = None

    def __init__(self, message, file=None, line=None, column=None,
                 status=None):
        self.message = message
        self.file = file
        self.line = line
        self.column = column
        if status is not None:
            self.status = status
        super().__init__(self.located())

    def __reduce__(self):
        # whole through pickle (multiprocessing)
        return (type(self), (self.message, self.file, self.line,
                             self.column, self.status))

    def located(self):
        """The diagnostic as the command line prints it after
        "wrenchcone: "."""
        if self.file is not None and self.line is not None:
            return "%s:%d:%d: %s" % (self.file, self.line,
                                     self.column or 0, self.message)
        if self.file is not None:
            return "%s: %s" % (self.file, self.message)
        return self.message


class InputError(Error):
    """Bad input: a problem file, a mode, a number (exit status 1)."""
    status = 1


class UsageError(Error):
    """A bad request: a missing, unknown or ill-typed key (status 2)."""
    status = 2


class InternalError(Error):
    """An internal, library or I/O failure (exit status 3)."""
    status = 3


_ERRORS = {1: InputError, 2: UsageError, 3: InternalError}


class _ErrorRecord(ctypes.Structure):
    # lib/core/error.h: wc_error_struct
    _fields_ = [("file", ctypes.c_char_p), ("line", ctypes.c_long),
                ("col", ctypes.c_long), ("message", ctypes.c_char_p)]


def _candidates():
    env = os.environ.get("WRENCHCONE_LIB")
    if env:
        yield env
        return
    if _INSTALLED_LIBDIR is None:
        # python/wrenchcone/ of a source tree: its build, in the tree or
        # in _build/
        top = os.path.dirname(os.path.dirname(os.path.dirname(
            os.path.abspath(__file__))))
        for build in (top, os.path.join(top, "_build")):
            for name in _NAMES:
                yield os.path.join(build, "lib", ".libs", name)
    else:
        for name in _NAMES:
            yield os.path.join(_INSTALLED_LIBDIR, name)
    found = ctypes.util.find_library("wrenchcone")
    if found:
        yield found


_lib = None
_lib_path = None
_lock = threading.Lock()


def _load():
    with _lock:
        return _load_locked()


def _load_locked():
    global _lib, _lib_path
    if _lib is not None:
        return _lib
    tried = []
    for path in _candidates():
        if os.sep in path and not os.path.exists(path):
            tried.append(path)
            continue
        try:
            lib = ctypes.CDLL(path)
        except OSError as e:
            tried.append("%s (%s)" % (path, e))
            continue
        _declare(lib)
        _lib, _lib_path = lib, path
        return lib
    raise InternalError(
        "cannot load libwrenchcone (tried: %s); set WRENCHCONE_LIB to the "
        "library file, such as _build/lib/.libs/libwrenchcone.so"
        % (", ".join(tried) or "nothing"))


def _declare(lib):
    rec = ctypes.POINTER(_ErrorRecord)
    lib.wc_error_init.argtypes = [rec]
    lib.wc_error_init.restype = None
    lib.wc_error_clear.argtypes = [rec]
    lib.wc_error_clear.restype = None
    lib.wc_request_json.argtypes = [
        ctypes.POINTER(ctypes.c_void_p), ctypes.POINTER(ctypes.c_size_t),
        ctypes.c_char_p, ctypes.c_size_t, rec]
    lib.wc_request_json.restype = ctypes.c_int
    lib.wc_request_free.argtypes = [ctypes.c_void_p]
    lib.wc_request_free.restype = None
    lib.wc_request_schema.argtypes = [
        ctypes.POINTER(ctypes.c_void_p), ctypes.POINTER(ctypes.c_size_t)]
    lib.wc_request_schema.restype = ctypes.c_int


def library_path():
    """The library file in use (loading it if need be)."""
    _load()
    return _lib_path


def request_json(text):
    """Send one request, a JSON object as text, to wc_request_json.

    Returns (status, answer): the exit status the command would have (0,
    or 4 for a comparison beyond its tolerance, or 1, 2, 3 with an error
    record as the answer) and the answer line without its newline."""
    lib = _load()
    # A lone surrogate goes as its bytes, which are not UTF-8: the
    # library refuses them with a located UsageError, as any bad byte.
    data = text.encode("utf-8", "surrogatepass")
    out = ctypes.c_void_p()
    outlen = ctypes.c_size_t()
    err = _ErrorRecord()
    lib.wc_error_init(ctypes.byref(err))
    try:
        status = lib.wc_request_json(ctypes.byref(out), ctypes.byref(outlen),
                                     data, len(data), ctypes.byref(err))
        if out.value is None:
            # out of memory: the error record alone
            raise InternalError((err.message or b"out of memory")
                                .decode("utf-8", "replace"))
        try:
            answer = ctypes.string_at(out.value, outlen.value)
        finally:
            lib.wc_request_free(out)
    finally:
        lib.wc_error_clear(ctypes.byref(err))
    return status, answer.decode("utf-8").rstrip("\n")


# Keys whose strings are labels, never numbers, at any depth below them:
# a state "10" or a problem named "7" stays a str.
_LABELS = frozenset((
    "mode", "modes", "holding", "strings", "needed", "needed_exact",
    "string", "in", "state", "states", "from", "to", "via", "verdict",
    "name", "note", "kind", "relation", "method", "file", "message",
    "reason", "summary", "type", "problem", "arith", "representation",
    "svg", "html", "problem_text",
))
_RATIONAL = re.compile(r"-?[0-9]+(/[0-9]+)?\Z")


def exact(value, key=None):
    """value (parsed JSON) with every exact rational string as a Fraction,
    except below the label keys; the shape is kept."""
    if key in _LABELS:
        return value
    if isinstance(value, dict):
        return {k: exact(v, k) for k, v in value.items()}
    if isinstance(value, list):
        return [exact(v) for v in value]
    if isinstance(value, str) and _RATIONAL.match(value):
        return Fraction(value)
    return value


def request(req):
    """Send the request dict req (as `wrenchcone batch` reads a line) and
    return the answer with exact values as Fraction (see exact).  A
    comparison beyond its tolerance is an answer, not an error."""
    status, answer = request_json(json.dumps(req))
    doc = json.loads(answer)
    if isinstance(doc, dict) and set(doc) - {"format"} == {"error"} and status != 0:
        e = doc["error"]
        raise _ERRORS.get(e.get("status", status), Error)(
            e.get("message"), e.get("file"), e.get("line"), e.get("column"),
            e.get("status", status))
    return exact(doc)


class Problem:
    """A problem: a regular file (read by the library at each call,
    relative to the working directory; a FIFO or a device is refused) or
    the text of one (named <problem_text> in messages).  wrenchcone(5)
    describes the format."""

    def __init__(self, path=None, text=None):
        if path is None and text is None:
            raise TypeError("Problem needs a path or a text")
        if path is not None and text is not None:
            raise TypeError("Problem takes a path or a text, not both")
        self.path = None if path is None else os.fspath(path)
        self.text = text

    @classmethod
    def read(cls, path):
        """The problem in the file path (str or os.PathLike)."""
        return cls(path=path)

    @classmethod
    def from_text(cls, text):
        """The problem written in the string text."""
        return cls(text=text)

    def _keys(self):
        if self.path is not None:
            return {"problem": self.path}
        return {"problem_text": self.text}

    def __repr__(self):
        if self.path is not None:
            return "Problem.read(%r)" % (self.path,)
        return "Problem.from_text(%r)" % (self.text,)


def _problem(problem):
    if isinstance(problem, Problem):
        return problem._keys()
    if isinstance(problem, (str, os.PathLike)):
        return {"problem": os.fspath(problem)}
    raise TypeError("a problem is a Problem or a path, not %s"
                    % type(problem).__name__)


def _number(x):
    """x as the request's exact number text: int, Fraction and other
    rationals exactly; a float by its exact binary value; a str as
    written (such as "-1/5" or "0.25")."""
    if isinstance(x, str):
        return x
    if isinstance(x, bool):
        raise TypeError("a number, not a bool")
    if isinstance(x, numbers.Integral):
        return str(int(x))
    if isinstance(x, numbers.Rational):
        return "%d/%d" % (x.numerator, x.denominator)
    if isinstance(x, numbers.Real):
        if not math.isfinite(x):
            # "nan", "inf", "-inf": refused by the library as the command
            # line refuses them (InputError, bad number)
            return repr(float(x))
        f = Fraction(float(x))
        return "%d/%d" % (f.numerator, f.denominator)
    raise TypeError("not a number: %r" % (x,))


def _wrench(g):
    return [_number(x) for x in g]


def _number_tol(tol):
    # the tolerance is an angle read with strtod: a decimal
    return tol if isinstance(tol, str) else repr(float(tol))


def _numbers(v):
    # a list of exact numbers, as the command line writes it: A,B,...
    if isinstance(v, str):
        return v
    return ",".join(_number(x) for x in v)


# A value of each kind of the schema (wrenchcone --schema) as the
# request's JSON value.
_CONVERT = {
    "flag": bool,
    "choice": str,
    "count": int,
    "seed": int,
    "number": _number,
    "numbers": _numbers,
    "wrench": _wrench,
    "angle": _number_tol,
    "string": str,
}

# What a function returns of its command's answer, when not the whole
# answer: cone's cone, random's problem, draw's SVG and report's HTML.
_RESULTS = {
    "cone": lambda d: d["cone"],
    "random": lambda d: Problem.from_text(d["problem_text"]),
    "draw": lambda d: d["svg"],
    "report": lambda d: d["html"],
}

_schema_doc = None


def schema():
    """The commands as the library describes them (wrenchcone --schema):
    {"commands": [{"name", "summary", "about", "request", "certificate",
    "operands": [...], "options": [...]}]}, each operand and option with
    its key, kind, metavar, default and help."""
    global _schema_doc
    if _schema_doc is None:
        lib = _load()
        out = ctypes.c_void_p()
        outlen = ctypes.c_size_t()
        if lib.wc_request_schema(ctypes.byref(out),
                                 ctypes.byref(outlen)) != 0:
            raise InternalError("out of memory")
        try:
            text = ctypes.string_at(out.value, outlen.value)
        finally:
            lib.wc_request_free(out)
        _schema_doc = json.loads(text.decode("utf-8"))
    return _schema_doc


def _doc(c):
    lines = [c["summary"].replace("\n", " ") + ".", "", c["about"], ""]
    args = [a for a in c["operands"] + c["options"] if a["request"]]
    if args:
        lines.append("Arguments (the request's keys; None leaves one out):")
    for a in args:
        text = a["key"]
        if a["kind"] == "input":
            text += " (a path; or %s_text, the text itself%s)" % (
                a["key"], "; or a Problem" if a["key"] == "problem" else "")
        if a.get("values"):
            text += ": " + " | ".join(a["values"])
        if a.get("default") is not None:
            text += " (default %s)" % a["default"]
        lines.append("  " + text)
        if a.get("help"):
            lines.extend("      " + h for h in a["help"].split("\n"))
    if c["certificate"]:
        lines.append("  certificate: True adds the certificate document, "
                     "for wrenchcone verify")
    return "\n".join(lines)


def _make(c):
    """The function of command c (its schema): operands in order, then
    the options as keywords."""
    params, kinds = [], {}
    # An input may be given as KEY_text instead, so it may be left out,
    # and the operands after it with it (compare(mode="na",
    # problem_text=T, foreign=F)): from the first input on, every operand
    # defaults to None and command() says which required one is missing.
    may = False
    for a in c["operands"]:
        may = may or a["optional"] or a["kind"] == "input"
        params.append(inspect.Parameter(
            a["key"], inspect.Parameter.POSITIONAL_OR_KEYWORD,
            default=None if may else inspect.Parameter.empty))
        kinds[a["key"]] = a["kind"]
    extra = [a["key"] + "_text" for a in c["operands"] + c["options"]
             if a["kind"] == "input"]
    for a in c["options"]:
        if a["request"]:
            kinds[a["key"]] = a["kind"]
    names = [k for k in kinds if k not in {p.name for p in params}]
    names += extra + (["certificate"] if c["certificate"] else [])
    for k in names:
        params.append(inspect.Parameter(
            k, inspect.Parameter.KEYWORD_ONLY, default=None))
    sig = inspect.Signature(params)
    name = c["name"]

    def command(*args, **kwargs):
        bound = sig.bind(*args, **kwargs)
        req = {"command": name}
        for key, value in bound.arguments.items():
            if value is None or value is False:
                continue
            if key == "problem" and isinstance(value, Problem):
                req.update(value._keys())
            elif kinds.get(key) == "input":
                req[key] = os.fspath(value)
            elif key in kinds:
                req[key] = _CONVERT[kinds[key]](value)
            else:       # KEY_text, certificate
                req[key] = value
        for a in c["operands"]:
            key = a["key"]
            if a["kind"] != "input":
                if not a["optional"] and bound.arguments.get(key) is None:
                    raise TypeError("%s() missing a required argument: %r"
                                    % (name, key))
            elif key in req and key + "_text" in req:
                raise TypeError("%s takes %s or %s_text, not both"
                                % (name, key, key))
            elif not a["optional"] and key not in req \
                    and key + "_text" not in req:
                raise TypeError("%s needs %s or %s_text"
                                % (name, key, key))
        answer = request(req)
        return _RESULTS.get(name, lambda d: d)(answer)

    command.__name__ = command.__qualname__ = name
    command.__signature__ = sig
    command.__doc__ = _doc(c)
    return command


# The commands' functions, made from the schema when first asked for.
_COMMANDS = {}


def __getattr__(name):
    if name.startswith("_"):
        raise AttributeError(name)
    for c in schema()["commands"]:
        if c["name"] == name and c["request"]:
            if name not in _COMMANDS:
                _COMMANDS[name] = _make(c)
            return _COMMANDS[name]
    raise AttributeError("module 'wrenchcone' has no attribute %r" % name)


def __dir__():
    try:
        names = [c["name"] for c in schema()["commands"] if c["request"]]
    except Error:
        names = []
    return sorted(set(globals()) | set(names))
