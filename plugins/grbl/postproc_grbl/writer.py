"""grbl writer: the grbl family's writer (``postproc.grbl_family.writer``: ``%`` and O-numbers as comments,
M19 per the set-up, a pause that stops the spindle) with grbl 1.1's tables and its refusals.

What grbl lacks is an ``UnsupportedError`` naming the construct, except where the target has one
faithful spelling of the same physical action. The block rewrites (a tool change as a ``T<n> M0``
pause, G49 before motion, full circles) are the lean-controller lowering steps grbl lists
(``postproc.rs274.lean_controller``); here:

* an oriented spindle stop follows the set-up's ``<Cycles orientation=...>``: ``m19`` writes M19 anyway
  (a grbl build that has it), ``stop`` a program pause for the operator, ``error`` (default) refuses;
  grbl's M0 leaves the spindle turning, so a pause for the operator (also inside a cycle's
  expansion) stops a running spindle first with M5;
* G64 (continuous path) writes nothing: grbl runs its one mode, the exact path (which keeps every point a
  blending mode may leave); G98/G99 write nothing: grbl runs no cycles
  (they arrive expanded), so the retract level has no meaning left; G80 writes nothing either: there is
  no cycle to cancel, and grbl's G80 leaves no motion mode in force, so it would refuse the axis words of
  a following ``G28 Z0.`` (error 31, "axis words exist", even for non-modal commands);
* ``%`` and an O-number, which grbl's parser rejects, are written as comments;
* grbl's serial layer acts on ``?``, ``!``, ``~`` and bytes above 0x7F wherever they stand, and its
  protocol layer keeps 79 characters of a line: every line written obeys ``Grbl.LINE_RULE``
  (``text.py``), applied where lines are emitted (``postproc.output.line_format``), so no path - a block, a
  template's output, a comment copied from grbl itself - writes one of them.

With ``--on-unsupported warn``, a block loses only what grbl refuses and what cannot be written without it,
after a comment of the original block, as for every writer (``postproc.output.partial_block``).
"""

from __future__ import annotations

from typing import Any, ClassVar

from postproc.grbl_family.writer import GrblFamilyWriter
from postproc.ir import Block
from postproc.rs274.codes import CodeTable

from .codes import CODES

GRBL_AXES = frozenset("XYZ")
"""Axes of a stock grbl 1.1 build."""


class GrblWriter(GrblFamilyWriter):
    DIALECT: ClassVar[str] = "grbl"
    CODES: ClassVar[CodeTable] = CODES
    WORK_OFFSET_SETTING: ClassVar[str] = "G10 L2"
    """G10 L2 P1-P6 sets work system P's offset, absolutely (G91 does not change it)."""
    WORK_OFFSET_COUNT: ClassVar[int] = 6
    SETTING_AXES: ClassVar[frozenset[str]] = GRBL_AXES
    DWELL_WORD: ClassVar[str] = "P"
    CYCLE_CANCEL_IS_MOTION: ClassVar[bool] = True
    """G80 is a motion code here: ``G80 G0`` is refused, a block's G0-G3 ends the cycle by itself."""
    BARE_FEED_MOTION_NEEDS_FEED: ClassVar[bool] = True
    DRIVEN_AXES: ClassVar[frozenset[str]] = GRBL_AXES
    FULL_CIRCLE_HELIX: ClassVar[bool] = False
    """What ``close_full_circles`` could not close (a helix with no end point in its plane, in absolute
    mode) grbl refuses: its arc needs an end point in the plane."""
    STRUCTURE: ClassVar[frozenset[str]] = frozenset(("TapeMark",))
    BLANK_AS_TRACE: ClassVar[bool] = True
    """G80, G98/G99, G64 and the like are not grbl's: a block of nothing else is a trace of its source."""

    def table_refusal(self, register: int | None) -> str:
        number = "" if register is None else f" H{register}"
        return f"a tool length offset from a table (G43{number}; grbl has only G43.1)"

    # -- section words -----------------------------------------------------------------------------
    def block_delete_words(self, s: Any, block: Block) -> list[str]:
        self.unsupported("block delete '/' (grbl ignores it: the block would always run)", block)
        return []

    def return_level_words(self, s: Any, block: Block) -> list[str]:
        """G98/G99 only steer canned cycles, which grbl never runs (they arrive expanded)."""
        return []

    def cycle_cancel_words(self, s: Any, block: Block) -> list[str]:
        """No cycle ever runs on grbl (see the module docstring): nothing to cancel."""
        return []


    def tool_change_words(self, s: Any, block: Block) -> list[str]:
        """What ``pause_for_tool_change`` leaves: a tool change with no tool selected before it."""
        self.unsupported("a tool change with no tool selected (grbl's manual tool change, T<n> M0, names the "
                         "tool to load: program T before M6)", block)
