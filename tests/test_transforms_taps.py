"""Rigid taps under ``--transform`` and ``--units`` (issue #27): a LinuxCNC ``G33.1`` and a Fanuc ``M29`` tap
cycle moved rigidly about Z (translation, rotation about Z, a mirror of X or Y) keep their pitch and tap
along the carried line; a map that scales or tilts or turns over Z is refused by name. Expected words by
hand; each output verified against its source with the same transform.
"""

from __future__ import annotations

import io

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.simulate.verify import verify_lines
from postproc.transforms.spec import parse_transform

NGC = "G21 G90 G17\nG0 X0 Y0 Z5\nS500 M3\nG1 X10 F100\nG33.1 X5 Y5 Z-10 K1.5\nM2\n"
"""A tap along the line from (10, 0, 5) to (5, 5, -10)."""
FANUC = ("G21 G17 G90 G94\nG00 X0. Y0. Z5.\nS500 M03\nM29 S500\nG99 G84 X10. Y0 Z-8. R2. F750.\nX20. Y5.\nG80\n"
         "M30\n")


def _moved(text: str, source: str, target: str, transform: str | None = None, units: str | None = None) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="t", source=source, target=target, transform=transform, units=units)
    report = verify_lines(io.StringIO(text), io.StringIO(out.getvalue()), file_in="t", file_out="o", source=source,
                          target=target, transform=parse_transform(transform) if transform else None)
    assert report.ok, report.summary()
    return out.getvalue()


def test_a_g33_1_tap_is_carried_by_a_rotation_and_a_shift() -> None:
    """(5, 5) turned 30 degrees: (5 cos 30 - 5 sin 30, 5 sin 30 + 5 cos 30) = (1.830127, 6.830127); shifted by
    (1, 2, 3): X2.830127 Y8.830127 Z-7, K as written."""
    out = _moved(NGC, "linuxcnc", "linuxcnc", transform="rotate 30; translate 1,2,3")
    assert "G33.1 X2.830127 Y8.830127 Z-7. K1.5" in out.splitlines()


def test_a_g33_1_tap_is_carried_by_a_mirror() -> None:
    out = _moved(NGC, "linuxcnc", "linuxcnc", transform="mirror x")
    assert "G33.1 X-5. Y5. Z-10. K1.5" in out.splitlines()


def test_a_g33_1_tap_converted_to_inches_converts_its_pitch() -> None:
    out = _moved(NGC, "linuxcnc", "linuxcnc", units="inch")
    assert "G33.1 X0.19685039 Y0.19685039 Z-0.39370079 K0.05905512" in out.splitlines()


@pytest.mark.parametrize("transform", ["scale 2,2,1", "mirror z", "rotate 10 in zx"])
def test_a_tap_under_a_map_that_scales_or_moves_z_is_refused(transform: str) -> None:
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(NGC), io.StringIO(), file="t", source="linuxcnc", target="linuxcnc", transform=transform)
    assert "a rigid tap cannot be transformed" in str(info.value.errors[0])


def test_a_fanuc_rigid_tap_cycle_expanded_for_linuxcnc_taps_at_the_turned_holes() -> None:
    """Rotated 90 degrees then shifted X+1: (10, 0) -> (1, 10), (20, 5) -> (-4, 20)."""
    lines = _moved(FANUC, "fanuc", "linuxcnc", transform="rotate 90; translate 1,0").splitlines()
    assert lines.count("G33.1 Z-8. K1.5") == 2
    assert "G0 X1. Y10. Z5." in lines and "G0 X-4. Y20. Z2." in lines


def test_a_fanuc_rigid_tap_cycle_kept_for_fanuc_moves_its_holes() -> None:
    lines = _moved(FANUC, "fanuc", "fanuc", transform="rotate 90; translate 1,0").splitlines()
    assert "G99 G84 X1. Y10. Z-8. R2. F750." in lines and "X-4. Y20." in lines
