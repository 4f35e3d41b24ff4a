"""Whether a compensated stretch cuts the same path under the target's cutter compensation rules as under
the source's: the resolver (``cutter_compensation``) runs the target's rules beside the source's on the
same programmed moves, and keeps the stretch's G41/G42 native where every compensated move ends at the
same point (and an arc about the same centre); else the source's path is written as moves.

A Fanuc contour whose corners are all inner or tangent, entered and left along its own direction, cuts
the same path under LinuxCNC's rules (inner corners meet, start-up and cancel square to the move), so its
G41/G42 stays; an outer corner is an arc about the corner under LinuxCNC's and straight under Fanuc's, so
a stretch with one is written as moves. A stretch longer than ``STRETCH_LIMIT`` blocks is resolved
without trial (the blocks it holds back are bounded).
"""

from __future__ import annotations

import copy
import math
from typing import Any, Callable

from ..compensation.cutter_radius import CutterRadius, Item, Segment
from ..compensation.geometry_for import cutter_for
from ..compensation.rules import CutterRules
from ..errors import Diagnostics, PostprocError
from ..ir import Block, Section

SAME_POINT = 1e-6
"""mm within which two compensated points are one."""
STAND_IN_RADIUS = 1.0
"""mm: the radius a stretch is tried with when the set-up lacks its register's. Which corners are inner,
outer or straight does not depend on the radius, nor do the rules' constructions, so two rules that agree
for it agree for the true radius; where they differ the path must be written, which needs the radius
(then a located error naming the register)."""
STRETCH_LIMIT = 10_000
"""Most blocks of one compensated stretch held back to decide whether it stays native."""

Mark = tuple[str, Any, Any]


def _mark(item: Item) -> Mark | None:
    if not isinstance(item, Segment):
        return None
    return item.kind, item.xy, item.ccentre if item.turn != 0 else None


class RuleTrial:
    """The target's rules run beside the source's over one compensated stretch."""

    def __init__(self, rules: CutterRules) -> None:
        self.ours: list[Mark] = []
        self.theirs: list[Mark] = []
        self.failed = False
        """The target's rules refuse the stretch (or cannot be simulated): it is written as moves."""
        self.refusal: PostprocError | None = None
        """Why the target's rules refuse the stretch (its first error)."""
        self.cutter: CutterRadius = cutter_for(rules, self._release)
        self.missing: PostprocError | None = None
        """The set-up lacks a register's radius: the stretch was tried with ``STAND_IN_RADIUS``."""
        self.stretch: list[tuple[Block, dict[str, Section], str | None]] = []
        """The stretch's blocks as read (sections and text), to write them native again."""
        self.resolved: list[Block] = []
        """The stretch's blocks as resolved (the source's path as moves)."""

    def hold(self, block: Block) -> None:
        """A block of the stretch, before the resolver rewrites it."""
        self.stretch.append((block, dict(block.sections), block.text))

    def as_read(self) -> list[Block]:
        """The stretch's blocks as they were read (their G41/G42 native)."""
        for block, sections, text in self.stretch:
            block.sections, block.text = sections, text
        return [block for block, _, _ in self.stretch]

    def outcome(self, decided: bool, diagnostics: Diagnostics, refused: bool = False) -> list[Block]:
        """The stretch's blocks: as read where both rules cut the same path (or the target's refuse it and
        no radius is known, or the source's rules refused the program (``refused``, reported): the target's
        writer speaks), else as resolved; a path that needs the radius the set-up lacks is the set-up's
        located error."""
        if refused or (decided and self.same()) or (self.failed and self.missing is not None):
            return self.as_read()
        if self.missing is None:
            return self.resolved
        diagnostics.error(self.missing)  # moves made with a stand-in radius: none is written
        return self.as_read()

    def _release(self, item: Item) -> None:
        mark = _mark(item)
        if mark is not None:
            self.theirs.append(mark)

    def record(self, item: Item) -> None:
        """A move the source's rules released."""
        mark = _mark(item)
        if mark is not None:
            self.ours.append(mark)

    def mirror(self, call: Callable[[CutterRadius], None]) -> None:
        """Run the same step under the target's rules."""
        if self.failed:
            return
        try:
            call(self.cutter)
        except PostprocError as err:
            self.failed = True
            self.refusal = err

    def move(self, seg: Segment, start: tuple[float, float]) -> None:
        twin = copy.copy(seg)
        self.mirror(lambda cutter: cutter.line(twin, start) if twin.turn == 0 else cutter.arc(twin, start))

    def same(self) -> bool:
        """Every compensated move of the stretch ends at the same point under both rules."""
        self.mirror(lambda cutter: cutter.finish())
        if self.failed or len(self.ours) != len(self.theirs):
            return False
        return all(a[0] == b[0] and _near(a[1], b[1]) and _near(a[2], b[2]) for a, b in zip(self.ours, self.theirs))


def _near(a: Any, b: Any) -> bool:
    if a is None or b is None:
        return a is b
    return bool(math.dist(a, b) <= SAME_POINT)
