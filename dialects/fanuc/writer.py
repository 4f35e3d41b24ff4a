"""Fanuc writer: the RS274 word writer spelling every code from Fanuc's table (G00, M03, G04 X seconds),
expressions and Custom Macro B statements in Fanuc's spelling, and calls as ``M98``/``G65``/``G66``."""

from __future__ import annotations

from typing import ClassVar

from postproc.context import Context
from postproc.control import Assign, Call, EndFor, EndWhile, For, ModalCall, ModalCallCancel, Return, While
from postproc.dialect import Dialect
from postproc.errors import UnsupportedError
from postproc.expr import Binary, Expr, Num, Var
from postproc.ir import Block, Section
from postproc.rs274.codes import CodeTable
from postproc.rs274.expressions import FANUC_SPELLING, ExprSpelling, spell_word_value
from postproc.rs274.macro_b import spell_statement_fanuc
from postproc.rs274.writer import WordWriter

from .codes import CODES
from .macro import LOCAL_LETTERS


class FanucWriter(WordWriter):
    DIALECT: ClassVar[str] = "fanuc"
    CODES: ClassVar[CodeTable] = CODES
    DWELL_WORD: ClassVar[str] = "X"
    SPELLING: ClassVar[ExprSpelling | None] = FANUC_SPELLING
    MACHINE_MOVES: ClassVar[frozenset[str]] = frozenset(("rapid",))
    """Fanuc's G53 always moves at rapid: a feed move in machine coordinates has no spelling."""

    def __init__(self, ctx: Context, source_dialect: str, target: type[Dialect] | None = None) -> None:
        super().__init__(ctx, source_dialect, target)
        self.loops: list[tuple[str, Var | None, float]] = []
        """Open loops written from another dialect: (source label, counter, step) of a counted loop, or
        (label, None, 0) of a while loop; the depth is the ``DO`` number (Fanuc nests DO1-DO3)."""

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
            return [spell_statement_fanuc(section)]
        except UnsupportedError as err:
            if err.location is None:
                err.located(self.ctx.at(block))
            raise

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
        if isinstance(name, Expr):
            return _whole(name)
        if not name.isdigit():
            self.unsupported(f"a call of the named subprogram {name} ({code} calls program numbers)", block)
        return name

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


def _grown(counter: Var, step: float) -> Binary:
    """The counter after one pass: ``#i+step`` or ``#i-|step|``."""
    return Binary("add", counter, Num(step)) if step > 0 else Binary("sub", counter, Num(-step))
