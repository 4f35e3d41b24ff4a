"""Reading SINUMERIK calls: cycles (``CYCLE81(..)``, ``MCALL CYCLE81(..)``, ``HOLES1(..)``), subprograms (``PROC``
with parameters, ``NAME(args)``, ``NAME P3``, ``RET``, ``M17``) and tools by name (``T="DRILL"``), for the
reader's per-file state (``reader._State``, which inherits them). What each is read as is in ``cycles``,
``holes`` and the methods' docstrings.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from postproc.interp.control import CONTROL, Assign, Call, Return
from postproc.errors import ParseError
from postproc.ir.expr import Expr, Num, Var
from postproc.ir import Block, Comments, CycleCall, CycleCancel
from postproc.isg_family.expressions import Unmodelled
from postproc.rs274.expressions import skip_blanks

from .cycles import CYCLES, NotModelled, cycle_words
from .expressions import name_at, parse_expr
from .holes import PARAMETERS as HOLES
from .holes import read_holes

ADDRESSES = frozenset("GXYZABCIJKFSTDMH")
"""Single-letter addresses a word may have."""
TYPES = {"REAL": "real", "INT": "int", "BOOL": "bool"}
"""DEF types whose values the IR models (numbers)."""
MAX_PARAMETERS = 64
"""A cycle call, a ``PROC`` or a call with more parameters is a located error (hostile input)."""
PARAMETER_COUNT = "%n"
"""The variable a ``PROC`` with parameters sets to their number (``variables``: more arguments are an error)."""
DIGITS = frozenset("0123456789")
NUMBER_START = frozenset("0123456789+-.")
NAME_START = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz_")


class CallReading:
    """The call-reading methods of the reader's state; it supplies the attributes and ``error``/``stored``."""

    types: dict[str, str]
    tool_names: dict[str, int]
    subprogram: bool

    if TYPE_CHECKING:  # the reader's state defines them
        def error(self, line: int, col: int, message: str) -> ParseError: ...

        def stored(self, var: Var, value: Expr) -> Expr: ...

    def mcall(self, block: Block, code: str, pos: int, end: int) -> None:
        """``MCALL CYCLE8x(..)`` with number parameters: the cycle's data block (``cycles``); a bare ``MCALL``
        cancels it. Other modal calls are kept verbatim."""
        at = skip_blanks(code, end)
        if at >= len(code):
            block.add(CycleCancel())
            return
        stop = name_at(code, at)
        name = code[at:stop].upper()
        if name not in CYCLES or code[skip_blanks(code, stop):skip_blanks(code, stop) + 1] != "(":
            raise Unmodelled(f"MCALL {name or '..'} (a modal subprogram or cycle call)", pos)
        self.cycle(block, code, pos, stop, name, once=False)

    def cycle(self, block: Block, code: str, pos: int, stop: int, name: str, once: bool) -> None:
        """``name(p1, , p3)`` from ``stop`` (after the name) to the end of the block: read on the neutral cycle
        IR (``cycles``), or kept verbatim."""
        shown = name if once else f"MCALL {name}"
        params: list[float | None] = []
        at = skip_blanks(code, stop) + 1
        while True:
            at = skip_blanks(code, at)
            if code[at:at + 1] in (",", ")"):
                params.append(None)
            else:
                at, value = parse_expr(code, at)
                if not isinstance(value, Num):
                    raise Unmodelled(f"{shown} with computed parameters", pos)
                params.append(value.value)
                at = skip_blanks(code, at)
            if len(params) > MAX_PARAMETERS:
                raise self.error(block.line, at + 1, f"{name}(..) has more than {MAX_PARAMETERS} parameters")
            if code[at:at + 1] == ",":
                at += 1
                continue
            if code[at:at + 1] != ")":
                raise self.error(block.line, at + 1, f"',' or ')' expected in {name}(..)")
            break
        if skip_blanks(code, at + 1) < len(code):
            raise self.error(block.line, skip_blanks(code, at + 1) + 1, f"{shown}(..) is alone in its block")
        if name in HOLES:
            try:
                block.add(read_holes(name, params))
            except ValueError as err:
                raise self.error(block.line, pos + 1, str(err)) from None
            return
        names = CYCLES[name].parameters
        if len(params) > len(names):
            raise Unmodelled(f"{shown} with parameters after {names[-1]} (GMODE, DMODE...)", pos)
        try:
            kind, words, levels = cycle_words(name, params, once)
        except NotModelled as err:
            raise Unmodelled(err.what if once else f"MCALL {err.what}", pos) from None
        except ValueError as err:
            raise self.error(block.line, pos + 1, str(err)) from None
        block.words.extend(words)
        block.add(levels)
        block.add(CycleCall(kind))

    # -- subprograms -------------------------------------------------------------------------------------
    def procedure(self, block: Block, code: str, pos: int, end: int, word: str) -> None:
        """``PROC NAME`` opens a subprogram (the file is its body); ``RET`` returns [K: 840D Fundamentals,
        "Subprograms"]. ``PROC NAME(REAL A, INT B)``: parameters called by value, each a local variable of
        the subprogram set from the call's argument in its place (``procedure_parameters``). Parameters by
        reference (``VAR``), arrays and the attributes ``SAVE``/``DISPLOF`` are not modelled (kept
        verbatim)."""
        at = skip_blanks(code, end)
        if word == "RET":
            if at < len(code):
                raise Unmodelled("RET with a target or a value", at)
            block.add(Return())
            return
        stop = name_at(code, at)
        if stop == at or code[at] not in NAME_START:
            raise self.error(block.line, at + 1, "PROC needs a subprogram name")
        rest = skip_blanks(code, stop)
        if code[rest:rest + 1] == "(":
            rest = self.procedure_parameters(block, code, rest)
        if rest < len(code):
            raise Unmodelled("PROC with attributes (SAVE, DISPLOF)", rest)
        self.subprogram = True
        if "Comments" not in block.sections:
            block.add(Comments([code[pos:].strip()]))

    def procedure_parameters(self, block: Block, code: str, at: int) -> int:
        """``(REAL A, INT B)`` from its ``(``: each parameter is declared (its type rounds an INT, as ``DEF``
        does) and assigned the call's argument in its place; the position after ``)``. A call passes its
        arguments as the subprogram level's ``%1``, ``%2``... (``variables``); ``%n`` set to the number of
        parameters first makes a call with more arguments an error [K: 840D Job planning, "Subprogram with
        parameter transfer (PROC, VAR)": call by value, parameters typed and positional; an argument left
        out is not read here [?: its default is not confirmed]]."""
        items: list[tuple[Var, Expr]] = []
        while True:
            at = skip_blanks(code, at + 1)
            if code[at:at + 1] == ")" and not items:
                break
            type_end = name_at(code, at)
            kind = code[at:type_end].upper()
            if kind == "VAR":
                raise Unmodelled("a parameter by reference (VAR)", at)
            if kind not in TYPES:
                raise Unmodelled(f"a PROC parameter of type {kind or '..'} (only REAL, INT and BOOL values are "
                                 "modelled)", at)
            start = skip_blanks(code, type_end)
            name_end = name_at(code, start)
            name = code[start:name_end]
            upper = name.upper()
            if not name or code[start] not in NAME_START or upper[:1] == "R" and upper[1:].isdigit() \
                    or len(name) == 1 and upper in ADDRESSES:
                raise self.error(block.line, start + 1, "a PROC parameter needs a name that is no address or R "
                                                        "parameter")
            at = skip_blanks(code, name_end)
            if code[at:at + 1] == "[":
                raise Unmodelled("array parameters", start)
            if len(items) >= MAX_PARAMETERS:
                raise self.error(block.line, start + 1, f"PROC has more than {MAX_PARAMETERS} parameters")
            var = Var(name=name.lower())
            self.types[name.lower()] = TYPES[kind]
            items.append((var, self.stored(var, Var(name=f"%{len(items) + 1}"))))
            if code[at:at + 1] == ",":
                continue
            if code[at:at + 1] != ")":
                raise self.error(block.line, at + 1, "',' or ')' expected in the PROC parameters")
            break
        if items:
            block.add(Assign([(Var(name=PARAMETER_COUNT), Num(float(len(items)))), *items]))
        return skip_blanks(code, at + 1)

    def call(self, block: Block, code: str, pos: int, end: int) -> bool:
        """``NAME`` or ``NAME P3`` alone in its block: a call of subprogram ``NAME`` (file ``NAME.SPF``), run
        3 times, with its own local variables [K: 840D Fundamentals, "Subprogram call", "Program repetition
        P"]. ``NAME(1, R2*2)``: a call with arguments, by value, in the order of the subprogram's ``PROC``
        parameters (``procedure_parameters``). Anything else is no call (the words are read)."""
        name = code[pos:end]
        upper = name.upper()
        n = len(code)
        at = skip_blanks(code, end)
        if upper[:1] == "R" and upper[1:].isdigit() or name.lower() in self.types or upper[:1] == "$" \
                or len(name) == 1 or upper[:1] in ADDRESSES and upper[1:2] in NUMBER_START \
                or code[at:at + 1] == "=":
            return False
        args: dict[int, Expr] = {}
        if code[at:at + 1] == "(":
            at = self.arguments(block, code, at, upper, args)
        repeat: Expr | None = None
        if at < n:
            if args:
                raise Unmodelled(f"a call of {upper} with arguments and more after them (P repetitions)", pos)
            if code[at] not in "Pp":
                raise Unmodelled(f"'{name}' (an instruction or a subprogram call)", pos)
            start = skip_blanks(code, at + 1 + (code[skip_blanks(code, at + 1):skip_blanks(code, at + 1) + 1] == "="))
            stop = start
            while stop < n and code[stop] in DIGITS:
                stop += 1
            if stop == start or skip_blanks(code, stop) < n:
                raise self.error(block.line, at + 1, f"a call of {upper} repeats a whole number of times: {upper} P3")
            repeat = Num(float(int(code[start:stop])))
        block.add(Call(upper, args, repeat=repeat, kind="macro"))
        return True

    def arguments(self, block: Block, code: str, at: int, name: str, args: dict[int, Expr]) -> int:
        """``(1, R2*2)`` from its ``(`` into ``args`` (1, 2...); the position after ``)``."""
        while True:
            at = skip_blanks(code, at + 1)
            if code[at:at + 1] == ")" and not args:
                break
            if code[at:at + 1] in (",", ")"):
                raise self.error(block.line, at + 1, f"an empty argument of {name}: its default is not confirmed "
                                                     "here [?]")
            if len(args) >= MAX_PARAMETERS:
                raise self.error(block.line, at + 1, f"a call of {name} has more than {MAX_PARAMETERS} arguments")
            at, value = parse_expr(code, at)
            args[len(args) + 1] = value
            at = skip_blanks(code, at)
            if code[at:at + 1] == ",":
                continue
            if code[at:at + 1] != ")":
                raise self.error(block.line, at + 1, f"',' or ')' expected in the arguments of {name}")
            break
        return skip_blanks(code, at + 1)

    def returns(self, block: Block, code: str) -> None:
        """``M17`` returns from a subprogram; ``M2``/``M30`` in a subprogram file is refused (whether it
        returns or ends the program is not confirmed here [?])."""
        for i, (letter, num) in enumerate(block.words):
            if letter not in "Mm" or not num.isdigit():
                continue
            if int(num) == 17:
                if CONTROL in block.sections:
                    raise self.error(block.line, 1, "M17: one call or return per block")
                del block.words[i]
                block.add(Return())
                return
            if int(num) in (2, 30) and self.subprogram:
                raise self.error(block.line, 1, f"M{num} in a subprogram: write RET or M17 (whether M{num} returns "
                                                "or ends the program is not confirmed here)")

    def tool(self, block: Block, code: str, at: int) -> int:
        """``T="DRILL_8"`` from its opening quote: the set-up's tool of that name, read as its number (``T3``);
        a name no tool has keeps the block verbatim (a SINUMERIK program is still copied; elsewhere it is a
        located error naming it). The name is matched exactly [?: whether tool management
        compares names ignoring case is not confirmed here]."""
        close = code.find('"', at + 1)
        if close < 0:
            raise self.error(block.line, at + 1, "the tool's name has no closing '\"'")
        name = code[at + 1:close]
        number = self.tool_names.get(name)
        if number is None:
            known = ", ".join(sorted(self.tool_names)) or "none has a name"
            raise Unmodelled(f'T="{name}" (no tool of the set-up has this name: <Tool number=".." name="{name}"/>; '
                             f'named: {known})', at)
        block.words.append(("T", str(number)))
        return close + 1

