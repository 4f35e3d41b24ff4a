"""Tool data towards SINUMERIK (``dialects/siemens``: ``LOWERING``): a ``D`` carries the cutting edge's length
and radius together [K: 840D Fundamentals "Tool offsets"], so a radius register whose length is not the one in
force becomes the compensated path (as for ISG, ``postproc.isg_family.tool_data``), a D whose length matches
stays ``G41 D<n>``, and where neither holds the error names the set-up element to add.

Expected points are derived by hand (radius 3 on the left of a 20 mm square) and, where rs274 is installed,
checked against LinuxCNC's own compensation of the source."""

from __future__ import annotations

import io
from typing import Any

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine import ToolData
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support import rs274


def _setup() -> MachineSetup:
    setup = MachineSetup()
    setup.tools = {"1": ToolData(number=1, length=100.0, radius=3.0), "21": ToolData(number=21, length=100.0, radius=4.0),
                   "19": ToolData(number=19, length=7.0, radius=4.0)}
    return setup


def _translate(text: str, source: str, setup: MachineSetup | None = None) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="in.nc", source=source, target="siemens",
              setup=_setup() if setup is None else setup,
              diagnostics=Diagnostics(warn_stream=io.StringIO()))
    return out.getvalue()


def _verify(text: str, out: str, source: str) -> Any:
    return verify_lines(io.StringIO(text, newline=""), io.StringIO(out, newline=""), file_in="in.nc",
                        file_out="out", source=source, target="siemens", setup=_setup())


LINUXCNC_RADIUS_ONLY = ("G21 G90 G0 X0 Y0 Z5\nT1 M6\nG41 D1\nG1 X20 Y0 F100\nG1 X20 Y20\nG1 X0 Y20\n"
                        "G40 G1 X-10 Y10\nM2\n")
"""G41 D1 with no length offset in force (the corpus's comp_g1, comp311): SINUMERIK's D1 would bring edge 1's
100 mm length with its radius."""


def test_a_radius_whose_d_brings_a_length_not_in_force_is_written_as_the_compensated_path() -> None:
    """Radius 3 on the left of the square's sides: the entry move ends at the inside corner X17 Y3, then X17 Y17
    and X0 Y17; no D is written, so no length either."""
    out = _translate(LINUXCNC_RADIUS_ONLY, "linuxcnc")
    assert out.splitlines() == ["G710 G90 G0 X0. Y0. Z5.", "T1 M6", "G1 X17. Y3. F100.", "G1 X17. Y17.",
                                "G1 X0. Y17.", "G1 X-10. Y10.", "M2"]
    report = _verify(LINUXCNC_RADIUS_ONLY, out, "linuxcnc")
    assert report.ok and report.max_deviation == 0, report.summary()
    moves = [e for e in toolpath_events(io.StringIO(out), file="out", dialect="siemens", setup=_setup()) if "move" in e]
    assert [(m["x"], m["y"], m["z"]) for m in moves] == [(0, 0, 5), (17, 3, 5), (17, 17, 5), (0, 17, 5), (-10, 10, 5)]
    if rs274.available():
        calls = rs274.run_rs274(LINUXCNC_RADIUS_ONLY, tool_table=f"T1 P1 Z{100 / 25.4:.6f} D{6 / 25.4:.6f} ;\n")
        theirs = [(m["x"], m["y"]) for m in rs274.canonical_moves(calls) if "move" in m]
        assert theirs == [(m["x"], m["y"]) for m in moves]


def test_a_radius_whose_d_brings_the_length_in_force_stays_g41() -> None:
    """Register 21 has H1's length (100 mm): D21 carries both, so SINUMERIK compensates itself; at G40 the D
    goes back to the length register (D01)."""
    text = LINUXCNC_RADIUS_ONLY.replace("G41 D1", "G43 H1 Z5\nG41 D21")
    out = _translate(text, "linuxcnc")
    assert out.splitlines() == ["G710 G90 G0 X0. Y0. Z5.", "T1 M6", "D01 G0 Z5.", "G41 D21", "G1 X20. Y0. F100.",
                                "G1 X20. Y20.", "G1 X0. Y20.", "G40 D01 G1 X-10. Y10.", "M2"]
    assert _verify(text, out, "linuxcnc").ok


def test_a_d_that_cannot_carry_both_registers_names_the_register_to_set() -> None:
    """Fagor's compensation rules are not modelled, so the path cannot be resolved: the program runs with no
    length offset (Fagor's D brings its length only under G43), register 19 (the radius) is 7 mm long, and one
    SINUMERIK D cannot give the radius of the one without the length. (A Haas mill, the example here before,
    has its rules modelled since issue 26's comp26: its path is resolved.)"""
    with pytest.raises(ErrorList) as caught:
        _translate("G71 G90\nG42 D19 G01 X0. Y0. F100.\nM30\n", "fagor")
    assert [str(e) for e in caught.value.errors] == [
        "in.nc:2:5: error: D19 selects the length and the radius together, and its length (7 mm) is not the zero "
        "the program runs with (no length offset): give register 19 that length in the set-up's <Tools>, or use one "
        "register for both"]


def test_a_haas_d_that_cannot_carry_both_registers_is_written_as_the_compensated_path() -> None:
    """The same Haas program from a known start point: H1 is 100 mm long, register 19 (radius 4) 7 mm, so the
    path is resolved under the Haas rules (start-up type A: the start-up move ends square to the next move,
    along +X, at its start: 4 mm to its right, (0, -4); the last move ends square to itself at (20, -4)) and
    verified."""
    haas = _setup()
    haas.controller.variant = "haas"
    text = "G21 G90\nG0 X-20. Y0.\nG43 H01 Z50.\nG42 D19 G01 X0. Y0. F100.\nX20.\nG40 X30.\nM30\n"
    out = _translate(text, "fanuc", haas)
    assert "G42" not in out and "X0. Y-4." in out.replace("X0 ", "X0. "), out
    assert verify_lines(io.StringIO(text), io.StringIO(out), file_in="in.nc", file_out="out", source="fanuc",
                        target="siemens", setup=haas).ok
