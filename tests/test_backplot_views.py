"""What a machinist reads off a backplot, checked on the SVG's elements (not pixels): one feed colour
per tool and the same in every view, rapids dashed, the start point and the work origin where the path
puts them, ticks that agree with the path, a legend naming each tool."""

from __future__ import annotations

import io
import math
import re

from lxml import etree

from postproc.drawing.backplot import Backplot
from postproc.commands.export import export_toolpath
from postproc.setup.machine_setup import InputSettings, MachineSetup

SVG = "{http://www.w3.org/2000/svg}"
TWO_TOOLS = ("G21 G90 G17\nT1 M06\nG00 X-20. Y-10. Z5.\nG01 Z-1. F100.\nX40.\nG03 X60. Y10. I0. J20.\n"
             "G00 Z5.\nT2 M06\nG00 X10. Y30.\nG01 Z-3. F80.\nG02 X30. Y30. I10. J0.\nG00 Z50.\nM30\n")


def svg_of(text: str, setup: MachineSetup | None = None, dialect: str = "fanuc") -> etree._Element:
    out = io.StringIO()
    export_toolpath(text.splitlines(keepends=True), out, file="p.nc", dialect=dialect, fmt="svg", setup=setup)
    return etree.fromstring(out.getvalue().encode())


def plot_svg(plot: Backplot) -> etree._Element:
    out = io.StringIO()
    plot.write_svg(out)
    return etree.fromstring(out.getvalue().encode())


def views(root: etree._Element) -> dict[str, etree._Element]:
    return {g.get("data-view"): g for g in root.iter(SVG + "g") if g.get("class") == "view"}


def points(path: etree._Element) -> list[tuple[float, float]]:
    return [(float(x), float(y)) for x, y in re.findall(r"(-?[\d.]+),(-?[\d.]+)", path.get("d") or "")]


def centre(el: etree._Element) -> tuple[float, float]:
    return float(el.get("cx") or "nan"), float(el.get("cy") or "nan")


def test_three_views_each_with_one_feed_colour_per_tool_and_dashed_rapids() -> None:
    root = svg_of(TWO_TOOLS)
    found = views(root)
    assert list(found) == ["Plan (XY)", "Front (XZ)", "Side (YZ)"]
    colours: dict[str, set[str]] = {}
    for view in found.values():
        paths = view.findall(SVG + "path")
        feeds = [p for p in paths if p.get("class") == "feed"]
        rapids = [p for p in paths if p.get("class") == "rapid"]
        assert sorted(p.get("data-tool") for p in feeds) == ["T1", "T2"]
        for p in feeds:
            colours.setdefault(p.get("data-tool") or "", set()).add(p.get("stroke") or "")
            assert p.get("stroke-dasharray") is None
        assert rapids and all(p.get("stroke-dasharray") == "6,4" for p in rapids)
        assert len({p.get("stroke") for p in rapids}) == 1
    assert all(len(c) == 1 for c in colours.values())  # a tool has one colour in every view
    t1, t2 = colours["T1"].pop(), colours["T2"].pop()
    rapid = [p for p in root.iter(SVG + "path") if p.get("class") == "rapid"][0].get("stroke")
    assert len({t1, t2, rapid}) == 3


def test_the_legend_names_each_tool_with_its_colour_and_moves() -> None:
    root = svg_of(TWO_TOOLS)
    legend = [g for g in root.iter(SVG + "g") if g.get("class") == "legend"][0]
    tools = [t.text for t in legend.iter(SVG + "text") if t.get("class") == "tool"]
    # T1: the plunge, the X move and the arc are feeds; the approach and the retract rapids.
    # T2: the plunge and the arc; the approach and the final retract.
    assert tools == ["T1: 3 feed, 2 rapid", "T2: 2 feed, 2 rapid"]
    swatches = [line.get("stroke") for line in legend.iter(SVG + "line") if line.get("class") == "tool-swatch"]
    plan = views(root)["Plan (XY)"]
    feed_colour = {p.get("data-tool"): p.get("stroke") for p in plan.findall(SVG + "path")
                   if p.get("class") == "feed"}
    assert swatches == [feed_colour["T1"], feed_colour["T2"]]


def test_a_program_without_a_tool_is_drawn_as_no_tool() -> None:
    root = svg_of("G21 G90\nG00 X10. Y5. Z5.\nG01 Z0. F50.\n")
    legend = [g for g in root.iter(SVG + "g") if g.get("class") == "legend"][0]
    assert [t.text for t in legend.iter(SVG + "text") if t.get("class") == "tool"] == ["no tool: 1 feed, 1 rapid"]


def start_and_origin_plot() -> Backplot:
    plot = Backplot({"X": 50.0, "Y": 40.0, "Z": 30.0})
    plot.add({"move": "rapid", "x": 0.0, "y": 0.0, "z": 0.0})
    plot.add({"move": "feed", "x": -20.0, "y": 10.0, "z": -5.0, "f": 100.0})
    return plot


def test_start_and_origin_marks_sit_where_the_path_is_there() -> None:
    """The rapid runs from the start (50, 40, 30) to the origin: its first point is the start mark and its
    last the origin mark, in every view; the offset between the marks has the start's proportions."""
    expected = {"Plan (XY)": (50, 40), "Front (XZ)": (50, 30), "Side (YZ)": (40, 30)}
    for title, view in views(plot_svg(start_and_origin_plot())).items():
        rapid = [p for p in view.findall(SVG + "path") if p.get("class") == "rapid"][0]
        first, last = points(rapid)[0], points(rapid)[-1]
        start = [c for c in view.iter(SVG + "circle") if c.get("class") == "start"]
        origin = [c for c in view.iter(SVG + "circle") if c.get("class") == "origin"]
        assert len(start) == 1 and len(origin) == 1
        assert math.dist(centre(start[0]), first) < 0.02 and math.dist(centre(origin[0]), last) < 0.02
        dx, dy = centre(start[0])[0] - centre(origin[0])[0], centre(start[0])[1] - centre(origin[0])[1]
        h, v = expected[title]
        assert dx > 0 and dy < 0 and abs(-dy / dx - v / h) < 1e-3  # up the page is +Y/+Z


def ticks(view: etree._Element, axis: str) -> list[tuple[float, float]]:
    """(value, pixel position along the edge) of one axis' ticks."""
    group = [g for g in view.iter(SVG + "g") if g.get("class") == "ticks" and g.get("data-axis") == axis][0]
    labels = [t for t in group.iter(SVG + "text")]
    lines = [ln for ln in group.iter(SVG + "line")]
    assert len(labels) == len(lines) >= 3
    horizontal = lines[0].get("x1") == lines[0].get("x2")
    return [(float(t.text or ""), float(ln.get("x1" if horizontal else "y1") or ""))
            for t, ln in zip(labels, lines)]


def test_ticks_are_round_evenly_spaced_and_agree_with_the_path() -> None:
    """Tick values step by 1, 2 or 5 times a power of ten, one px/mm for every axis of every view, and the
    0 tick lines up with the origin mark."""
    root = plot_svg(start_and_origin_plot())
    scales: set[float] = set()
    for title, view in views(root).items():
        h, v = title[-3], title[-2]
        origin = centre([c for c in view.iter(SVG + "circle") if c.get("class") == "origin"][0])
        for axis, along, sign in ((h, origin[0], 1), (v, origin[1], -1)):
            found = ticks(view, axis)
            values = [val for val, _ in found]
            steps = {round(b - a, 9) for a, b in zip(values, values[1:])}
            assert len(steps) == 1
            step = steps.pop()
            assert round(step / 10 ** math.floor(math.log10(step)), 9) in (1, 2, 5)
            (v0, p0), (v1, p1) = found[0], found[-1]
            scale = sign * (p1 - p0) / (v1 - v0)
            scales.add(scale)
            zero = [p for val, p in found if val == 0]
            assert zero and abs(zero[0] - along) < 0.02
    assert max(scales) / min(scales) < 1.001  # pixels are written to 0.01
    units = [t.text for t in root.iter(SVG + "text") if t.get("class") == "unit"]
    assert sorted(set(units)) == ["X (mm)", "Y (mm)", "Z (mm)"]


def test_a_lathe_draws_zx_with_ticks_in_radius() -> None:
    lathe = MachineSetup(input=InputSettings(machine_type="lathe"))
    root = svg_of("S500 M03\nG00 X100. Z5.\nG01 Z-20. F0.2\nX60.\n", setup=lathe)
    found = views(root)
    assert list(found) == ["Turning (Z across, X radius up)", "Mirrored (X radius down)"]
    turning = found["Turning (Z across, X radius up)"]
    values = [v for v, _ in ticks(turning, "X")]  # X100 diameter is 50 radius: ticks in radii stop near 50
    assert 40.0 in values and max(values) < 75.0  # (in diameters they would run to 100)
    assert "X radius (mm)" in [t.text for t in root.iter(SVG + "text") if t.get("class") == "unit"]
