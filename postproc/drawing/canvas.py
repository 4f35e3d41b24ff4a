"""Two drawing surfaces with one small vocabulary (lines, paths, circles, text), so a backplot is drawn
once and written as SVG (streamed with lxml) or PNG (Pillow, the optional ``render`` extra).

Why not SVG only: a PNG opens everywhere a shop has a screen; why not PNG only: SVG can be parsed, so
tests check what is drawn (classes, colours, dash patterns) rather than pixels.
"""

from __future__ import annotations

import contextlib
import math
from typing import Any, BinaryIO, Iterable, Iterator, Sequence, TextIO

from lxml import etree

from ..errors import UsageError

SVG_NS = "http://www.w3.org/2000/svg"
Point = tuple[float, float]
CHAR_WIDTH = 7.0
"""Width in pixels a character of text takes at most, as the layout counts it: the SVG's 12 px sans-serif
averages about 6.7 px for digits and capitals, Pillow's default font 6 px. Neither surface measures text
for the layout (SVG cannot), so text is placed and wrapped by this bound."""


def text_width(text: str) -> float:
    """The width ``text`` takes at most (``CHAR_WIDTH`` per character)."""
    return len(text) * CHAR_WIDTH


def wrap(text: str, width: float) -> list[str]:
    """``text`` in lines of at most ``width`` pixels: broken at spaces, and within a word (a long file
    name) only where a word alone is too wide."""
    import textwrap
    return textwrap.wrap(text, max(1, int(width // CHAR_WIDTH)), break_on_hyphens=False) or [""]


class _TextSink:
    """Lets lxml's incremental writer (which writes bytes) write into a text stream."""

    def __init__(self, out: TextIO) -> None:
        self.out = out

    def write(self, data: bytes) -> None:
        self.out.write(data.decode("utf-8"))


def _num(value: float) -> str:
    return f"{value:.2f}".rstrip("0").rstrip(".")


class SvgCanvas:
    """Writes each element as it is drawn: one path's data at a time is in memory."""

    def __init__(self, xf: Any) -> None:
        self.xf = xf

    @staticmethod
    @contextlib.contextmanager
    def open(out: TextIO, width: int, height: int) -> Iterator["SvgCanvas"]:
        size = {"width": str(width), "height": str(height)}
        with etree.xmlfile(_TextSink(out), encoding="utf-8") as xf:
            xf.write_declaration()
            with xf.element(f"{{{SVG_NS}}}svg", {**size, "viewBox": f"0 0 {width} {height}",
                                                 "font-family": "sans-serif", "font-size": "12"},
                            nsmap={None: SVG_NS}):
                xf.write("\n", etree.Element("rect", {**size, "fill": "white"}), "\n")
                yield SvgCanvas(xf)
        out.write("\n")

    @contextlib.contextmanager
    def group(self, cls: str, **attrs: str) -> Iterator[None]:
        with self.xf.element("g", {"class": cls, **attrs}):
            yield
        self.xf.write("\n")

    def _put(self, tag: str, attrs: dict[str, str], text: str | None = None) -> None:
        el = etree.Element(tag, attrs)
        if text is not None:
            el.text = text
        self.xf.write(el, "\n")

    def rect(self, x: float, y: float, w: float, h: float, stroke: str) -> None:
        self._put("rect", {"x": _num(x), "y": _num(y), "width": _num(w), "height": _num(h), "fill": "none",
                           "stroke": stroke})

    def line(self, a: Point, b: Point, colour: str, width: float = 1.0, dash: Sequence[float] | None = None,
             cls: str | None = None) -> None:
        attrs = {"x1": _num(a[0]), "y1": _num(a[1]), "x2": _num(b[0]), "y2": _num(b[1]), "stroke": colour,
                 "stroke-width": f"{width:g}"}
        if dash:
            attrs["stroke-dasharray"] = ",".join(f"{d:g}" for d in dash)
        if cls:
            attrs["class"] = cls
        self._put("line", attrs)

    def circle(self, c: Point, r: float, colour: str, fill: str = "none", cls: str | None = None) -> None:
        attrs = {"cx": _num(c[0]), "cy": _num(c[1]), "r": f"{r:g}", "stroke": colour, "fill": fill}
        if cls:
            attrs["class"] = cls
        self._put("circle", attrs)

    def text(self, at: Point, text: str, anchor: str = "start", colour: str = "black",
             cls: str | None = None) -> None:
        attrs = {"x": _num(at[0]), "y": _num(at[1])}
        if anchor != "start":
            attrs["text-anchor"] = anchor
        if colour != "black":
            attrs["fill"] = colour
        if cls:
            attrs["class"] = cls
        self._put("text", attrs, text)

    def path(self, runs: Iterable[Sequence[Point]], colour: str, width: float, dash: Sequence[float] | None,
             cls: str, **extra: str) -> None:
        """One <path> of several connected runs (``M`` starts each)."""
        d = " ".join("M" + " L".join(f"{x:.2f},{y:.2f}" for x, y in run) for run in runs)
        attrs = {"class": cls, "fill": "none", "stroke": colour, "d": d, "stroke-width": f"{width:g}",
                 "stroke-linejoin": "round", **extra}
        if dash:
            attrs["stroke-dasharray"] = ",".join(f"{v:g}" for v in dash)
        self._put("path", attrs)


class PngCanvas:
    """The same drawing rasterised with Pillow; groups and classes have no meaning here."""

    def __init__(self, width: int, height: int) -> None:
        try:
            from PIL import Image, ImageDraw
        except ImportError:
            raise UsageError("a PNG picture needs Pillow: pip install 'postproc[render]'") from None
        self.image = Image.new("RGB", (width, height), "white")
        self.draw = ImageDraw.Draw(self.image)

    def save(self, out: BinaryIO) -> None:
        self.image.save(out, format="PNG")

    @contextlib.contextmanager
    def group(self, cls: str, **attrs: str) -> Iterator[None]:
        yield

    def rect(self, x: float, y: float, w: float, h: float, stroke: str) -> None:
        self.draw.rectangle((x, y, x + w, y + h), outline=stroke)

    def line(self, a: Point, b: Point, colour: str, width: float = 1.0, dash: Sequence[float] | None = None,
             cls: str | None = None) -> None:
        self.path([(a, b)], colour, width, dash, cls or "")

    def circle(self, c: Point, r: float, colour: str, fill: str = "none", cls: str | None = None) -> None:
        self.draw.ellipse((c[0] - r, c[1] - r, c[0] + r, c[1] + r), outline=colour,
                          fill=None if fill == "none" else fill)

    def text(self, at: Point, text: str, anchor: str = "start", colour: str = "black",
             cls: str | None = None) -> None:
        left, top, right, bottom = self.draw.textbbox((0, 0), text)
        width = right - left
        x = at[0] - (width if anchor == "end" else width / 2 if anchor == "middle" else 0)
        self.draw.text((x, at[1] - (bottom - top) - 2), text, fill=colour)

    def path(self, runs: Iterable[Sequence[Point]], colour: str, width: float, dash: Sequence[float] | None,
             cls: str, **extra: str) -> None:
        px = max(1, round(width))
        for run in runs:
            if dash:
                for seg in dashes(run, (dash[0], dash[1])):
                    self.draw.line(seg, fill=colour, width=px)
            else:
                self.draw.line(list(run), fill=colour, width=px, joint="curve")


Canvas = SvgCanvas | PngCanvas


def dashes(points: Sequence[Point], pattern: tuple[float, float]) -> Iterable[list[Point]]:
    """Split a polyline into its drawn dashes; the pattern runs on across vertices (PIL has no dashes)."""
    on, off = pattern
    period = on + off
    phase = 0.0  # distance into the current period
    dash: list[Point] = []
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
