"""Fanuc writer: the RS274 word writer spelling every code from Fanuc's table (G00, M03, G04 X seconds),
expressions and Custom Macro B statements in Fanuc's spelling, and calls as ``M98``/``G65``/``G66``."""

from __future__ import annotations

from typing import ClassVar

from postproc.control import Call, ModalCall, ModalCallCancel, Return
from postproc.errors import UnsupportedError
from postproc.expr import Expr, Num
from postproc.ir import Block, Section
from postproc.rs274.codes import CodeTable
from postproc.rs274.expressions import FANUC_SPELLING, ExprSpelling, spell_word_value
from postproc.rs274.macro_b import spell_statement_fanuc
from postproc.rs274.lathe_writer import LatheWordWriter

from .codes import CODES
from .lathe_codes import LATHE_CODES
from .macro import LOCAL_LETTERS


class FanucWriter(LatheWordWriter):
    DIALECT: ClassVar[str] = "fanuc"
    CODES: ClassVar[CodeTable] = CODES
    DWELL_WORD: ClassVar[str] = "X"
    SPELLING: ClassVar[ExprSpelling | None] = FANUC_SPELLING
    MACHINE_MOVES: ClassVar[frozenset[str]] = frozenset(("rapid",))
    """Fanuc's G53 always moves at rapid: a feed move in machine coordinates has no spelling."""

    def table(self) -> CodeTable:
        """The lathe table of the set-up's G-code system on a lathe, else the milling table."""
        if self.ctx.lathe:
            return LATHE_CODES[self.ctx.setup.input.gcode_system]
        return self.CODES

    def statement_words(self, section: Section, block: Block) -> list[str]:
        """``#1=..``, ``IF``/``GOTO``/``WHILE``/``END`` through ``spell_statement_fanuc``; calls as
        ``M98 P L``, ``G65 P L <arguments>`` (spec I letters), ``G66``/``G67``, returns as ``M99 [P]``."""
        try:
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
