"""verify --plot: both toolpaths in one picture with the largest deviation marked where it happens."""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any

import pytest
from lxml import etree

SVG = "{http://www.w3.org/2000/svg}"
SOURCE = ("G21 G90 G17\nG00 X0. Y0. Z5.\nG01 Z-1. F100.\nX40.\nY30.\nG00 Z5.\nM30\n")
SHIFTED = SOURCE.replace("Y30.", "Y30.5")  # the corner 0.5 mm off, by hand


def run(cli: Any, tmp_path: Path, translation: str, plot: str) -> tuple[Any, Path]:
    src, out, picture = tmp_path / "in.nc", tmp_path / "out.nc", tmp_path / plot
    src.write_text(SOURCE)
    out.write_text(translation)
    return cli("verify", src, out, "--from", "fanuc", "--to", "fanuc", "--plot", picture), picture


def test_the_overlay_marks_the_largest_deviation_at_its_place(cli: Any, tmp_path: Path) -> None:
    result, picture = run(cli, tmp_path, SHIFTED, "diff.svg")
    assert result.status == 1  # 0.5 mm exceeds the tolerance: the picture is still written
    root = etree.parse(str(picture)).getroot()
    texts = [t.text or "" for t in root.iter(SVG + "text")]
    assert "largest deviation 0.5000 mm at IN:5 / OUT:5" in texts
    plan = [g for g in root.iter(SVG + "g") if g.get("data-view") == "Plan (XY)"][0]
    sides = {p.get("data-side") for p in plan.iter(SVG + "path")}
    assert sides == {"in", "out"}
    feed_in = [p for p in plan.iter(SVG + "path") if p.get("data-side") == "in" and p.get("class") == "feed"][0]
    corner = [tuple(map(float, xy)) for xy in re.findall(r"(-?[\d.]+),(-?[\d.]+)", feed_in.get("d") or "")][-1]
    mark = [c for c in plan.iter(SVG + "circle") if c.get("class") == "deviation"]
    assert len(mark) == 1
    assert math.dist((float(mark[0].get("cx") or 0), float(mark[0].get("cy") or 0)), corner) < 0.02
    # the line from IN's point to OUT's is 0.5 mm straight up the page, in the picture's px per mm
    group = [g for g in plan.iter(SVG + "g") if g.get("class") == "deviation"][0]
    line = group.find(SVG + "line")
    assert line is not None
    ticks = [g for g in plan.iter(SVG + "g") if g.get("class") == "ticks" and g.get("data-axis") == "X"][0]
    values = [float(t.text or "") for t in ticks.iter(SVG + "text")]
    xs = [float(ln.get("x1") or "") for ln in ticks.iter(SVG + "line")]
    px_per_mm = (xs[-1] - xs[0]) / (values[-1] - values[0])
    dx = float(line.get("x2") or "") - float(line.get("x1") or "")
    dy = float(line.get("y2") or "") - float(line.get("y1") or "")
    assert abs(dx) < 0.02 and dy == pytest.approx(-0.5 * px_per_mm, abs=0.03)
    for title in ("Front (XZ)", "Side (YZ)"):
        view = [g for g in root.iter(SVG + "g") if g.get("data-view") == title][0]
        assert len([c for c in view.iter(SVG + "circle") if c.get("class") == "deviation"]) == 1


def test_identical_programs_plot_with_zero_deviation(cli: Any, tmp_path: Path) -> None:
    result, picture = run(cli, tmp_path, SOURCE, "same.svg")
    assert result.status == 0, result.err
    texts = [t.text or "" for t in etree.parse(str(picture)).getroot().iter(SVG + "text")]
    assert any(t.startswith("largest deviation 0.0000 mm") for t in texts)


def test_the_overlay_as_png(cli: Any, tmp_path: Path) -> None:
    pytest.importorskip("PIL")
    from PIL import Image
    result, picture = run(cli, tmp_path, SHIFTED, "diff.png")
    assert result.status == 1
    image = Image.open(picture).convert("RGB")
    colours = image.getcolors(maxcolors=1 << 20) or []
    assert any(c == (0xE6, 0x00, 0x8A) for _, c in colours)  # the deviation mark


def test_a_plot_name_without_a_picture_suffix_is_wrong_usage(cli: Any, tmp_path: Path) -> None:
    result, picture = run(cli, tmp_path, SOURCE, "diff.txt")
    assert result.status == 2 and "--plot" in result.err and "must end in .svg or .png" in result.err
    assert not picture.exists()


def test_a_lathe_overlay_marks_the_deviation_on_the_radius_drawing(cli: Any, tmp_path: Path) -> None:
    """GSK programs diameters; the picture draws radii, so the mark must be halved too: it sits on the
    source's corner at X30 diameter (radius 15), not at radius 30."""
    src, out, picture = tmp_path / "in.nc", tmp_path / "out.nc", tmp_path / "lathe.svg"
    src.write_text("G00 X40. Z2.\nG01 X30. F80.\nZ-20.\nG00 X40.\n")
    out.write_text("G00 X40. Z2.\nG01 X30. F80.\nZ-20.5\nG00 X40.\n")
    assert cli("verify", src, out, "--from", "gsk", "--to", "gsk", "--plot", picture).status == 1
    root = etree.parse(str(picture)).getroot()
    turning = [g for g in root.iter(SVG + "g") if g.get("data-view") == "Turning (Z across, X radius up)"][0]
    feed_in = [p for p in turning.iter(SVG + "path") if p.get("data-side") == "in" and p.get("class") == "feed"][0]
    corner = [tuple(map(float, xy)) for xy in re.findall(r"(-?[\d.]+),(-?[\d.]+)", feed_in.get("d") or "")][-1]
    mark = [c for c in turning.iter(SVG + "circle") if c.get("class") == "deviation"][0]
    assert math.dist((float(mark.get("cx") or 0), float(mark.get("cy") or 0)), corner) < 0.02
