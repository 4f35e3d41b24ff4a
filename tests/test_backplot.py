"""Backplot: the SVG is well-formed with one path per view, tool and kind of move; the PNG is not blank."""

from __future__ import annotations

import io
import math

import pytest
from lxml import etree

from postproc.drawing.backplot import DASH, HEIGHT, WIDTH, Backplot, dashes
from postproc.commands.export import export_toolpath
from postproc.simulate.toolpath import toolpath_events

SVG = "{http://www.w3.org/2000/svg}"
PROGRAM = "G21 G90\nG00 X10. Y0. Z5.\nG01 Z-1. F100.\nG03 X-10. Y0. I-10. J0.\nG00 Z5.\nX30.\nG01 Z0.\nM30\n"


def svg_of(text: str) -> etree._Element:
    out = io.StringIO()
    export_toolpath(text.splitlines(keepends=True), out, file="p.nc", dialect="fanuc", fmt="svg")
    return etree.fromstring(out.getvalue().encode())


def test_svg_parses_and_has_a_rapid_and_a_feed_path_per_view() -> None:
    root = svg_of(PROGRAM)
    assert root.tag == SVG + "svg" and root.get("viewBox") == f"0 0 {WIDTH} {HEIGHT}"
    paths = root.findall(f".//{SVG}path")
    assert len(paths) == 6  # plan, front and side views
    assert sorted(p.get("class") for p in paths) == ["feed"] * 3 + ["rapid"] * 3
    assert all(p.get("stroke-dasharray") for p in paths if p.get("class") == "rapid")
    assert not any(p.get("stroke-dasharray") for p in paths if p.get("class") == "feed")
    texts = [t.text for t in root.iter(SVG + "text")]
    assert "Plan (XY)" in texts and "Front (XZ)" in texts and "Side (YZ)" in texts
    assert any(t.startswith("feed (") for t in texts) and any(t.startswith("rapid (") for t in texts)


def test_svg_paths_stay_inside_the_canvas_and_break_at_kind_changes() -> None:
    root = svg_of(PROGRAM)
    for path in root.findall(f".//{SVG}path"):
        d = path.get("d") or ""
        points = [tuple(map(float, tok.lstrip("ML").split(","))) for tok in d.split()]
        assert all(0 <= x <= WIDTH and 0 <= y <= HEIGHT for x, y in points)
    feed = [p for p in root.findall(f".//{SVG}path") if p.get("class") == "feed"][0].get("d") or ""
    assert feed.count("M") == 2  # two separate feed runs: the plunge-and-arc, then the last plunge


def test_arcs_are_linearised_finely() -> None:
    plot = Backplot({"X": 10.0, "Y": 0.0, "Z": 0.0})
    plot.add({"move": "ccw", "x": -10, "y": 0, "z": 0, "cx": 0, "cy": 0, "cz": 0, "plane": "XY", "f": 1})
    points = list(plot.all_points())  # the points now stream through a spill store, not a plot.xyz array
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    assert len(xs) > 36
    assert all(abs(math.hypot(x, y) - 10) < 1e-9 and y >= -1e-9 for x, y in zip(xs, ys))


def test_only_rapids_gives_a_path_per_view() -> None:
    assert len(svg_of("G21 G90\nG00 X10. Y5. Z5.\nZ50.\n").findall(f".//{SVG}path")) == 3


def test_a_program_without_moves_still_draws() -> None:
    assert len(svg_of("G21\nM30\n").findall(f".//{SVG}path")) == 0


def test_png_has_the_canvas_size_and_both_colours() -> None:
    pytest.importorskip("PIL")
    from PIL import Image
    out = io.BytesIO()
    export_toolpath(PROGRAM.splitlines(keepends=True), out, file="p.nc", dialect="fanuc", fmt="png")
    image = Image.open(io.BytesIO(out.getvalue())).convert("RGB")
    assert image.size == (WIDTH, HEIGHT)
    colours = image.getcolors(maxcolors=1 << 16)
    assert colours is not None
    counts = {c: n for n, c in colours}
    assert counts.get((255, 255, 255), 0) < WIDTH * HEIGHT  # not blank
    assert any(r > 150 and g < 100 and b < 100 for r, g, b in counts)  # red rapids
    assert any(b > 120 and r < 80 for r, g, b in counts)  # blue feeds


def test_dashes_follow_the_pattern_across_vertices() -> None:
    on, off = DASH
    assert (on, off) == (6, 4)
    pieces = list(dashes([(0.0, 0.0), (12.0, 0.0), (12.0, 12.0)], (on, off)))
    lengths = [sum(math.dist(a, b) for a, b in zip(p, p[1:])) for p in pieces]
    assert lengths == pytest.approx([6.0, 6.0, 4.0])  # 0-6, 10-16 (round the corner), 20-24 (cut at the end)
    assert [c for p in pieces[1] for c in p] == pytest.approx([10.0, 0.0, 12.0, 0.0, 12.0, 4.0])


def test_backplot_from_events_api() -> None:
    plot = Backplot({"X": 0.0, "Y": 0.0, "Z": 0.0})
    plot.add_all(toolpath_events(PROGRAM.splitlines(keepends=True), file="p.nc", dialect="fanuc"))
    assert plot.moves == {1: 3, 2: 3}


def test_a_long_run_is_split_into_bounded_paths_that_join_up(monkeypatch: pytest.MonkeyPatch) -> None:
    """Memory stays bounded on long programs: at most PATH_POINTS points per <path>, and each piece
    starts where the previous one ended, so the drawing is unbroken."""
    import postproc.drawing.backplot as backplot
    monkeypatch.setattr(backplot, "PATH_POINTS", 10)
    moves = "".join(f"X{i}. Y{(i % 3)}.\n" for i in range(1, 26))
    root = svg_of("G21 G90\nG00 X0. Y0. Z0.\nG01 F100.\n" + moves + "M30\n")
    feeds = [p for p in root.findall(f".//{SVG}path") if p.get("class") == "feed"]
    assert len(feeds) == 9  # 25 moves -> 3 pieces per view
    plan = [p.get("d") for p in feeds[:3]]
    ends = [d.split(" L")[-1] for d in plan[:-1]]
    starts = [d[1:].split(" L")[0] for d in plan[1:]]
    assert ends == starts
