"""What the frame evaluation (``postproc.frames.lowering``) has reached where the program stands, kept apart
from the evaluator so that the readers of the position (``postproc.frames.parameters``, the measured tool
entries) and the evaluator's own modules (``commands``, ``offset_changes``) depend on it, not on the evaluator."""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from ..compensation.tool_length import ToolLength
from ..lowering.move_words import MoveWords, NotedPoint
from .frame import Frame, Position
from .run_order import RunOrder

@mypyc_attr(allow_interpreted_subclasses=True)
class FrameRun:
    """What the evaluation has reached (``Context.frame_run``): copied into a translation's dry run, which starts from
    the reading state and the frame where the program stands (``postproc.api``)."""

    __slots__ = ("frame", "p", "g5x", "symbolic", "work", "order", "unsettled", "scale", "cutter", "tools", "sideways",
                 "tools_known", "table_known", "notes")

    def __init__(self, p: Position, words: MoveWords) -> None:
        self.frame: Frame | None = None
        """None until the first frame command (or a rotation of a work system)."""
        self.p = p
        """The program position, mm (degrees on rotary axes), None where unknown; read through ``point``: the X, Y
        and Z of the plain moves since it was last read are noted apart (``notes``)."""
        self.notes = NotedPoint(words)
        """The X, Y and Z plain moves noted since ``p`` was brought up to date (``settle``): the commonest block, a
        plain move with no frame, writes no dictionary."""
        self.unsettled: set[str] = set(p)
        """Axes not programmed absolutely since the start: their ``p`` is the set-up's assumed start, not what
        the machine reads as its current point (a read of the current position there is the machine's,
        ``postproc.frames.parameters``)."""
        self.tools: ToolLength | None = None
        """The tool length offset in force (made at the first change), on a controller that keeps the machine
        point at a change (``offset_changes.tool_change``)."""
        self.sideways: dict[str, float] = {}
        """The X and Y offsets of the tool entry in force (mm)."""
        self.tools_known = True
        """The offsets in force are known (False after a change this evaluation cannot work out)."""
        self.table_known = True
        """The tool table's entries are known (False after a program's entry not worked out here)."""
        self.scale = 1.0
        """mm per program length unit where the program stands (G20: 25.4)."""
        self.cutter = False
        """Cutter radius compensation is on where the program stands."""
        self.g5x: dict[int, dict[str, float]] = {}
        """Work offsets a G10 in the program set, mm (the rest are unknown here)."""
        self.symbolic = False
        """A construct (an assignment, a control statement) went by: the program is kept symbolically."""
        self.work: int | None = None
        """The work system the program selected last (1 = G54); None before it selects one (the machine's)."""
        self.order = RunOrder()
        """The constructs and jumps of the symbolic part: which frame command runs in the text's order."""

    def settle(self) -> None:
        """The noted X, Y and Z into ``p`` (before anything reads it)."""
        self.notes.into(self.p)

    def point(self) -> Position:
        """The program position (``p``), brought up to date."""
        self.settle()
        return self.p
