"""expand_hole_patterns: keep a hole pattern native where the target runs it, else write the cycle at
every machined point.

A target whose ``HOLE_PATTERNS`` holds the pattern's kind gets the block as it is (its motion dropped,
as a native canned cycle's is), as long as it keeps the active cycle native too (``expands``: a cycle
the set-up forces to motion, or one already written as motion, leaves no cycle for the pattern to
repeat, so the pattern is then written point by point like any other). Any other target gets one block per machined point, each a repeat of
the active cycle there (``CannedCycle``) with its share of the pattern's motion (``HolePattern.split``):
``expand_canned_cycles``, which runs next, keeps those repeats native where the target runs the cycle
(``X.. Y..`` under the modal cycle) and writes their motion otherwise. Moves between points other than
rapids (a feed move, an arc) cancel a cycle on every RS274-family target, so such a pattern's points
are marked ``expand`` and written as motion, with the rest of the cycle after them. Under ``--units`` or
``--transform`` every pattern is written point by point (``POINT_BY_POINT_KEY``).
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr
from typing import Iterator

from postproc.context import Context
from postproc.cycles.lowering import cancels, expands
from postproc.cycles.section import CannedCycle
from postproc.dialect import Dialect
from postproc.errors import UnsupportedError
from postproc.ir.expr import Expr
from postproc.ir import Block, Comments, CompoundMotion, Motion, Section

from .geometry import first_point, pattern_hops
from .resolve import cycle_at
from .section import HolePattern
from ..lowering.lower import BlockStep, LoweringStep


POINT_BY_POINT_KEY = "patterns.point_by_point"
"""``ctx.run_data`` key: write every pattern point by point, back to a target that runs it too (a program
transform or unit conversion carries each point's cycle exactly; a pattern's own words it does not know)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class ExpandHolePatterns(LoweringStep):
    """Lowering transform (see the module docstring)."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return _Patterns(ctx, target)


expand_hole_patterns = ExpandHolePatterns()


@mypyc_attr(allow_interpreted_subclasses=True)
class _Patterns(BlockStep):
    """One run: a block that is only a move is its business while the active cycle is expanded (it may
    cancel it)."""

    def __init__(self, ctx: Context, target: type[Dialect]) -> None:
        super().__init__()
        self.moves = False
        self.ctx = ctx
        self.target = target
        self.native: frozenset[str] = frozenset() if ctx.run_data.get(POINT_BY_POINT_KEY) else target.HOLE_PATTERNS
        self.expanding = False  # the target gets the active cycle as motion (``expand_canned_cycles`` decides alike)

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        if not self.expanding and "HolePattern" not in sections and "CannedCycle" not in sections:
            return None  # most blocks: no pattern, and no cycle to follow or cancel
        ctx, target = self.ctx, self.target
        pattern = sections.get("HolePattern")
        if pattern is None or not isinstance(pattern, HolePattern):
            cycle = sections.get("CannedCycle")
            if isinstance(cycle, CannedCycle):
                self.expanding = self.moves = self.expanding or expands(cycle, ctx, target)
            elif self.expanding and cancels(sections):
                self.expanding = self.moves = False
            return None
        if pattern.kind in self.native and not (self.expanding or pattern.cycle is not None
                                                and expands(pattern.cycle, ctx, target)):
            sections.pop("CompoundMotion", None)
            return None
        # a native pattern needs its cycle active on the target: where the cycle becomes motion,
        # so does the pattern
        made: list[Block] = []
        for out in point_by_point(block, pattern, ctx):
            here = out.sections.get("CannedCycle")
            if isinstance(here, CannedCycle):
                self.expanding = self.moves = self.expanding or expands(here, ctx, target)
            made.append(out)
        return made


def point_by_point(block: Block, pattern: HolePattern, ctx: Context) -> Iterator[Block]:
    """One block per machined point (see the module docstring); the pattern block's other sections (its
    number, modal words, comments) go on the first."""
    compound = block.sections.get("CompoundMotion")
    cycle = pattern.cycle
    if cycle is None or not isinstance(compound, CompoundMotion):
        raise UnsupportedError(f"a {pattern.kind} hole pattern that was not resolved against its program "
                               "cannot be written point by point", ctx.at(block))
    rest = {k: v for k, v in block.sections.items() if k not in ("HolePattern", "CompoundMotion")}
    hops = pattern_hops(pattern)
    if not hops:
        note = Block(block.line, None, block.eol, list(block.words))
        note.sections = rest
        note.sections["Comments"] = Comments(
            [*getattr(rest.get("Comments"), "texts", []), f"hole pattern of line {block.line}: every point skipped"])
        yield note
        return
    pos = dict(pattern.start)
    previous = first_point(pattern)
    at = 0
    for index, (hop, count) in enumerate(zip(hops, pattern.split)):
        items = compound.items[at:at + count]
        at += count
        out = Block(block.line, None, block.eol if index == len(hops) - 1 else "\n", list(block.words))
        if index == 0:
            out.sections = dict(rest)
        here = cycle_at(pattern, cycle, pos, hop.point, previous)
        here.expand = pattern.move != "rapid"
        out.sections["CannedCycle"] = here
        out.sections["CompoundMotion"] = CompoundMotion(compound.term, items)
        previous = hop.point
        pos = _end(items, pos)
        yield out


def _end(items: list[Section], pos: dict[str, float]) -> dict[str, float]:
    """Where the tool is after ``items`` (their moves are absolute)."""
    end = dict(pos)
    for item in items:
        if isinstance(item, Motion):
            end.update({k: float(v) for k, v in item.axes.items() if not isinstance(v, Expr)})
    return end
