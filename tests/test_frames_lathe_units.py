"""Lathe programs under the user's program transforms (issue #27 item 3, on the frame machinery): ``--units``
converts a lathe program (X diameters, Z, arc radii, feeds and thread leads per revolution, and the surface
speed under G96: metres to feet per minute [V: LinuxCNC G-code reference, G96; K: Fanuc 0i-TF operator's
manual]); a lathe cycle kept for the target is refused by name. Each conversion verifies. (``--transform`` on a
lathe: ``tests/test_transforms_lathe.py``.)
"""

from __future__ import annotations

import io
import re
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.verify import verify_lines

ROOT = Path(__file__).resolve().parents[1]
FANUC_T = ROOT / "examples" / "setups" / "fanuc_0i_tf.xml"
GSK = ROOT / "examples" / "setups" / "gsk_980tdc.xml"

PROGRAM = """%
O3001
G21 G99
T0101
G50 S2000
G96 S200 M03
G00 X50. Z2.
G01 Z-20. F0.2
X60. Z-30.
G02 X70. Z-35. R5.
G01 Z-50.
G97 S500
G32 Z-60. F1.5
G00 X100. Z50.
M30
%
"""


def _translate(text: str, source: str, target: str, setup: Path, **options: str) -> str:
    out = io.StringIO(newline="")
    translate(io.StringIO(text, newline=""), out, file="t.nc", source=source, target=target,
              setup=load_setup(str(setup)), diagnostics=Diagnostics(warn_stream=io.StringIO()), **options)
    return out.getvalue()


def _verify(text: str, out: str, source: str, target: str, setup: Path) -> None:
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="a", file_out="b", source=source,
                          target=target, setup=load_setup(str(setup)), tolerance=1e-3)
    assert report.ok, report.summary() + "\n" + out


def _numbers(out: str, letter: str) -> list[float]:
    return [float(v) for v in re.findall(rf"{letter}(-?\d*\.?\d+)", out)]


def test_a_lathe_program_in_inches_converts_lengths_feeds_and_the_surface_speed() -> None:
    out = _translate(PROGRAM, "fanuc", "fanuc", FANUC_T, units="inch")
    assert "G20" in out and "G21" not in out, out
    # S: G50's clamp 2000 rpm and G97's 500 rpm stay; G96's 200 m/min is 200 / 0.3048 = 656.168 ft/min,
    # written S656: a Fanuc S is a whole number (tests/test_defects_fanuc_speed.py)
    speeds = _numbers(out, "S")
    assert speeds[0] == 2000 and speeds[1] == 656 and speeds[2] == 500, out
    # X50 (a diameter) is 1.9685 in; F0.2 mm/rev is 0.007874 in/rev; the thread's F1.5 lead is 0.059055 in
    assert abs(_numbers(out, "X")[0] - 50 / 25.4) < 1e-4, out
    feeds = _numbers(out, "F")
    assert abs(feeds[0] - 0.2 / 25.4) < 1e-6 and abs(feeds[1] - 1.5 / 25.4) < 1e-6, out
    _verify(PROGRAM, out, "fanuc", "fanuc", FANUC_T)


@pytest.mark.parametrize("path, source, setup", [
    *[(p, "fanuc", FANUC_T) for p in sorted((ROOT / "examples" / "fanuc-lathe").glob("*.nc"))],
    *[(p, "gsk", GSK) for p in sorted((ROOT / "examples" / "gsk").glob("*.nc"))],
], ids=lambda v: v.stem if isinstance(v, Path) and v.suffix == ".nc" else "")
def test_the_lathe_examples_convert_to_inches_for_linuxcnc_and_verify(path: Path, source: str, setup: Path) -> None:
    text = path.read_text(encoding="utf-8")
    out = _translate(text, source, "linuxcnc", setup, units="inch")
    assert "G20" in out, out
    _verify(text, out, source, "linuxcnc", setup)


def test_a_lathe_cycle_kept_for_the_target_is_refused_by_name() -> None:
    text = (ROOT / "examples" / "fanuc-lathe" / "o2002_grooves.nc").read_text(encoding="utf-8")
    with pytest.raises(ErrorList) as caught:
        _translate(text, "fanuc", "fanuc", FANUC_T, units="inch")
    assert "a lathe cycle kept for the target (groove) cannot be converted" in str(caught.value.errors[0])

