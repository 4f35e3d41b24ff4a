"""Fagor hole patterns (G160-G165) under ``--units`` and ``--transform`` (issue #27): written point by point
(each point a repeat of the active cycle, carried exactly), back to Fagor too, and verified against the
source with the same options; what is kept as written and not converted is refused by its own name.
"""

from __future__ import annotations

import io
import math
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from postproc.transforms.spec import parse_transform

ROOT = Path(__file__).resolve().parents[1]
PATTERNS = ["bolt_circle.nc", "bolt_circle_arcs.nc", "grid.nc"]
OPTIONS = [{"units": "inch"}, {"transform": "rotate 30 about 5,5; mirror x"}, {"units": "inch", "transform": "translate 3,-2"}]


@pytest.mark.parametrize("name", PATTERNS)
@pytest.mark.parametrize("target", ["fagor", "fanuc"])
@pytest.mark.parametrize("options", OPTIONS, ids=lambda o: ",".join(o))
def test_a_pattern_is_carried_point_by_point_and_verifies(name: str, target: str, options: dict[str, str]) -> None:
    text = (ROOT / "examples/fagor" / name).read_text()
    out = io.StringIO()
    translate(io.StringIO(text), out, file=name, source="fagor", target=target, **options)  # type: ignore[arg-type]
    assert not [line for line in out.getvalue().splitlines() if line.lstrip("N0123456789 ").startswith("G16")]
    transform = options.get("transform")
    report = verify_lines(io.StringIO(text), io.StringIO(out.getvalue()), file_in=name, file_out="o", source="fagor",
                          target=target, transform=parse_transform(transform) if transform else None)
    assert report.ok, report.summary()


def test_a_bolt_circle_rotated_by_hand() -> None:
    """bolt_circle.nc: six holes on the circle about (50, 50), radius 40, the first at (90, 50); rotated 90
    degrees about (50, 50) the first is at (50, 90), the rest 60 degrees on, counter-clockwise."""
    text = (ROOT / "examples/fagor/bolt_circle.nc").read_text()
    out = io.StringIO()
    translate(io.StringIO(text), out, file="b", source="fagor", target="fagor", transform="rotate 90 about 50,50")
    holes = [(round(e["x"], 4), round(e["y"], 4)) for e in toolpath_events(io.StringIO(out.getvalue()), file="o",
             dialect="fagor") if e.get("move") == "feed"]
    want = [(round(50 + 40 * math.cos(math.radians(90 + 60 * k)), 4) + 0.0,
             round(50 + 40 * math.sin(math.radians(90 + 60 * k)), 4) + 0.0) for k in range(6)]
    assert [(x + 0.0, y + 0.0) for x, y in holes] == want


def test_a_dynamic_tool_length_is_carried_through_a_transform() -> None:
    """LinuxCNC's G43.1 is the neutral dynamic offset (it was kept as written and refused here): a rotation
    about Z leaves the length along Z as it is and turns the move (hand-derived: X10 by 30 degrees)."""
    text = "G21 G90 G17\nG0 X0 Y0 Z5\nG43.1 Z2.5\nG1 X10 F100\nM2\n"
    out = io.StringIO()
    translate(io.StringIO(text), out, file="t", source="linuxcnc", target="linuxcnc", transform="rotate 30")
    lines = out.getvalue().splitlines()
    assert lines[2:4] == ["G43.1 Z2.5", "G1 X8.660254 Y5. F100."], lines
