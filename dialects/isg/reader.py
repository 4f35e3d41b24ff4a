"""ISG reader: physical lines -> blocks with words, control statements, assignments, calls and ``#`` commands.

Program structure: ``%L name`` opens a local subroutine (``SubStart``), which ends at its ``M17`` or
``M29`` outside any open construct (``SubEnd``); an ``M17``/``M29`` elsewhere, or in a file without
``%L`` (a global subroutine), returns (``Return``). ``%name`` is the main program (``ProgramStart``).
An implicit subroutine call ``G80``-``G89``/``G800``-``G899`` is a call of the file the set-up's
``<CodeCall code="G81" file="..."/>`` names (what the machine builder configured); without one it stays a
code kept verbatim, refused by the simulator and by every other dialect.
``LL name`` calls the local subroutine ``<name>``, ``L file`` the global subroutine file ``file``; both
are calls with their own level of ``V.L.`` variables (P parameters are shared, see ``variables``).

A block continued with ``\\`` at the end of its line is one block whose text holds every line (written
back as it was); it is located at its first line. ``#COMMENT BEGIN`` ... ``#COMMENT END`` lines are
comment blocks. ``#VAR`` ... ``#ENDVAR``: declarations, typed or not (``declarations``). ``#SUPPRESS OFFSETS`` with axis positions is a move in machine coordinates; ``#ROTATION`` is the contour rotation where its meaning is settled (``rotation``). Every other ``#`` command is kept verbatim (``NativeCode``): it round-trips in ISG and
is refused by every other dialect and by the simulator, naming the command. So is a block using an
array element (``P100[3]``, ``V.L.A[2]``), which the IR does not model (in a ``$`` statement it is an
error: the statement's construct could not be paired).

A no-break space (U+00A0, what a program copied from Beckhoff's documentation web pages carries between
its words) is read as a blank, with one warning for the file; the text keeps it, so it is written back
byte for byte.

Errors are reported per block; the block is kept as text only, and reading goes on.
"""

from __future__ import annotations

from typing import Callable, ClassVar, Iterable, Iterator

from postproc.interp.control import CONTROL, Assign, Call, Label, Return, SubEnd, SubStart
from postproc.dialect import Reader
from postproc.errors import Location, ParseError, PostprocError
from postproc.ir import BlockDelete, Block, Comments, MachineCoordinates, NativeCode, ProgramStart, Sequence, TapeMark
from postproc.rs274.lexer import split_lines

from postproc.ir.expr import Expr, Num, Var
from postproc.rs274.expressions import ExprSyntaxError

from .commands import command_name, describe_command
from .rotation import rotation_command
from .declarations import IsgTypes, parse_declaration, stored
from postproc.isg_family.expressions import Unmodelled
from postproc.isg_family.lexer import Lexed, command_words, lex, strip_comments
from postproc.isg_family.statements import Nesting, parse_statement
from postproc.isg_family.zero_offsets import ZeroOffsets

ZERO_OFFSETS = ZeroOffsets("isg", r"V\.G\.NP\[\s*(?P<index>\d+)\s*\]\.V\.(?P<axis>[A-Z]\w*)\s*=\s*(?P<value>{NUMBER})", 6)
"""``V.G.NP[n].V.<axis>=<number>``: zero offset n's axis, taken at G53+n's next selection (the writer's
``WORK_OFFSET_VARIABLE`` says the sources); n 1-6 (G54-G59). Another form (a computed value, ``V.G.NP_AKT``)
stays an array element, not modelled."""

RETURN_CODES = frozenset({17, 29})
"""``M17``/``M29`` end a subroutine."""

NO_BREAK_SPACE = "\u00a0"


class IsgReader(Reader):
    BLANKS: ClassVar[str] = NO_BREAK_SPACE
    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        file = self.ctx.file
        report = self.ctx.diagnostics.error
        state = _State(file, self.ctx.setup.code_calls, report)
        pending: list[tuple[int, str, str]] = []
        blank_warned = False
        for number, text, eol in split_lines(lines):
            if NO_BREAK_SPACE in text and not blank_warned:
                blank_warned = True
                self.ctx.diagnostics.warn("U+00A0 (a no-break space) is read as a blank here and wherever else "
                                          "this file has one (the text keeps it)",
                                          Location(file, number, text.index(NO_BREAK_SPACE) + 1))
            if not state.in_comment and text.rstrip().endswith("\\"):
                pending.append((number, text, eol))
                continue
            if pending:
                first = pending[0][0]
                code = " ".join(_blanks(_unbackslash(t)) for _, t, _ in pending) + " " + _blanks(text)
                text = "".join(t + e for _, t, e in pending) + text
                number, pending = first, []
            else:
                code = _blanks(text)
            try:
                yield state.block(number, text, code, eol)
            except PostprocError as err:
                report(err)
                yield Block(number, text, eol)
        if pending:
            number, text, eol = pending[0]
            report(ParseError("the last block ends with '\\' (a continuation) and no line follows",
                              Location(file, pending[-1][0], len(pending[-1][1].rstrip()))))
            yield Block(number, "".join(t + e for _, t, e in pending[:-1]) + pending[-1][1], pending[-1][2])
        for problem in state.finish():
            report(problem)


def _blanks(text: str) -> str:
    """The text to read: each no-break space a blank (one character for one, so columns stay)."""
    return text.replace(NO_BREAK_SPACE, " ") if NO_BREAK_SPACE in text else text


def _unbackslash(text: str) -> str:
    cut = text.rstrip()
    return cut[:-1] + " " * (len(text) - len(cut) + 1)


class _State:
    """What reading a file remembers between blocks."""

    def __init__(self, file: str, code_calls: dict[str, str], report: Callable[[PostprocError], None]) -> None:
        self.file = file
        self.report = report
        """Reports an error that leaves the block as read (its constructs still pair up)."""
        self.code_calls = code_calls
        """The set-up's ``<CodeCall>``s: what file each implicit subroutine call (G80-G89, G800-G899) runs."""
        self.nesting = Nesting(file)
        self.sub: tuple[str, int, int] | None = None
        """The open local subroutine: (name, line, nesting depth at its start)."""
        self.in_comment = False
        self.in_var: int | None = None
        """Line of an open ``#VAR``."""
        self.types = IsgTypes()

    def error(self, line: int, col: int, message: str) -> ParseError:
        return ParseError(message, Location(self.file, line, col))

    def block(self, number: int, text: str, code: str, eol: str) -> Block:
        block = Block(number, text, eol)
        if self.in_comment:
            if command_words(code) == ["#COMMENT", "END"]:  # alone in its block (a block number may precede it)
                self.in_comment = False
            block.add(Comments([text]))
            return block
        lexed = Lexed()
        code = strip_comments(self.file, number, code, lexed)
        if self.in_var is not None and code.strip() and "#" not in code and ("=" not in code or ":" in code):
            return self.declare(block, code, lexed.comments)
        if "V.G.NP[" in code.upper() and ZERO_OFFSETS.read(block, code, self.file):
            if lexed.comments:
                block.add(Comments(lexed.comments))
            return block
        try:
            lex(self.file, number, code, lexed)
        except Unmodelled as err:
            block.add(NativeCode("isg", f"{err.what} (not modelled)", text))
            return block
        if lexed.comments:
            block.add(Comments(lexed.comments))
        if lexed.skip:
            block.add(BlockDelete(lexed.skip))
        if lexed.header is not None:
            self.header(block, lexed.header)
            return block
        if lexed.number is not None:
            block.words.append(("N", lexed.number))
            if lexed.number_value is not None:
                block.values["N"] = lexed.number_value
            else:
                block.add(Sequence(int(lexed.number)))
        if lexed.label_name is not None:
            block.add(Label(lexed.label_name))
        if lexed.statement is not None:
            statement = parse_statement(code, lexed.statement, self.nesting, number)
            for role in getattr(statement, "ROLES", ()):
                value = getattr(statement, role)
                if isinstance(value, Expr):
                    self.numeric(block, value, "a condition")
            block.add(statement)
            return block
        if lexed.command is not None:
            self.command(block, code, lexed.command)
            return block
        block.words.extend(lexed.words)
        block.values.update(lexed.values)
        for letter, value in lexed.values.items():
            self.numeric(block, value, f"the value of {letter}")
        if lexed.assigns:
            block.add(Assign(self.assigned(block, lexed.assigns)))
        if lexed.call is not None:
            kind, name, at = lexed.call
            block.add(Call(f"<{name}>" if kind == "LL" else name, kind="macro"))
        self.returns(block, code)
        if self.code_calls:
            self.implicit_call(block)
        return block

    def declare(self, block: Block, code: str, comments: list[str]) -> Block:
        """A line of a ``#VAR`` block: a declaration (``declarations``); the variable gets its value."""
        try:
            declaration = parse_declaration(code)
        except Unmodelled as err:
            block.add(NativeCode("isg", f"{err.what} (not modelled)", block.text or ""))
            return block
        except ExprSyntaxError as err:
            raise err.at(self.file, block.line)
        if comments:
            block.add(Comments(comments))
        self.types.declare(declaration, block.line)
        if declaration.is_string:
            block.add(NativeCode("isg", f"{declaration.name} : {declaration.type} (a string variable: strings are "
                                        f"not modelled)", block.text or "", inert=True))
            return block
        value = declaration.value if declaration.value is not None else Num(0.0)
        self.numeric(block, value, f"the initial value of {declaration.name}")
        block.add(Assign([(Var(name=declaration.name), stored(declaration.type, value))]))
        return block

    def assigned(self, block: Block, items: list[tuple[Var, Expr]]) -> list[tuple[Var, Expr]]:
        """Assignments as the declared types store them (a STRING variable takes no number)."""
        out = []
        for var, value in items:
            self.numeric(block, value, f"the value assigned to {var.name or 'a P parameter'}")
            try:
                out.append((var, self.types.assigned(var, value)))
            except ValueError as err:
                raise self.error(block.line, 1, str(err)) from None
        return out

    def numeric(self, block: Block, value: Expr, what: str) -> None:
        """A located error when ``value`` reads a STRING variable (a string is no axis value); the block
        stays as read, so what it opens or closes still pairs up."""
        problem = self.types.string_used(value)
        if problem is not None:
            self.report(self.error(block.line, 1, f"{what}: {problem}"))

    def implicit_call(self, block: Block) -> None:
        """``G81``: a call of the file the set-up says the machine builder configured for it (non-modal,
        one call per block); an unconfigured one stays a code the block syntax keeps verbatim."""
        for i, (letter, num) in enumerate(block.words):
            if letter not in "Gg" or not num.isdigit() or not (80 <= int(num) <= 89 or 800 <= int(num) <= 899):
                continue
            file = self.code_calls.get(f"G{int(num)}")
            if file is None:
                continue
            if CONTROL in block.sections:
                raise self.error(block.line, 1, f"G{num}: one call or return per block")
            del block.words[i]
            block.add(Call(file, kind="macro"))
            return

    def header(self, block: Block, header: tuple[str, str]) -> None:
        kind, name = header
        if kind == "tape":
            block.add(TapeMark())
            return
        if self.sub is not None:
            raise self.error(block.line, 1, f"%L {self.sub[0]} from line {self.sub[1]} has no M17/M29 before "
                                            f"this program header")
        if kind == "sub":
            if self.nesting.stack:
                raise self.error(block.line, 1, "a local subroutine cannot start inside an open construct")
            self.sub = (name, block.line, len(self.nesting.stack))
            block.add(SubStart(f"<{name}>"))
            return
        block.add(ProgramStart(int(name), None) if name.isdigit() else ProgramStart(None, name))

    def command(self, block: Block, code: str, pos: int) -> None:
        words = command_words(code[pos:])
        if words[:2] == ["#COMMENT", "BEGIN"]:
            self.in_comment = True
            block.add(Comments([block.text or ""]))
            return
        if words[:1] == ["#VAR"] and len(words) == 1:
            self.in_var = block.line
            block.add(Comments([code[pos:].strip()]))
            return
        if words[:1] == ["#ENDVAR"] and len(words) == 1:
            if self.in_var is None:
                raise self.error(block.line, pos + 1, "#ENDVAR without #VAR")
            self.in_var = None
            block.add(Comments([code[pos:].strip()]))
            return
        if words[:2] == ["#SUPPRESS", "OFFSETS"] and "[" not in code[pos:]:
            self.suppress_offsets(block, code, pos)
            return
        if words[:1] == ["#ROTATION"]:
            change = rotation_command(code[pos:].rstrip())
            if change is not None:
                block.add(change)
                return
        name = command_name(code, pos)
        block.add(NativeCode("isg", describe_command(name), code[pos:].rstrip()))

    def suppress_offsets(self, block: Block, code: str, pos: int) -> None:
        """``#SUPPRESS OFFSETS X.. Z..``: the axis positions without any offset (zero, tool, preset...), in
        this block only [V: TF5200 programming manual 207072907]: a move in machine coordinates, its words
        read as a block's (the motion mode in force moves it)."""
        start = code.upper().index("OFFSETS", pos) + len("OFFSETS")
        lexed = Lexed()
        lex(self.file, block.line, " " * start + code[start:], lexed)
        if lexed.statement is not None or lexed.command is not None or lexed.assigns or lexed.call is not None \
                or any(letter.upper() not in "XYZABCUVW" for letter, _ in lexed.words):
            raise self.error(block.line, pos + 1, "#SUPPRESS OFFSETS takes axis positions only")
        block.words.extend(lexed.words)
        block.values.update(lexed.values)
        block.add(MachineCoordinates())

    def returns(self, block: Block, code: str) -> None:
        """``M17``/``M29``: the end of the open local subroutine, or a return."""
        found = [(i, num) for i, (letter, num) in enumerate(block.words)
                 if letter in "Mm" and num.isdigit() and int(num) in RETURN_CODES]
        if not found:
            return
        i, num = found[0]
        if len(found) > 1 or CONTROL in block.sections:
            raise self.error(block.line, 1, f"M{num}: one call or return per block")
        del block.words[i]
        if self.sub is not None and len(self.nesting.stack) == self.sub[2]:
            block.add(SubEnd(f"<{self.sub[0]}>"))
            self.sub = None
        else:
            block.add(Return())

    def finish(self) -> list[ParseError]:
        errors = [self.error(line, 1, f"${kind} is never closed (${'UNTIL' if kind == 'REPEAT' else 'END' + kind} "
                                      f"missing)")
                  for kind, _, line in self.nesting.stack]
        if self.sub is not None:
            errors.append(self.error(self.sub[1], 1, f"%L {self.sub[0]} is never ended (M17 or M29 missing)"))
        if self.in_comment:
            errors.append(self.error(1, 1, "#COMMENT BEGIN is never ended (#COMMENT END missing)"))
        if self.in_var is not None:
            errors.append(self.error(self.in_var, 1, "#VAR is never ended (#ENDVAR missing)"))
        return errors
