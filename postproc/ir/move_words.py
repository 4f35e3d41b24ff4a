"""The X, Y and Z numbers of a plain move (``MoveWords``), read once a run for everything that follows the point.

The reading's modal state (``postproc.syntaxes.modal_state``: where each move leaves the tool) reads every plain
move first; the lowering steps that follow the programmed point (the frame evaluation, the tool length timing, the
arc pass: ``postproc.lowering.move_words``) read the same ``Motion`` after it, and find it read (a comparison).
Read word by word, the modal state's pass over the move's items and its test of each letter against the machine's
axes cost ~630 instructions a block compiled, and the lowering's own read ~550 more (callgrind, issue 30).

A read is keyed on the ``Motion`` and its dictionary, held here (so neither is freed and its address reused), and
on the dictionary's size: a step that changes a move's words makes a new ``Motion`` (``tool_length_timing``,
``sideways_offsets``), as the steps after it must see. A move that names another axis, or a word that is no
``float`` (a computed word, an ``int``), is not read here (``OTHER``): each reader takes it its general way.
"""

from __future__ import annotations

from typing import Final

from mypy_extensions import mypyc_attr

from .expr import Expr
from .motion import Motion

X: Final = 1
Y: Final = 2
Z: Final = 4
"""The bits of ``MoveWords.read``: the axes the move gives as numbers."""
OTHER: Final = -1
"""``MoveWords.read``: the move names another axis than X, Y and Z, or a word that is no ``float``."""

@mypyc_attr(allow_interpreted_subclasses=True)
class MoveWords:
    """The last move read: its bits (``X``, ``Y``, ``Z``, or ``OTHER``) and its numbers (program units). One a run
    (``Context.move_words``), for all its readers: the second reader of a move finds it read."""

    def __init__(self) -> None:
        self.motion: Motion | None = None
        self.axes: dict[str, float | Expr] | None = None
        self.size = 0
        self.bits = OTHER
        self.x = 0.0
        self.y = 0.0
        self.z = 0.0
        self.x_word: object = None
        self.y_word: object = None
        self.z_word: object = None
        """The words read (the ``float`` objects of ``x``, ``y``, ``z``, where ``bits`` has theirs): a reader that
        stores them (the modal state's position) stores these, not new numbers."""
        self.machine: frozenset[str] | None = None
        """The axes ``on`` was last asked about (a run's machine: one set for the run)."""
        self.machine_bits = 0
        """The bits of X, Y and Z among ``machine``."""

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
            self.x_word = x  # (before the type test: narrowed, compiled, it would be unboxed and boxed anew)
            if type(x) is not float:
                return self._other(motion, axes, size)
            self.x = float(x)
            bits = X
            found = 1
        if found < size:
            y = axes.get("Y")
            if y is not None:
                self.y_word = y
                if type(y) is not float:
                    return self._other(motion, axes, size)
                self.y = float(y)
                bits |= Y
                found += 1
        if found < size:
            z = axes.get("Z")
            if z is not None:
                self.z_word = z
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

    def on(self, machine: frozenset[str]) -> int:
        """The bits of X, Y and Z among ``machine`` (the set-up's axes, ``Context.axis_words``: worked out once a
        run, where three tests of a set cost ~230 instructions a block compiled)."""
        if machine is not self.machine:
            self.machine = machine
            self.machine_bits = (X if "X" in machine else 0) | (Y if "Y" in machine else 0) | \
                (Z if "Z" in machine else 0)
        return self.machine_bits

