"""What ``postproc info`` lists of a program's constructs: the features it uses (in neutral words, as the
IR says them: no dialect's spelling), its holes and its cycles by kind."""

from __future__ import annotations

from typing import Any, Iterator

from ..context import Context
from ..dialect import Dialect
from ..ir import Block, CompoundMotion, Motion
from ..ir.state import PLANE_AXES

_BY_SECTION = {
    "CutterCompensation": "cutter radius compensation", "DynamicCutterCompensation": "cutter radius compensation",
    "WorkOffset": "work coordinate systems", "DataSetting": "programmable data setting",
    "MachineCoordinates": "moves in machine coordinates", "RigidTap": "rigid tapping",
    "SpindleOrientation": "spindle orientation", "MachineFunction": "machine-specific codes",
    "HolePattern": "hole patterns", "LatheCycle": "lathe cycles", "CoordinateSet": "coordinate setting",
    "Dwell": "dwells", "Coolant": "coolant", "PathControl": "path control",
}
"""Section -> the feature it shows (when it does something: a cancel shows nothing)."""
_OFF = frozenset(("off", "cancel"))
_FEED_MODES = {"per_rev": "feed per revolution", "inverse_time": "inverse-time feed"}
_MOTIONS = {"home": "reference return", "home2": "reference return", "thread": "threading"}
SAME_LEVEL = 1e-9
"""Program units: a move ending this close to a cycle's bottom arrives there."""


class Features:
    """Filled while the program streams past (``observe`` before lowering, ``count_cycles`` just
    before the cycles are expanded, ``finish`` at the end)."""

    def __init__(self) -> None:
        self.used: set[str] = set()
        self.holes = 0
        self.cycles: dict[str, int] = {}

    def observe(self, blocks: Iterator[Block], ctx: Context) -> Iterator[Block]:
        for block in blocks:
            sections = block.sections
            for key, section in sections.items():
                feature = _BY_SECTION.get(key)
                if feature is not None and getattr(section, "mode", None) not in _OFF:
                    self.used.add(feature)
                self._section(key, section, ctx)
            yield block

    def _section(self, key: str, section: Any, ctx: Context) -> None:
        used = self.used
        if key == "Motion" and isinstance(section, Motion):
            mode = section.mode
            if mode in ("cw", "ccw"):
                used.add("arcs in radius form" if section.radius is not None else "arcs")
                plane_axes = {"XY": "Z", "ZX": "Y", "YZ": "X"}
                if plane_axes.get(ctx.state.plane) in section.axes:
                    used.add("helical arcs")
            elif mode in _MOTIONS:
                used.add(_MOTIONS[mode])
        elif key == "Units" and section.system == "inch":
            used.add("inch units")
        elif key == "DistanceMode" and section.mode == "incremental":
            used.add("incremental distances")
        elif key == "Plane" and section.plane != "XY":
            used.add(f"the {section.plane} plane")
        elif key == "FeedMode" and section.mode in _FEED_MODES:
            used.add(_FEED_MODES[section.mode])
        elif key == "ToolLengthOffset" and section.mode != "cancel":
            used.add("tool length offset")
        elif key == "FrameChange":
            used.add(f"frame: {section.kind.replace('_', ' ')}")
        elif key == "NativeCode":
            used.add(f"native: {section.what}")
        elif key == "CannedCycle":
            used.add(f"canned cycle: {section.kind.replace('_', ' ')}")

    def count_cycles(self, blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
        """A lowering step (before the cycles are expanded): each hole cycle block's repeats, each
        block programming a cycle by kind."""
        for block in blocks:
            sections = block.sections
            cycle = sections.get("CannedCycle")
            if cycle is not None:
                self.holes += holes_made(cycle, block)
                if cycle.call:  # type: ignore[attr-defined]
                    kind = cycle.kind  # type: ignore[attr-defined]
                    self.cycles[kind] = self.cycles.get(kind, 0) + 1
            lathe = sections.get("LatheCycle")
            if lathe is not None and getattr(lathe, "form", "") != "first":  # a first block holds data only
                kind = str(getattr(lathe, "kind", "lathe cycle"))
                self.cycles[kind] = self.cycles.get(kind, 0) + 1
            yield block

    def finish(self, ctx: Context) -> None:
        if ctx.state.computes:
            self.used.add("variables and control flow")
        if ctx.lathe:
            self.used.add("lathe")
        if ctx.diameter:
            self.used.add("diameter programming")


def holes_made(cycle: Any, block: Block) -> int:
    """The holes a cycle block makes: its repeat count, but where the block's motion is written whatever
    the target (``expand``: a SINUMERIK ``HOLES1``/``HOLES2`` row or circle made in one block with the first
    hole's record), the times that motion arrives at the cycle's bottom along the drilling axis (each hole
    reaches it once; a shift or dwell there stays at it)."""
    compound = block.sections.get("CompoundMotion")
    bottom = cycle.bottom
    if not cycle.expand or not isinstance(compound, CompoundMotion) or bottom is None:
        return int(cycle.repeat)
    normal = PLANE_AXES.get(cycle.plane, ("X", "Y", "Z"))[2]
    level = cycle.start.get(normal)
    arrivals = 0
    for item in compound.items:
        if isinstance(item, Motion):
            value = item.axes.get(normal)
            if isinstance(value, (int, float)):
                if abs(value - bottom) <= SAME_LEVEL and (level is None or abs(level - bottom) > SAME_LEVEL):
                    arrivals += 1
                level = float(value)
    return arrivals or int(cycle.repeat)
