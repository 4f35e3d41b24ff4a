"""Fuzz kind "owords": LinuxCNC o-word subprograms across dialects (issue #31, items 2, 3 and 13).

Numbered and named ``o<n> sub`` .. ``o<n> endsub [v]`` definitions (a number Fanuc cannot write, a name in
mixed case, a number a named one might be given), ``return [v]`` inside an ``if``, ``call`` with 0-3
parameters, ``#<_value>`` read after a call, Fanuc-style ``O<n>`` .. ``M99`` called by ``M98 P L`` after the
main program's end: each translated to every writer with the subprograms kept where the target can (the
checks of the "macros" kind: read back, ``verify``, a LinuxCNC output run by ``rs274``). The source itself
is run by ``rs274`` too: what it refuses must not simulate here, and where both run, the moves agree.
"""

from __future__ import annotations

import io
import math

from hypothesis import strategies as st

from postproc.errors import Diagnostics
from postproc.simulate.toolpath import toolpath_events
from tests.support.rs274 import RS274Error, available, canonical_moves, run_rs274

from . import Case
from .macros import check, runs

KIND = "owords"
TARGETS = ("fanuc", "linuxcnc", "isg", "grbl", "mach3")

_NAMES = ["100", "12345", "2000", "<probe>", "<Edge_2>", "7"]
_VALUES = ["[#1*2]", "[#1+#2]", "[-1.5]", "[#2]", "[ABS[#1]]"]


def _if_label(name: str) -> str:
    """A label for an ``if`` inside subprogram ``name``, distinct from every subprogram's."""
    return "9" + "".join(c for c in name if c.isdigit())[:3] if name[0].isdigit() else f"<{name[1:-1]}_if>"


@st.composite
def programs(draw: st.DrawFn) -> str:
    names = draw(st.lists(st.sampled_from(_NAMES), min_size=1, max_size=3, unique=True))
    lines = ["G21 G90 G0 X0 Y0 Z5"]
    for name in names:
        label = _if_label(name)
        lines.append(f"o{name} sub")
        body = [f"G91 G1 X#1 Y[#2/2] F100", "G90"]
        if draw(st.booleans()):
            body += [f"o{label} if [#1 GT 1]", f"o{name} return {draw(st.sampled_from(_VALUES))}", f"o{label} endif"]
        if draw(st.booleans()):
            body += ["#<local>=[#1+1]", "G0 Z#<local>"]
        lines += body
        value = draw(st.sampled_from(["", *_VALUES]))
        lines.append(f"o{name} endsub {value}".rstrip())
    fanuc_style = draw(st.booleans())
    calls = draw(st.lists(st.sampled_from(names), min_size=1, max_size=4))
    for name in calls:
        args = draw(st.lists(st.sampled_from(["[1]", "[2.5]", "[-1]", "[#<_value>]"]), min_size=0, max_size=3))
        lines.append(f"o{name.upper() if draw(st.booleans()) else name} call {' '.join(args)}".rstrip())
        if draw(st.booleans()):
            lines.append("G0 X[#<_value>+0] Y0")
    if fanuc_style:
        lines.append(f"M98 P300{draw(st.sampled_from(['', ' L2']))}")
    lines.append("M2")
    if fanuc_style:
        lines += ["O300", "G91 G0 Y1", "G90", "M99"]
    return "\n".join(lines) + "\n"


def source_agrees_with_rs274(program: str) -> None:
    """What rs274 refuses does not simulate here; where both run, X, Y and Z agree move for move."""
    if not available():
        return
    ours = runs("linuxcnc", program)
    try:
        calls = run_rs274(program)
    except RS274Error as err:
        assert not ours, f"rs274 refuses what postproc simulates: {err.stderr or err}\n{program}"
        return
    if not ours:
        return  # postproc is stricter than rs274 by choice in places (an o-word left open)
    theirs = [e for e in canonical_moves(calls, start=(0.0, 0.0, 0.0)) if "move" in e]
    here = [e for e in toolpath_events(io.StringIO(program), file="in.ngc", dialect="linuxcnc",
                                                   diagnostics=Diagnostics(warn_stream=io.StringIO())) if "move" in e]
    assert len(here) == len(theirs), f"{len(here)} moves here, {len(theirs)} in rs274\n{program}"
    for n, (a, b) in enumerate(zip(here, theirs)):
        gap = math.dist((a["x"], a["y"], a["z"]), (b["x"], b["y"], b["z"]))
        assert a["move"] == b["move"] and gap < 2e-3, f"move {n}: {a} here, {b} in rs274\n{program}"


def _run(program: str, target: str) -> str:
    source_agrees_with_rs274(program)
    return check("linuxcnc", target, program)


def _case(program: str, target: str) -> Case:
    return Case(f"owords linuxcnc-{target}", target, program, lambda p, t=target: _run(p, t))


def cases() -> st.SearchStrategy[Case]:
    return st.builds(_case, programs(), st.sampled_from(TARGETS))
