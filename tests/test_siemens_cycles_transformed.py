"""SINUMERIK drilling cycles changed by ``--units``/``--transform`` and written back to SINUMERIK (the defect
where a call once drilled twice, an ``MCALL CYCLE8x`` definition drilled where the tool stood and holes moved:
translate exited 0, verify failed).

Expected holes are hand-derived from the examples' text and the cycles' meaning [K: PGZ cycles manual 11/2006
2.1.2-2.1.10, as ``dialects/siemens/cycles.py`` reads them]: each hole is one feed move down to its depth,
at its position moved by the transform. Every bundled example is also checked by ``verify`` under the
options with the other mill examples (``tests/test_program_options_examples.py``); here the map that mirrors
and the inch output of each cycle example.
"""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics
from postproc.setup.machine_setup import load_setup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from postproc.transforms import parse_transform

ROOT = Path(__file__).resolve().parents[1]
SETUP = str(ROOT / "examples" / "setups" / "siemens_840d_mill.xml")
CYCLE_EXAMPLES = ("cycles.mpf", "drill_mcall.mpf", "holes.mpf", "deep_hole.mpf", "plate.mpf")


def _translate(name: str, **options: str) -> str:
    out = io.StringIO(newline="")
    text = (ROOT / "examples" / "siemens" / name).read_text(encoding="utf-8")
    translate(io.StringIO(text, newline=""), out, file=name, source="siemens", target="siemens",
              setup=load_setup(SETUP), diagnostics=Diagnostics(warn_stream=io.StringIO()), **options)
    return out.getvalue()


def _bottoms(text: str) -> list[tuple[float, float, float]]:
    """Each hole: where a feed move goes down below the work's top (Z0), in mm."""
    events = toolpath_events(io.StringIO(text, newline=""), file="out.mpf", dialect="siemens", setup=load_setup(SETUP))
    found = []
    z = None
    for event in events:
        if "move" not in event:
            continue
        if event["move"] == "feed" and float(event["z"]) < 0.0 and (z is None or float(event["z"]) < z):
            found.append((round(float(event["x"]), 4), round(float(event["y"]), 4), round(float(event["z"]), 4)))
        z = float(event["z"])
    return found


def test_cycles_moved_drill_each_hole_once_where_the_program_says() -> None:
    """cycles.mpf moved 5 mm along X: CYCLE81 once at (10,10) to -6, CYCLE82 once at (25,10) to -8, MCALL
    CYCLE85 at (40,10) and (40,25) to -12 (the definition block drills nothing), MCALL CYCLE89 at (55,25) to
    -12, CYCLE88 once at (70,25) to -15."""
    out = _translate("cycles.mpf", transform="translate 5,0,0")
    assert _bottoms(out) == [(15.0, 10.0, -6.0), (30.0, 10.0, -8.0), (45.0, 10.0, -12.0), (45.0, 25.0, -12.0),
                             (60.0, 25.0, -12.0), (75.0, 25.0, -15.0)]
    assert "N80 CYCLE81(20., 2., 0, -6.)" in out  # called once, not under MCALL: RFP+SDIS as RFP, SDIS 0
    assert out.count("MCALL CYCLE85") == 1 and out.count("MCALL CYCLE89") == 1


def test_cycles_in_inches_drill_the_same_holes() -> None:
    out = _translate("cycles.mpf", units="inch")
    assert "G700" in out
    assert _bottoms(out) == [(10.0, 10.0, -6.0), (25.0, 10.0, -8.0), (40.0, 10.0, -12.0), (40.0, 25.0, -12.0),
                             (55.0, 25.0, -12.0), (70.0, 25.0, -15.0)]


def test_drill_mcall_mirrored_drills_the_loops_holes_mirrored() -> None:
    """drill_mcall.mpf: MCALL CYCLE81 to -8 at X15, 30, 45 on Y10 (the WHILE loop), MCALL CYCLE82 to
    RFP-DPR = -2.5 at (15,30) and (45,30); mirrored in X."""
    out = _translate("drill_mcall.mpf", transform="mirror x")
    assert _bottoms(out) == [(-15.0, 10.0, -8.0), (-30.0, 10.0, -8.0), (-45.0, 10.0, -8.0), (-15.0, 30.0, -2.5),
                             (-45.0, 30.0, -2.5)]


def test_holes_moved_drill_the_row_and_the_circle() -> None:
    """holes.mpf: HOLES1 from (10,10) at 20 degrees, 5 then every 12 mm, 4 holes; HOLES2 about (80,40),
    radius 25, from 45 degrees, 6 holes 60 degrees apart; each to -8; moved 5 mm along X."""
    import math
    row = [(10 + (5 + 12 * k) * math.cos(math.radians(20)), 10 + (5 + 12 * k) * math.sin(math.radians(20)))
           for k in range(4)]
    circle = [(80 + 25 * math.cos(math.radians(45 + 60 * k)), 40 + 25 * math.sin(math.radians(45 + 60 * k)))
              for k in range(6)]
    expected = [(round(x + 5, 4), round(y, 4), -8.0) for x, y in row + circle]
    assert _bottoms(_translate("holes.mpf", transform="translate 5,0,0")) == expected


@pytest.mark.parametrize("option", ["units", "mirror"])
@pytest.mark.parametrize("name", CYCLE_EXAMPLES)
def test_a_cycle_example_verifies_under_the_option(name: str, option: str) -> None:
    options = {"units": "inch"} if option == "units" else {"transform": "mirror y about 20"}
    out = _translate(name, **options)
    text = (ROOT / "examples" / "siemens" / name).read_text(encoding="utf-8")
    report = verify_lines(io.StringIO(text, newline=""), io.StringIO(out, newline=""), file_in="a", file_out="b",
                          source="siemens", target="siemens", setup=load_setup(SETUP), allow_ignored=True,
                          transform=parse_transform(options["transform"]) if option == "mirror" else None)
    assert report.ok and report.moves > 10, report.summary() + "\n" + out


@pytest.mark.parametrize("options", [{"units": "inch"}, {"transform": "translate 5,0,0"}])
def test_a_changed_mcall_definition_is_written_where_it_stands(options: dict[str, str]) -> None:
    """The defect: the ``N110 MCALL CYCLE85(..)`` block, changed by the option, came out as a bare ``N110`` (its
    call was written later, before the first hole). Now the definition is its block: ``N110 G0`` (G0 stated, as
    before each written call) and the ``MCALL``, the holes their own position blocks, nothing without words."""
    out = _translate("cycles.mpf", **options)
    written = out.splitlines()
    assert not [line for line in written if line.strip().isalnum() and line.startswith("N")], out
    for number, name, hole in (("N110", "CYCLE85", "N120 X"), ("N150", "CYCLE89", "N160 X")):
        at = written.index(f"{number} G0")
        assert written[at + 1].startswith(f"MCALL {name}(") and written[at + 2].startswith(hole), out
    assert out.count("MCALL CYCLE85") == 1 and out.count("MCALL CYCLE89") == 1
