"""The verify overlay: a program's toolpath and its translation's drawn over each other on one frame,
with the largest deviation marked, so a person sees where and how far the translation strays.

The source is drawn wide and light, the translation thin and dark on top: where they agree, a dark line
runs inside a light band; where they do not, the two separate. Both stream past ``verify`` once and
are kept as backplots (their points in spill files), so a picture costs disk rather than memory, and
only when one is asked for.
"""

from __future__ import annotations

import os
from typing import Any, BinaryIO, Iterable, Iterator, Protocol, TextIO

from .backplot import HEIGHT, RAPID, FEED, STROKE, WIDTH, Backplot, Frame, Style, View, legend_text, marks, render
from .canvas import Canvas, PngCanvas, Point, SvgCanvas
from ..errors import UsageError


class Report(Protocol):
    """What the overlay reads of a verify report (``postproc.simulate.verify.Report``; named here, not imported,
    since verify draws through this module)."""

    max_deviation: float
    where: tuple[int, int] | None
    where_at: Any
    """The largest deviation's end points (IN, OUT) in true geometry, or None."""
    mismatch: str | None
    mismatch_at: tuple[int | None, int | None]

    def summary(self) -> str: ...

SOURCE = Style(colour="#8fb8de", rapid_colour="#c7c7c7", width=5.0, side="in", opacity=0.7)
TARGET = Style(colour="#08306b", rapid_colour="#d62728", width=1.2, side="out")
DEVIATION_COLOUR = "#e6008a"
FORMATS = ("svg", "png")


def plot_format(path: str) -> str:
    """The picture's format from its file name (``.svg`` or ``.png``)."""
    fmt = path.rpartition(".")[2].lower()
    if fmt not in FORMATS:
        raise UsageError(f"--plot {path}: the name must end in .svg or .png")
    return fmt


class Overlay:
    """Collects both toolpaths during ``verify``; ``write_svg``/``write_png`` draw them with a report."""

    def __init__(self, name_in: str = "IN", name_out: str = "OUT") -> None:
        self.names = (name_in, name_out)
        self.source = Backplot({})
        self.target = Backplot({})

    def begin(self, start_in: dict[str, float], start_out: dict[str, float], lathe: bool) -> None:
        self.close()
        self.source, self.target = Backplot(start_in, lathe), Backplot(start_out, lathe)

    def close(self) -> None:
        """Remove both toolpaths' spill files (see ``Backplot.close``)."""
        self.source.close()
        self.target.close()

    def source_events(self, events: Iterable[dict[str, Any]]) -> Iterator[dict[str, Any]]:
        return _drawn(events, self.source)

    def target_events(self, events: Iterable[dict[str, Any]]) -> Iterator[dict[str, Any]]:
        return _drawn(events, self.target)

    # -- drawing -----------------------------------------------------------------------------------
    def write(self, out: Any, fmt: str, report: Report) -> None:
        if fmt == "svg":
            self.write_svg(out, report)
        else:
            self.write_png(out, report)

    def write_svg(self, out: TextIO, report: Report) -> None:
        with SvgCanvas.open(out, WIDTH, HEIGHT) as canvas:
            self.draw(canvas, report)

    def write_png(self, out: BinaryIO, report: Report) -> None:
        canvas = PngCanvas(WIDTH, HEIGHT)
        self.draw(canvas, report)
        canvas.save(out)

    def draw(self, canvas: Canvas, report: Report) -> None:
        frame = Frame([self.source, self.target], self.source.lathe)

        def deviation(view: View) -> None:
            if report.where_at is None:
                return
            a, b = (frame.to_px(view, p) for p in report.where_at)
            with canvas.group("deviation"):
                canvas.line(a, b, DEVIATION_COLOUR, 2)
                canvas.circle(a, 10, DEVIATION_COLOUR, cls="deviation")
                canvas.text((a[0] + 13, a[1] - 11), f"{report.max_deviation:.4f} mm", colour=DEVIATION_COLOUR)

        render(canvas, frame, [(self.source, SOURCE), (self.target, TARGET)],
               lambda at: self.legend(canvas, frame, report, at), deviation)

    def legend(self, canvas: Canvas, frame: Frame, report: Report, at: Point) -> None:
        """Each program by its file's name (the command line has its path), the deviation and the verdict,
        the marks and the extent: every text wrapped to the legend's width."""
        x, y = at
        width = frame.legend_width
        for (name, plot, style) in ((self.names[0], self.source, SOURCE), (self.names[1], self.target, TARGET)):
            side = "IN" if style is SOURCE else "OUT"
            canvas.line((x, y - 4), (x + 30, y - 4), style.colour or "", style.width, cls=f"swatch-{style.side}")
            canvas.line((x + 36, y - 4), (x + 60, y - 4), style.rapid_colour, STROKE, (6, 4))
            y = legend_text(canvas, (x + 66, y), f"{side} {os.path.basename(name) or name}: {plot.moves[FEED]} "
                            f"feed, {plot.moves[RAPID]} rapid (rapids dashed)", width - 66, cls=f"name-{style.side}")
        y += 8
        canvas.circle((x + 15, y - 4), 8, DEVIATION_COLOUR)
        if report.where is not None:
            text = (f"largest deviation {report.max_deviation:.4f} mm at IN:{report.where[0]} / "
                    f"OUT:{report.where[1]}")
        else:
            text = "no moves compared"
        y = legend_text(canvas, (x + 36, y), text, width - 36, cls="deviation-text")
        for text in report.summary().splitlines()[:1] + _mismatch(report):
            y = legend_text(canvas, (x + 36, y), text, width - 36, cls="verdict")
        y = marks(canvas, frame, (x, y + 8), self.source, width)
        legend_text(canvas, (x, y + 8), self.source.extent_text(frame.scale, frame.units) + " (IN)", width,
                    cls="extent")


def _mismatch(report: Report) -> list[str]:
    if report.mismatch is None:
        return []
    a, b = report.mismatch_at
    return [f"first difference at IN:{'-' if a is None else a} / OUT:{'-' if b is None else b}:",
            report.mismatch]


def _drawn(events: Iterable[dict[str, Any]], plot: Backplot) -> Iterator[dict[str, Any]]:
    """The events unchanged, each also given to ``plot``."""
    take = plot.take
    for ev in events:
        take(ev)
        yield ev
