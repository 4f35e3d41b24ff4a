"""An R arc at (or within rounding reach of) 180 degrees, written for each target that has a rules module.

grbl refuses an R arc whose chord exceeds 2R by any amount (``4R^2 - d^2 < 0``, error 34, in float32 [K: grbl
``gcode.c``]): an exact semicircle by R passes or fails by rounding, so the grbl family writes it by I/J about
the chord's midpoint (``Dialect.R_ARC_FLOAT_SLACK``, ``postproc.lowering.arcs.settle_arc_ends``). LinuxCNC
takes a half chord up to R plus ``RADIUS_TOLERANCE`` (0.00005 in, 0.00127 mm) and makes it a semicircle [K:
interp_internal.hh, interp_arc.cc ``arc_data_r``], so R stays there; rs274 itself checks it (``tests/support/linuxcnc_rules.py``).

Expected centres are hand-derived: a semicircle's centre is its chord's midpoint.
"""

from __future__ import annotations

import io
import math
import re

import pytest
from hypothesis import given, settings, strategies as st

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel
from postproc.setup.machine_setup import MachineSetup
from tests.support import output_rules
from tests.support.grbl_rules import grbl_problems
from tests.support.linuxcnc_rules import available as rs274_available

MM_PER_INCH = 25.4


def written(program: str, target: str, units: str | None = None) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(program, newline=""), out, file="t.nc", source="fanuc", target=target, units=units,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def arc_lines(text: str) -> list[str]:
    return [line for line in text.splitlines() if re.match(r"G[23]\b", line)]


def words(line: str) -> dict[str, float]:
    return {m[0]: float(m[1:]) for m in re.findall(r"[A-Z][-+.\d]+", line)}


SEMICIRCLE_INCH = "G20 G90 G17\nG0 X-0.9 Y0\nG1 Z-0.25 F1\nG2 Y0 X1.05 R0.975 F30\nG0 Z0.1\nM30\n"
"""The held-out ``fanuc/aed_circular_pocket.nc`` case: the chord 1.95 in is exactly 2R."""
SEMICIRCLE_MM = "G21 G90 G17\nG0 X-22.86 Y0\nG1 Z-6.35 F25\nG2 Y0 X26.67 R24.765 F760\nG0 Z2.54\nM30\n"
"""The same arc in mm (every number the inch one times 25.4, exact in decimal)."""


@pytest.mark.parametrize("target", ["grbl", "grblhal"])
@pytest.mark.parametrize("program, units, mm", [
    (SEMICIRCLE_INCH, None, 1.0), (SEMICIRCLE_INCH, "mm", MM_PER_INCH), (SEMICIRCLE_MM, None, 1.0),
    (SEMICIRCLE_MM, "inch", 1.0 / MM_PER_INCH)])
def test_a_grbl_family_semicircle_by_r_is_written_by_its_centre(target: str, program: str, units: str | None,
                                                                 mm: float) -> None:
    text = written(program, target, units)
    assert output_rules.problems(target, text, MachineSetup()) == []
    (arc,) = arc_lines(text)
    w = words(arc)
    assert "R" not in w, arc
    start_x = -22.86 if program is SEMICIRCLE_MM else -0.9
    end_x = 26.67 if program is SEMICIRCLE_MM else 1.05
    assert w["X"] == pytest.approx(end_x * mm, abs=1e-6)
    assert w["I"] == pytest.approx((end_x - start_x) / 2 * mm, abs=1e-6)  # the chord's midpoint, from the start
    assert w.get("J", 0.0) == 0.0


def test_the_checker_refuses_the_semicircle_as_it_was_written_before() -> None:
    """The failure the fix removes, shown on the checker: the arc as the writer wrote it before (R kept), whose
    chord, taken to mm as grbl takes it, comes out a rounding longer than 2R."""
    found = grbl_problems("G20 G90 G17\nG0 X-0.9 Y0\nG2 X1.05 Y0 R0.975 F30\n")
    assert found and "error:34" in found[0]


def test_an_arc_short_of_180_degrees_keeps_its_r() -> None:
    """90 degrees: R places the centre well, so the words stay as programmed (the held-out program's last arc)."""
    text = written("G20 G90 G17\nG0 X1.125 Y0\nG2 Y-0.375 X0.75 R0.375 F30\nM30\n", "grbl")
    (arc,) = arc_lines(text)
    assert words(arc)["R"] == 0.375 and "I" not in words(arc)


@pytest.mark.skipif(not rs274_available(), reason="rs274 is not installed")
@pytest.mark.parametrize("program, units", [(SEMICIRCLE_INCH, None), (SEMICIRCLE_INCH, "mm"),
                                            (SEMICIRCLE_MM, None), (SEMICIRCLE_MM, "inch")])
def test_linuxcnc_takes_the_semicircle_by_r(program: str, units: str | None) -> None:
    """LinuxCNC's tolerance on R (0.00127 mm) covers the rounding: R is written, and rs274 runs it."""
    text = written(program, "linuxcnc", units)
    assert output_rules.problems("linuxcnc", text, MachineSetup()) == []
    (arc,) = arc_lines(text)
    assert "R" in words(arc)


@settings(max_examples=60, deadline=None)
@given(radius=st.integers(min_value=1, max_value=400_000), inch=st.booleans(), convert=st.booleans(),
       angle=st.integers(min_value=0, max_value=359), short=st.integers(min_value=0, max_value=3),
       target=st.sampled_from(["grbl", "grblhal"]), clockwise=st.booleans())
def test_no_semicircle_or_near_semicircle_by_r_is_refused(radius: int, inch: bool, convert: bool, angle: int,
                                                           short: int, target: str, clockwise: bool) -> None:
    """Random semicircles (and chords a few last places short of 2R) on a chord at a random angle, in
    either units, converted to the other or not: grbl's radius check never refuses the written arc, and
    the centre it runs about lies on the chord's perpendicular bisector within grbl's own tolerance."""
    places = 4 if inch else 3
    unit = 10.0 ** -places
    r = radius * unit
    a = math.radians(angle)
    sx, sy = round(-r * math.cos(a), places), round(-r * math.sin(a), places)
    ex, ey = round(r * math.cos(a) - short * unit * math.cos(a), places), round(
        r * math.sin(a) - short * unit * math.sin(a), places)
    if math.hypot(ex - sx, ey - sy) > 2 * r or math.hypot(ex - sx, ey - sy) < r:
        return  # rounding the ends made the chord longer than 2R: the source itself is out of reach
    program = (f"{'G20' if inch else 'G21'} G90 G17\nG0 X{sx:.{places}f} Y{sy:.{places}f}\n"
               f"G{2 if clockwise else 3} X{ex:.{places}f} Y{ey:.{places}f} R{r:.{places}f} F100\nM30\n")
    units = ("mm" if inch else "inch") if convert else None
    text = written(program, target, units)
    assert output_rules.problems(target, text, MachineSetup()) == [], text
    (arc,) = arc_lines(text)
    w = words(arc)
    if "R" not in w:
        k = (MM_PER_INCH if inch else 1 / MM_PER_INCH) if convert else 1.0
        cx, cy = sx * k + w.get("I", 0.0), sy * k + w.get("J", 0.0)
        mx, my = (sx + ex) / 2 * k, (sy + ey) / 2 * k
        dx, dy = (ex - sx) * k, (ey - sy) * k
        off_bisector = abs((cx - mx) * dx + (cy - my) * dy) / math.hypot(dx, dy)
        written_inch = inch != convert
        assert off_bisector <= 0.005 / (MM_PER_INCH if written_inch else 1.0) + 1e-9  # grbl's 0.005 mm
