"""LinuxCNC's Fanuc-style subprograms (``O<n>`` ... ``M99``, ``M98 P L``), checked against rs274.

Every program here is also run by the packaged ``rs274`` (when installed): the ones it runs must give
our moves; the ones it refuses must be refused here too, with a pinned located error. The facts (and
rs274's own messages) are in ``postproc_linuxcnc.calls`` and ``postproc.interp.rules``.
"""

from __future__ import annotations

import io
import math
from pathlib import Path
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import RS274Error, available, canonical_moves, run_rs274

ROOT = Path(__file__).resolve().parents[1]
TOLERANCE_MM = 2e-4
needs_rs274 = pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")


def _ours(text: str, dialect: str = "linuxcnc", file: str = "t.ngc") -> list[dict[str, Any]]:
    return [e for e in toolpath_events(io.StringIO(text, newline=""), file=file, dialect=dialect) if "move" in e]


def _theirs(text: str) -> list[dict[str, Any]]:
    return [e for e in canonical_moves(run_rs274(text), start=(0.0, 0.0, 0.0)) if "move" in e]


def _same(ours: list[dict[str, Any]], theirs: list[dict[str, Any]]) -> None:
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in rs274"
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"], (n, a, b)
        dev = math.dist((a["x"], a["y"], a["z"]), (b["x"], b["y"], b["z"]))
        assert dev <= TOLERANCE_MM, (n, a, b)


RUNS = {
    "repeat": "G21 G90\nM98 P1 L2\nM30\nO1\nG91 G0 X1\nM99\n",
    "blanks": "G21 G90\nM 9 8 P 1 L 2\nM30\nO 1\nG91 G0 X1\nM 99\n",
    "lower case and zeros": "G21 G90\nM98 P0001\nM30\no0001 (name)\nG91 G0 X1\nm99 (back)\n",
    "zero repeats of a missing program": "G21 G90\nM98 P7 L0\nG0 X2\nM30\n",
    "nested": "G21 G90\nM98 P1 L2\nM30\nO1\nG91 G0 X1\nM98 P2 L2\nM99\nO2\nG0 Y1\nM99\n",
    "shared #1": "G21 G90\n#1=0\nM98 P1 L3\nG0 Y#1\nM30\nO1\n#1=[#1+1]\nG0 X#1\nM99\n",
    "computed P and L": "G21 G90\n#5=3\nM98 P#5 L[1+1]\nM30\nO3\nG91 G0 X1\nM99\n",
    "first line is the name": "O1 (name)\nG21 G90\nM98 P1\nM30\nO1\nG0 X1\nM99\n",
    "an O line in the flow does nothing": "G21 G90\nG0 X1\nO1\nG0 Y1\nG0 Z1\nM30\n",
    "the body runs past the next O": "G21 G90\nM98 P1\nM30\nO1\nG0 X1\nO2\nG0 Y1\nM99\n",
    "found once, found again from later": (
        "G21 G90\nM98 P1\nM98 P2\nM30\nO1\nG91 G0 X1\nM99\nO2\nG0 Y2\nM98 P1\nM99\n"),
    "the first O after the call wins": "G21 G90\nM98 P1\nM30\nO1\nG0 X1\nM99\nO1\nG0 Y1\nM99\n",
    "M99 in the main program ends it": "G21 G90\nG0 X1\nM99\nG0 Y5\nM30\n",
    "M30 in a subprogram ends the program": "G21 G90\nM98 P1\nG0 Z1\nM30\nO1\nG0 X1\nM30\n",
    "no packed P form": "G21 G90\nM98 P00032100\nM30\nO2100\nG0 Y1\nM99\nO32100\nG0 X3\nM99\n",
    "an o-word call from the subprogram": (
        "G21 G90\nM98 P1\nM30\nO1\nG0 Y1\no2 call\nM99\no2 sub\nG0 X4\no2 endsub\n"),
    "endsub and return set #<_value>": (
        "G21 G90\no100 sub\no100 endsub [#1*2+1]\no101 sub\no101 return [7]\no101 endsub\n"
        "o100 call [2]\nG0 X#<_value>\no101 call\nG0 Y#<_value>\nM30\n"),
    "#<_value> is 0 before a call returns one, and after a return or M99 without one": (
        "G21 G90\nG0 X[#<_value>+1] Y[#<_value_returned>+1]\no101 sub\no101 endsub [5]\no100 sub\no100 endsub\n"
        "o101 call\nG0 X#<_value> Y#<_value_returned>\no100 call\nG0 X[#<_value>+2] Y[#<_value_returned>+2]\n"
        "o101 call\nM98 P7\nG0 X[#<_value>+3] Y[#<_value_returned>+3]\nM30\nO7\nG0 Z1\nM99\n"),
    "the flow passing a definition runs its endsub": (
        "G21 G90\n#1=3\no100 sub\nG0 Z9\no100 endsub [#1*2]\nG0 X#<_value> Y#<_value_returned>\n"
        "o101 sub\no101 return [7]\no101 endsub\nG0 X[#<_value>+1] Y[#<_value_returned>+1]\n"
        "o100 call [1]\nG0 X#<_value>\nM30\n"),
}


@pytest.mark.parametrize("name", RUNS)
def test_subprograms_move_as_rs274_runs_them(name: str) -> None:
    text = RUNS[name]
    ours = _ours(text)
    assert ours, "no moves"
    if available():
        _same(ours, _theirs(text))


REFUSED = {
    "M98 to a missing program": (
        "G21 G90\nM98 P2\nM30\nO1\nG0 X1\nM99\n",
        "t.ngc:2:1: error: 'M98 P2': subprogram o2 not found after line 2 of t.ngc (the call looks for it from "
        "the call onward)"),
    "M98 to a program only before the call": (
        "G21 G90\nM98 P2\nM30\nO1\nG0 X1\nM99\nO2\nG0 Y2\nM98 P1\nM99\n",
        "t.ngc:9:1: error: 'M98 P1': subprogram o1 not found after line 9 of t.ngc (the call looks for it from "
        "the call onward) (in o2, called from t.ngc line 2)"),
    "the first line's O is a name, not a subprogram": (
        "O1\nG21 G90\nG0 X1\nM98 P1\nM30\n",
        "t.ngc:4:1: error: 'M98 P1': subprogram o1 not found after line 4 of t.ngc (the call looks for it from "
        "the call onward)"),
    "M99 P in a subprogram": (
        "G21 G90\nM98 P1\nM30\nO1\nG0 X1\nM99 P5\n",
        "t.ngc:6:5: error: M99 P (a return to a block number) is not LinuxCNC: rs274 refuses it"),
    "M99 P in the main program": (
        "G21 G90\nG0 X1\nM99 P5\nM30\n",
        "t.ngc:3:5: error: M99 P (a return to a block number) is not LinuxCNC: rs274 refuses it"),
    "M99 with other words": (
        "G21 G90\nM98 P1\nM30\nO1\nG0 Y1\nG0 X1 M99\n",
        "t.ngc:6:1: error: M99 stands alone on its line in LinuxCNC: G0 cannot share it"),
    "M98 with a move": (
        "G21 G90\nG0 X1 M98 P1\nM30\nO1\nG0 Y1\nM99\n",
        "t.ngc:2:1: error: M98 stands alone on its line in LinuxCNC: G0 cannot share it (rs274: Unknown m code "
        "used: M98)"),
    "M98 with a feed": (
        "G21 G90\nF10 M98 P1\nM30\nO1\nG1 Y1\nM99\n",
        "t.ngc:2:1: error: M98 stands alone on its line in LinuxCNC: F10 cannot share it (rs274: Unknown m code "
        "used: M98)"),
    "M98 without P": (
        "G21 G90\nM98 L2\nM30\nO1\nG0 X1\nM99\n",
        "t.ngc:2:1: error: M98 needs a program number P (rs274: Found 'm98' code with no P-word)"),
    "a negative repeat count": (
        "G21 G90\nM98 P1 L-1\nM30\nO1\nG0 X1\nM99\n",
        "t.ngc:2:8: error: M98 L-1: a negative repeat count"),
    "a fractional repeat count": (
        "G21 G90\nM98 P1 L1.5\nM30\nO1\nG0 X1\nM99\n",
        "t.ngc:2:8: error: L1.5 of M98 is not a whole number"),
    "a fractional program number": (
        "G21 G90\nM98 P1.5\nM30\nO1\nG0 X1\nM99\n",
        "t.ngc:2:5: error: P1.5 of M98 is not a whole number"),
    "M98 to an o-word subprogram": (
        "G21 G90\nM98 P1\nM30\no1 sub\nG0 X1\no1 endsub\n",
        "t.ngc:2:1: error: 'M98 P1' calls o1, an o-word subprogram (o.. sub), which only an o-word call runs"),
    "an o-word call to an O subprogram": (
        "G21 G90\no1 call\nM30\nO1\nG0 X1\nM99\n",
        "t.ngc:2:1: error: 'o1 call' calls o1, a numbered subprogram ended by a return code, which only a "
        "subprogram call runs (not an o-word call)"),
    "a subprogram that runs off the end of the file": (
        "G21 G90\nM98 P1\nM30\nO1\nG0 X1\n",
        "t.ngc:5:1: error: subprogram o1 runs to the end of the file without returning (in o1, called from t.ngc "
        "line 2)"),
}


@pytest.mark.parametrize("name", REFUSED)
def test_what_rs274_refuses_is_a_located_error(name: str) -> None:
    text, message = REFUSED[name]
    with pytest.raises(ErrorList) as info:
        _ours(text)
    errors = [str(e) for e in info.value.errors]
    assert errors[0] == message
    # A refused line is kept as text only, so a subprogram whose M99 line is refused then runs off the file.
    assert errors[1:] in ([], ["t.ngc:6:1: error: subprogram o1 runs to the end of the file without returning (in o1, "
                               "called from t.ngc line 2)"])
    if available():
        with pytest.raises(RS274Error):
            run_rs274(text)


def test_m98_shares_numbered_parameters_but_not_named_ones() -> None:
    """rs274: the caller's ``#<a>`` is "not defined" inside an M98 subprogram."""
    with pytest.raises(ErrorList) as info:
        _ours("G21 G90\n#<a>=5\nM98 P1\nM30\nO1\nG0 X#<a>\nM99\n")
    assert len(info.value.errors) == 1 and str(info.value.errors[0]).startswith("t.ngc:6:")
    if available():
        with pytest.raises(RS274Error, match="Named parameter #<a> not defined"):
            run_rs274("G21 G90\n#<a>=5\nM98 P1\nM30\nO1\nG0 X#<a>\nM99\n")


# -- Fanuc -> LinuxCNC: kept symbolic exactly when rs274 runs the output with the same moves ----------

def _translate(text: str, file: str = "t.nc") -> tuple[str, list[str]]:
    out = io.StringIO(newline="")
    diagnostics = translate(io.StringIO(text, newline=""), out, file=file, source="fanuc", target="linuxcnc")
    return out.getvalue(), [str(w) for w in diagnostics.warnings]


def test_fanuc_m98_repeats_stay_symbolic_for_linuxcnc() -> None:
    path = ROOT / "tests" / "golden" / "macro" / "subprogram_repeat.nc"
    text, warnings = _translate(path.read_text(), str(path))
    assert warnings == []
    lines = text.splitlines()
    assert "M98 P2100 L4" in lines
    assert "M98 P2100 L3" in lines, "the packed P00032100 is written as LinuxCNC reads it: P2100 L3"
    assert lines.index("M30") < lines.index("O2100 (ONE SLOT STEP, INCREMENTAL)") < lines.index("M99")
    assert lines[1].startswith("(O2004)"), "the program number before M30 stays a comment"
    assert _ours(text) and len(_ours(text)) == len(_ours(path.read_text(), "fanuc", str(path)))
    if available():
        _same(_ours(path.read_text(), "fanuc", str(path)), _theirs(text))


FLATTENED = {
    "a call sharing a line with a move": (
        "%\nG21 G90 G00 X0 Y0 Z5.\nG00 X5. M98 P100 L2\nM30\nO100\nG91 G00 Y1.\nG90\nM99\n%\n"),
    "a return to a block number": (
        "%\nG21 G90 G00 X0 Y0 Z5.\nM98 P100\nN50 G00 X7.\nG00 Z9.\nM30\nO100\nG00 Y1.\nM99 P50\n%\n"),
}


@pytest.mark.parametrize("name", FLATTENED)
def test_what_linuxcnc_would_run_differently_is_flattened(name: str) -> None:
    """rs274 refuses ``G00 X5. M98 ..`` and ``M99 P``: those programs are flattened, and the flat program
    moves as the Fanuc one does, in rs274 too."""
    source = FLATTENED[name]
    text, warnings = _translate(source)
    assert len(warnings) == 1 and "flattened" in warnings[0], warnings
    assert "M98" not in text.replace("(", "\n(").split("\n(")[0] or all(
        "M98" not in line.split("(")[0] for line in text.splitlines())
    fanuc = _ours(source, "fanuc", "t.nc")
    _same(_ours(text), fanuc)
    if available():
        _same(fanuc, _theirs(text))
