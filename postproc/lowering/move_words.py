"""The X, Y and Z numbers of a plain move, read once for every lowering step that follows the programmed point.

Three steps of a translation follow where each plain move (``lower.plain_move``, most blocks of a CAM program)
takes the program: the frame evaluation (``postproc.frames.lowering``), the tool length timing
(``length_timing``) and the arc pass (``arcs``); the cutter compensation resolver keeps the moves unread until
it needs the point (``cutter_point``: a copy's check, its one follower, read every move here). Each read
the move's words from its dictionary, ~130 instructions a word compiled, and most of them wrote them into a
dictionary of their own (``dict.update``, ~800). Here the words are read once for all of them, as native numbers
(``MoveWords``, ``postproc.ir.move_words``: the reading's modal state reads each move first, and the same ``Motion``
read again by a step costs a comparison), and a step notes them in native fields, brought into its dictionary only
before something reads it (each step's ``settle``).

A move that names another axis, or a word that is no ``float`` (a computed word, an ``int``), is not read
(``OTHER``): the steps take it their general way. A step notes the numbers in a ``NotedPoint`` (the one holder of
the frame evaluation, the tool length timing and the arc pass); while its ``BlockStep.point`` is set, the lowering
loop notes a straight move into it without calling the step (``lower.Walk.through``): one read and three stores
a step, where a call, a look-up of the move and the step's own tests cost it ~400 instructions compiled.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from ..context import Context
from ..ir.move_words import OTHER as OTHER, X as X, Y as Y, Z as Z, MoveWords as MoveWords


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
        self.follows = True
        """``note`` notes (False: a ``PassedPoint``, which notes nothing: the lowering loop does not call it)."""
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


@mypyc_attr(allow_interpreted_subclasses=True)
class PassedPoint(NotedPoint):
    """The ``BlockStep.point`` of a step that reads no point: a straight move alone in its block leaves the step as it
    is, so the loop passes it as a noted point's step, and nothing is noted (``postproc.rs274.lean_controller.passed``:
    a note nothing read cost ~55 instructions a block compiled, every grbl and grblHAL translation: the loop reads
    ``follows`` instead of calling it)."""

    def __init__(self, words: MoveWords) -> None:
        super().__init__(words)
        self.follows = False

    def note(self, words: MoveWords, bits: int) -> None:
        return


def moving(mode: str | None) -> bool:
    """``mode`` is a straight move or an arc (rapid, linear, cw, ccw): four comparisons of the commonest first,
    cheaper compiled than a frozenset's ``in`` (~75 instructions), asked by the steps of every plain move."""
    return mode == "linear" or mode == "rapid" or mode == "cw" or mode == "ccw"


def move_words(ctx: Context) -> MoveWords:
    """The run's ``MoveWords`` (one for all its steps, and the reading's modal state before them: the second reader
    of a move finds it read: ``Context.move_words``)."""
    return ctx.move_words
