"""Fagor 8070 reader: physical lines -> blocks, with the ISG/Fagor family's lexer (``postproc.isg_family``).

What the reference confirms is read into neutral sections: the ``%name`` header [V], ``N`` block
numbers [V], ``;`` comments, ``( .. )`` comments and ``#COMMENT BEGIN`` ... ``#COMMENT END`` (below),
DIN words, ``P`` parameter assignments and bracketed expressions [K], ``G159=n``
[V]. What it marks uncertain [?] is checked by the family grammar and kept verbatim as ``NativeCode``
tagged ``fagor``: it round-trips byte for byte to Fagor and is refused, naming it, by every other
dialect and by the simulator:

* ``$`` control flow (its nesting is still checked: a statement that closes nothing is an error);
* ``L``/``LL`` calls, ``#CALL``, ``#PCALL``, ``#MCALL``, ``#MDOFF``, ``#RET`` and every other ``#``
  command; a local subroutine ``%L name`` and every block up to the next ``%`` header;
* ``[NAME]`` and ``N100:`` labels, computed block numbers ``N[..]``, block skip ``/``;
* array elements (``P100[3]``).

Comments: Fagor's table of programming commands lists ``;`` (to the end of the block), ``(`` (to the end
of the block) and ``( )`` (the piece between) as block comments [V: Fagor CNC 8065 manual, "Programming
commands", easymanua.ls p.45; K for the 8070, whose language the 8065 shares]. Whether a ``(`` inside a
comment nests is not stated [?]: the family's rule (ISG: nested) is used, as is its error for a ``)``
that closes nothing. ``#COMMENT BEGIN``/``END`` [?] is read as a comment: it carries no motion either way.

Errors are reported per block; the block is kept as text only, and reading goes on.
"""

from __future__ import annotations

from typing import Iterable, Iterator

from postproc.interp.control import Assign
from postproc.dialect import Reader
from postproc.errors import Location, ParseError, PostprocError
from postproc.ir import Block, Comments, NativeCode, ProgramStart, Sequence
from postproc.isg_family.expressions import Unmodelled
from postproc.isg_family.lexer import Grammar, Lexed, command_words, lex, strip_comments
from postproc.isg_family.statements import Nesting, parse_statement
from postproc.isg_family.zero_offsets import ZeroOffsets
from postproc.rs274.lexer import split_lines

from .codes import PATTERN_CODES

GRAMMAR = Grammar(parens=True, bare_dwell_time=False, assigned_g=frozenset({"159"}), p_words_after=PATTERN_CODES)
"""Parenthesised comments, no bare dwell time, ``G159=n``, ``P`` a plain word after ``G160``-``G165``."""

ZERO_OFFSETS = ZeroOffsets("fagor", r"V\.A\.ORGT\[\s*(?P<index>\d+)\s*\]\.(?P<axis>[A-Z]\w*)\s*=\s*(?P<value>{NUMBER})", 6)
"""``V.A.ORGT[n].<axis>=<number>``: zero offset n's axis, taken at its next selection (the writer's
``WORK_OFFSET_VARIABLE`` says the sources [K/?]); n 1-6 (G54-G59, ``G159=1``-``6``). Another form stays an array
element, not modelled."""

COMMANDS = {
    "#CALL": "subroutine call [?]", "#PCALL": "subroutine call with local parameters [?]",
    "#MCALL": "modal subroutine call [?]", "#MDOFF": "modal subroutine call cancel [?]",
    "#RET": "subroutine return [?]",
}
"""The ``#`` commands the reference names, for messages; any other is named by its word alone."""


class FagorReader(Reader):
    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        report = self.ctx.diagnostics.error
        state = _State(self.ctx.file)
        for number, text, eol in split_lines(lines):
            try:
                yield state.block(number, text, eol)
            except PostprocError as err:
                report(err)
                yield Block(number, text, eol)
        for problem in state.finish():
            report(problem)


class _State:
    """What reading a file remembers between blocks."""

    def __init__(self, file: str) -> None:
        self.file = file
        self.nesting = Nesting(file)
        self.sub: tuple[str, int] | None = None
        """The open local subroutine ``%L name``: (name, line)."""
        self.in_comment: int | None = None
        """Line of an open ``#COMMENT BEGIN``."""

    def native(self, block: Block, what: str) -> Block:
        block.sections.clear()
        block.words.clear()
        block.values.clear()
        block.add(NativeCode("fagor", what, block.text or ""))
        return block

    def block(self, number: int, text: str, eol: str) -> Block:
        block = Block(number, text, eol)
        if self.in_comment is not None:
            if command_words(text) == ["#COMMENT", "END"]:
                self.in_comment = None
            block.add(Comments([text]))
            return block
        lexed = Lexed()
        code = strip_comments(self.file, number, text, lexed, parens=GRAMMAR.parens)
        if self.sub is not None and not code.lstrip().startswith("%"):
            return self.native(block, f"a block of the local subroutine %L {self.sub[0]} [?]")
        if "V.A.ORGT[" in code.upper() and ZERO_OFFSETS.read(block, code, self.file):
            if lexed.comments:
                block.add(Comments(lexed.comments))
            return block
        try:
            lex(self.file, number, code, lexed, GRAMMAR)
        except Unmodelled as err:
            return self.native(block, f"{err.what} (not modelled)")
        if lexed.comments:
            block.add(Comments(lexed.comments))
        if lexed.header is not None:
            return self.header(block, lexed.header)
        if lexed.statement is not None:
            section = parse_statement(code, lexed.statement, self.nesting, number)
            word = code[lexed.statement:].split(None, 1)[0].upper()
            return self.native(block, f"{word} (control flow [?]: {type(section).__name__})")
        if lexed.skip:
            return self.native(block, f"block skip /{lexed.skip} [?]")
        if lexed.label or lexed.label_name is not None:
            return self.native(block, "a jump label [?]")
        if lexed.number_value is not None:
            return self.native(block, "a computed block number [?]")
        if lexed.command is not None:
            return self.command(block, code, lexed.command)
        if lexed.call is not None:
            kind, name, _ = lexed.call
            return self.native(block, f"{kind} {name} (subroutine call [?])")
        if lexed.number is not None:
            block.words.append(("N", lexed.number))
            block.add(Sequence(int(lexed.number)))
        block.words.extend(lexed.words)
        block.values.update(lexed.values)
        if lexed.assigns:
            block.add(Assign(lexed.assigns))
        return block

    def header(self, block: Block, header: tuple[str, str]) -> Block:
        kind, name = header
        if kind == "tape":
            raise ParseError("a program header is %<name> (a lone % is not a Fagor header)",
                             Location(self.file, block.line, 1))
        if kind == "sub":
            if self.nesting.stack:
                raise ParseError("a local subroutine cannot start inside an open construct",
                                 Location(self.file, block.line, 1))
            self.sub = (name, block.line)
            return self.native(block, f"%L {name} (local subroutine [?])")
        self.sub = None
        block.add(ProgramStart(int(name), None) if name.isdigit() else ProgramStart(None, name))
        return block

    def command(self, block: Block, code: str, pos: int) -> Block:
        words = command_words(code[pos:])
        if words[:2] == ["#COMMENT", "BEGIN"]:
            self.in_comment = block.line
            block.sections.clear()
            block.add(Comments([block.text or ""]))
            return block
        name = words[0] if words else "#"
        return self.native(block, f"{name} ({COMMANDS[name]})" if name in COMMANDS else f"{name} [?]")

    def finish(self) -> list[ParseError]:
        errors = [ParseError(f"${kind} is never closed", Location(self.file, line, 1))
                  for kind, _, line in self.nesting.stack]
        if self.in_comment is not None:
            errors.append(ParseError("#COMMENT BEGIN is never ended (#COMMENT END missing)",
                                     Location(self.file, self.in_comment, 1)))
        return errors
