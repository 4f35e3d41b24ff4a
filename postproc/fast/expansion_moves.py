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
from ..ir import Block, CompoundMotion, Motion, Section
from ..ir.expr import Expr
from ..output.writer_base import Lane, Writer
from ..rs274.word_numbers import _position
from ..rs274.writer import _STANDING, MoveLane, WordWriter, _is_straight, _left_out
from .straight import StraightLane

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
        """Per axis (X, Y, Z): number -> its text, spelt likewise, for the moves that write more than one word
        (a hole's positioning, ``G0 X6.35 Y0. Z2.``: the level and the row's other axis repeat)."""
        self.recent = [Spelt(), Spelt(), Spelt()]
        """Per axis (X, Y, Z): the number ``numbers`` gave last and its text (a float compared, not hashed: a hole's
        level and its row's other axis repeat)."""
        self.seen: list[Seen] = []
        """The one-word lines of the moves since the last move that had no ``before`` (a hole's first), by
        their place among them: the next hole's moves are the same lines in the same places, found by a compare
        of numbers (``lines`` hashes a float)."""
        self.place = 0
        """The place of the next move among them."""
        self.made: list[Made] = []
        """The line of each ``PathMove`` of the last expansion by its place among the expansion's items, where
        spelling it changed nothing of the writer (``write``): the next hole's moves write the same lines, found
        by a compare of numbers (its first move, to the next spot, is the one spelt anew)."""
        self.made_units = writer.modal.units
        """The units the lines of ``made`` were spelt in."""
        self.rest = ""
        """The lines of ``made`` from the second place on, joined, where an expansion of ``rest_count`` items had a
        line of ``made`` at each of them ('': none since ``made`` last changed): the next whose moves after its
        first are all found there writes them as this one text (a hole's moves but its first are the last hole's)."""
        self.rest_count = 0
        self.last: dict[str, float | Expr] | None = None
        """The axes of the move this lane wrote last, where they are X, Y and Z only, while the moves it writes
        follow one another (``before`` is then that very dict: its numbers are the ones below, compared without
        a look-up by letter)."""
        self.at_x = self.at_y = self.at_z = 0.0
        self.has_x = self.has_y = self.has_z = False
        """Where ``last`` stands: its X, Y and Z numbers, and which of them it has."""

    def write(self, items: list[Section], block: Block, lines: list[str]) -> None:
        """``write_items``: the lines of an expansion's items, appended to ``lines``. A move the tool makes to a
        spot known in X, Y and Z (``PathMove``) writes the line the move at the same place of the last expansion
        wrote where the two write the same words (``Made``), else ``line``'s; a move ``line`` leaves, and any
        other item, is the general path's."""
        writer = self.writer
        before: dict[str, float | Expr] | None = None
        units = writer.modal.units
        if units != self.made_units:
            self.made.clear()
            self.made_units = units
            self.rest = ""
        made = self.made
        kept = len(made)
        place = 0
        found = 0
        """The items from the second on that are moves whose line is ``made``'s, while every one is: not appended
        yet (``rest`` holds them, or they are appended at the first item that is not)."""
        remade = False
        """A line of ``made`` changed at a place after the first (``rest`` is then made again)."""
        words = -1
        """Which of X, Y and Z (bits 1, 2, 4) the block as read has a word of, where the writer copies such a word's
        text (``source_number``): a line with one of them is spelt anew (-1: not found yet)."""
        at_x = at_y = at_z = 0.0
        follows = False
        """``before`` is the axes of the ``PathMove`` written just before (X, Y, Z at ``at_x``, ``at_y``, ``at_z``)."""
        for item in items:
            if isinstance(item, Motion):
                line: str | None = None
                if type(item) is PathMove and item.axes is item.made and self.drives_xyz \
                        and item.center is None and item.radius is None:
                    mode = item.mode
                    feeding = mode == "linear"
                    straight = feeding or mode == "rapid"
                    x, y, z = item.x, item.y, item.z
                    if before is None:
                        write_x = write_y = write_z = True
                    elif follows:
                        write_x, write_y, write_z = x != at_x, y != at_y, z != at_z
                    else:
                        was = before.get("X")
                        write_x = not (type(was) is float and was == x)
                        was = before.get("Y")
                        write_y = not (type(was) is float and was == y)
                        was = before.get("Z")
                        write_z = not (type(was) is float and was == z)
                    if straight and (write_x or write_y or write_z) and not writer.carry \
                            and not writer.rounding and writer.modal.distance == "absolute" \
                            and writer.modal.units == units:
                        if words < 0:
                            words = _words_of(block) if block.canonical and writer.source_numbers else 0
                        written = int(write_x) | int(write_y) << 1 | int(write_z) << 2
                        if not written & words:
                            if place < kept:
                                was_made = made[place]
                                if was_made.written == written and was_made.feeding == feeding \
                                        and (not write_x or was_made.x == x) and (not write_y or was_made.y == y) \
                                        and (not write_z or was_made.z == z):
                                    line = was_made.line
                                    if place == found + 1:  # (the lane's own bookkeeping, as below)
                                        found = place
                                        self.last = item.axes
                                        self.at_x, self.at_y, self.at_z = x, y, z
                                        self.has_x = self.has_y = self.has_z = True
                                        at_x, at_y, at_z = x, y, z
                                        before = item.axes
                                        follows = True
                                        place += 1
                                        continue
                            if line is None:
                                line = self.line(item, before, block)
                                if line is not None and not writer.carry and place < LINES_KEPT:
                                    record = Made(feeding, written, x, y, z, line)
                                    remade = remade or place > 0
                                    if place < kept:
                                        made[place] = record
                                    else:
                                        while kept < place:  # (the places before it keep no line)
                                            made.append(_NO_LINE)
                                            kept += 1
                                        made.append(record)
                                        kept += 1
                            else:  # (the lane's own bookkeeping, as ``line`` keeps it)
                                self.last = item.axes
                                self.at_x, self.at_y, self.at_z = x, y, z
                                self.has_x = self.has_y = self.has_z = True
                    at_x, at_y, at_z = x, y, z
                    made_move = straight
                else:
                    straight = _is_straight(item)
                    made_move = False
                if line is None:
                    line = self.line(item, before, block)
                    if line is None:
                        line = writer.move_line(item if before is None else _left_out(item, before), block)
                if found > 0:
                    _found(made, found, lines)
                    found = -1
                lines.append(line)
                before = item.axes if straight else None
                follows = made_move
            else:
                line = writer.item_line(item, block)
                if found > 0:
                    _found(made, found, lines)
                    found = -1
                lines.append(line)
                if not isinstance(item, _STANDING):
                    before = None
                    follows = False
            place += 1
        if found > 0:  # every item after the first a move found in ``made``
            rest = self.rest
            if not rest or self.rest_count != place:
                rest = self.rest = "".join([made[at].line for at in range(1, place)])
                self.rest_count = place
            lines.append(rest)
        elif remade:
            self.rest = ""

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
            words = [code]
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
                    words.append(axis + self._word(writer, block, axis, value, as_written))
            text = " ".join(words) + "\n"
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
        if written == 1:
            axis, slot, value = ("X", 0, x) if write_x else ("Y", 1, y) if write_y else ("Z", 2, z)
            if writer.rounding or writer.carry or (as_written and _has_word(block, axis)):
                text = f"{code} {axis}{self._number(writer, block, axis, value, as_written)}\n"
            else:
                text = self._one_word(code, feeding, axis, slot, value)
        else:
            words = [code]
            if write_x and write_y and write_z:  # (a hole's move to its spot: one string, no list joined)
                text = (f"{code} X{self._word(writer, block, 'X', x, as_written)} "
                        f"Y{self._word(writer, block, 'Y', y, as_written)} "
                        f"Z{self._word(writer, block, 'Z', z, as_written)}\n")
            else:
                if write_x:
                    words.append("X" + self._word(writer, block, "X", x, as_written))
                if write_y:
                    words.append("Y" + self._word(writer, block, "Y", y, as_written))
                if write_z:
                    words.append("Z" + self._word(writer, block, "Z", z, as_written))
                text = " ".join(words) + "\n"
        self.last = item.axes
        self.at_x, self.at_y, self.at_z = x, y, z
        self.has_x = self.has_y = self.has_z = True
        return text

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
        for recent in self.recent:
            recent.value = _NOT_A_NUMBER
        self.seen.clear()

    def _word(self, writer: WordWriter, block: Block, axis: str, value: float, as_written: bool) -> str:
        """``_number``, from ``numbers`` where spelling it changes nothing of the writer (as ``lines``)."""
        slot = 0 if axis == "X" else 1 if axis == "Y" else 2 if axis == "Z" else -1
        if writer.rounding or writer.carry or slot < 0 or (as_written and _has_word(block, axis)):
            return self._number(writer, block, axis, value, as_written)
        recent = self.recent[slot]
        if recent.value == value:
            return recent.text
        numbers = self.numbers[slot]
        text = numbers.get(value)
        if text is None:
            text = _position(writer, axis, value, False)
            if writer.carry:
                return text
            _keep(numbers, value, text)
        recent.value, recent.text = value, text
        return text

    @staticmethod
    def _number(writer: WordWriter, block: Block, axis: str, value: float, as_written: bool) -> str:
        """An axis word's number as ``motion_words`` spells it: the source's text where that is the
        writer's, else ``_position``."""
        number = writer.source_number(block, axis, value, False) if as_written else None
        return number if number is not None else _position(writer, axis, value, False)


@mypyc_attr(allow_interpreted_subclasses=True)
class Made:
    """The line ``ExpansionMoves.write`` wrote for a ``PathMove`` at a place of an expansion: its code (feed or
    rapid), which of X, Y, Z it writes (bits 1, 2, 4) and their numbers (one not written is not compared)."""

    __slots__ = ("feeding", "written", "x", "y", "z", "line")

    def __init__(self, feeding: bool, written: int, x: float, y: float, z: float, line: str) -> None:
        self.feeding, self.written, self.x, self.y, self.z, self.line = feeding, written, x, y, z, line


@mypyc_attr(allow_interpreted_subclasses=True)
class Spelt:
    """A number ``ExpansionMoves._word`` spelt last for an axis, and its text (none yet: not a number)."""

    __slots__ = ("value", "text")

    def __init__(self) -> None:
        self.value = _NOT_A_NUMBER
        self.text = ""


_NOT_A_NUMBER: Final = float("nan")
"""Equal to no number: a ``Spelt`` that holds none."""
_NO_LINE: Final = Made(False, 0, 0.0, 0.0, 0.0, "")
"""The place of an expansion whose item left no line in ``made`` (it writes no axis: it matches no move)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class Seen:
    """A one-word line ``ExpansionMoves`` wrote at a place of a hole: its code (feed or rapid), axis (0, 1, 2:
    X, Y, Z) and number."""

    __slots__ = ("feeding", "slot", "value", "line")

    def __init__(self, feeding: bool, slot: int, value: float, line: str) -> None:
        self.feeding, self.slot, self.value, self.line = feeding, slot, value, line


def _found(made: list[Made], found: int, lines: list[str]) -> None:
    """The lines of ``made`` from the second place to ``found``, to ``lines`` (``ExpansionMoves.write``)."""
    for at in range(1, found + 1):
        lines.append(made[at].line)


def _keep(memory: dict[float, str], value: float, text: str) -> None:
    """Remember ``text`` for ``value``, at most ``LINES_KEPT`` numbers (then start again)."""
    if len(memory) >= LINES_KEPT:
        memory.clear()
    memory[value] = text


def _words_of(block: Block) -> int:
    """Which of X, Y and Z (bits 1, 2, 4) the block as read has a word of."""
    found = 0
    for word, _ in block.words:
        if word == "X":
            found |= 1
        elif word == "Y":
            found |= 2
        elif word == "Z":
            found |= 4
    return found


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


@mypyc_attr(allow_interpreted_subclasses=True)
class ExpansionBlocks(Lane):
    """Writes a block whose motion is an expansion (``CompoundMotion``) and that has no ``Motion``, as
    ``write_block`` writes it (through ``words_block``, ``generate``, ``unsplit`` and ``_generate``, which give
    such a block to ``compound``): ``compound``'s text, or the source as a comment where that is blank and the
    controller writes such a block so (``BLANK_AS_TRACE``), then ``after_block`` where the dialect follows its
    blocks. Offered by the straight lane (``StraightLane.expansions``) a block of no ``Motion``: a call
    instead of six dispatches through the writer's (interpreted) class (~3,500 instructions a hole)."""

    def __init__(self, writer: WordWriter) -> None:
        super().__init__()
        self.writer = writer
        cls = type(writer)
        self.apart: tuple[str, ...] = tuple(sorted(cls.STRUCTURE | cls.SPLIT))
        """The sections that send a block elsewhere (``structure_block``, ``split_block``): a block with one is
        the general path's."""

    def write(self, block: Block) -> str | None:
        sections = block.sections
        compound = sections.get("CompoundMotion")
        if not isinstance(compound, CompoundMotion) or "Motion" in sections:
            return None
        for key in self.apart:
            if key in sections:
                return None
        writer = self.writer
        if writer.rounding or writer.whole_speed:
            writer.at_block = block  # (``words_block``: where a rounding warning points)
        text = WordWriter.compound(writer, block, compound)
        if writer.blank_as_trace and (not text or text.isspace()):  # (``unsplit``)
            text = "" if block.text is None else writer.comment(block.text.strip()) + (block.eol or "\n")
        if writer.after_blocks:
            writer.after_block(block)  # (``generate``)
        return text


BLOCK_METHODS: Final = ("write_block", "refuse_feed_without_speed", "words_block", "generate", "unsplit", "_generate",
                        "compound")
"""What the general path calls to write a block whose motion is an expansion (``ExpansionBlocks``). Not among
them: ``structure_block`` and ``split_block``, offered only a block of a ``STRUCTURE`` or ``SPLIT`` section
(which the lane leaves) or of a ``Motion`` (likewise); ``after_block`` and ``comment``, which the lane calls as
the general path does."""


def choose_blocks(writer: Writer) -> ExpansionBlocks | None:
    """The expanded-block lane for ``writer``'s run, or None: where the writer writes another dialect's blocks (it
    copies or normalises none: ``words_block``) with the base's own ``BLOCK_METHODS``."""
    if not isinstance(writer, WordWriter) or writer.copy_ok or writer.source_dialect == writer.DIALECT:
        return None
    cls = type(writer)
    for name in BLOCK_METHODS:
        if _owner(cls, name) not in _BASE:
            return None
    return ExpansionBlocks(writer)


def install_expansion(writer: Writer) -> None:
    """Give ``writer`` its run's expansion-move lane (``WordWriter.move_lane``), where one applies, and its
    straight lane the expanded-block lane (``StraightLane.expansions``), where that applies."""
    if isinstance(writer, WordWriter):
        writer.move_lane = choose_moves(writer)
        lane = writer.lane
        if isinstance(lane, StraightLane):
            lane.expansions = choose_blocks(writer)
