"""Fuzz kind "malformed input": the bundled example programs of every reading dialect, damaged (a hostile
character put in, a span cut out, a line doubled or swapped, the file cut short, a number made huge or
empty, brackets nested deep, a very long line, CR or NUL bytes, a byte-order mark), then read by every
path a user has: ``translate`` (to another dialect and to the same), ``toolpath`` and ``info``.

Each must finish (within ``make fuzz``'s time limit per case) either with a result or with errors that
each name FILE:LINE:COL on a line of the file; a traceback (any other exception) is a defect. A translation
to another dialect must meet that controller's rules (grbl, grblHAL, LinuxCNC by ``rs274``).
"""

from __future__ import annotations

import contextlib
import io
import json
from pathlib import Path

from hypothesis import strategies as st

from postproc.api import translate
from postproc.commands.info import program_info, render_text
from postproc.errors import Diagnostics, ErrorList, PostprocError
from postproc.simulate.toolpath import toolpath_events

from ..fuzzing import READERS
from ..output_rules import problems
from ..tools import with_tools
from . import Case

KIND = "malformed input"
EXAMPLES = Path(__file__).resolve().parents[3] / "examples"
_FOLDERS = {"fagor": ["fagor"], "fanuc": ["fanuc", "fanuc-lathe"], "gsk": ["gsk"], "isg": ["isg"],
            "linuxcnc": ["linuxcnc"], "grbl": ["linuxcnc"], "grblhal": ["linuxcnc"], "mach3": ["linuxcnc"],
            "siemens": ["siemens"]}
"""Where each reader's seeds come from (grbl, grblHAL and Mach3 read RS274/NGC too: LinuxCNC's examples)."""
HOSTILE = list("[]()#=*/;%<>\"'$@:?{}!&|^~\\,.-+eE0123456789GMNOPXYZIJKRFSTHDLQ \t") + [
    "\x00", "\r", "\ufeff", "é", "\u2212", "\x1a", "\x7f", "\u00a0"]
NUMBERS = ["1e999", "9" * 400, "-0", ".", "-.", "+", "1.2.3", "0x10", "1e-400", "-9" * 30, "nan", "inf", "[1/0]",
           "[SQRT[-1]]", "#0", "#99999999", "[" * 80 + "1" + "]" * 80]


def seeds(dialect: str) -> list[str]:
    return sorted(str(p) for folder in _FOLDERS[dialect] for p in (EXAMPLES / folder).glob("*")
                  if p.suffix in (".nc", ".ngc", ".mpf"))


@st.composite
def damaged(draw: st.DrawFn, dialect: str) -> str:
    text = Path(draw(st.sampled_from(seeds(dialect)))).read_text(encoding="utf-8")
    for _ in range(draw(st.integers(1, 4))):
        kind = draw(st.sampled_from(["insert", "insert", "cut", "double", "swap", "truncate", "number",
                                     "nest", "long", "endings"]))
        at = draw(st.integers(0, max(0, len(text) - 1)))
        lines = text.splitlines(keepends=True)
        if kind == "insert":
            text = text[:at] + draw(st.text(st.sampled_from(HOSTILE), min_size=1, max_size=4)) + text[at:]
        elif kind == "cut":
            text = text[:at] + text[at + draw(st.integers(1, 40)):]
        elif kind in ("double", "swap") and lines:
            i = draw(st.integers(0, len(lines) - 1))
            j = draw(st.integers(0, len(lines) - 1))
            if kind == "double":
                lines.insert(i, lines[j])
            else:
                lines[i], lines[j] = lines[j], lines[i]
            text = "".join(lines)
        elif kind == "truncate":
            text = text[:at]
        elif kind == "number":
            digits = [i for i, c in enumerate(text) if c.isdigit() and i > 0 and text[i - 1].isalpha()]
            if digits:
                i = draw(st.sampled_from(digits))
                end = i
                while end < len(text) and (text[end].isdigit() or text[end] == "."):
                    end += 1
                text = text[:i] + draw(st.sampled_from(NUMBERS)) + text[end:]
        elif kind == "nest":
            text = text[:at] + "X" + "[" * draw(st.sampled_from([50, 500, 5000])) + text[at:]
        elif kind == "long":
            text = text[:at] + draw(st.sampled_from(["X1", "(", "G1", "#1=", "N"])) * 20000 + text[at:]
        else:
            text = text.replace("\n", draw(st.sampled_from(["\r", "\r\n", "\n\n", "\x00\n"])))
    return text


def located_errors(errs: ErrorList, text: str) -> None:
    lines = max(1, len(text.splitlines()) + 1)
    for err in errs.errors:
        loc = err.location
        assert loc is not None and loc.line >= 1 and loc.col >= 1, f"an error without a place: {err}"
        assert loc.line <= lines, f"an error on line {loc.line} of a {lines - 1}-line file: {err}"


def check(dialect: str, target: str, text: str) -> str:
    setup = with_tools()
    refused = False
    with contextlib.redirect_stderr(io.StringIO()):
        for run in ("translate", "toolpath", "info"):
            try:
                if run == "translate":
                    out = io.StringIO()
                    translate(io.StringIO(text, newline=""), out, file="bad.nc", source=dialect,
                              target=target, setup=setup, diagnostics=Diagnostics(warn_stream=io.StringIO()))
                    if dialect != target:  # (a program copied to its own dialect is the input itself)
                        bad = problems(target, out.getvalue(), setup, source=dialect)
                        assert not bad, f"the {target} controller refuses the output: {'; '.join(bad)}\n{out.getvalue()}"
                elif run == "toolpath":
                    for _ in toolpath_events(io.StringIO(text, newline=""), file="bad.nc", dialect=dialect,
                                             setup=setup, diagnostics=Diagnostics(warn_stream=io.StringIO())):
                        pass
                else:
                    report = program_info(io.StringIO(text, newline=""), file="bad.nc", dialect=dialect,
                                          setup=setup)
                    json.dumps(report, allow_nan=False)
                    render_text(report, io.StringIO())
            except ErrorList as errs:
                located_errors(errs, text)
                refused = True
            except PostprocError as err:
                located_errors(ErrorList([err]), text)
                refused = True
    return "refused" if refused else "ok"


def _case(dialect: str, target: str, text: str) -> Case:
    return Case(f"malformed {dialect}", target, text, lambda p: check(dialect, target, p), f"to {target}")


@st.composite
def _cases(draw: st.DrawFn) -> Case:
    dialect = draw(st.sampled_from(READERS))
    target = draw(st.sampled_from([dialect, "linuxcnc", "fanuc", "grbl"]))
    return _case(dialect, target, draw(damaged(dialect)))


def cases() -> st.SearchStrategy[Case]:
    return _cases()
