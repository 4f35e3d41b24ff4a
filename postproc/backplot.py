"""Backplot: a toolpath drawn as a plan view (XY) and a side view (XZ) side by side, as SVG or PNG.

Streaming-friendly: the whole drawing keeps one flat array of points (three doubles and one byte
each), never an object per move; arcs are linearised on arrival within ``CHORD_ERROR`` mm. Scaling
needs the extent of the whole path, so the picture is written at the end. Rapids are dashed, feeds
solid; both views share one scale so X lines up.
"""

from __future__ import annotations

import math
from array import array
from typing import Any, BinaryIO, Iterable, Sequence, TextIO

from lxml import etree

from .errors import UsageError
from .geometry import CENTRE_KEYS, arc_points

SVG_NS = "http://www.w3.org/2000/svg"
PATH_POINTS = 20000
"""Most points in one SVG <path>: long programs get several paths of a kind instead of one huge one."""


def _svg(tag: str) -> str:
    """A child element's tag: written without a prefix, it sits in the root's default SVG namespace."""
    return tag


class _TextSink:
    """Lets lxml's incremental writer (which writes bytes) write into a text stream."""

    def __init__(self, out: TextIO) -> None:
        self.out = out

    def write(self, data: bytes) -> None:
        self.out.write(data.decode("utf-8"))

CHORD_ERROR = 0.01
"""Largest distance in mm between a drawn chord and the arc it stands for."""

RAPID, FEED = 1, 2
"""Point codes: the kind of the segment that ends at the point (0: the path's first point)."""

WIDTH, HEIGHT = 1000, 560
PANEL = 470
"""Each view is a square panel of this many pixels; the plot inside keeps ``MARGIN`` from its edge."""
MARGIN = 20
TOP = 30
"""Room above the panels for the view titles."""
COLOURS = {RAPID: "#d62728", FEED: "#1f4e9c"}
DASH = (6, 4)
"""Rapid dash pattern in pixels: drawn, gap."""
STROKE = 1.2


class Backplot:
    """Collects a toolpath's points; ``write_svg``/``write_png`` draw them."""

    def __init__(self, start: dict[str, float], lathe: bool = False) -> None:
        self.lathe = lathe
        """Draw the ZX plane of a lathe: Z across, X (a radius, true geometry) up, and mirrored below the
        axis in the second view; a diameter toolpath (``x_mode``) is halved as it comes."""
        self.half = False
        self.pos = (start.get("X", 0.0), start.get("Y", 0.0), start.get("Z", 0.0))
        self.xyz = array("d", self.pos)
        self.codes = array("B", [0])
        self.moves = {RAPID: 0, FEED: 0}

    # -- collecting --------------------------------------------------------------------------------
    def add_all(self, events: Iterable[dict[str, Any]]) -> None:
        add = self.add
        for ev in events:
            if "move" in ev:
                add(ev)
            elif ev.get("x_mode") == "diameter":
                self.half = True

    def add(self, ev: dict[str, Any]) -> None:
        """One motion event (other events are ignored)."""
        kind = ev.get("move")
        if kind is None:
            return
        x, y, z = self.pos
        if self.half:
            ev = {k: (v / 2.0 if k in ("x", "cx") else v) for k, v in ev.items()}
        end = (float(ev.get("x", x)), float(ev.get("y", y)), float(ev.get("z", z)))
        code = RAPID if kind == "rapid" else FEED
        self.moves[code] += 1
        if kind in ("cw", "ccw"):
            centre = tuple(float(ev.get(CENTRE_KEYS[a], p)) for a, p in zip("XYZ", self.pos))
            for p in arc_points(self.pos, end, centre, ev.get("plane", "XY"), kind == "cw",  # type: ignore[arg-type]
                                CHORD_ERROR):
                self.xyz.extend(p)
                self.codes.append(code)
        else:
            self.xyz.extend(end)
            self.codes.append(code)
        self.pos = end

    # -- layout ------------------------------------------------------------------------------------
    def bounds(self) -> tuple[float, float, float, float, float, float]:
        xs, ys, zs = self.xyz[0::3], self.xyz[1::3], self.xyz[2::3]
        return min(xs), max(xs), min(ys), max(ys), min(zs), max(zs)

    def transforms(self) -> tuple[Any, Any, float]:
        """Model -> pixel maps for the plan and side views, and the common scale (px per mm)."""
        x0, x1, y0, y1, z0, z1 = self.bounds()
        inner = PANEL - 2 * MARGIN
        spans = [s for s in (x1 - x0, y1 - y0, z1 - z0) if s > 1e-9]
        scale = inner / max(spans) if spans else 1.0
        xc, yc, zc = (x0 + x1) / 2, (y0 + y1) / 2, (z0 + z1) / 2
        cy = TOP + PANEL / 2
        left_c = MARGIN / 2 + PANEL / 2
        right_c = WIDTH - MARGIN / 2 - PANEL / 2

        def plan(i: int) -> tuple[float, float]:
            return left_c + (self.xyz[i] - xc) * scale, cy - (self.xyz[i + 1] - yc) * scale

        def side(i: int) -> tuple[float, float]:
            return right_c + (self.xyz[i] - xc) * scale, cy - (self.xyz[i + 2] - zc) * scale

        if self.lathe:
            def turning(i: int) -> tuple[float, float]:
                return left_c + (self.xyz[i + 2] - zc) * scale, cy - (self.xyz[i] - xc) * scale

            def mirrored(i: int) -> tuple[float, float]:
                return right_c + (self.xyz[i + 2] - zc) * scale, cy + (self.xyz[i] - xc) * scale

            return turning, mirrored, scale
        return plan, side, scale

    def polylines(self, kind: int, view: Any) -> Iterable[list[tuple[float, float]]]:
        """The connected runs of one kind of segment, in pixels; a run longer than ``PATH_POINTS`` comes
        in pieces that continue from each other's last point."""
        codes = self.codes
        run: list[tuple[float, float]] = []
        for n in range(1, len(codes)):
            if codes[n] == kind:
                if not run:
                    run.append(view(3 * (n - 1)))
                run.append(view(3 * n))
                if len(run) > PATH_POINTS:
                    yield run
                    run = [run[-1]]
            elif run:
                yield run
                run = []
        if run:
            yield run

    def panels(self) -> list[tuple[str, float]]:
        """Title and left edge of each view panel."""
        if self.lathe:
            return [("Turning (Z across, X radius up)", MARGIN / 2),
                    ("Mirrored (X radius down)", WIDTH - MARGIN / 2 - PANEL)]
        return [("Plan (XY)", MARGIN / 2), ("Side (XZ)", WIDTH - MARGIN / 2 - PANEL)]

    # -- SVG ---------------------------------------------------------------------------------------
    def write_svg(self, out: TextIO) -> None:
        """One <path> per view and kind of move that occurs (at most four), a frame and a legend.
        Streamed with lxml's incremental writer: one path's data at a time is in memory."""
        plan, side, scale = self.transforms()
        size = {"width": str(WIDTH), "height": str(HEIGHT)}
        with etree.xmlfile(_TextSink(out), encoding="utf-8") as xf:
            xf.write_declaration()
            with xf.element(f"{{{SVG_NS}}}svg", {**size, "viewBox": f"0 0 {WIDTH} {HEIGHT}", "font-family": "sans-serif",
                                          "font-size": "12"}, nsmap={None: SVG_NS}):
                xf.write("\n", etree.Element(_svg("rect"), {**size, "fill": "white"}), "\n")
                for (title, left), view in zip(self.panels(), (plan, side)):
                    with xf.element(_svg("g"), {"class": "view"}):
                        frame = etree.Element(_svg("rect"), x=f"{left:g}", y=f"{TOP:g}", width=f"{PANEL:g}",
                                              height=f"{PANEL:g}", fill="none", stroke="#bbbbbb")
                        label = etree.Element(_svg("text"), x=f"{left + 4:g}", y=f"{TOP - 8:g}")
                        label.text = title
                        xf.write("\n", frame, "\n", label, "\n")
                        for kind, cls in ((RAPID, "rapid"), (FEED, "feed")):  # cuts drawn over rapids
                            if self.moves[kind]:
                                for path in self._svg_paths(kind, cls, view):
                                    xf.write(path, "\n")
                    xf.write("\n")
                legend = etree.Element(_svg("g"), {"class": "legend"})
                self._svg_legend(legend, scale)
                xf.write(legend, "\n")
        out.write("\n")

    def _svg_paths(self, kind: int, cls: str, view: Any) -> Iterable[etree._Element]:
        """The moves of one kind as <path>s of at most ``PATH_POINTS`` points each: one path for any
        ordinary program, and bounded memory however long the program is."""
        parts: list[str] = []
        count = 0
        for run in self.polylines(kind, view):
            parts.append("M" + " L".join(f"{px:.2f},{py:.2f}" for px, py in run))
            count += len(run)
            if count >= PATH_POINTS:
                yield self._svg_path(kind, cls, " ".join(parts))
                parts, count = [], 0
        if parts:
            yield self._svg_path(kind, cls, " ".join(parts))

    @staticmethod
    def _svg_path(kind: int, cls: str, d: str) -> etree._Element:
        path = etree.Element(_svg("path"), {"class": cls, "fill": "none", "stroke": COLOURS[kind], "d": d,
                                            "stroke-width": f"{STROKE:g}", "stroke-linejoin": "round"})
        if kind == RAPID:
            path.set("stroke-dasharray", f"{DASH[0]:g},{DASH[1]:g}")
        return path

    def _svg_legend(self, legend: etree._Element, scale: float) -> None:
        y = TOP + PANEL + 28
        x = MARGIN / 2
        for dx, kind, label in ((0, FEED, "feed"), (130, RAPID, "rapid")):
            line = etree.SubElement(legend, _svg("line"), x1=f"{x + dx:g}", y1=f"{y - 4:g}", x2=f"{x + dx + 30:g}",
                                    y2=f"{y - 4:g}", stroke=COLOURS[kind])
            line.set("stroke-width", f"{STROKE:g}")
            if kind == RAPID:
                line.set("stroke-dasharray", f"{DASH[0]:g},{DASH[1]:g}")
            etree.SubElement(legend, _svg("text"), x=f"{x + dx + 36:g}", y=f"{y:g}").text = \
                f"{label} ({self.moves[kind]})"
        etree.SubElement(legend, _svg("text"), x=f"{x + 280:g}", y=f"{y:g}").text = self._extent_text(scale)

    def _extent_text(self, scale: float) -> str:
        x0, x1, y0, y1, z0, z1 = self.bounds()
        return (f"X {x0:g}..{x1:g}  Y {y0:g}..{y1:g}  Z {z0:g}..{z1:g} mm  "
                f"(1 mm = {scale:.3g} px)")

    # -- PNG ---------------------------------------------------------------------------------------
    def write_png(self, out: BinaryIO) -> None:
        """The same drawing rasterised with Pillow (the ``render`` extra)."""
        try:
            from PIL import Image, ImageDraw
        except ImportError:
            raise UsageError("--format png needs Pillow: pip install 'postproc[render]'") from None
        plan, side, scale = self.transforms()
        image = Image.new("RGB", (WIDTH, HEIGHT), "white")
        draw = ImageDraw.Draw(image)
        width = max(1, round(STROKE))
        for (title, left), view in zip(self.panels(), (plan, side)):
            draw.rectangle((left, TOP, left + PANEL, TOP + PANEL), outline="#bbbbbb")
            draw.text((left + 4, TOP - 20), title, fill="black")
            for run in self.polylines(RAPID, view):
                for seg in dashes(run, DASH):
                    draw.line(seg, fill=COLOURS[RAPID], width=width)
            for run in self.polylines(FEED, view):  # cuts drawn over rapids
                draw.line(run, fill=COLOURS[FEED], width=width, joint="curve")
        y = TOP + PANEL + 28
        x = MARGIN / 2
        draw.line(((x, y - 4), (x + 30, y - 4)), fill=COLOURS[FEED], width=width)
        draw.text((x + 36, y - 10), f"feed ({self.moves[FEED]})", fill="black")
        for seg in dashes([(x + 130, y - 4), (x + 160, y - 4)], DASH):
            draw.line(seg, fill=COLOURS[RAPID], width=width)
        draw.text((x + 166, y - 10), f"rapid ({self.moves[RAPID]})", fill="black")
        draw.text((x + 280, y - 10), self._extent_text(scale), fill="black")
        image.save(out, format="PNG")


def dashes(points: Sequence[tuple[float, float]], pattern: tuple[float, float]) -> Iterable[list[tuple[float, float]]]:
    """Split a polyline into its drawn dashes; the pattern runs on across vertices (PIL has no dashes)."""
    on, off = pattern
    period = on + off
    phase = 0.0  # distance into the current period
    dash: list[tuple[float, float]] = []
    for (ax, ay), (bx, by) in zip(points, points[1:]):
        length = math.hypot(bx - ax, by - ay)
        done = 0.0
        while done < length:
            drawing = phase < on
            left = (on - phase) if drawing else (period - phase)
            step = min(left, length - done)
            t0, t1 = done / length, (done + step) / length
            if drawing:
                if not dash:
                    dash.append((ax + (bx - ax) * t0, ay + (by - ay) * t0))
                dash.append((ax + (bx - ax) * t1, ay + (by - ay) * t1))
            done += step
            phase += step
            if phase >= period - 1e-9:
                phase = 0.0
            if phase >= on and dash:
                yield dash
                dash = []
    if len(dash) > 1:
        yield dash
