"""SINUMERIK's rigid tap: the strokes ``G331`` (in) and ``G332`` (out, the spindle reversed by the control),
read and written as ISG's (``postproc.isg_family.taps``; ``postproc.cycles.rigid_tap_lowering.as_strokes``
splits a synchronised tap of another family into them), after the oriented stop that puts the spindle
under position control.

[K] SINUMERIK 840D sl Fundamentals, "Tapping without compensating chuck (G331, G332)", as quoted at
https://en.cncforum.net/t/siemens-cnc-milling-g331-g332-codes-thread-interpolation/197: before G331 the
spindle must be switched to position control with ``SPOS=``; the sign of the pitch gives the direction of
rotation; the speed is programmed with S and without M3/M4; the manual's example goes back to speed
control with ``M3`` after G332. So ``orient_before_taps`` writes ``SPOS=`` (the set-up's orientation angle,
``<Cycles orientAngle>``) before an in stroke unless the spindle is still under position control: an
oriented stop or a tap stroke came last, and no spindle code (M3, M4, M5) or tool change since.

The angle a tap starts at does not change the thread it cuts in a hole not yet threaded, so the
simulation takes an oriented stop right before a tap as the tap's own preparation, as Fanuc's ``M29`` is
(``postproc.simulate.stream.prepared_taps``).
"""

from __future__ import annotations

from postproc.context import Context
from postproc.dialect import Dialect
from postproc.ir import Block, CompoundMotion, Section, SpindleOrientation
from postproc.lowering.lower import BlockStep, LoweringStep
from postproc.lowering.synchronised_tap import RigidTap

_ENDS_POSITION_CONTROL = frozenset(("SpindleControl", "ToolChange"))
"""Sections after which the spindle runs under speed control again (M3/M4/M5; a tool change)."""


class OrientBeforeTaps(LoweringStep):
    """Lowering step (the module docstring): an oriented stop before each in stroke that needs one, in a
    block of its own before the stroke's block, or as an item before it in an expansion."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return _Orient(float(ctx.setup.cycles.orient_angle))


orient_before_taps = OrientBeforeTaps()


class _Orient(BlockStep):
    """One run: whether the spindle is under position control. A block that is only a move is none of its
    business (no tap, no oriented stop, no spindle code)."""

    def __init__(self, angle: float) -> None:
        super().__init__()
        self.angle = angle
        self.controlled = False
        """The spindle is under position control (an oriented stop or a tap stroke came last)."""
        self.moves = False

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        controlled = self.controlled
        if "RigidTap" not in sections and "CompoundMotion" not in sections and "SpindleOrientation" not in sections:
            if not controlled or _ENDS_POSITION_CONTROL.isdisjoint(sections):
                return None  # the common block
        if "SpindleControl" in sections or "ToolChange" in sections:
            controlled = False
        if "SpindleOrientation" in sections:
            controlled = True
        compound = sections.get("CompoundMotion")
        if isinstance(compound, CompoundMotion) and "CannedCycle" not in sections:
            items, controlled = _orient_items(compound.items, controlled, self.angle)
            if len(items) != len(compound.items):
                sections["CompoundMotion"] = CompoundMotion(compound.term, items)
                block.changed()
        made: list[Block] | None = None
        tap = sections.get("RigidTap")
        if isinstance(tap, RigidTap) and tap.stroke is not None:
            if tap.stroke == "in" and not controlled:
                before = Block(block.line, None, block.eol or "\n")
                before.sections = {"SpindleOrientation": SpindleOrientation(self.angle)}
                made = [before, block]
            controlled = True
        self.controlled = controlled
        return made


def _orient_items(items: list[Section], controlled: bool, angle: float) -> tuple[list[Section], bool]:
    """An expansion's items with an oriented stop before each in stroke that needs one, and whether the
    spindle is under position control after them."""
    out: list[Section] = []
    for item in items:
        key = item.KEY
        if key in _ENDS_POSITION_CONTROL:
            controlled = False
        elif key == "SpindleOrientation":
            controlled = True
        elif isinstance(item, RigidTap) and item.stroke is not None:
            if item.stroke == "in" and not controlled:
                out.append(SpindleOrientation(angle))
            controlled = True
        out.append(item)
    return out, controlled
