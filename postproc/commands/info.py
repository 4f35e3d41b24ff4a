"""``postproc info``: what a machinist asks of a program before running it, from its simulation
(``postproc.simulate.toolpath``): its extent per axis, the tools in order with their feed distance and
time, an estimated run time, its holes and cycles, the features it uses, and which targets take it.

Assumptions (the text and the JSON say them where they apply):
- Extents are of the points the tool's controlled point reaches (with tool length and cutter radius
  compensation where the simulation applies them), end points and the quadrant points arcs sweep
  through, in mm (a lathe's X as a diameter where the machine programs diameters; rotary axes in
  degrees). Work coordinates are the simulator's: a work offset is zero unless the program sets one.
  Machine coordinates (with ``--machine``) add the set-up's work and tool offsets as the travel check
  does (``postproc.simulate.travel``); an axis whose offset the set-up lacks is unknown, with why.
- Time: a feed move takes its length at its feed (per minute; per revolution at the programmed spindle
  speed, untimed under constant surface speed; inverse time as programmed); a rapid takes its slowest axis's distance at that axis's
  ``<Axis rapid>`` rate; dwells their seconds. Acceleration, tool changes and M-code waits take no
  time. A move whose time cannot be known (a rapid on an axis without a rate, a feed per revolution
  without a spindle speed) is left out of the total, which then says "at least".
- Holes are the hole-cycle repeats the program makes (a pattern's points included); cycles are the
  blocks that program a cycle, by kind.
"""

from __future__ import annotations

import io
import math
from typing import Any, Iterable, TextIO

from ..cycles.lowering import expand_canned_cycles
from ..core_plugin import expand_lathe_cycles
from ..dialect import Dialect
from ..errors import Diagnostics, ErrorList, PostprocError, UsageError
from ..geometry.arcs import CENTRE_KEYS, PLANE_INDEX, arc_sweep
from ..ir import Block
from ..lowering.lower import Lowering, lower_for
from ..plugins import Registry, default_registry
from ..collector import gc_paused
from ..reading import read_blocks
from ..setup.machine import ROTARY_AXES
from ..setup.machine_setup import MachineSetup
from ..simulate.move_record import Emitted, as_event
from ..simulate.toolpath import TRANSLATE_ONLY, Simulator, ToolpathTarget, start_position
from ..simulate.travel import TravelCheck
from .info_features import Features

SCHEMA = 1
"""The ``"info"`` version of the JSON report (docs/cli.md describes it)."""
LINEAR = frozenset("xyzuvw")


class _MachineExtent(TravelCheck):
    """The travel check's machine positions, recorded instead of checked: every axis, limited or not."""

    def __init__(self, sim: Simulator) -> None:
        super().__init__(sim, lambda err: None)
        self.checked = tuple(sim.axes)
        self.low: dict[str, float] = {}
        self.high: dict[str, float] = {}
        self.unknown: dict[str, str] = {}

    def _check(self, block: Block, axis: str, value: float | None, how: str | None) -> bool:
        if value is not None:
            self.low[axis] = min(value, self.low.get(axis, value))
            self.high[axis] = max(value, self.high.get(axis, value))
        return False

    def _unknown(self, block: Block | None, axis: str, reason: str) -> None:
        self.why[axis] = reason
        if block is not None:
            self.unknown.setdefault(axis, reason)


class _Tally:
    """Distances and times, for the whole program and for one tool."""

    def __init__(self) -> None:
        self.feed_mm = 0.0
        self.feed_s = 0.0
        self.feed_untimed = 0.0
        self.rapid_mm = 0.0
        self.rapid_s = 0.0
        self.rapid_untimed = 0.0


class ProgramInfo:
    """The report of one program, filled by ``collect``."""

    def __init__(self, file: str, dialect: type[Dialect], setup: MachineSetup, machine: bool) -> None:
        self.file = file
        self.dialect = dialect
        self.setup = setup
        self.machine = machine
        self.low: dict[str, float] = {}
        self.high: dict[str, float] = {}
        self.machine_extent: _MachineExtent | None = None
        self.total = _Tally()
        self.dwell_s = 0.0
        self.tools: list[tuple[int | None, int | None, _Tally]] = []
        """(tool number, line of its change, its tally), in the order the program changes them."""
        self.features = Features()
        self.diameter = False
        self.untimed_rapid_axes: set[str] = set()
        self.per_rev_without_speed = False
        self.css = False
        """Constant surface speed is on: S is a surface speed, the revolutions vary with the diameter."""
        self.per_rev_under_css = False
        self.targets: dict[str, dict[str, Any]] = {}

    # -- the simulation ------------------------------------------------------------------------------
    def collect(self, lines: list[str], registry: Registry, diagnostics: Diagnostics) -> None:
        with gc_paused():
            ctx, blocks = read_blocks(lines, self.file, self.dialect, self.setup, diagnostics, program_mode="execute")
            self.diameter = ctx.diameter
            steps: list[Lowering] = []
            for step in registry.lowerings:
                if step in TRANSLATE_ONLY:
                    continue
                if step in (expand_canned_cycles, expand_lathe_cycles) and self.features.count_cycles not in steps:
                    steps.append(self.features.count_cycles)  # once, before either expansion: a pattern's points made
                steps.append(step)
            lowered = lower_for(self.features.observe(blocks, ctx), ctx, ToolpathTarget, "error", steps)
            sim = Simulator(ctx, False, ctx.cutter_rules)
            if self.machine:
                sim.travel = self.machine_extent = _MachineExtent(sim)
            self.rates = self._rates(sim)
            self.pos = {k.lower(): v for k, v in start_position(self.setup).items()}
            self.tally: _Tally | None = None
            out: list[Emitted] = []  # (dictionaries: this simulator makes no records)
            sim.out = out  # where it releases events: the block's own
            for block in lowered:
                mode = block.sections.get("SpindleMode")
                if mode is not None:
                    self.css = getattr(mode, "mode", "rpm") == "css"
                try:
                    sim.block(block, out.append)
                except PostprocError as err:
                    diagnostics.error(err.located(ctx.at(block)) if err.location is None else err)
                for ev in out:
                    self.event(as_event(ev), sim)
                out.clear()
            try:
                sim.finish()
            except PostprocError as err:
                diagnostics.error(err)
            for ev in out:
                self.event(as_event(ev), sim)
            self.features.finish(ctx)
        diagnostics.check()

    def _rates(self, sim: Simulator) -> dict[str, float]:
        """Rapid rate per axis, mm (or degrees) per minute, where the set-up gives one."""
        mm = self.setup.machine.mm()
        return {a.lower(): t.rapid * (1.0 if a in ROTARY_AXES else mm) for a, t in self.setup.travel.items()
                if t.rapid is not None and a in sim.axes}

    def event(self, ev: dict[str, Any], sim: Simulator) -> None:
        kind = ev.get("move")
        if kind is None:
            what = ev.get("event")
            if what == "tool":
                self.tally = _Tally()
                self.tools.append((ev.get("number"), ev.get("line"), self.tally))
            elif what == "dwell":
                self.dwell_s += float(ev["seconds"])
            return
        controlled = ev.get("controlled")
        point = {k: float(v) for k, v in {**ev, **(controlled or {})}.items()
                 if len(k) == 1 and k in "xyzabcuvw"}
        start = self.pos
        self._extent(point)
        if kind in ("cw", "ccw"):
            length = self._arc(ev, controlled, start, point)
        else:
            length = math.dist([point.get(k, 0.0) for k in point if k in LINEAR],
                               [start.get(k, 0.0) for k in point if k in LINEAR])
        if self.tally is None:
            self.tally = _Tally()
            self.tools.append((None, None, self.tally))  # moves before the first tool change
        for tally in (self.total, self.tally):
            if kind == "rapid":
                seconds = self._rapid_seconds(start, point)
                tally.rapid_mm += length
                if seconds is None:
                    tally.rapid_untimed += length
                else:
                    tally.rapid_s += seconds
            else:
                seconds = self._feed_seconds(ev, length, sim)
                tally.feed_mm += length
                if seconds is None:
                    tally.feed_untimed += length
                else:
                    tally.feed_s += seconds
        self.pos = point

    def _extent(self, point: dict[str, float]) -> None:
        for axis, value in point.items():
            self.low[axis] = min(value, self.low.get(axis, value))
            self.high[axis] = max(value, self.high.get(axis, value))

    def _arc(self, ev: dict[str, Any], controlled: dict[str, Any] | None, start: dict[str, float],
             end: dict[str, float]) -> float:
        """The arc's length, its quadrant points added to the extent."""
        plane = ev.get("plane", "XY")
        i, j, n = PLANE_INDEX[plane]
        k1, k2, kn = "xyz"[i], "xyz"[j], "xyz"[n]
        centre_of = {**ev, **(controlled or {})}
        half = 0.5 if self.diameter else 1.0  # a diameter's centre and point, as radii
        scale = {k1: half if k1 == "x" else 1.0, k2: half if k2 == "x" else 1.0}
        s = (start.get(k1, 0.0) * scale[k1], start.get(k2, 0.0) * scale[k2])
        e = (end.get(k1, 0.0) * scale[k1], end.get(k2, 0.0) * scale[k2])
        c = (float(centre_of.get(CENTRE_KEYS[k1.upper()], s[0] / scale[k1])) * scale[k1],
             float(centre_of.get(CENTRE_KEYS[k2.upper()], s[1] / scale[k2])) * scale[k2])
        clockwise = ev["move"] == "cw"
        sweep = arc_sweep(s, e, c, clockwise)
        r = math.hypot(s[0] - c[0], s[1] - c[1])
        a0 = math.atan2(s[1] - c[1], s[0] - c[0])
        for quarter in range(4):
            angle = quarter * math.pi / 2
            if ((a0 - angle) if clockwise else (angle - a0)) % (2 * math.pi) <= sweep:
                along = (c[0] + r * math.cos(angle), c[1] + r * math.sin(angle))
                self._extent({k1: along[0] / scale[k1], k2: along[1] / scale[k2]})
        rise = end.get(kn, 0.0) - start.get(kn, 0.0)
        return math.hypot(r * sweep, rise)

    def _rapid_seconds(self, start: dict[str, float], end: dict[str, float]) -> float | None:
        slowest = 0.0
        for axis, value in end.items():
            distance = abs(value - start.get(axis, 0.0)) * (0.5 if self.diameter and axis == "x" else 1.0)
            if distance == 0.0:
                continue
            rate = self.rates.get(axis)
            if rate is None:
                self.untimed_rapid_axes.add(axis.upper())
                return None
            slowest = max(slowest, distance / rate * 60.0)
        return slowest

    def _feed_seconds(self, ev: dict[str, Any], length: float, sim: Simulator) -> float | None:
        f = ev.get("f")
        if f is None or f <= 0:
            return None
        mode = sim.modal.feed_mode
        if ev["move"] == "tap" or mode == "per_rev":
            if self.css:
                self.per_rev_under_css = True
                return None
            rpm = sim.modal.spindle_rpm
            if not isinstance(rpm, (int, float)) or rpm <= 0:
                self.per_rev_without_speed = True
                return None
            return length / (float(f) * rpm) * 60.0
        if mode == "inverse_time":
            return 60.0 / float(f)
        return length / float(f) * 60.0

    # -- the targets ----------------------------------------------------------------------------------
    def try_targets(self, lines: list[str], registry: Registry) -> None:
        """Each writable dialect's translation of the program, written nowhere: ok, or its refusals."""
        from ..api import translate
        for name, dialect in sorted(registry.dialects.items()):
            if dialect.WRITER is None:
                continue
            quiet = Diagnostics(warn_stream=io.StringIO())
            try:
                translate(lines, _Discard(), file=self.file, source=self.dialect.NAME, target=name,
                          setup=self.setup, registry=registry, diagnostics=quiet)
            except ErrorList as errs:
                self.targets[name] = {"ok": False, "errors": [str(e) for e in errs.errors]}
                continue
            except PostprocError as err:
                self.targets[name] = {"ok": False, "errors": [str(err)]}
                continue
            except UsageError as err:
                self.targets[name] = {"ok": False, "errors": [err.message]}
                continue
            self.targets[name] = {"ok": True, "warnings": len(quiet.warnings)}

    # -- the report ------------------------------------------------------------------------------------
    def as_json(self) -> dict[str, Any]:
        total = self.total
        timed_all = total.feed_untimed == 0.0 and total.rapid_untimed == 0.0
        return {
            "info": SCHEMA,
            "file": self.file,
            "dialect": self.dialect.NAME,
            "units": "mm",
            "x_mode": "diameter" if self.diameter else "radius",
            "extent": {"work": {a.upper(): {"min": _n(self.low[a]), "max": _n(self.high[a])} for a in self.low},
                       "machine": self._machine_json()},
            "tools": [{"number": number, "line": line, "feed_mm": _n(t.feed_mm), "feed_s": _n(t.feed_s),
                       "feed_untimed_mm": _n(t.feed_untimed), "rapid_mm": _n(t.rapid_mm)}
                      for number, line, t in self.tools],
            "time": {"feed_s": _n(total.feed_s), "rapid_s": _n(total.rapid_s), "dwell_s": _n(self.dwell_s),
                     "total_s": _n(total.feed_s + total.rapid_s + self.dwell_s), "complete": timed_all,
                     "untimed_feed_mm": _n(total.feed_untimed), "untimed_rapid_mm": _n(total.rapid_untimed)},
            "assumed": self.assumptions(),
            "holes": self.features.holes,
            "cycles": dict(sorted(self.features.cycles.items())),
            "features": sorted(self.features.used),
            "targets": self.targets,
        }

    def _machine_json(self) -> dict[str, Any] | None:
        extent = self.machine_extent
        if extent is None:
            return None
        factor = {a: 2.0 if self.diameter and a == "X" else 1.0 for a in extent.sim.axes}
        found: dict[str, Any] = {}
        for axis in extent.sim.axes:
            if axis in extent.unknown:
                found[axis] = {"unknown": extent.unknown[axis]}
            elif axis in extent.low:
                found[axis] = {"min": _n(extent.low[axis] * factor[axis]), "max": _n(extent.high[axis] * factor[axis])}
        return found

    def assumptions(self) -> list[str]:
        said = ["feeds at their programmed rate from the start of each move: no acceleration, no override",
                "tool changes and machine-specific codes take no time"]
        if self.untimed_rapid_axes:
            axes = ", ".join(sorted(self.untimed_rapid_axes))
            said.append(f"rapids moving {axes} are not timed: the set-up gives no rapid rate "
                        f"(<Axes><Axis name=\"{sorted(self.untimed_rapid_axes)[0]}\" rapid=...>)")
        else:
            said.append("rapids at the set-up's rates, the slowest axis deciding")
        if self.per_rev_without_speed:
            said.append("feeds per revolution without a programmed spindle speed are not timed")
        if self.per_rev_under_css:
            said.append("feeds per revolution under constant surface speed are not timed (the revolutions "
                        "follow the diameter)")
        if not self.machine:
            said.append("work offsets are zero unless the program sets them; no machine extent without --machine")
        return said


class _Discard(io.StringIO):
    """An output that keeps nothing: a trial translation's text is not needed (a long program's would
    otherwise be held whole, once per target)."""

    def write(self, text: str) -> int:
        return len(text)


def _n(value: float) -> float:
    """A number as reported: 4 decimals, never -0."""
    r = round(value, 4)
    return 0.0 if r == 0 else r


def program_info(lines: Iterable[str], *, file: str, dialect: str, setup: MachineSetup | None = None,
                 registry: Registry | None = None, targets: bool = True, machine: bool | None = None) -> dict[str, Any]:
    """The report of a program as the JSON ``postproc info --format json`` prints (docs/cli.md). Raises
    ``ErrorList`` when the program cannot be simulated. ``machine``: report the extent in machine
    coordinates too (default: when a set-up is given)."""
    registry = registry or default_registry()
    text = list(lines)
    info = ProgramInfo(file, registry.dialect(dialect), setup or MachineSetup(),
                       setup is not None if machine is None else machine)
    info.collect(text, registry, Diagnostics(warn_stream=io.StringIO()))
    if targets:
        info.try_targets(text, registry)
    return info.as_json()


def render_text(report: dict[str, Any], out: TextIO) -> None:
    """The report for people."""
    w = out.write
    w(f"{report['file']} ({report['dialect']})\n")
    extent = report["extent"]
    w("extent, work coordinates (mm" + (", X as a diameter" if report["x_mode"] == "diameter" else "") + "):\n")
    for axis, span in extent["work"].items():
        w(f"  {axis} {span['min']:>12.4f} .. {span['max']:.4f}\n")
    if extent["machine"] is not None:
        w("extent, machine coordinates:\n")
        for axis, span in extent["machine"].items():
            if "unknown" in span:
                w(f"  {axis} unknown: {span['unknown']}\n")
            else:
                w(f"  {axis} {span['min']:>12.4f} .. {span['max']:.4f}\n")
    w("tools, in order:\n")
    for tool in report["tools"]:
        name = "(before any tool change)" if tool["number"] is None else f"tool {tool['number']} (line {tool['line']})"
        untimed = f", {tool['feed_untimed_mm']:.1f} mm untimed" if tool["feed_untimed_mm"] else ""
        w(f"  {name}: feed {tool['feed_mm']:.1f} mm in {_clock(tool['feed_s'])}{untimed}, rapid {tool['rapid_mm']:.1f} mm\n")
    time = report["time"]
    w(f"run time: {'at least ' if not time['complete'] else ''}{_clock(time['total_s'])} (feeds {_clock(time['feed_s'])}, "
      f"rapids {_clock(time['rapid_s'])}, dwells {_clock(time['dwell_s'])})\n")
    for said in report["assumed"]:
        w(f"  assumed: {said}\n")
    cycles = ", ".join(f"{kind} {n}" for kind, n in report["cycles"].items()) or "none"
    w(f"holes: {report['holes']}; cycles: {cycles}\n")
    w(f"features: {', '.join(report['features']) or 'none'}\n")
    if report["targets"]:
        w("targets:\n")
        for name, verdict in report["targets"].items():
            if verdict["ok"]:
                w(f"  {name:<12} ok" + (f" ({verdict['warnings']} warnings)" if verdict["warnings"] else "") + "\n")
            else:
                errors = verdict["errors"]
                more = f" (and {len(errors) - 1} more)" if len(errors) > 1 else ""
                w(f"  {name:<12} refused: {errors[0]}{more}\n")


def _clock(seconds: float) -> str:
    whole = int(round(seconds))
    return f"{whole // 3600}:{whole // 60 % 60:02d}:{whole % 60:02d}"
