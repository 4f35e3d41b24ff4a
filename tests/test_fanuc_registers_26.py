"""Issue 26, done when: a Fanuc program with G43 H and G41 D (length and radius in separate registers, the
set-up's tool table given) translates to grbl, ISG, Fagor and LinuxCNC and verify passes without
--allow-ignored. Fagor, whose D brings its length while G43 is on, is given the compensated path where the
radius register's length is not the one in force (``resolve_radius_where_d_cannot``, as ISG)."""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.simulate.verify import verify_lines
from tests.support.tools import with_tools

SOURCE = """%
O0001
G21 G17 G90 G40 G49
T1 M06
G43 H01 G00 X-5. Y-5. Z5.
G01 Z-1. F100.
G41 D11 G01 X0. Y0.
X10.
Y10.
X0.
Y0.
G40 G01 X-5. Y-5.
G00 Z5.
T2 M06
G43 H02 G00 X-5. Y-5. Z5.
G42 D12 G01 X0. Y0.
X10.
Y10.
G40 G01 X-5. Y-5.
G00 Z5.
M30
%
"""
SETUP = with_tools(lengths={1: 10.0, 2: 20.0}, radii={11: 2.0, 12: 3.0})
RESOLVED = ["X0. Y2.", "X8. Y2.", "X8. Y8.", "X2. Y8.", "X2. Y0.", "X-5. Y-5.",
            "X0. Y-3.", "X13. Y-3.", "X13. Y10.", "X-5. Y-5."]
"""By hand, Fanuc compensation C start-up and cancel type A: radius 2 on the left of the square (the
start-up ends square to the next side at its start, inside corners at the offset sides' intersection, the
cancel's last move square at its end); radius 3 on the right, its outer corner X13 Y-3 at the
intersection."""


def _translated(target: str, text: str = SOURCE) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="fanuc", target=target, setup=SETUP)
    return out.getvalue()


@pytest.mark.parametrize("target", ["grbl", "isg", "fagor", "linuxcnc"])
def test_separate_length_and_radius_registers_translate_and_verify(target: str) -> None:
    report = verify_lines(io.StringIO(SOURCE), io.StringIO(_translated(target)), file_in="in.nc", file_out="out",
                          source="fanuc", target=target, setup=SETUP, allow_ignored=False)
    assert report.ok, report.summary()


def test_fagor_is_given_the_compensated_path_where_d_would_bring_another_length() -> None:
    moves = [line.split(" ", 1)[1] for line in _translated("fagor").splitlines() if line.startswith("G01 X")]
    assert moves == RESOLVED


def test_fagor_keeps_its_compensation_where_no_length_is_on() -> None:
    text = SOURCE.replace("G43 H01 G00", "G00").replace("G43 H02 G00", "G00")
    lines = _translated("fagor", text).splitlines()
    assert "G41 D11 G01 X0. Y0." in lines and "G42 D12 G01 X0. Y0." in lines
