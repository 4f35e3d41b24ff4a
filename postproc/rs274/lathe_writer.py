"""LatheWordWriter: the RS274 family's writer with the lathe's words (Fanuc T, GSK 980TDc).

A resolved ``LatheCycle`` is written back with every word its block uses, defaults included: a GSK
control takes an omitted word from its data parameters (No.051-060), which may not be what the
source's control had, so nothing is left to them (DIALECTS.md 3.2). U/W end points are written as
absolute X/Z (the cycle read them relative to its start). The one-block forms (``G71 P Q U W D F``,
``G76 X Z I K D F A P``) are written where the set-up's ``latheCycleFormat`` says so and the target has
them (``Dialect.LATHE_ONE_BLOCK``); a first block then writes nothing of its own (its values go with the
next block), and a one-block cycle read elsewhere is written as two blocks.
"""

from __future__ import annotations

from typing import Any, ClassVar, Iterable, Iterator, TextIO

from ..errors import UnsupportedError
from ..ir.expr import Expr
from ..ir import Block, Motion
from ..ir.lathe_sections import LatheCycle, ThreadLead
from .lathe_words import FIRST_WORDS, ONE_WORDS, SECOND_WORDS
from .writer import WordWriter

_INCREMENT = {"X": "U", "Z": "W"}
_LETTER_ORDER: dict[str, tuple[str, ...]] = {
    "first:thread_multi": ("P", "Q", "R"),
}


class LatheWordWriter(WordWriter):
    """Writes lathe sections; a dialect with lathe tables subclasses it (mill blocks are unchanged)."""

    IGNORED: ClassVar[frozenset[str]] = frozenset(("InProfile", "ThreadLead"))
    MONOTONIC_CHECK_WORD: ClassVar[str] = ""
    """The letter of the profile monotonicity check of G71/G72 (GSK: K), '' where there is none (the
    check is left out: the translation has already checked the profile)."""
    EXPLICIT_FIRST_BLOCKS: ClassVar[bool] = False
    """A two-block cycle always gets its first block, even where the source had none: the control would
    take the omitted values from its own data parameters (GSK No.051-060)."""
    _first_written: str | None = None
    """The kind of the last first block written (its second block needs no other)."""

    _pending_first: str | None = None
    """The first block of a one-block cycle being written as two (set while its block is generated)."""
    _merged_first = False
    """A first block whose values go into the next block's one-block cycle (set while it is generated)."""

    def one_block(self) -> bool:
        return self.capable("LATHE_ONE_BLOCK") and self.ctx.setup.input.lathe_cycle_format == "one-block"

    def lathe_cycle_words(self, s: LatheCycle, block: Block) -> list[str]:
        code = self.code("lathe_cycle", s.kind, f"the {s.kind.replace('_', ' ')} cycle", block)
        form = s.form
        kind = s.kind
        if form == "first":
            if self.one_block() and kind in ONE_WORDS:
                self._merged_first = True
                return []
            self._first_written = kind
            return [code, *self._words(s, FIRST_WORDS[kind], block, _LETTER_ORDER.get("first:" + kind))]
        if form in ("second", "one") and self.one_block() and kind in ONE_WORDS:
            return [code, *self._words(s, ONE_WORDS[kind], block)]
        if kind in FIRST_WORDS and (form == "one" or self.EXPLICIT_FIRST_BLOCKS and self._first_written != kind):
            # the first block's values go on a line of their own before this one
            first = self._words(s, FIRST_WORDS[kind], block, _LETTER_ORDER.get("first:" + kind))
            self._pending_first = " ".join([code, *first])
        self._first_written = None
        return [code, *self._words(s, SECOND_WORDS[kind], block)]

    def generate(self, block: Block) -> str:
        """A block; a one-block cycle written as two gets its first block on a line before it, and a
        first block merged into a one-block cycle leaves a comment where it stood. A spindle clamp beside a
        spindle speed (LinuxCNC's ``G96 S.. D..``) goes on a line of its own before it: both are S here."""
        sections = block.sections
        if "SpindleClamp" in sections and "SpindleSpeed" in sections and "CoordinateSet" not in sections:
            return self._clamp_first(block)
        if "LatheCycle" not in sections:
            return WordWriter.generate(self, block)  # the common block: no cycle words to place
        self._pending_first = None
        self._merged_first = False
        text = super().generate(block)
        if self._pending_first is not None and "CompoundMotion" not in block.sections:
            text = self._pending_first + "\n" + text
        elif self._merged_first:
            rest = text.rstrip("\r\n")
            note = self.comment(f"{self.source_text(block)}: in the next block")
            text = (rest + " " if rest else "") + note + (block.eol or "\n")
        return text

    def _clamp_first(self, block: Block) -> str:
        first = Block(block.line, None, "\n")
        first.sections = {k: v for k, v in block.sections.items() if k in ("BlockDelete", "SpindleClamp")}
        rest = Block(block.line, None, block.eol)
        rest.sections = {k: v for k, v in block.sections.items() if k != "SpindleClamp"}
        return self.generate(first) + self.generate(rest)

    def _words(self, s: LatheCycle, table: dict[str, tuple[str, str]], block: Block,
               order: tuple[str, ...] | None = None) -> list[str]:
        words: list[str] = []
        done: set[str] = set()
        letters = order or tuple(table)
        p = s.params
        for letter in letters:
            name, how = table[letter]
            if name in done or how == "increment":
                continue
            done.add(name)
            if how == "packed":
                words.append("P" + "".join(f"{int(p[n]):02d}" for n in ("finish_passes", "chamfer", "angle")))
                continue
            if name == "check":
                if self.MONOTONIC_CHECK_WORD and int(p.get(name, 0)):
                    words.append(self.MONOTONIC_CHECK_WORD + str(int(p[name])))
                continue
            if name not in p:
                if name in ("taper", "infeed"):
                    continue  # no taper / the one infeed method: nothing to say
                self.unsupported(f"the {s.kind.replace('_', ' ')} cycle without its {name.replace('_', ' ')}", block)
            value = p[name]
            if name in ("taper", "step_x", "step_z") and float(value) == 0.0:
                continue  # no taper; a peck or groove in one column (the control's own default is 0)
            words.append(letter + self._value(value, how, letter, block))
        return words

    def _value(self, value: Any, how: str, letter: str, block: Block) -> str:
        if how == "count":
            return str(int(value))
        if how == "increments":
            step = self.ctx.setup.input.increment(self.modal.units)
            count = round(float(value) / step)
            if abs(count * step - float(value)) > step * 1e-6:
                raise UnsupportedError(f"{letter}{float(value):g} is not a whole number of least input increments "
                                       f"({step:g})", self.ctx.at(block))
            return str(count)
        return self.number(float(value), letter)

    def write(self, blocks: Iterable[Block], out: TextIO) -> None:
        target = self.target
        if not self.ctx.lathe and target is not None and {"mill", "lathe"} <= target.MACHINE_TYPES \
                and self.ctx.setup.input.machine_type == "lathe":  # (the target reads this set-up as a lathe)
            blocks = self._mill_program_refused(blocks, target.NAME)
        super().write(blocks, out)

    def _mill_program_refused(self, blocks: Iterable[Block], name: str) -> Iterator[Block]:
        """A mill dialect's program (grbl, Mach3: read with mill meanings) on a lathe set-up, for a target that
        reads that set-up's programs as a lathe's: its words would be read back with other meanings (Fanuc T:
        G90 a turning cycle, G94 a facing cycle, G98/G99 feed modes). Refused at its first block, whatever
        ``--on-unsupported`` says: no block of it means there what it says [found by make fuzz]."""
        it = iter(blocks)
        for block in it:
            yield block
            if block.sections:
                self.ctx.diagnostics.error(UnsupportedError(
                    f"a milling program on a lathe set-up: the {name} lathe reads its words with lathe meanings "
                    "(a mill's distance and feed mode codes are its turning and facing cycles); read it with a "
                    "dialect that has lathe meanings, or with a mill set-up", self.ctx.at(block)))
                break
        yield from it

    def cycle_cancel_words(self, s: Any, block: Block) -> list[str]:
        """A lathe reads no drilling cycle into a neutral one (they stay verbatim), so its canned-cycle cancel
        (G80 on Fanuc T and Haas) has nothing to end: a control without the code writes nothing for it."""
        if self.ctx.lathe and self.codes.spell("cycle_cancel", None) is None:
            return []
        return super().cycle_cancel_words(s, block)

    def cutter_compensation_words(self, s: Any, block: Block) -> list[str]:
        """A turret lathe's G41/G42 names no register: the nose radius and tip are those of the offset the T
        code selected [K: Fanuc T and GSK offset pages, radius R and tip T per offset number]. A register from
        another controller (LinuxCNC's ``G42 D2``) has no word here: refused rather than written as a D the
        control would not read as one."""
        if self.ctx.lathe and s.mode != "off" and s.register is not None:
            self.unsupported(f"tool nose radius compensation by register {s.register} (a turret lathe compensates by "
                             "the offset its tool code selected: select that offset there, and turn compensation on "
                             "without a register)", block)
        return super().cutter_compensation_words(s, block)

    def coordinate_set_words(self, s: Any, block: Block) -> list[str]:
        code = self.code("coordinate_set", None, "coordinate setting", block)
        return [code, *(axis + self.length(value, block, axis) for axis, value in s.axes.items())]

    def distance_mode_words(self, s: Any, block: Block) -> list[str]:
        """G90/G91 where the table has them; a system A lathe (GSK, Fanuc T A) has none: its incremental
        moves are written with U/W (``motion_words``)."""
        if self.ctx.lathe and self.codes.spell("distance", s.mode) is None:
            self.modal.distance = s.mode
            return []
        return super().distance_mode_words(s, block)

    _feed_stale = False
    """A thread move's lead was written as F (``ThreadLead``), where the source's feed rate stayed: the next
    feed move restates it."""

    def motion_words(self, s: Motion, block: Block) -> list[str]:
        """A lathe's move (``_lathe_motion_words``). A thread move whose lead is no feed rate (``ThreadLead``,
        read from LinuxCNC's ``G33 K``) is written with its lead as F, which here sets the feed rate too: the
        next feed move that names none writes the source's rate again."""
        words = self._lathe_motion_words(s, block)
        sections = block.sections
        if "Feed" in sections:
            self._feed_stale = False
        lead = sections.get("ThreadLead")
        if s.mode == "thread" and isinstance(lead, ThreadLead):
            if "Feed" in sections:
                self.unsupported("a thread move with both a lead and a feed rate", block)
            words.append("F" + self.feed_number(lead.lead, block))
            self._feed_stale = True
        elif self._feed_stale and s.mode in ("linear", "cw", "ccw") and "Feed" not in sections:
            rate = self.modal.feed
            if not isinstance(rate, (int, float)):
                self.unsupported("a feed move after a thread, at a feed rate not known here", block)
            words.append("F" + self.feed_number(float(rate), block))
            self._feed_stale = False
        return words

    def feed_words(self, s: Any, block: Block) -> list[str]:
        self._feed_stale = False
        return super().feed_words(s, block)

    def _lathe_motion_words(self, s: Motion, block: Block) -> list[str]:
        """In incremental mode on a lathe without G91, X and Z are written as U and W. A lathe-only target
        refuses a mill program's motion (its Y, its XY arcs and their centres mean nothing there)."""
        target = self.target
        if not self.ctx.lathe and target is not None and "mill" not in target.MACHINE_TYPES:
            self.unsupported(f"motion read from a milling program ({target.NAME} is a lathe control: read "
                             "the program with a lathe set-up)", block)
        if self.modal.distance == "incremental" and self.ctx.lathe and self.codes.spell("distance", "incremental") is None \
                and s.mode not in ("home", "home2"):
            if any(a in s.axes for a in ("U", "W")):
                self.unsupported("U/W in incremental mode", block)
            axes = {_INCREMENT.get(a, a): v for a, v in s.axes.items()}
            self.modal.distance = "absolute"  # U/W say the increment: the words are written as they stand
            try:
                return super().motion_words(Motion(s.mode, axes, s.center, s.radius), block)
            finally:
                self.modal.distance = "incremental"
        return super().motion_words(s, block)

    def move_line(self, item: Motion, block: Block) -> str:
        """An expansion's move is absolute: a lathe without G90 leaves U/W mode for it by itself."""
        if self.ctx.lathe and self.codes.spell("distance", "absolute") is None:
            incremental = self.modal.distance == "incremental"
            self.modal.distance = "absolute"
            try:
                return super().move_line(item, block)
            finally:
                if incremental:
                    self.modal.distance = "incremental"
        return super().move_line(item, block)

    def spindle_clamp_words(self, s: Any, block: Block) -> list[str]:
        words = [] if "CoordinateSet" in block.sections else [self.code("coordinate_set", None, "a spindle speed clamp", block)]
        return [*words, "S" + (self.expression(s.rpm, block) if isinstance(s.rpm, Expr) else self.speed(s.rpm))]

    def tool_select_words(self, s: Any, block: Block) -> list[str]:
        """A lathe's T: tool and offset in four digits (T0101)."""
        if self.ctx.lathe and isinstance(s.number, int):
            return [f"T{s.number:04d}"]
        return super().tool_select_words(s, block)

