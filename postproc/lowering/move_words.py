"""The X, Y and Z numbers of a plain move, read once for every lowering step that follows the programmed point.

Three steps of a translation follow where each plain move (``lower.plain_move``, most blocks of a CAM program)
takes the program: the frame evaluation (``postproc.frames.lowering``), the tool length timing
(``length_timing``) and the arc pass (``arcs``); the cutter compensation resolver keeps the moves unread until
it needs the point (``cutter_point``: a copy's check, its one follower, read every move here). Each read
the move's words from its dictionary, ~130 instructions a word compiled, and most of them wrote them into a
dictionary of their own (``dict.update``, ~800). Here the words are read once for all of them, as native numbers
(``MoveWords.read``: the same ``Motion`` read again by the next step costs a comparison), and a step notes them
in native fields, brought into its dictionary only before something reads it (each step's ``settle``).

A move that names another axis, or a word that is no ``float`` (a computed word, an ``int``), is not read here
(``OTHER``): the steps take it their general way. A step notes the numbers in a ``NotedPoint`` (the one holder of
the frame evaluation, the tool length timing and the arc pass); while its ``BlockStep.point`` is set, the lowering
loop notes a straight move into it without calling the step (``lower.Walk.through``): one read and three stores
a step, where a call, a look-up of the move and the step's own tests cost it ~400 instructions compiled. A read is keyed on the ``Motion`` and its dictionary, held
here (so neither is freed and its address reused), and on the dictionary's size: a step that changes a move's
words makes a new ``Motion`` (``tool_length_timing``, ``sideways_offsets``), as the steps after it must see.
"""

from __future__ import annotations

from typing import Final

from mypy_extensions import mypyc_attr

from ..context import Context
from ..ir import Motion
from ..ir.expr import Expr

X: Final = 1
Y: Final = 2
Z: Final = 4
"""The bits of ``MoveWords.read``: the axes the move gives as numbers."""
OTHER: Final = -1
"""``MoveWords.read``: the move names another axis than X, Y and Z, or a word that is no ``float``."""

KEY: Final = "lowering.move_words"
"""``Context.run_data`` key of the run's ``MoveWords`` (``move_words``)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class MoveWords:
    """The last move read: its bits (``X``, ``Y``, ``Z``, or ``OTHER``) and its numbers (program units)."""

    def __init__(self) -> None:
        self.motion: Motion | None = None
        self.axes: dict[str, float | Expr] | None = None
        self.size = 0
        self.bits = OTHER
        self.x = 0.0
        self.y = 0.0
        self.z = 0.0

    def read(self, motion: Motion) -> int:
        """The bits of the axes ``motion`` gives, its numbers in ``x``, ``y``, ``z`` (``OTHER``: read it the
        general way)."""
        axes = motion.axes
        if motion is self.motion and axes is self.axes and len(axes) == self.size:
            return self.bits
        size = len(axes)
        bits = 0
        found = 0  # (three looks by key: a loop over the items costs ~300 instructions a word compiled)
        x = axes.get("X")
        if x is not None:
            if type(x) is not float:
                return self._other(motion, axes, size)
            self.x = float(x)
            bits = X
            found = 1
        if found < size:
            y = axes.get("Y")
            if y is not None:
                if type(y) is not float:
                    return self._other(motion, axes, size)
                self.y = float(y)
                bits |= Y
                found += 1
        if found < size:
            z = axes.get("Z")
            if z is not None:
                if type(z) is not float:
                    return self._other(motion, axes, size)
                self.z = float(z)
                bits |= Z
                found += 1
        if found < size:
            return self._other(motion, axes, size)  # another axis
        self.motion = motion
        self.axes = axes
        self.size = size
        self.bits = bits
        return bits

    def _other(self, motion: Motion, axes: dict[str, float | Expr], size: int) -> int:
        """``read``'s answer for a move it does not read (``OTHER``), kept for the next step."""
        self.motion = motion
        self.axes = axes
        self.size = size
        self.bits = OTHER
        return OTHER


@mypyc_attr(allow_interpreted_subclasses=True)
class NotedPoint:
    """The X, Y and Z numbers of the plain moves a step follows, noted (``note``) since the step last brought its
    position up to date (the step's ``settle``: ``into``, before anything reads the position). The step's own
    ``take_move`` and the lowering loop note the same way, through ``note``."""

    def __init__(self, words: MoveWords) -> None:
        self.words = words
        """The run's reader (``move_words``): what the loop reads a move with before it notes it here."""
        self.noted = 0
        """Bits (``X``, ``Y``, ``Z``) of the axes noted since the position was last brought up to date."""
        self.x = 0.0
        self.y = 0.0
        self.z = 0.0

    def note(self, words: MoveWords, bits: int) -> None:
        """The numbers ``words`` read last (``bits``, ``MoveWords.read``: no ``OTHER``), noted."""
        self.noted |= bits
        if bits & X:
            self.x = words.x
        if bits & Y:
            self.y = words.y
        if bits & Z:
            self.z = words.z

    def note_end(self, end: dict[str, float | None]) -> bool:
        """Where an expansion's moves end (``point_after.compound_end``: program units, absolute) noted, where it gives X,
        Y and Z numbers only (True; False: another axis, one not known, or a word that is no ``float``, for the position
        at once). An expanded hole: three look-ups, where bringing the position up to date and a ``dict.update`` cost
        ~900 instructions compiled. (The words are read as objects: typed ``float``, compiled code would take an
        ``int`` for one, where the interpreter does not.)"""
        size = len(end)
        found = 0
        x: object = end.get("X")
        y: object = end.get("Y")
        z: object = end.get("Z")
        if x is not None:
            if type(x) is not float:
                return False
            found = 1
        if y is not None:
            if type(y) is not float:
                return False
            found += 1
        if z is not None:
            if type(z) is not float:
                return False
            found += 1
        if found < size:
            return False  # another axis, or one not known (None)
        if x is not None:
            self.x = float(x)  # (a float, tested above)
            self.noted |= X
        if y is not None:
            self.y = float(y)
            self.noted |= Y
        if z is not None:
            self.z = float(z)
            self.noted |= Z
        return True

    def into(self, position: dict[str, float | None]) -> None:
        """The noted numbers into ``position`` (and none noted any more)."""
        noted = self.noted
        if not noted:
            return
        self.noted = 0
        if noted & X:
            position["X"] = self.x
        if noted & Y:
            position["Y"] = self.y
        if noted & Z:
            position["Z"] = self.z


def moving(mode: str | None) -> bool:
    """``mode`` is a straight move or an arc (rapid, linear, cw, ccw): four comparisons of the commonest first,
    cheaper compiled than a frozenset's ``in`` (~75 instructions), asked by the steps of every plain move."""
    return mode == "linear" or mode == "rapid" or mode == "cw" or mode == "ccw"


def move_words(ctx: Context) -> MoveWords:
    """The run's ``MoveWords`` (one for all its steps: the second reader of a move finds it read)."""
    words = ctx.run_data.get(KEY)
    if not isinstance(words, MoveWords):
        words = ctx.run_data[KEY] = MoveWords()
    return words
