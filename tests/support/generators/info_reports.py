"""Fuzz kind "info reports": ``postproc info`` on random programs of every reading dialect (the suite's
fragment programs, lathe programs on a lathe set-up, the option generator's mill programs), with and without
a set-up (machine coordinates).

``info`` must never traceback: a program is reported, or refused with errors that each name FILE:LINE:COL.
A report must be JSON without NaN or infinity, render as text, have every extent's min at most its max,
every time and length finite and at least 0, and contain every point the toolpath reaches (``toolpath``'s
move end points, in the report's 4 decimals).
"""

from __future__ import annotations

import io
import json
import math
from typing import Any

from hypothesis import strategies as st

from postproc.commands.info import program_info, render_text
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events

from ..fuzzing import READERS, located, programs as fragment_programs, setups
from . import Case
from .lathe_threading import lathe_setup, programs as lathe_programs
from .program_options import programs as option_programs, spelled

KIND = "info reports"
SLACK = 1.5e-4
"""mm: the report's 4 decimals (half a unit) and the float noise of a diameter halved and doubled."""


def _numbers(value: Any, where: str = "report") -> None:
    """Every number in the report is finite; lengths, times and counts are at least 0."""
    if isinstance(value, dict):
        for key, item in value.items():
            _numbers(item, f"{where}.{key}")
    elif isinstance(value, list):
        for n, item in enumerate(value):
            _numbers(item, f"{where}[{n}]")
    elif isinstance(value, float) or (isinstance(value, int) and not isinstance(value, bool)):
        assert math.isfinite(value), f"{where} is {value}"
        if where.rsplit(".", 1)[-1].endswith(("_mm", "_s", "holes")):
            assert value >= 0, f"{where} is {value}"


def check(dialect: str, program: str, setup: MachineSetup | None, targets: bool) -> str:
    try:
        report = program_info(io.StringIO(program), file="in.nc", dialect=dialect, setup=setup, targets=targets)
    except ErrorList as errs:
        for err in errs.errors:
            located(err)
        return "refused"
    json.dumps(report, allow_nan=False)
    render_text(report, io.StringIO())
    _numbers(report)
    work = report["extent"]["work"]
    for axis, span in work.items():
        assert span["min"] <= span["max"], f"extent of {axis}: {span}"
    for ev in toolpath_events(io.StringIO(program), file="in.nc", dialect=dialect, setup=setup,
                              diagnostics=Diagnostics(warn_stream=io.StringIO())):
        if "move" not in ev:
            continue
        for key, value in ev.items():
            axis = key.upper()
            if len(key) == 1 and axis in work and isinstance(value, (int, float)):
                span = work[axis]
                assert span["min"] - SLACK <= value <= span["max"] + SLACK, \
                    f"a move reaches {axis}{value} (line {ev.get('line')}) outside the extent {span}"
    return "ok"


def _case(dialect: str, program: str, setup: MachineSetup | None, targets: bool) -> Case:
    return Case(f"info {dialect}", dialect, program, lambda p: check(dialect, p, setup, targets),
                f"set-up {'given' if setup else 'none'}, targets {targets}")


def cases() -> st.SearchStrategy[Case]:
    targets = st.sampled_from([False, False, False, True])
    mill = st.builds(_case, st.sampled_from(READERS), fragment_programs(), st.one_of(st.none(), setups()), targets)
    lathe = st.builds(lambda d, p, t: _case(d, p, lathe_setup(d), t), st.sampled_from(["fanuc", "gsk"]),
                      lathe_programs(), targets)
    options = st.builds(lambda d, p, s, t: _case(d, spelled(d, p), s, t),
                        st.sampled_from(["fanuc", "linuxcnc", "grbl", "grblhal", "mach3", "isg"]),
                        option_programs(), st.one_of(st.none(), setups()), targets)
    return st.one_of(mill, lathe, options)
