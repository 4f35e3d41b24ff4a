"""Fanuc writer: the RS274 word writer spelling every code from Fanuc's table (G00, M03, G04 X seconds),
expressions and Custom Macro B statements in Fanuc's spelling, and calls as ``M98``/``G65``/``G66``.

A subprogram defined in another dialect's program (ISG ``%L SUB_CONT`` ... ``M17`` before the main
program, LinuxCNC ``o100 sub`` ... ``o100 endsub``) becomes an ``O`` program after the main program's end,
where Fanuc finds it. Its number, for the definition and every call alike, is decided once by
``SubprogramNames`` (``SUBPROGRAM_NAMES``): a number Fanuc can write stays (``o100`` -> ``O0100``,
``G65 P100``), a name or a longer number gets the first free one of ``O2000``-``O7999``."""

from __future__ import annotations

from typing import Any, ClassVar, Mapping

from postproc.context import Context
from postproc.interp.control import (
    ASSIGN, CONTROL, Assign, Call, EndFor, EndWhile, For, ModalCall, ModalCallCancel, Return, SubEnd, SubStart,
    While,
)
from postproc.dialect import Dialect
from postproc.errors import UnsupportedError
from postproc.ir.expr import Binary, Expr, Func, Num, Unary, Var
from postproc.ir import Block, Section
from postproc.rs274.codes import CodeTable
from postproc.rs274.expressions import FANUC_SPELLING, ExprSpelling, spell_word_value
from postproc.rs274.macro_b import spell_statement_fanuc
from postproc.rs274.lathe_writer import LatheWordWriter
from postproc.interp.subprogram_names import NameRule, SubprogramNames

from .block_syntax import FanucBlockSyntax
from .codes import CODES
from .lathe_codes import LATHE_CODES
from .macro import LOCAL_LETTERS


_BESIDE_A_STATEMENT = frozenset((ASSIGN, "Sequence", "BlockDelete", "Comments"))
"""What a macro statement may share its block with (Fanuc reads ``N10 #1=2. (NOTE)``, not ``#1=2. X10.``)."""


class FanucWriter(LatheWordWriter):
    DIALECT: ClassVar[str] = "fanuc"
    CODES: ClassVar[CodeTable] = CODES
    DWELL_WORD: ClassVar[str] = "X"
    SPELLING: ClassVar[ExprSpelling | None] = FANUC_SPELLING
    MACHINE_MOVES: ClassVar[frozenset[str]] = frozenset(("rapid",))
    """Fanuc's G53 always moves at rapid: a feed move in machine coordinates has no spelling."""
    PATH_CONTROL_LACK: ClassVar[str] = (
        "the lathe code tables have no G61/G64: whether a Fanuc T control has a cutting mode G64 that blends as "
        "LinuxCNC's does is [?], not found in a Fanuc T manual here (the lathe G-code lists found, G code system A, "
        "list neither G61 nor G64): refused by name")
    """Only a lathe's table lacks the modal path codes (the milling table has G61/G64 [K]), so only a lathe
    target says this."""
    WORK_OFFSET_SETTING: ClassVar[str] = "G10 L2"
    """G10 L2 P1-P6 sets G54-G59's offset (P0 is the external offset, which other dialects lack)."""
    WORK_OFFSET_COUNT: ClassVar[int] = 6
    SETTING_ADDS_IN_INCREMENTAL: ClassVar[bool] = True
    TOOL_DATA_SETTINGS: ClassVar[Mapping[str, tuple[str, int, str]]] = {
        table: (f"G10 L{ell}", highest, "R") for ell, (table, _, highest) in FanucBlockSyntax.DATA_TABLES.items()
        if table.startswith(("tool_length", "cutter_offset"))}
    """G10 L10-L13 P R (the milling offset memory's registers), the reader's own table read backwards; under
    G91 the value adds to the register, so it is written in absolute mode only. [K] L10/L11 the H geometry/
    wear, L12/L13 the D geometry/wear, and G90 sets while G91 adds: Fanuc 0i-MD B-64304EN "Changing of tool
    offset value (programmable data input) (G10)" from memory; the same table and rule in the Fanuc-compatible
    Mitsubishi M700V manual 12.7 ("tool compensation memory II") and the Allen-Bradley 9-series mill manual
    20.4 (stored pages); B-63324EN/03 (15i-MA) appendix B lists memory A's one value as G10 L11 P R."""
    SUBPROGRAM_NAMES: ClassVar[NameRule] = NameRule(numbers=range(1, 10000), spare=range(2000, 8000), names=False)
    """Program numbers are ``O0001``-``O9999`` (DIALECTS.md 1.1 [K]; 8 digits only on a 30i with an option);
    a subprogram of another dialect without one gets the first free number from O2000 (below O8000,
    which controls often lock [V])."""

    STRUCTURE: ClassVar[frozenset[str]] = frozenset((CONTROL, ASSIGN))
    """A subprogram of another dialect starts or ends (it goes after the main program), or an assignment
    shares its block with words (Fanuc reads a macro statement on a block of its own)."""

    def __init__(self, ctx: Context, source_dialect: str, target: type[Dialect] | None = None) -> None:
        super().__init__(ctx, source_dialect, target)
        self.loops: list[tuple[str, Var | None, float]] = []
        """Open loops written from another dialect: (source label, counter, step) of a counted loop, or
        (label, None, 0) of a while loop; the depth is the ``DO`` number (Fanuc nests DO1-DO3)."""
        self.names = SubprogramNames(self.SUBPROGRAM_NAMES)
        """Another dialect's subprogram names and program numbers -> the program numbers written."""
        self.subprograms: list[str] = []
        """The named subprograms written (``set_aside`` holds the one being written), for after the main
        program."""
        self.ended = False
        """The main program's end (M02/M30) was written."""

    def structure_block(self, block: Block) -> str | None:
        if ASSIGN in block.sections and not block.sections.keys() <= _BESIDE_A_STATEMENT:
            return self.words_then_assignment(block)
        control = block.sections.get(CONTROL)
        if self.source_dialect != self.DIALECT and isinstance(control, (SubStart, SubEnd)):
            return self.named_subprogram(control, block)
        return super().structure_block(block)

    def program_control_words(self, s: Any, block: Block) -> list[str]:
        """The main program's end is noted (the named subprograms follow it, ``finish``)."""
        words = super().program_control_words(s, block)
        if s.kind in ("end", "end_rewind") and self.set_aside is None:
            self.ended = True
        return words

    def words_then_assignment(self, block: Block) -> str | None:
        """A block that assigns and has words (ISG ``G01 X10 P1=2``, LinuxCNC ``#1=2 G1 X10``): Fanuc
        reads a macro statement only on a block of its own, so the words go first and the assignment on
        the next line, the order the interpreter gives them (``postproc.interp.machine``: a block's words
        are evaluated before its assignments, as in LinuxCNC). A block skip goes on both lines."""
        sections = block.sections
        words = Block(block.line, None, "\n")
        words.sections = {k: v for k, v in sections.items() if k != ASSIGN}
        assignment = Block(block.line, None, block.eol)
        assignment.sections = {k: v for k, v in sections.items() if k == ASSIGN or k == "BlockDelete"}
        texts = [self.write_block(words), self.write_block(assignment)]
        return "".join(text for text in texts if text)

    def named_subprogram(self, control: SubStart | SubEnd, block: Block) -> str | None:
        """Start setting a named subprogram's text aside (``O<n>``; ``Writer.set_aside``), or end it
        (``M99``) and keep it for after the main program."""
        eol = block.eol or "\n"
        if isinstance(control, SubStart):
            if self.set_aside is not None:
                self.unsupported("a subprogram defined inside another", block)
            comments = block.sections.get("Comments")
            note = "".join(f" {self.comment(t)}" for t in getattr(comments, "texts", ()))
            self.set_aside = [f"O{self.subprogram_number(control.name, block):04d}{note}{eol}"]
            return None
        if self.set_aside is None:
            self.unsupported(f"the end of subprogram {control.name}, which no written line opened", block)
        if control.value is not None:
            self.unsupported("a subprogram end returning a value", block)
        self.set_aside.append("M99" + eol)
        self.subprograms.append("".join(self.set_aside))
        self.set_aside = None
        return None

    def subprogram_number(self, name: str, block: Block) -> int:
        """The program number another dialect's subprogram ``name`` is written as (``SubprogramNames``)."""
        try:
            return int(self.names.of(name))
        except UnsupportedError as err:
            self.unsupported(err.message, block)

    def program_start(self, s: Any, block: Block) -> str:
        """Another dialect's program number as the number its calls use (``subprogram_number``); a name it
        had follows as a comment, as the base writes it."""
        if self.source_dialect == self.DIALECT or s.number is None:
            return super().program_start(s, block)
        text = f"O{self.subprogram_number(str(int(s.number)), block):04d}"
        return text + " " + self.comment(str(s.name)) if s.name else text

    def finish(self) -> str:
        """The named subprograms, after the main program's end (where Fanuc looks for them)."""
        if not self.subprograms:
            return super().finish()
        if not self.ended or self.set_aside is not None:
            raise UnsupportedError("named subprograms need the main program's end (M02/M30) before them, and "
                                   "each its own end")
        return super().finish() + "".join(self.subprograms)

    def table(self) -> CodeTable:
        """The lathe table of the set-up's G-code system on a lathe, else the milling table."""
        if self.ctx.lathe:
            return LATHE_CODES[self.ctx.setup.input.gcode_system]
        return self.CODES

    def statement_words(self, section: Section, block: Block) -> list[str]:
        """``#1=..``, ``IF``/``GOTO``/``WHILE``/``END`` through ``spell_statement_fanuc``; calls as
        ``M98 P L``, ``G65 P L <arguments>`` (spec I letters), ``G66``/``G67``, returns as ``M99 [P]``.
        From another dialect a loop's ``DO`` number is its depth, and a counted loop (``For``) is its
        counter set before ``WHILE [#i LE end] DOm`` and grown before ``ENDm``."""
        try:
            if self.source_dialect != self.DIALECT and isinstance(section, (While, EndWhile, For, EndFor)):
                return self.loop_words(section, block)
            if isinstance(section, Call):
                return self.call_words(section, block)
            if isinstance(section, ModalCall):
                return ["G66", *self.macro_words(section.name, section.repeat, section.args, "G66", block)]
            if isinstance(section, ModalCallCancel):
                return ["G67"]
            if isinstance(section, Return):
                return self.return_words(section, block)
            if isinstance(section, Assign) and len(section.items) > 1:
                return [self.assignments_apart(section, block)]
            return [spell_statement_fanuc(section)]
        except UnsupportedError as err:
            if err.location is None:
                err.located(self.ctx.at(block))
            raise

    def assignments_apart(self, section: Assign, block: Block) -> str:
        """Another dialect's assignments of one block (SINUMERIK ``R1=40 R2=30``), one a line: Fanuc sets one
        variable a block. The neutral block reads every right-hand side first, so each line must read nothing
        a line before it set."""
        done: list[Var] = []
        lines = []
        for var, value in section.items:
            if any(_reads(value, target) or _reads(var, target) for target in done):
                self.unsupported("assignments of one block where one reads a variable another sets first (Fanuc "
                                 "sets one variable a block)", block)
            lines.append(spell_statement_fanuc(Assign([(var, value)])))
            done.append(var)
        return (block.eol or "\n").join(lines)

    def loop_words(self, section: While | EndWhile | For | EndFor, block: Block) -> list[str]:
        eol = block.eol or "\n"
        if isinstance(section, (While, For)):
            depth = str(len(self.loops) + 1)
            if isinstance(section, While):
                head = spell_statement_fanuc(While(depth, section.cond))
                self.loops.append((section.label, None, 0.0))
                return [head]
            step, end = section.step, section.end
            if not (isinstance(step, Num) and step.value != 0.0 and isinstance(end, Num)):
                self.unsupported("a counted loop whose end or step is computed or whose step is 0 (WHILE "
                                 "would evaluate it on every pass, the counted loop once)", block)
            assert isinstance(section.counter, Var)  # For's constructor holds it
            init = spell_statement_fanuc(Assign([(section.counter, section.start)]))
            test = Binary("le" if step.value > 0 else "ge", section.counter, end)
            head = spell_statement_fanuc(While(depth, test))
            self.loops.append((section.label, section.counter, step.value))
            return [init + eol + head]
        if not self.loops or self.loops[-1][0] != section.label:
            self.unsupported(f"the end of loop {section.label!r}, which no written loop opened", block)
        depth = str(len(self.loops))
        _, counter, step_value = self.loops.pop()
        end_words = spell_statement_fanuc(EndWhile(depth))
        if counter is None:
            return [end_words]
        grow = spell_statement_fanuc(Assign([(counter, _grown(counter, step_value))]))
        return [grow + eol + end_words]

    def call_words(self, call: Call, block: Block) -> list[str]:
        if call.kind == "macro":
            return ["G65", *self.macro_words(call.name, call.repeat, call.args, "G65", block)]
        if call.args:
            self.unsupported("a subprogram call with arguments (M98 passes none; G65 would give the "
                             "subprogram its own local variables)", block)
        return ["M98", *self.macro_words(call.name, call.repeat, {}, "M98", block)]

    def macro_words(self, name: str | Expr, repeat: Expr | None, args: dict[int, Expr], code: str,
                    block: Block) -> list[str]:
        """``P<program> [L<count>] <argument letters>``."""
        words = ["P" + self.program_number(name, code, block)]
        if repeat is not None:
            words.append("L" + _whole(repeat))
        for number in sorted(args):
            letter = LOCAL_LETTERS.get(number)
            if letter is None:
                self.unsupported(f"a {code} argument for #{number} (argument specification I sets only "
                                 f"#1-#9, #11, #13, #17-#26)", block)
            words.append(letter + spell_word_value(args[number], FANUC_SPELLING))
        return words

    def program_number(self, name: str | Expr, code: str, block: Block) -> str:
        """The called program's number: from another dialect, the number its definition is written with."""
        if self.source_dialect == self.DIALECT:
            if not isinstance(name, str):
                return _whole(name)
            if not name.isdigit():
                self.unsupported(f"a call of the named subprogram {name} ({code} calls program numbers)", block)
            return name
        if not isinstance(name, str):
            try:
                self.names.computed()
            except UnsupportedError as err:
                self.unsupported(err.message, block)
            return _whole(name)
        if not name.isdigit() and not name.startswith("<"):
            self.unsupported(f"a call of the subprogram file {name} ({code} calls program numbers)", block)
        return str(self.subprogram_number(name, block))

    def return_words(self, ret: Return, block: Block) -> list[str]:
        if ret.value is not None:
            self.unsupported("a subprogram return with a value", block)
        if ret.target is None:
            return ["M99"]
        return ["M99", "P" + _whole(ret.target)]


def _whole(expr: Expr) -> str:
    """An integer address's value (P, L): a whole number without a point, else the expression."""
    if isinstance(expr, Num) and expr.value.is_integer() and expr.value >= 0:
        return str(int(expr.value))
    return spell_word_value(expr, FANUC_SPELLING)


def _reads(expr: Expr, var: Var) -> bool:
    """Whether ``expr`` reads ``var`` (an indirect variable ``#[..]`` may be any)."""
    stack = [expr]
    while stack:
        item = stack.pop()
        if isinstance(item, Var):
            if item == var or item.name is None and not isinstance(item.index, Num):
                return True
            if isinstance(item.index, Expr):
                stack.append(item.index)
        elif isinstance(item, Unary):
            stack.append(item.operand)
        elif isinstance(item, Binary):
            stack.extend((item.left, item.right))
        elif isinstance(item, Func):
            stack.extend(item.args)
    return False


def _grown(counter: Var, step: float) -> Binary:
    """The counter after one pass: ``#i+step`` or ``#i-|step|``."""
    return Binary("add", counter, Num(step)) if step > 0 else Binary("sub", counter, Num(-step))
