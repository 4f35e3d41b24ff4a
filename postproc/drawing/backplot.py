"""Backplot: a toolpath drawn as a machinist reads one, as SVG or PNG.

Three views in third-angle layout on one scale (plan XY above front XZ, side YZ right of the front, so
X and Z line up between views); a lathe gets its ZX plane (X as a radius) and the mirror image below,
each the page's width (a turned part is long in Z). Feed moves are solid in one colour per tool, rapids
dashed red (a rapid into the part stands out); the start point and the work origin are marked; every
view has ticks in the program's units (mm, or inches for a program in inches: the toolpath's header
says which, ``program_units``); a legend lists the tools. Text is placed and wrapped so that it stays on
the page (``canvas.CHAR_WIDTH``).

A lathe whose set-up gives no start (X0 Z0, the default: on the spindle axis at the part's face, where
no tool starts) has no known position before its first move: the drawing begins where that move ends,
rather than with a rapid drawn through the part.

Flat memory: points go to a ``PointStore`` (a spill file past one chunk) as they arrive, each tagged
with its kind of move and its tool, never an object per move; arcs are linearised on arrival within
``CHORD_ERROR`` mm. Scaling needs the extent of the whole path, so the picture is written at the end,
reading the points back once per view and kind of move and writing each <path> as it fills.
"""

from __future__ import annotations

import math
from array import array
from dataclasses import dataclass
from types import TracebackType
from typing import Any, BinaryIO, Callable, Iterable, Iterator, Sequence, TextIO

from .canvas import Canvas, PngCanvas, Point, SvgCanvas, dashes, text_width, wrap
from ..geometry.arcs import CENTRE_KEYS, arc_points
from .pointstore import PointStore

__all__ = ["Backplot", "Frame", "Style", "dashes", "render"]

PATH_POINTS = 20000
"""Most points in one SVG <path>: long programs get several paths of a kind instead of one huge one."""
CHORD_ERROR = 0.01
"""Largest distance in mm between a drawn chord and the arc it stands for."""
RAPID, FEED = 1, 2
"""Point codes: the kind of the segment that ends at the point (0: the path's first point). A point's
tag is its code plus four times its tool's slot (the tool's place in order of first move)."""

PANEL = 400
"""A mill's views are square panels of this many pixels; the plot inside keeps ``MARGIN`` from its edge."""
MARGIN = 20
LEFT, TOP = 70, 30
"""Room left of the first column (tick labels) and above the first row (view titles)."""
GAP_X, GAP_Y = 90, 80
"""Room between panels for the next panel's tick labels, axis units and title."""
WIDTH, HEIGHT = 1000, 1000
PAGE_MARGIN = 6
"""Text keeps this far from the page's edges."""
LATHE_PANEL = (2 * PANEL + GAP_X, 300)
"""A lathe view: both columns wide, so the two views and the legend below them fill the page."""
MM_PER_INCH = 25.4
RAPID_COLOUR = "#d62728"
LINE_STYLE_COLOUR = "#333333"
"""The feed line in the legend of line styles (tools have their own colours)."""
TOOL_COLOURS = ("#1f4e9c", "#2ca02c", "#ff7f0e", "#9467bd", "#17becf", "#8c564b", "#e377c2", "#7f7f7f",
                "#bcbd22", "#393b79", "#637939", "#7b4173")
"""Feed colours in order of a tool's first move (red is the rapids'); a 13th tool reuses the first."""
DASH = (6, 4)
"""Rapid dash pattern in pixels: drawn, gap."""
STROKE = 1.2
START_COLOUR = "#2ca02c"
TICKS = 6
"""About this many ticks along each panel edge."""


@dataclass(frozen=True)
class View:
    """One panel: which model axes go across (``h``) and up (``v``, or down when ``down``)."""

    title: str
    h: int
    v: int
    col: int
    row: int
    down: bool = False
    width: float = PANEL
    height: float = PANEL

    @property
    def left(self) -> float:
        return LEFT + self.col * (self.width + GAP_X)

    @property
    def top(self) -> float:
        return TOP + self.row * (self.height + GAP_Y)

    def size(self, axis: int) -> float:
        """The panel's extent in pixels along model ``axis`` (across for ``h``, up for ``v``)."""
        return self.width if axis == self.h else self.height


MILL_VIEWS = (View("Plan (XY)", 0, 1, 0, 0), View("Front (XZ)", 0, 2, 0, 1), View("Side (YZ)", 1, 2, 1, 1))
LATHE_VIEWS = (View("Turning (Z across, X radius up)", 2, 0, 0, 0, width=LATHE_PANEL[0], height=LATHE_PANEL[1]),
               View("Mirrored (X radius down)", 2, 0, 0, 1, down=True, width=LATHE_PANEL[0],
                    height=LATHE_PANEL[1]))
MILL_LEGEND = (LEFT + PANEL + GAP_X, TOP + 10)
"""Where the legend starts: a mill's in the free cell right of the plan, a lathe's below its views."""
LATHE_LEGEND = (LEFT, TOP + 2 * (LATHE_PANEL[1] + GAP_Y) + 10)
AXIS_NAMES = ("X", "Y", "Z")


@dataclass(frozen=True)
class Style:
    """How one toolpath is drawn: per-tool feed colours (``colour`` None) or one colour for all."""

    colour: str | None = None
    rapid_colour: str = RAPID_COLOUR
    width: float = STROKE
    side: str | None = None
    """``in``/``out`` in a verify overlay (written as ``data-side``)."""
    opacity: float = 1.0


class Backplot:
    """Collects a toolpath's points and tools; ``write_svg``/``write_png`` draw them. Close it (or use
    it as a context manager) to remove its spill file at once rather than when it is collected."""

    def __init__(self, start: dict[str, float], lathe: bool = False) -> None:
        self.lathe = lathe
        """Draw the ZX plane of a lathe: Z across, X (a radius, true geometry) up, and mirrored below the
        axis in the second view; a diameter toolpath (``x_mode``) is halved as it comes."""
        self.half = False
        self.pos = (start.get("X", 0.0), start.get("Y", 0.0), start.get("Z", 0.0))
        self._start = self.pos
        self.start_known = not lathe or any(self.pos)
        """False for a lathe at the default start X0 Z0 (see the module docstring): the first move's
        end is then where the drawing starts."""
        self.units = "mm"
        """The program's units (the header's ``program_units``): ticks and texts are in them, the points
        always in mm."""
        self.points = PointStore()
        self.started = False
        """The path's first point is stored (the start, or the first move's end)."""
        self.moves = {RAPID: 0, FEED: 0}
        self.tool: int | None = None
        self.tool_moves: dict[int | None, list[int]] = {}
        """Per tool in order of its first move: [rapids, feeds]."""
        self.slots: dict[int | None, int] = {}
        """Each tool's slot: its place in ``tool_moves``."""

    def __enter__(self) -> "Backplot":
        return self

    def __exit__(self, kind: type[BaseException] | None, exc: BaseException | None,
                 tb: TracebackType | None) -> None:
        self.close()

    def close(self) -> None:
        self.points.close()

    # -- collecting --------------------------------------------------------------------------------
    def add_all(self, events: Iterable[dict[str, Any]]) -> None:
        for ev in events:
            self.take(ev)

    def take(self, ev: dict[str, Any]) -> None:
        """Any toolpath event: moves are drawn, a tool event changes the colour, a header sets x_mode."""
        if "move" in ev:
            self.add(ev)
        elif ev.get("event") == "tool":
            self.tool = ev.get("number")
        elif "toolpath" in ev:
            self.half = ev.get("x_mode") == "diameter"
            self.units = "inch" if ev.get("program_units") == "inch" else "mm"

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
        if not self.started:
            self.started = True
            if not self.start_known:  # where the tool was is unknown: the path starts here
                self.points.append(end, 0)
                self.pos = self._start = end
                self._tool_slot()[code - 1] += 1
                return
            self.points.append(self.pos, 0)
        counts = self._tool_slot()
        counts[code - 1] += 1
        tag = code + 4 * self.slots[self.tool]
        append = self.points.append
        if kind in ("cw", "ccw"):
            centre = tuple(float(ev.get(CENTRE_KEYS[a], p)) for a, p in zip("XYZ", self.pos))
            for p in arc_points(self.pos, end, centre, ev.get("plane", "XY"), kind == "cw",  # type: ignore[arg-type]
                                CHORD_ERROR):
                append(p, tag)
        else:
            append(end, tag)
        self.pos = end

    def _tool_slot(self) -> list[int]:
        """The move counts of the tool in use, which gets its slot at its first move."""
        counts = self.tool_moves.get(self.tool)
        if counts is None:
            self.slots[self.tool] = len(self.tool_moves)
            counts = self.tool_moves[self.tool] = [0, 0]
        return counts

    # -- reading back ------------------------------------------------------------------------------
    def start(self) -> tuple[float, float, float]:
        return self._start

    def bounds(self) -> tuple[float, float, float, float, float, float]:
        if not self.started:  # no move: the start alone
            self.started = True
            self.points.append(self.pos, 0)
        return self.points.bounds()

    def all_points(self) -> Iterator[tuple[float, float, float]]:
        """Every drawn point in order, the start first."""
        for xyz, _ in self.points.chunks():
            for i in range(0, len(xyz), 3):
                yield xyz[i], xyz[i + 1], xyz[i + 2]

    def tools(self) -> list[int | None]:
        """The tools by slot: in order of their first move."""
        return list(self.tool_moves)

    def tool_colours(self) -> dict[int | None, str]:
        """Each tool's feed colour, in order of its first move."""
        return {tool: TOOL_COLOURS[i % len(TOOL_COLOURS)] for i, tool in enumerate(self.tool_moves)}

    def polylines(self, kind: int, mapper: Callable[[array[float]], Callable[[int], Point]]
                  ) -> Iterator[tuple[int, int, list[Point]]]:
        """The connected runs of one kind of segment in pixels, in order, as (stretch, slot, run): a
        stretch is a stretch of the path one tool drew (numbered from 0), and no run crosses from one to
        the next. A run longer than ``PATH_POINTS`` comes in pieces that continue from each other's last
        point. ``mapper`` makes the pixel function of one chunk of points (point index times three)."""
        limit = PATH_POINTS
        run: list[Point] = []
        stretch, slot = -1, -1
        carry: Point = (0.0, 0.0)  # the previous chunk's last point, in pixels
        for xyz, tags in self.points.chunks():
            px = mapper(xyz)
            for i, tag in enumerate(tags):
                code = tag & 3
                if code == 0:  # the start point: no segment ends here
                    continue
                if tag >> 2 != slot:
                    if run:
                        yield stretch, slot, run
                        run = []
                    stretch, slot = stretch + 1, tag >> 2
                if code == kind:
                    if not run:
                        run.append(px(3 * (i - 1)) if i else carry)
                    run.append(px(3 * i))
                    if len(run) > limit:
                        yield stretch, slot, run
                        run = [run[-1]]
                elif run:
                    yield stretch, slot, run
                    run = []
            if tags:
                carry = px(3 * (len(tags) - 1))
        if run:
            yield stretch, slot, run

    def extent_text(self, scale: float, units: str = "mm") -> str:
        """The extent of the path in ``units`` and the picture's scale."""
        unit = MM_PER_INCH if units == "inch" else 1.0
        b = [v / unit for v in self.bounds()]
        name = "in" if units == "inch" else "mm"
        return (f"X {b[0]:g}..{b[1]:g}  Y {b[2]:g}..{b[3]:g}  Z {b[4]:g}..{b[5]:g} {name}  "
                f"(1 {name} = {scale * unit:.3g} px)")

    # -- writing -----------------------------------------------------------------------------------
    def write_svg(self, out: TextIO) -> None:
        """Streamed with lxml's incremental writer: one path's data at a time is in memory."""
        with SvgCanvas.open(out, WIDTH, HEIGHT) as canvas:
            self.draw(canvas)

    def write_png(self, out: BinaryIO) -> None:
        """The same drawing rasterised with Pillow (the ``render`` extra)."""
        canvas = PngCanvas(WIDTH, HEIGHT)
        self.draw(canvas)
        canvas.save(out)

    def draw(self, canvas: Canvas) -> None:
        frame = Frame([self], self.lathe)
        render(canvas, frame, [(self, Style())], lambda at: tool_legend(canvas, frame, self, at))


class Frame:
    """The layout shared by every toolpath in one picture: views, one centre per axis and one scale
    (px per mm), so the same model point is in the same place for all of them. The work origin is
    always inside the frame."""

    def __init__(self, plots: Sequence[Backplot], lathe: bool) -> None:
        self.views = LATHE_VIEWS if lathe else MILL_VIEWS
        self.legend_at = LATHE_LEGEND if lathe else MILL_LEGEND
        self.legend_width: float = WIDTH - PAGE_MARGIN - self.legend_at[0]
        self.units = plots[0].units if plots else "mm"
        """The units of ticks and texts: the (first) program's. Points are in mm whatever they are."""
        self.unit = MM_PER_INCH if self.units == "inch" else 1.0
        self.unit_name = "in" if self.units == "inch" else "mm"
        lo, hi = [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]  # the work origin
        for plot in plots:
            b = plot.bounds()
            for a in range(3):
                lo[a], hi[a] = min(lo[a], b[2 * a]), max(hi[a], b[2 * a + 1])
        scales = [(view.size(a) - 2 * MARGIN) / (2 * span) for view in self.views for a in (view.h, view.v)
                  for span in (hi[a] / 2 - lo[a] / 2,) if span > 1e-9]  # halves: no overflow near the float range
        self.scale = min(scales) if scales else 1.0
        self.centre = [lo[a] / 2 + hi[a] / 2 for a in range(3)]

    def to_px(self, view: View, p: Sequence[float]) -> Point:
        sign = -1.0 if view.down else 1.0
        h = view.left + view.width / 2 + (p[view.h] - self.centre[view.h]) * self.scale
        v = view.top + view.height / 2 - sign * (p[view.v] - self.centre[view.v]) * self.scale
        return h, v

    def mapper(self, view: View, xyz: array[float]) -> Callable[[int], Point]:
        """Point index (into ``xyz``, a chunk of points, times three) -> pixel, for one view."""
        scale, sign = self.scale, (-1.0 if view.down else 1.0)
        h0 = view.left + view.width / 2 - self.centre[view.h] * scale
        v0 = view.top + view.height / 2 + sign * self.centre[view.v] * scale
        hi, vi = view.h, view.v

        def px(i: int) -> Point:
            return h0 + xyz[i + hi] * scale, v0 - sign * xyz[i + vi] * scale
        return px

    def ticks(self, view: View, axis: int) -> list[tuple[float, str]]:
        """(pixel offset from the panel's centre, label) of round values (in the program's units) along
        one panel edge."""
        if not (self.scale > 0 and math.isfinite(self.scale)):
            return []
        unit = self.unit
        half = view.size(axis) / 2 / self.scale / unit
        c = self.centre[axis] / unit
        step = nice_step(2 * half / (TICKS * view.size(axis) / PANEL))
        if not (math.isfinite(step) and step > 0 and math.isfinite(c)) or abs(c) / step > 1e12:
            return []
        places = max(0, -math.floor(math.log10(step)))
        first = math.ceil((c - half) / step)
        out = []
        for k in range(first, first + int(TICKS * view.size(axis) / PANEL) + 2):
            value = k * step
            if value > c + half:
                break
            label = f"{value:.{places}f}"
            out.append(((value - c) * self.scale * unit, "0" if float(label) == 0 else label))
        return out


def nice_step(raw: float) -> float:
    """The next step of 1, 2 or 5 times a power of ten at least ``raw``."""
    if not (raw > 0 and math.isfinite(raw)):
        return 0.0
    power = 10.0 ** math.floor(math.log10(raw))
    for m in (1, 2, 5, 10):
        if m * power >= raw * (1 - 1e-9):
            return m * power
    return 10 * power


def render(canvas: Canvas, frame: Frame, layers: Sequence[tuple[Backplot, Style]],
           legend: Callable[[Point], None], marks: Callable[[View], None] | None = None) -> None:
    """Panels with ticks, each layer's path (rapids first, cuts over them), the origin and start marks,
    then ``marks`` (a verify overlay's deviation) and the legend in its cell."""
    for view in frame.views:
        with canvas.group("view", **{"data-view": view.title}):
            panel(canvas, frame, view)
            for plot, style in layers:
                draw_path(canvas, frame, view, plot, style)
            origin = frame.to_px(view, (0.0, 0.0, 0.0))
            with canvas.group("origin"):
                canvas.circle(origin, 6, "black", cls="origin")
                canvas.line((origin[0] - 9, origin[1]), (origin[0] + 9, origin[1]), "black")
                canvas.line((origin[0], origin[1] - 9), (origin[0], origin[1] + 9), "black")
            for plot, style in layers[:1]:
                canvas.circle(frame.to_px(view, plot.start()), 4, START_COLOUR, fill=START_COLOUR, cls="start")
            if marks is not None:
                marks(view)
    with canvas.group("legend"):
        legend(frame.legend_at)


def panel(canvas: Canvas, frame: Frame, view: View) -> None:
    """Frame, title, ticks along the bottom and left edges, and the axes' names with their unit. The
    vertical axis's name starts at the column's left edge above the panel, the title after it, so a
    long name (``X radius (in)``) stays on the page."""
    left, top, width, height = view.left, view.top, view.width, view.height
    canvas.rect(left, top, width, height, "#bbbbbb")
    radius = " radius" if view.v == 0 and frame.views is LATHE_VIEWS else ""
    vertical = f"{AXIS_NAMES[view.v]}{radius} ({frame.unit_name})"
    name_at = max(PAGE_MARGIN, left - LEFT + PAGE_MARGIN)
    canvas.text((name_at, top - 8), vertical, cls="unit")
    canvas.text((max(left + 4, name_at + text_width(vertical) + 12), top - 8), view.title)
    mid_h, mid_v = left + width / 2, top + height / 2
    sign = -1.0 if view.down else 1.0
    with canvas.group("ticks", **{"data-axis": AXIS_NAMES[view.h]}):
        for off, label in frame.ticks(view, view.h):
            x = mid_h + off
            canvas.line((x, top + height), (x, top + height + 5), "#555555", cls="tick")
            canvas.text((x, top + height + 18), label, anchor="middle", cls="tick-label")
    with canvas.group("ticks", **{"data-axis": AXIS_NAMES[view.v]}):
        for off, label in frame.ticks(view, view.v):
            y = mid_v - sign * off
            canvas.line((left - 5, y), (left, y), "#555555", cls="tick")
            canvas.text((left - 8, y + 4), label, anchor="end", cls="tick-label")
    canvas.text((left + width, top + height + 34), f"{AXIS_NAMES[view.h]} ({frame.unit_name})", anchor="end",
                cls="unit")


def legend_text(canvas: Canvas, at: Point, text: str, width: float, cls: str | None = None,
                colour: str = "black") -> float:
    """``text`` from ``at``, wrapped to ``width`` pixels; returns the y of the line after it."""
    x, y = at
    for line in wrap(text, width):
        canvas.text((x, y), line, colour=colour, cls=cls)
        y += 20
    return y


def draw_path(canvas: Canvas, frame: Frame, view: View, plot: Backplot, style: Style) -> None:
    """Rapids dashed, then feeds solid over them: one <path> per stretch of a tool, kind and
    ``PATH_POINTS`` points, each written as soon as it is full."""
    colours = plot.tool_colours()
    tools = plot.tools()
    for kind, cls in ((RAPID, "rapid"), (FEED, "feed")):
        dash = DASH if kind == RAPID else None
        runs: list[list[Point]] = []
        count, current = 0, -1
        colour = ""
        extra: dict[str, str] = {}
        for stretch, slot, run in plot.polylines(kind, lambda xyz: frame.mapper(view, xyz)):
            if stretch != current:
                if runs:
                    canvas.path(runs, colour, style.width, dash, cls, **extra)
                    runs, count = [], 0
                current, tool = stretch, tools[slot]
                colour = style.rapid_colour if kind == RAPID else (style.colour or colours[tool])
                extra = path_attributes(tool, style)
            runs.append(run)
            count += len(run)
            if count >= PATH_POINTS:
                canvas.path(runs, colour, style.width, dash, cls, **extra)
                runs, count = [], 0
        if runs:
            canvas.path(runs, colour, style.width, dash, cls, **extra)


def path_attributes(tool: int | None, style: Style) -> dict[str, str]:
    extra = {"data-tool": tool_name(tool)}
    if style.side:
        extra["data-side"] = style.side
    if style.opacity < 1.0:
        extra["opacity"] = f"{style.opacity:g}"
    return extra


def tool_name(tool: int | None) -> str:
    return "no tool" if tool is None else f"T{tool}"


def tool_legend(canvas: Canvas, frame: Frame, plot: Backplot, at: Point) -> None:
    """Line styles, the tools with their colours and move counts, the marks, and the extent. A lathe's
    legend (the page's width, below the views) puts the marks and the extent in a second column."""
    x, y = at
    width = frame.legend_width / 2 if frame.views is LATHE_VIEWS else frame.legend_width
    canvas.line((x, y - 4), (x + 30, y - 4), LINE_STYLE_COLOUR, STROKE)
    canvas.text((x + 36, y), f"feed ({plot.moves[FEED]})")
    canvas.line((x + 130, y - 4), (x + 160, y - 4), RAPID_COLOUR, STROKE, DASH)
    canvas.text((x + 166, y), f"rapid ({plot.moves[RAPID]})")
    y += 28
    top = y
    canvas.text((x, y), "Tools (feed colour)")
    for tool, colour in plot.tool_colours().items():
        y += 20
        rapids, feeds = plot.tool_moves[tool]
        canvas.line((x, y - 4), (x + 30, y - 4), colour, 3, cls="tool-swatch")
        canvas.text((x + 36, y), f"{tool_name(tool)}: {feeds} feed, {rapids} rapid", cls="tool")
    y += 28
    if frame.views is LATHE_VIEWS:
        x, y = x + width, top
    y = marks(canvas, frame, (x, y), plot, width)
    legend_text(canvas, (x, y + 8), plot.extent_text(frame.scale, frame.units), width, cls="extent")


def marks(canvas: Canvas, frame: Frame, at: Point, plot: Backplot, width: float) -> float:
    """The legend of the start and origin marks, in the program's units; returns the y after it."""
    x, y = at
    canvas.circle((x + 15, y - 4), 4, START_COLOUR, fill=START_COLOUR)
    sx, sy, sz = (v / frame.unit for v in plot.start())
    where = f"start X{sx:g} Y{sy:g} Z{sz:g}" if plot.start_known else \
        f"start (none in the set-up): the first move's end X{sx:g} Z{sz:g}"
    y = legend_text(canvas, (x + 36, y), where, width - 36)
    canvas.circle((x + 15, y - 4), 6, "black")
    canvas.text((x + 36, y), "work origin X0 Y0 Z0")
    return y + 20
