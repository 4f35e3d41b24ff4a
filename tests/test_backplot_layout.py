"""Backplot layout (issue 31, item 18): every text stays on the page, a lathe fills the page and its
drawing starts where the program's first move ends when the set-up gives no start, and an inch program
is labelled in inches. Checked on the SVG's elements; a text's extent is bounded by ``CHAR_WIDTH`` per
character (what the layout counts: the SVG's 12 px sans-serif averages less)."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import pytest
from lxml import etree

from postproc.drawing.backplot import HEIGHT, WIDTH
CHAR_WIDTH = 7.0  # postproc.drawing.canvas.CHAR_WIDTH (kept here: the test must run against the layout before it)
from postproc.commands.export import export_toolpath
from postproc.setup.machine_setup import InputSettings, MachineSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events

SVG = "{http://www.w3.org/2000/svg}"
LATHE = MachineSetup(input=InputSettings(machine_type="lathe"), machine=MachineSettings(axes="XZ"))
TURNING = "G21 G99\nT0101\nS500 M03\nG00 X64. Z2.\nG01 Z-40. F0.2\nX80.\nG00 X150. Z100.\nM30\n"
"""A bar turned from X64 Z2 (radius 32) to Z-40, then off to a change position at X150 Z100."""


def svg_of(text: str, setup: MachineSetup | None = None) -> etree._Element:
    out = io.StringIO()
    export_toolpath(text.splitlines(keepends=True), out, file="p.nc", dialect="fanuc", fmt="svg", setup=setup)
    return etree.fromstring(out.getvalue().encode())


def text_extents(root: etree._Element) -> list[tuple[str, float, float, float]]:
    """(text, left, right, baseline) of every text element, its width bounded by CHAR_WIDTH a character."""
    found = []
    for t in root.iter(SVG + "text"):
        x, y, width = float(t.get("x") or 0), float(t.get("y") or 0), len(t.text or "") * CHAR_WIDTH
        anchor = t.get("text-anchor") or "start"
        left = x - (width if anchor == "end" else width / 2 if anchor == "middle" else 0)
        found.append((t.text or "", left, left + width, y))
    return found


def off_the_page(root: etree._Element) -> list[str]:
    return [text for text, left, right, y in text_extents(root) if left < 0 or right > WIDTH or not 12 <= y <= HEIGHT]


def test_every_text_of_a_lathe_plot_is_on_the_page() -> None:
    """The vertical axis's name ``X radius (mm)`` was anchored at its end 8 px left of the panel: 91 px
    wide, it began left of the page."""
    root = svg_of(TURNING, LATHE)
    assert "X radius (mm)" in [t for t, *_ in text_extents(root)]
    assert off_the_page(root) == []


def test_every_text_of_a_mill_plot_with_a_wide_extent_is_on_the_page() -> None:
    """The extent line grew past the page's right edge with long numbers; it wraps now."""
    root = svg_of("G21 G90\nG00 X-12345.678 Y-23456.789 Z98765.4321\nG01 X12345.678 Y23456.789 Z-98765.4321 F100.\n")
    assert off_the_page(root) == []
    extent = " ".join(t.text or "" for t in root.iter(SVG + "text") if t.get("class") == "extent")
    assert "X -12345.7..12345.7" in extent and "Z -98765.4..98765.4 mm" in extent


def test_the_verify_legend_names_each_file_and_stays_on_the_page(cli: Any, tmp_path: Path) -> None:
    """It printed each program's path as given: an absolute one ran off the page."""
    deep = tmp_path.joinpath(*["a-rather-long-folder-name"] * 6)
    deep.mkdir(parents=True)
    src, out, picture = deep / "o1001_plate.nc", deep / "o1001_plate.ngc", tmp_path / "v.svg"
    src.write_text("G21 G90\nG00 X0. Y0. Z5.\nG01 Z-1. F100.\nX40.\nM30\n")
    out.write_text("G21 G90\nG0 X0. Y0. Z5.\nG1 Z-1. F100.\nX40.\nM2\n")
    result = cli("verify", src.resolve(), out.resolve(), "--from", "fanuc", "--to", "linuxcnc", "--plot", picture)
    assert result.status == 0, result.err
    root = etree.parse(str(picture)).getroot()
    names = [t.text or "" for t in root.iter(SVG + "text") if (t.get("class") or "").startswith("name-")]
    assert names == ["IN o1001_plate.nc: 2 feed, 1 rapid (rapids dashed)",
                     "OUT o1001_plate.ngc: 2 feed, 1 rapid (rapids dashed)"]
    assert off_the_page(root) == []


def _rects(root: etree._Element) -> list[tuple[float, float, float, float]]:
    return [(float(r.get("x") or 0), float(r.get("y") or 0), float(r.get("width") or 0), float(r.get("height") or 0))
            for g in root.iter(SVG + "g") if g.get("class") == "view" for r in g.iter(SVG + "rect")]


def test_a_lathe_fills_the_page() -> None:
    """Its two views took the left column, the legend the right top: half the page stayed empty. Now each
    view is the page's width (a turned part is long in Z) and the legend sits below them."""
    root = svg_of(TURNING, LATHE)
    rects = _rects(root)
    assert len(rects) == 2
    for x, y, w, h in rects:
        assert x + w > 0.9 * WIDTH and w > 2 * h  # across the whole page, wider than high
    bottom = max(y + h for x, y, w, h in rects)
    legend = [y for text, left, right, y in text_extents(root) if text.startswith("feed (")]
    assert legend and legend[0] > bottom  # the legend below the views, not beside them
    assert max(y for *_, y in text_extents(root)) > 0.75 * HEIGHT


def _rapids(root: etree._Element, title: str) -> list[list[tuple[float, float]]]:
    import re
    view = [g for g in root.iter(SVG + "g") if g.get("data-view") == title][0]
    return [[(float(a), float(b)) for a, b in re.findall(r"(-?[\d.]+),(-?[\d.]+)", run)]
            for p in view.iter(SVG + "path") if p.get("class") == "rapid" for run in (p.get("d") or "").split("M")
            if run.strip()]


def test_a_lathe_without_a_start_begins_at_its_first_move() -> None:
    """X0 Z0, the set-up's default start, is on the spindle axis at the part's face: the first rapid
    (to X64 Z2) was drawn from there through the part. The drawing now begins where it ends, and the
    start mark sits there; the legend says so."""
    root = svg_of(TURNING, LATHE)
    turning = "Turning (Z across, X radius up)"
    view = [g for g in root.iter(SVG + "g") if g.get("data-view") == turning][0]
    start = [c for c in view.iter(SVG + "circle") if c.get("class") == "start"][0]
    mark = (float(start.get("cx") or 0), float(start.get("cy") or 0))
    origin = [c for c in view.iter(SVG + "circle") if c.get("class") == "origin"][0]
    assert mark != (float(origin.get("cx") or 0), float(origin.get("cy") or 0))
    rapids = _rapids(root, turning)
    assert len(rapids) == 1  # only the move off to X150 Z100: none from the origin
    feed = [p for p in view.iter(SVG + "path") if p.get("class") == "feed"][0]
    assert (feed.get("d") or "").startswith(f"M{mark[0]:.2f},{mark[1]:.2f}")  # the cut starts at the mark
    texts = [t.text or "" for t in root.iter(SVG + "text")]
    assert "start (none in the set-up): the first move's end X32 Z2" in texts


def test_a_lathe_with_a_start_in_its_set_up_draws_the_first_rapid_from_it() -> None:
    placed = MachineSetup(input=InputSettings(machine_type="lathe"),
                          machine=MachineSettings(axes="XZ", start_x=100.0, start_z=150.0))
    root = svg_of(TURNING, placed)
    assert len(_rapids(root, "Turning (Z across, X radius up)")) == 2
    assert "start X100 Y0 Z150" in [t.text for t in root.iter(SVG + "text")]


INCH = "G20 G90 G17\nG00 X0. Y0. Z0.5\nG01 Z-0.1 F10.\nX4.\nY2.\nG00 Z1.\nM30\n"


def test_an_inch_program_is_labelled_in_inches() -> None:
    """It was drawn with ticks, extents and axis names in mm only. A 4 x 2 inch rectangle: ticks at whole
    inches, the extent in inches, the scale per inch; the toolpath itself stays in mm."""
    head = next(iter(toolpath_events(io.StringIO(INCH), file="p.nc", dialect="fanuc")))
    assert head == {"toolpath": 1, "units": "mm", "dialect": "fanuc", "program_units": "inch"}
    root = svg_of(INCH)
    units = sorted({t.text or "" for t in root.iter(SVG + "text") if t.get("class") == "unit"})
    assert units == ["X (in)", "Y (in)", "Z (in)"]
    plan = [g for g in root.iter(SVG + "g") if g.get("data-view") == "Plan (XY)"][0]
    ticks = [g for g in plan.iter(SVG + "g") if g.get("class") == "ticks" and g.get("data-axis") == "X"][0]
    labels = [t.text for t in ticks.iter(SVG + "text")]
    assert "4" in labels and "100" not in labels
    extent = " ".join(t.text or "" for t in root.iter(SVG + "text") if t.get("class") == "extent")
    assert extent.startswith("X 0..4  Y 0..2  Z -0.1..1 in")


@pytest.mark.parametrize("program", [INCH, INCH.replace("G20", "G21")])
def test_a_metric_program_keeps_mm_and_an_inch_one_says_so(program: str) -> None:
    head = next(iter(toolpath_events(io.StringIO(program), file="p.nc", dialect="fanuc")))
    assert head.get("program_units") == ("inch" if "G20" in program else None)
