"""verify where the translation keeps some stretches of cutter compensation native and resolved the others
into its path (LinuxCNC -> ISG: ``G41 D2`` while tool 1's length is in force would bring tool 2's length on
ISG, whose one D selects both, so that stretch is written compensated): the native stretch is compared as a
setting (ISG's rules are not modelled), the resolved one as the source's controlled points (DESIGN.md)."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.simulate.verify import verify_lines
from tests.support.tools import with_tools

SOURCE = """G21 G17 G90 G40
T1 M6 G43
G0 X0 Y0 Z5
G1 Z-1 F100
G41 D1 G1 X10 Y0
Y10
X0
G40 G1 X-5 Y-5
G41 D2 G1 X10 Y0
Y10
X0
G40 G1 X-5 Y-5
G0 Z5
M2
"""
SETUP = with_tools(lengths={1: 10.0, 2: 20.0}, radii={1: 1.0, 2: 2.0})


def _translated() -> str:
    out = io.StringIO()
    translate(io.StringIO(SOURCE), out, file="in.ngc", source="linuxcnc", target="isg", setup=SETUP)
    return out.getvalue()


def _verify(output: str) -> bool:
    report = verify_lines(io.StringIO(SOURCE), io.StringIO(output), file_in="in.ngc", file_out="out.nc",
                          source="linuxcnc", target="isg", setup=SETUP)
    return report.ok


def test_the_translation_keeps_one_stretch_and_resolves_the_other() -> None:
    lines = _translated().splitlines()
    assert sum(line.startswith("G41") for line in lines) == 1  # D1's stretch, native
    # D2's stretch, by hand: the square X10 Y0 - X10 Y10 - X0 Y10 run counter-clockwise with the tool on the
    # left, radius 2: the inside corners' centre points are X8 Y8 and X0 Y8 (the last line ends square)
    assert "G01 X8. Y8." in lines and "G01 X0. Y8." in lines


def test_verify_passes_comparing_the_native_stretch_as_a_setting_and_the_resolved_as_its_path() -> None:
    assert _verify(_translated())


@pytest.mark.parametrize("wrong", [
    ("G01 X8. Y8.", "G01 X8. Y8.01"),  # a resolved point off by 0.01
    ("G41 G01 X10. Y0.", "G42 G01 X10. Y0."),  # the native stretch on the other side
    ("G01 X0. Y8.", "G01 X0. Y10."),  # a resolved point left programmed
])
def test_verify_sees_a_fault_in_either_stretch(wrong: tuple[str, str]) -> None:
    output = _translated()
    assert wrong[0] in output
    assert not _verify(output.replace(wrong[0], wrong[1], 1))
