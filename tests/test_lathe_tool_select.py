"""A lathe program of a controller that changes tools with M6 (LinuxCNC, grblHAL) selects the next tool with a
``T`` alone and changes it with ``M6``: ``T1`` prepares tool 1 and changes nothing [V: rs274 prints
``SELECT_TOOL(1)`` and no ``CHANGE_TOOL`` for it, checked below; LinuxCNC G-code reference "T: Select Tool"
and "M6 Tool Change"; K: grblHAL ``gcode.c``, the T word only sets the tool to select, ``M6`` runs the change].
So every target keeps that select a select: a target that changes with a code of its own (ISG, Fagor ``M06``
[K: ISG/Fagor code tables, ``dialects/*/codes.py``]; LinuxCNC, grblHAL ``M6``; grbl's pause ``T<n> M0``)
writes ``T1`` without it, and a turret lathe (Fanuc T, GSK), whose T word indexes the turret [K: Fanuc 0i-TF
operator's manual, "Tool function"], writes no T for it (a comment notes it, ``postproc.rs274.lathe_tool_index``).

Found by ``make fuzz`` (new words, grblHAL lathe -> ISG, 2026-12-01): ``T1`` was written ``T1 M06`` (the
mill-control branch of ``postproc.cycles.lathe_lowering`` took every lathe T for a turret index), exit 0, and
``verify`` found "OUT has tool change to T1". Expected texts below are the rule applied by hand, not the tool's
output.
"""

from __future__ import annotations

import io
import re

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.simulate.verify import verify_lines
from tests.support.generators.new_words import LATHE
from tests.support.rs274 import available, run_rs274

PROGRAM = "G18 G21 G90 G0 X0 Z10\nT1\nG0 X1\nT2 M6\nG0 X2\nM2\n"
"""Tool 1 selected and never changed to; tool 2 selected and changed to."""

CHANGE = {"isg": r"\bM06\b", "fagor": r"\bM06\b", "linuxcnc": r"\bM6\b", "grblhal": r"\bM6\b", "grbl": r"\bM0\b"}
"""Each M6 target's tool change (grbl: the pause it writes for one, ``postproc.grbl_family``)."""


def _written(source: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(PROGRAM), out, file="in.ngc", source=source, target=target, setup=LATHE,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _code(text: str) -> str:
    """The text without its comments (grbl's pause names the tool in one)."""
    return re.sub(r"\([^)]*\)|;.*", "", text)


def _verified(source: str, target: str, text: str) -> None:
    """Same moves and events; of the settings only path control may differ (grblHAL runs in exact path from
    power-on, which a Fanuc or GSK lathe has no code for: the translation warns, ``verify`` lists it)."""
    report = verify_lines(io.StringIO(PROGRAM), io.StringIO(text), file_in="in.ngc", file_out="out.nc",
                          source=source, target=target, setup=LATHE, allow_ignored=True)
    assert report.ok and report.max_deviation == 0.0, report.summary() + "\n" + text
    assert all(line.startswith("path control") for line in report.ignored), report.summary()


@pytest.mark.parametrize("source", ["linuxcnc", "grblhal"])
@pytest.mark.parametrize("target", sorted(CHANGE))
def test_a_select_stays_a_select_on_a_target_that_changes_with_a_code(source: str, target: str) -> None:
    text = _written(source, target)
    lines = [line for line in map(_code, text.splitlines()) if re.search(r"\bT\d", line)]
    assert [re.findall(r"\bT\d+", line) for line in lines] == [["T1"], ["T2"]], text
    assert [bool(re.search(CHANGE[target], line)) for line in lines] == [False, True], text
    assert len(re.findall(CHANGE[target], _code(text))) == 1, text
    _verified(source, target, text)


@pytest.mark.parametrize("source", ["linuxcnc", "grblhal"])
@pytest.mark.parametrize("target", ["fanuc", "gsk"])
def test_a_select_indexes_nothing_on_a_turret_lathe(source: str, target: str) -> None:
    text = _written(source, target)
    assert re.findall(r"\bT\d+", _code(text)) == ["T0200"], text  # station 2, no offset in force
    assert "TOOL 1 PREPARED" in text
    _verified(source, target, text)


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
def test_rs274_selects_without_changing() -> None:
    """The source's semantics, and the LinuxCNC output's, from the interpreter itself."""
    for text in (PROGRAM, _written("grblhal", "linuxcnc")):
        calls = [c.split()[1] for c in run_rs274(text) if "_TOOL(" in c]
        assert calls == ["SELECT_TOOL(1)", "SELECT_TOOL(2)", "CHANGE_TOOL(2)"], text
