"""Moves in machine coordinates under incremental distance, for ISG and Fagor (a ``LOWERING`` step of each).

Both write a move in machine coordinates absolutely (ISG ``#SUPPRESS OFFSETS X..``, Fagor ``G53 X..``: the
positions are machine positions, ``G90`` before them) and a Fanuc reference return (``G28``) as its
intermediate move and then such a move to the set-up's home (``postproc.output.home_position``). Written block
by block, a program's ``G91 G28 Z0.`` then ``G28 X0. Y0.`` became ``G91`` / ``G90 G00`` / ``#SUPPRESS OFFSETS
Z0.`` / ``G91`` / ``G90 G00`` / ``#SUPPRESS OFFSETS X0. Y0.`` / ``G91``: each block switching to absolute and
back. An ISG or Fagor programmer writes ``G90`` once before the returns and ``G91`` again where an incremental
word is next read. This step does that in the IR:

* a reference return whose incremental intermediate point is where the tool stands (every axis word zero, the
  usual ``G91 G28 Z0.``) is the move to the set-up's home in machine coordinates itself (Fanuc moves to the
  intermediate point and then to the reference position [K: Fanuc 0i-MF operator's manual, "Reference position
  return"]: a zero increment moves nothing, so only the second move is left); where the set-up gives no home,
  the block is left for the writer's located error;
* the first of a run of such moves (and of ``G53`` moves) under incremental distance gets ``G90``; the next
  block that is not one of them and not a comment alone gets ``G91`` back, unless it programs its own distance
  mode; a reference return with a real intermediate move needs ``G91`` for it, so it gets it too.

The program's distance mode is unchanged wherever a word reads it: ``verify`` compares the same path.
"""

from __future__ import annotations

from typing import Final

from mypy_extensions import mypyc_attr

from ..context import Context
from ..dialect import Dialect
from ..ir import Block, DistanceMode, MachineCoordinates, Motion
from ..lowering.lower import BlockStep, LoweringStep
from ..output.home_position import home_position
from ..lowering.units_and_distance import UnitsAndDistance

REFERENCE: Final = frozenset(("home", "home2"))
QUIET: Final = frozenset(("Comments", "Sequence"))
"""A block of only these reads no distance mode."""


@mypyc_attr(allow_interpreted_subclasses=True)
class AbsoluteMachineMoves(LoweringStep):
    """Lowering step: see the module docstring."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return _AbsoluteMachineMoves(ctx)


absolute_machine_moves = AbsoluteMachineMoves()


@mypyc_attr(allow_interpreted_subclasses=True)
class _AbsoluteMachineMoves(BlockStep):
    """One run: the distance mode and units the program reads, and whether a ``G91`` is owed. A block that
    is only a move is its business only under incremental distance (it may be a reference return, ``G28 X0.``)
    or while a ``G91`` is owed (it reads the distance mode)."""

    def __init__(self, ctx: Context) -> None:
        super().__init__()
        self.ctx = ctx
        self.modes = UnitsAndDistance()
        """What the program reads (not the ``G90`` this step adds)."""
        self.absolute_there = False
        """The target runs absolute where the program is incremental (a ``G91`` is owed)."""
        self.moves = not self.modes.absolute

    def take(self, block: Block) -> list[Block] | None:
        s = block.sections
        modes = self.modes
        modes.follow(s)
        own = s.get("DistanceMode")
        m = s.get("Motion")
        machine = isinstance(m, Motion) and "BlockDelete" not in s and (
            "MachineCoordinates" in s or m.mode in REFERENCE)
        if machine and not modes.absolute and isinstance(m, Motion) and _settled(block, m, self.ctx, modes.inch):
            if not self.absolute_there:
                block.add(DistanceMode("absolute"))  # (replaces the block's own G91: restored after)
                self.absolute_there = True
            elif own is not None:
                del s["DistanceMode"]
            block.changed()
        elif self.absolute_there and not (s.keys() <= QUIET):
            self.absolute_there = False
            if own is None:
                block.add(DistanceMode("incremental"))
                block.changed()
        self.moves = self.absolute_there or not modes.absolute
        return None


def _settled(block: Block, motion: Motion, ctx: Context, inch: bool) -> bool:
    """The block is a move in machine coordinates (a zero-increment return made into one): True."""
    s = block.sections
    if "MachineCoordinates" in s:
        return True
    if motion.mode != "home" or any(not isinstance(v, (int, float)) or v != 0 for v in motion.axes.values()):
        return False  # G30, or a real intermediate move: written as it is
    homes = {axis: home_position(ctx.setup, axis, inch) for axis in motion.axes}
    if not homes or any(v is None for v in homes.values()):
        return False  # the writer's located error names the missing home
    s["Motion"] = Motion("rapid", {a: v for a, v in homes.items() if v is not None})
    s["MachineCoordinates"] = MachineCoordinates()
    return True
