"""What an expanded construct's moves and actions (``CompoundMotion.items``) hold that the steps of a lean
controller's translation ask of every expanded hole, read once a construct for all of them: whether an arc is among
its moves (the arc pass, ``arcs``: without one the construct only moves the position to where its moves end) and how
it leaves the spindle (the tool change pauses, ``postproc.rs274.lean_controller``).

A translation to grbl passes each expanded hole through both steps, one after the other: the second finds the
construct read (``ExpansionItems.read``), where each walked its items with type tests of its own (the arc pass's and
the pauses' walks cost ~1.2k instructions a hole each compiled, callgrind of the drilling benchmark: a hole's items are
``PathMove``s, a subclass of ``Motion``, so every failed ``isinstance`` walks the class's MRO). A read is keyed on the
construct, its items' list and that list's length, held here (so neither is freed and its address reused): a step
that gives a construct other moves gives it another list (``CompoundMotion.items``'s setter, the arc pass's pieces).
"""

from __future__ import annotations

from typing import Final, cast

from mypy_extensions import mypyc_attr

from ..context import Context
from ..ir import CompoundMotion, Motion, ProgramControl, Section, SpindleControl

KEY: Final = "lowering.expansion_items"
"""``Context.run_data`` key of the run's ``ExpansionItems`` (``expansion_items``)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class ExpansionItems:
    """The last construct read: an arc among its moves (``arcs``), and the spindle it leaves (``spindle``)."""

    def __init__(self) -> None:
        self.compound: CompoundMotion | None = None
        self.items: list[Section] | None = None
        self.size = 0
        self.arcs = False
        """A move of mode ``cw`` or ``ccw`` is among the items."""
        self.spindle: str | None = None
        """The spindle as the items leave it: the direction of their last ``SpindleControl``, or ``stop`` after a
        program stop (the writer stops a running spindle before a pause), whichever comes last; None: as it was."""

    def read(self, compound: CompoundMotion) -> None:
        """``arcs`` and ``spindle`` of ``compound`` (walked once; the same construct again is a comparison)."""
        items = compound.items
        size = len(items)
        if compound is self.compound and items is self.items and size == self.size:
            return
        arcs = False
        spindle: str | None = None
        for item in cast("list[object]", items):  # (objects: no cast of each item to ``Section``, a walk of its MRO)
            if isinstance(item, Motion):
                mode = item.mode
                if mode == "cw" or mode == "ccw":
                    arcs = True
            elif isinstance(item, SpindleControl):
                spindle = item.direction
            elif isinstance(item, ProgramControl) and item.kind == "stop":
                spindle = "stop"
        self.compound = compound
        self.items = items
        self.size = size
        self.arcs = arcs
        self.spindle = spindle


def expansion_items(ctx: Context) -> ExpansionItems:
    """The run's ``ExpansionItems`` (one for all its steps: the second to ask of a construct finds it read)."""
    read = ctx.run_data.get(KEY)
    if not isinstance(read, ExpansionItems):
        read = ctx.run_data[KEY] = ExpansionItems()
    return read
