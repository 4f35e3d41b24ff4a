"""The expansion-move lane: a straight move of an expanded hole cycle (``G0 X.. Y.. Z..``, ``G1 Z..``) written
without the word writer's item dispatch, and without a new ``Motion`` for the axes it leaves out.

A speed-only copy of what ``WordWriter.compound`` writes for such a move (``move_line`` of the move less the
axes ``_left_out`` leaves out, which ``motion_words`` spells), kept apart from the classes dialects extend
(STYLE.md 11). ``install_expansion`` gives it to a run only where the writer class writes a move of an
expansion with the base's own methods (``MOVE_METHODS``), and ``tests/test_expansion_moves.py`` holds it to
the general path on random hole programs. It answers None for any move it is not sure of; the general path
then writes it. Each number is spelt by the writer's own functions (``_position``, ``source_number``).
"""

from __future__ import annotations

from typing import Final

from mypy_extensions import mypyc_attr

from ..cycles.expansion import PathMove
from ..ir import Block, Motion
from ..ir.expr import Expr
from ..output.writer_base import Writer
from ..rs274.word_numbers import _position
from ..rs274.writer import MoveLane, WordWriter

MOVE_METHODS: Final = ("move_line", "motion_words")
"""What the general path calls to write a straight move of an expansion (``compound``'s loop calls
``move_line``, which calls ``motion_words``; ``_left_out`` is a module function, ``source_number`` and
``_position`` the lane calls too). Not among them: ``item_line``, which ``compound`` asks of an item that is
no move only (grbl's family adds a spindle stop there, before a program stop); ``left_out``, which
``motion_words`` asks only of a move with no axis words (the lane leaves such a move to it), and
``check_reference_return``, asked of a reference return only."""
_BASE: Final = frozenset(WordWriter.__mro__)
LINES_KEPT: Final = 256
"""The numbers of one axis (and code) ``ExpansionMoves`` remembers at most (then it starts again): a row of holes
writes a few."""


@mypyc_attr(allow_interpreted_subclasses=True)
class ExpansionMoves(MoveLane):
    """Writes a straight move of an expansion in absolute distance mode whose axis words are numbers, as
    ``move_line`` writes it after ``_left_out``: its motion code and each axis word it does not leave out
    (an axis at the number the move written just before it stands at: ``before``)."""

    def __init__(self, writer: WordWriter) -> None:
        super().__init__()
        self.writer = writer
        codes = writer.codes
        self.rapid = codes.spell("motion", "rapid") or ""
        self.linear = codes.spell("motion", "linear") or ""
        """The codes of a rapid and a feed move, spelled once ('': the table has none, the general path
        refuses the move)."""
        driven: frozenset[str] | None = writer.DRIVEN_AXES
        self.driven = driven
        """The axes the controller drives (None: every one): a move of another is left to the general path,
        which refuses it."""
        self.drives_x = driven is None or "X" in driven
        self.drives_y = driven is None or "Y" in driven
        self.drives_z = driven is None or "Z" in driven
        self.drives_xyz = self.drives_x and self.drives_y and self.drives_z
        """Whether it drives X, Y and Z, the axes of an expansion's moves (asked once, not at every move)."""
        self.units = writer.modal.units
        """The units the numbers below were spelt in (another: they are forgotten)."""
        self.lines: list[dict[float, str]] = [{} for _ in range(6)]
        """Per code (rapid, feed) and axis (X, Y, Z): number -> the line of a move that writes that one word,
        where spelling its number changes nothing of the writer (no rounding, nothing carried: ``_position``
        then reads the writer's table of exact texts): an expansion writes the same few lines (``G1 Z-5.``,
        ``G0 Z2.``) at every hole. A float key, not a tuple: no tuple to build and hash a move."""
        self.numbers: list[dict[float, str]] = [{}, {}, {}]
        """Per axis (X, Y, Z): number -> its word with the space before it (`` Z2.``), spelt likewise, for the
        moves that write more than one word (a hole's positioning, ``G0 X6.35 Y0. Z2.``: the level and the row's
        other axis repeat)."""
        self.seen: list[Seen] = []
        """The one-word lines of the moves since the last move that had no ``before`` (a hole's first), by
        their place among them: the next hole's moves are the same lines in the same places, found by a compare
        of numbers (``lines`` hashes a float)."""
        self.place = 0
        """The place of the next move among them."""
        self.last: dict[str, float | Expr] | None = None
        """The axes of the move this lane wrote last, where they are X, Y and Z only, while the moves it writes
        follow one another (``before`` is then that very dict: its numbers are the ones below, compared without
        a look-up by letter)."""
        self.at_x = self.at_y = self.at_z = 0.0
        self.has_x = self.has_y = self.has_z = False
        """Where ``last`` stands: its X, Y and Z numbers, and which of them it has."""

    def line(self, item: Motion, before: dict[str, float | Expr] | None, block: Block) -> str | None:
        """The move's line, or None. Its words are checked before any is spelt: spelling one may change the
        writer's state (what a rounding carries), so a move left to the general path is spelt there only.
        (One pass checks the words, compares each with where the tool stands and counts those written, and a
        move that writes one word, the commonest of a hole, spells it without walking its words again.)"""
        if before is None:
            self.last = None  # (a new expansion, or a move after an item the tool does not stand still for)
            self.place = 0
        if item.center is not None or item.radius is not None:
            return None
        mode = item.mode
        feeding = mode == "linear"
        code = self.rapid if mode == "rapid" else self.linear if feeding else ""
        writer = self.writer
        if not code or writer.modal.distance != "absolute":
            return None  # (not absolute: ``move_line`` writes the distance mode's code first)
        if type(item) is PathMove and item.axes is item.made and self.drives_xyz:
            return self._path_move(item, code, feeding, before, block)
        axes = item.axes
        remembered = before is not None and before is self.last
        written = 0
        last = ""
        last_value = 0.0
        last_slot = -1
        x = y = z = 0.0
        has_x = has_y = has_z = other = False
        write_x = write_y = write_z = False
        for axis, value in axes.items():
            if type(value) is not float:
                return None
            number: float = value
            slot = -1
            same = False
            if axis == "X":
                if not self.drives_x:
                    return None
                slot, x, has_x = 0, number, True
                same = remembered and self.has_x and number == self.at_x
            elif axis == "Y":
                if not self.drives_y:
                    return None
                slot, y, has_y = 1, number, True
                same = remembered and self.has_y and number == self.at_y
            elif axis == "Z":
                if not self.drives_z:
                    return None
                slot, z, has_z = 2, number, True
                same = remembered and self.has_z and number == self.at_z
            else:
                driven = self.driven
                if driven is not None and axis not in driven:
                    return None
                other = True  # (``remembered``: not in ``before``, written)
            if before is not None and not remembered:
                was = before.get(axis)
                same = type(was) is float and was == value
            if same:
                continue
            if slot == 0:
                write_x = True
            elif slot == 1:
                write_y = True
            elif slot == 2:
                write_z = True
            written += 1
            last, last_value, last_slot = axis, number, slot
        if written == 0:
            return None  # every axis left out: ``motion_words`` asks ``left_out`` of a move with none
        units = writer.modal.units
        if units != self.units:
            self._forget(units)
        as_written = block.canonical and writer.source_numbers
        if written == 1:
            if writer.rounding or writer.carry or last_slot < 0 or (as_written and _has_word(block, last)):
                text = f"{code} {last}{self._number(writer, block, last, last_value, as_written)}\n"
            else:
                text = self._one_word(code, feeding, last, last_slot, last_value)
        else:
            text = code
            for axis, value in axes.items():
                if not isinstance(value, float):
                    return None  # (none: tested above, before a word was spelt)
                if axis == "X":
                    write = write_x
                elif axis == "Y":
                    write = write_y
                elif axis == "Z":
                    write = write_z
                else:
                    was = None if before is None else before.get(axis)
                    write = not (type(was) is float and was == value)
                if write:
                    text += self._word(writer, block, axis, value, as_written)
            text += "\n"
        if other:
            self.last = None
        else:
            self.last = axes
            self.at_x, self.at_y, self.at_z = x, y, z
            self.has_x, self.has_y, self.has_z = has_x, has_y, has_z
        return text

    def _path_move(self, item: PathMove, code: str, feeding: bool, before: dict[str, float | Expr] | None,
                   block: Block) -> str | None:
        """``line`` of a ``PathMove`` (its axes X, Y and Z, in that order, at its ``x``, ``y``, ``z``), read from
        its floats: the same words, compared and spelt the same way, without walking its dict."""
        x, y, z = item.x, item.y, item.z
        if before is None:
            write_x = write_y = write_z = True
        elif before is self.last:
            write_x = not (self.has_x and x == self.at_x)
            write_y = not (self.has_y and y == self.at_y)
            write_z = not (self.has_z and z == self.at_z)
        else:
            was = before.get("X")
            write_x = not (type(was) is float and was == x)
            was = before.get("Y")
            write_y = not (type(was) is float and was == y)
            was = before.get("Z")
            write_z = not (type(was) is float and was == z)
        written = int(write_x) + int(write_y) + int(write_z)
        if written == 0:
            return None  # every axis left out: ``motion_words`` asks ``left_out`` of a move with none
        writer = self.writer
        units = writer.modal.units
        if units != self.units:
            self._forget(units)
        as_written = block.canonical and writer.source_numbers
        if written == 1:  # (no tuple of the one word's axis, slot and number: a branch each)
            if write_z:
                text = self._single(writer, block, code, feeding, "Z", 2, z, as_written)
            elif write_x:
                text = self._single(writer, block, code, feeding, "X", 0, x, as_written)
            else:
                text = self._single(writer, block, code, feeding, "Y", 1, y, as_written)
        else:  # (one string built of its parts, spelt in X, Y, Z order: no list to join)
            text = (f"{code}{self._word(writer, block, 'X', x, as_written) if write_x else ''}"
                    f"{self._word(writer, block, 'Y', y, as_written) if write_y else ''}"
                    f"{self._word(writer, block, 'Z', z, as_written) if write_z else ''}\n")
        self.last = item.axes
        self.at_x, self.at_y, self.at_z = x, y, z
        self.has_x = self.has_y = self.has_z = True
        return text

    def _single(self, writer: WordWriter, block: Block, code: str, feeding: bool, axis: str, slot: int,
                value: float, as_written: bool) -> str:
        """The line of a move that writes one word, an X, Y or Z (``slot`` 0, 1, 2) at ``value``."""
        if writer.rounding or writer.carry or (as_written and _has_word(block, axis)):
            return f"{code} {axis}{self._number(writer, block, axis, value, as_written)}\n"
        return self._one_word(code, feeding, axis, slot, value)

    def _one_word(self, code: str, feeding: bool, axis: str, slot: int, value: float) -> str:
        """The line of a move that writes one word, an X, Y or Z at ``value``, where spelling it changes nothing
        of the writer: the line at this place of the last hole where it is the same, else from ``lines``, else
        spelt."""
        place = self.place
        self.place = place + 1
        seen = self.seen
        if place < len(seen):
            was = seen[place]
            if was.value == value and was.slot == slot and was.feeding == feeding:
                return was.line
        lines = self.lines[3 + slot if feeding else slot]
        line = lines.get(value)
        if line is None:
            line = f"{code} {axis}{_position(self.writer, axis, value, False)}\n"
            if self.writer.carry:
                return line  # (not spelt exactly: not the same line every time)
            _keep(lines, value, line)
        if place < len(seen):
            seen[place] = Seen(feeding, slot, value, line)
        elif place < LINES_KEPT:
            seen.append(Seen(feeding, slot, value, line))
        return line

    def _forget(self, units: str) -> None:
        """Numbers spelt in other units than ``units``: forgotten."""
        self.units = units
        for lines in self.lines:
            lines.clear()
        for numbers in self.numbers:
            numbers.clear()
        self.seen.clear()

    def _word(self, writer: WordWriter, block: Block, axis: str, value: float, as_written: bool) -> str:
        """A word of a line, with the space before it (`` X6.35``): its number ``_number``'s, the word from
        ``numbers`` where spelling it changes nothing of the writer (as ``lines``)."""
        slot = 0 if axis == "X" else 1 if axis == "Y" else 2 if axis == "Z" else -1
        if writer.rounding or writer.carry or slot < 0 or (as_written and _has_word(block, axis)):
            return f" {axis}{self._number(writer, block, axis, value, as_written)}"
        numbers = self.numbers[slot]
        text = numbers.get(value)
        if text is None:
            text = f" {axis}{_position(writer, axis, value, False)}"
            if not writer.carry:
                _keep(numbers, value, text)
        return text

    @staticmethod
    def _number(writer: WordWriter, block: Block, axis: str, value: float, as_written: bool) -> str:
        """An axis word's number as ``motion_words`` spells it: the source's text where that is the
        writer's, else ``_position``."""
        number = writer.source_number(block, axis, value, False) if as_written else None
        return number if number is not None else _position(writer, axis, value, False)


@mypyc_attr(allow_interpreted_subclasses=True)
class Seen:
    """A one-word line ``ExpansionMoves`` wrote at a place of a hole: its code (feed or rapid), axis (0, 1, 2:
    X, Y, Z) and number."""

    __slots__ = ("feeding", "slot", "value", "line")

    def __init__(self, feeding: bool, slot: int, value: float, line: str) -> None:
        self.feeding, self.slot, self.value, self.line = feeding, slot, value, line


def _keep(memory: dict[float, str], value: float, text: str) -> None:
    """Remember ``text`` for ``value``, at most ``LINES_KEPT`` numbers (then start again)."""
    if len(memory) >= LINES_KEPT:
        memory.clear()
    memory[value] = text


def _has_word(block: Block, letter: str) -> bool:
    """Whether the block as read has a ``letter`` word (``source_number`` copies only such a word's text)."""
    for word, _ in block.words:
        if word == letter:
            return True
    return False


def _owner(cls: type, name: str) -> type | None:
    """The class of ``cls``'s MRO that defines ``name``."""
    return next((c for c in cls.__mro__ if name in c.__dict__), None)


def choose_moves(writer: Writer) -> MoveLane | None:
    """The expansion-move lane for ``writer``'s run, or None (``compound`` writes every move itself)."""
    if not isinstance(writer, WordWriter):
        return None
    cls = type(writer)
    for name in MOVE_METHODS:
        if _owner(cls, name) not in _BASE:
            return None
    return ExpansionMoves(writer)


def install_expansion(writer: Writer) -> None:
    """Give ``writer`` its run's expansion-move lane (``WordWriter.move_lane``), where one applies."""
    if isinstance(writer, WordWriter):
        writer.move_lane = choose_moves(writer)
