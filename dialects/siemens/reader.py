"""SINUMERIK reader: physical lines -> blocks with words, assignments, control statements and jump labels.

Block structure [K: 802D programming manual, "block structure" (manualslib.de manual 107156 p.133);
840D sl Job planning 02/2011]: ``/`` skip (``/0``-``/9``; a plain ``/`` is ``/0``), ``N10`` or ``:10``
(a main block), a jump label ``NAME:``, then words, then a ``;`` comment to the end of the line.
Addresses with more than one letter, expressions and R parameters as values take ``=``
(``X=R2``, ``CR=5``, ``X=AC(10)``); ``R1=5`` and ``DEPTH=R1*2`` (a ``DEF`` variable) are assignments.

Read into neutral sections:

* ``%_N_NAME_MPF`` / ``%_N_NAME_SPF`` headers (``ProgramStart`` named ``NAME_MPF``/``NAME_SPF``);
* skip levels: ``/k`` is the neutral level ``k + 1`` (``/`` and ``/0`` are level 1, Fanuc's ``/``);
* ``CR=`` (arc radius, negative for more than 180 degrees, as Fanuc's R [K]) as the arc's radius word;
* ``X=AC(..)``/``X=IC(..)``: the value as a plain word when the block's own ``G90``/``G91`` says the same
  thing (and ``I=IC(..)``: centres are incremental by default [K]); otherwise the per-address distance
  mode is not modelled and the block is kept verbatim;
* ``CYCLE81(..)`` ... ``CYCLE89(..)``, ``CYCLE840(..)`` alone in a block (called once), ``MCALL CYCLE8x(..)``
  and a bare ``MCALL`` (``cycles``: which are read, which kept verbatim); ``HOLES1(..)``/``HOLES2(..)`` (``holes``);
* ``TRANS``/``ATRANS``, ``ROT``/``AROT``, ``SCALE``/``ASCALE``, ``MIRROR``/``AMIRROR`` with numbers, alone in
  their block: the neutral frame change under the ``chain`` rules (``frames``);
* ``G75 FP=1 Z1=0`` alone in a block (``fixed_point``: a rapid move in machine coordinates to the set-up's
  home);
* ``DEF REAL|INT|BOOL NAME[=value], ...`` (an assignment of the value, 0 when none is given [K]);
* ``IF``/``ELSE``/``ENDIF``, ``WHILE``, ``FOR``, ``REPEAT``/``UNTIL``, ``LOOP`` and the ``GOTO`` jumps
  (``control_reading``, with the rules that check them);

Subprograms: ``NAME`` / ``NAME P3`` alone in a block calls ``NAME.SPF`` (3 times), ``NAME(1, R2)`` with
arguments; ``PROC NAME`` or ``PROC NAME(REAL A, INT B)`` (parameters by value) or an ``_SPF`` header makes the
file a subprogram; ``RET``/``M17`` return.

Kept verbatim (``NativeCode`` tagged ``siemens``: round trip byte for byte, refused by every other dialect
and by the simulator, by name): the frames ``frames`` does not model (``ROTS``, computed values...), the cycles
``cycles`` keeps verbatim, other ``MCALL``s, parameters by reference (``VAR``), every other instruction word
(``SOFT``, ``BRISK``, ``SPOSA``...; ``SUPA`` is read: ``frame_suppression``; ``SPOS=<angle>``:
``spindle_position``), multi-letter addresses other
than ``CR``, ``AR``, ``I1=``.. of ``CIP`` (``arcs``) and ``TURN`` (``helix``), strings other than ``T="name"`` (the set-up's tool of that name), array,
``CHAR``/``STRING``/``AXIS``/``FRAME`` declarations and the operators the IR lacks (``DIV``, ``B_AND``...).

Errors are reported per block; the block is kept as text only, and reading goes on.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Iterable, Iterator

from postproc.interp.control import Assign, Label
from postproc.dialect import Reader
from postproc.errors import Location, ParseError, PostprocError
from postproc.ir.expr import Binary, Expr, Func, Num, Var
from postproc.ir import Block, BlockDelete, Comments, NativeCode, ProgramStart, Sequence, SpindleOrientation
from postproc.isg_family.expressions import Unmodelled
from postproc.isg_family.zero_offsets import ZeroOffsets
from postproc.rs274.expressions import ExprSyntaxError, decimal_end, skip_blanks
from postproc.rs274.lexer import split_lines

from .call_reading import ADDRESSES, TYPES, CallReading
from .call_reading import DIGITS as _DIGITS
from .call_reading import NAME_START as _NAME_START
from .call_reading import NUMBER_START as _NUMBER_START
from .control_reading import CLOSERS, JUMPS, OPENERS, ControlReading, Jump
from .arcs import SiemensArc, SiemensCip
from .cycles import CYCLES
from .fixed_point import read_fixed_point
from .frame_suppression import SiemensSupa
from .helix import MAX_TURNS, SiemensTurn
from .frames import STATEMENTS as FRAME_STATEMENTS, read_frame
from .holes import PARAMETERS as HOLES
from .expressions import name_at, parse_expr, parse_variable, plain_number
from .keywords import describe

SKIP_LEVELS = 9
"""Block skip ``/0`` ... ``/9`` [K]."""
_WORDS_READ = frozenset(("CIP", "SUPA", "SPOS"))
"""Instruction words that start a block and are read with its words (``arcs``, ``frame_suppression``,
``spindle_position``)."""


ZERO_OFFSETS = ZeroOffsets(
    "siemens", r"\$P_UIFR\[\s*(?P<index>\d+)\s*,\s*(?P<axis>[A-Z]\w*)\s*,\s*TR\s*\]\s*=\s*(?P<value>{NUMBER})", 99)
"""``$P_UIFR[n,<axis>,TR]=<number>``: the coarse translation of settable frame n, taken at the next selection of
its G code (the writer's ``WORK_OFFSET_VARIABLE`` says the sources [K]); n 1-99 (G54-G57, G505-G599). Another
form (a whole frame ``=CTRANS(..)``, a fine offset FI, a computed value) stays a system variable, not modelled."""

class SiemensReader(Reader):
    def read(self, lines: Iterable[str]) -> Iterator[Block]:
        report = self.ctx.diagnostics.error
        state = _State(self.ctx.file, subprogram=self.ctx.file.upper().endswith(".SPF"),
                       tool_names={t.name: t.number for t in self.ctx.setup.tools.values() if t.name is not None})
        for number, text, eol in split_lines(lines):
            try:
                yield state.block(number, text, eol)
            except ExprSyntaxError as err:
                report(err.at(self.ctx.file, number) if err.location is None else err)
                yield Block(number, text, eol)
            except PostprocError as err:
                report(err)
                yield Block(number, text, eol)
        for problem in state.finish():
            report(problem)


@dataclass
class _State(CallReading, ControlReading):
    """What reading a file remembers between blocks (calls, cycles and tools: ``CallReading``; loops,
    conditions and jumps: ``ControlReading``)."""

    file: str
    stack: list[tuple[str, str, int]] = field(default_factory=list)
    """Open constructs: (opening word, label, line)."""
    count: int = 0
    labels: dict[str, list[int]] = field(default_factory=dict)
    """Jump label (lower case) or ``N<number>`` -> the lines that carry it."""
    jumps: list[Jump] = field(default_factory=list)
    types: dict[str, str] = field(default_factory=dict)
    """Declared user variables (lower case) -> their type."""
    tool_names: dict[str, int] = field(default_factory=dict)
    """The set-up's tool names -> their numbers (``T="name"``)."""
    subprogram: bool = False
    """The file is a subprogram: a ``.SPF`` file (every file a call loads is one), an ``_SPF`` header or a
    ``PROC`` line."""

    def error(self, line: int, col: int, message: str) -> ParseError:
        return ParseError(message, Location(self.file, line, col))

    def block(self, number: int, text: str, eol: str) -> Block:
        block = Block(number, text, eol)
        code, comment = _strip_comment(text)
        if comment is not None:
            block.add(Comments([comment]))
        if "$P_UIFR[" in code.upper() and ZERO_OFFSETS.read(block, code, self.file):
            return block
        try:
            self.lex(block, code)
        except Unmodelled as err:
            self.native(block, f"{err.what} (not modelled)")
        return block

    def native(self, block: Block, what: str) -> None:
        comments = block.sections.get("Comments")
        block.sections.clear()
        block.words.clear()
        block.values.clear()
        if comments is not None:
            block.add(comments)
        block.add(NativeCode("siemens", what, block.text or ""))

    # -- the block's structure --------------------------------------------------------------------------
    def lex(self, block: Block, code: str) -> None:
        line = block.line
        n = len(code)
        pos = skip_blanks(code, 0)
        if pos < n and code[pos] == "%":
            name = self.header(code, pos, line)
            if name.endswith("_SPF"):
                self.subprogram = True  # a subprogram file: its header names it, and starts nothing
                if "Comments" not in block.sections:
                    block.add(Comments([code.strip()]))
                return
            block.add(ProgramStart(None, name))
            return
        if pos < n and code[pos] == "/":
            end = pos + 1
            while end < n and code[end] in _DIGITS:
                end += 1
            level = int(code[pos + 1:end]) if end > pos + 1 else 0
            if level > SKIP_LEVELS:
                raise self.error(line, pos + 1, f"block skip level /{level} (levels are /0 to /{SKIP_LEVELS})")
            block.add(BlockDelete(level + 1))
            pos = skip_blanks(code, end)
        if pos < n and (code[pos] in "Nn:" and code[pos + 1:pos + 2].isdigit()):
            end = pos + 1
            while end < n and code[end] in _DIGITS:
                end += 1
            if end < n and code[end] == ".":
                raise self.error(line, pos + 1, "a block number is a whole number")
            number = code[pos + 1:end]
            block.words.append(("N", number))
            block.add(Sequence(int(number)))
            self.labels.setdefault(f"N{int(number)}", []).append(line)
            pos = skip_blanks(code, end)
        if pos < n and code[pos] in _NAME_START:
            end = name_at(code, pos)
            if code[end:end + 1] == ":" and code[end + 1:end + 2] != "=":
                name = code[pos:end].lower()
                block.add(Label(name))
                self.labels.setdefault(name, []).append(line)
                pos = skip_blanks(code, end + 1)
        if pos >= n:
            return
        point = read_fixed_point(code, pos)
        if point is not None:
            block.add(point)
            return
        if code[pos] in _NAME_START:
            end = name_at(code, pos)
            word = code[pos:end].upper()
            if word in OPENERS or word in CLOSERS or word in ("ELSE", *JUMPS):
                block.add(self.statement(code, pos, end, word, line))
                return
            if word == "DEF":
                self.declare(block, code, end)
                return
            if word in ("PROC", "RET"):
                self.procedure(block, code, pos, end, word)
                return
            if word in FRAME_STATEMENTS:
                block.add(read_frame(word, code, pos, end, self.file, line))
                return
            if word == "MCALL":
                self.mcall(block, code, pos, end)
                return
            if word == "CIP":
                block.add(SiemensCip())
                pos = end
            if (word in CYCLES or word in HOLES) and code[skip_blanks(code, end):skip_blanks(code, end) + 1] == "(" \
                    and BlockDelete.KEY not in block.sections:
                self.cycle(block, code, pos, end, word, once=True)
                return
            what = describe(word) if word not in _WORDS_READ else None
            if what is not None:
                raise Unmodelled(what, pos)
            if word not in _WORDS_READ and self.call(block, code, pos, end):
                return
        self.words(block, code, pos)
        self.returns(block, code)

    def header(self, code: str, pos: int, line: int) -> str:
        """``%_N_NAME_MPF`` -> ``NAME_MPF`` [K: the program header of an 840D file; a name starts with a letter
        or ``_`` (Fundamentals, "Program names": the first two characters, not checked here [?])]."""
        rest = code[pos + 1:].strip()
        if not rest.startswith("_N_") or not (rest.endswith("_MPF") or rest.endswith("_SPF")) \
                or len(rest) <= 7 or any(not (c.isalnum() or c == "_") for c in rest) or rest[3].isdigit():
            raise self.error(line, pos + 1, f"a program header is %_N_<NAME>_MPF or %_N_<NAME>_SPF, not %{rest}")
        return rest[3:]


    # -- control statements -----------------------------------------------------------------------------
    # -- declarations and words -------------------------------------------------------------------------
    def declare(self, block: Block, code: str, end: int) -> None:
        """``DEF REAL A, B=2``: each variable gets its value (0 when none is given [K])."""
        at = skip_blanks(code, end)
        type_end = name_at(code, at)
        kind = code[at:type_end].upper()
        if kind not in TYPES:
            raise Unmodelled(f"a DEF {kind or '..'} declaration (only REAL, INT and BOOL values are modelled)", at)
        items: list[tuple[Var, Expr]] = []
        at = type_end
        while True:
            at = skip_blanks(code, at)
            name_end = name_at(code, at)
            name = code[at:name_end]
            if not name or code[at] not in _NAME_START:
                raise self.error(block.line, at + 1, "DEF needs a variable name")
            upper = name.upper()
            if upper[:1] == "R" and upper[1:].isdigit() or len(name) == 1 and upper in ADDRESSES:
                raise self.error(block.line, at + 1, f"'{name}' is an address or an R parameter, not a variable name")
            if code[skip_blanks(code, name_end):skip_blanks(code, name_end) + 1] == "[":
                raise Unmodelled("arrays", at)
            var = Var(name=name.lower())
            self.types[name.lower()] = TYPES[kind]
            at = skip_blanks(code, name_end)
            value: Expr = Num(0.0)
            if code[at:at + 1] == "=":
                at, value = parse_expr(code, at + 1)
                at = skip_blanks(code, at)
            items.append((var, self.stored(var, value)))
            if code[at:at + 1] == ",":
                at += 1
                continue
            if at < len(code):
                raise self.error(block.line, at + 1, f"unexpected {code[at:].strip()[:20]!r} in DEF")
            break
        block.add(Assign(items))

    def stored(self, var: Var, value: Expr) -> Expr:
        """What a typed variable holds: an INT the rounded value [K: REAL -> INT conversion rounds], a BOOL
        1 or 0 (non-zero is TRUE [K])."""
        kind = self.types.get(var.name or "")
        if kind == "int" and not (isinstance(value, Num) and value.value.is_integer()):
            return Func("round", [value])
        if kind == "bool" and not (isinstance(value, Num) and value.value in (0.0, 1.0)):
            return Binary("ne", value, Num(0.0))
        return value

    def words(self, block: Block, code: str, pos: int) -> None:
        n = len(code)
        assigns: list[tuple[Var, Expr]] = []
        modes: list[tuple[str, str, int]] = []
        seen: set[str] = set()
        # The end of the name scanned last: words written without blanks (``G1G1G1``) are one name, and a word
        # inside it ends where that name does, found once (scanning and slicing the rest of the line at every
        # word took time quadratic in the line: minutes for a long one, the fuzz's ``malformed siemens``).
        run_end = 0
        while True:
            pos = skip_blanks(code, pos)
            if pos >= n:
                break
            c = code[pos]
            up = c.upper()
            if c not in _NAME_START and c != "$":
                raise self.error(block.line, pos + 1, f"unexpected character {c!r}")
            end = run_end if pos < run_end else name_at(code, pos)
            run_end = end
            eq = skip_blanks(code, end)
            assigned = code[eq:eq + 1] == "=" and code[eq + 1:eq + 2] != "="
            if not assigned and up in ADDRESSES and code[pos + 1:pos + 2] in _DIGITS:
                # an address and its number (``G1``, ``X10``): what the branches below decide for it, without
                # the name (the whole run of letters and digits it starts)
                key = up
                if key not in "GM" and key in seen:
                    raise self.error(block.line, pos + 1, f"address {key} appears twice in one block")
                seen.add(key)
                pos = self.number(block, code, pos, c)
                continue
            name = code[pos:end]
            upper = name.upper()
            if assigned and (upper[:1] == "R" and upper[1:].isdigit() or name.lower() in self.types
                             or upper[:1] == "$"):
                target = parse_variable(code, pos)[1]
                at, value = parse_expr(code, eq + 1)
                assigns.append((target, self.stored(target, value)))
                pos = at
                continue
            single = end == pos + 1 or upper[1:2].isdigit()
            if up in ADDRESSES and assigned and end == pos + 1:
                letter = c
            elif upper == "CR" and assigned:
                letter = "R"
            elif upper == "AR" and assigned:
                pos = self.opening_angle(block, code, pos, eq + 1)
                continue
            elif upper in ("I1", "J1", "K1") and assigned and SiemensCip.KEY in block.sections:
                pos = self.intermediate_point(block, code, pos, eq + 1, upper)
                continue
            elif up in ADDRESSES and single and not assigned and code[pos + 1:pos + 2] in _NUMBER_START:
                letter = c
            elif up in ADDRESSES and end == pos + 1:
                raise self.error(block.line, pos + 1, f"address {up} needs a value")
            elif upper == "TURN" and assigned:
                pos = self.turns(block, code, pos, eq + 1)
                continue
            elif upper == "SPOS" and assigned:
                pos = self.spindle_position(block, code, pos, eq + 1)
                continue
            elif upper == "SUPA" and not assigned:
                block.add(SiemensSupa())  # frames suppressed in this block (``frame_suppression``)
                pos = end
                continue
            else:
                if upper[:1] == "$":
                    raise self.error(block.line, pos + 1, f"a system variable {name} alone: set it with "
                                                          f"{name}=<value> or use it as a value (X={name})")
                what = describe(upper) or (f"the address {upper}= " if assigned else
                                           f"'{name}' (an instruction or a subprogram call)")
                raise Unmodelled(what, pos)
            key = letter.upper()
            if key not in "GM" and key in seen:
                raise self.error(block.line, pos + 1, f"address {key} appears twice in one block")
            seen.add(key)
            if assigned:
                pos = self.value(block, code, pos, eq + 1, letter, modes)
            else:
                pos = self.number(block, code, pos, letter)
        if modes:
            self.distance_modes(block, modes)
        if SiemensArc.KEY in block.sections and not block.values.keys().isdisjoint("XYIJ"):
            raise Unmodelled("AR= with computed coordinates", 0)
        if assigns:
            block.add(Assign(assigns))

    def intermediate_point(self, block: Block, code: str, pos: int, start: int, name: str) -> int:
        """``I1=5`` in a ``CIP`` block: a coordinate of the circle's intermediate point (``arcs``), a number."""
        cip = block.sections[SiemensCip.KEY]
        attr = name[0].lower() + "1"
        if getattr(cip, attr) is not None:
            raise self.error(block.line, pos + 1, f"{name} appears twice in one block")
        end, value = parse_expr(code, start)
        if not isinstance(value, Num):
            raise Unmodelled(f"{name}= with a computed value", pos)
        setattr(cip, attr, value.value)
        return end

    def turns(self, block: Block, code: str, pos: int, start: int) -> int:
        """``TURN=3``: a helix's additional full circles (``helix``), a whole number from 0 to 999."""
        if SiemensTurn.KEY in block.sections:
            raise self.error(block.line, pos + 1, "TURN appears twice in one block")
        end, value = parse_expr(code, start)
        if not isinstance(value, Num):
            raise Unmodelled("TURN= with a computed value", pos)
        if value.value != int(value.value) or not 0 <= value.value <= MAX_TURNS:
            raise self.error(block.line, pos + 1, f"TURN={value.value:g}: a whole number of full circles from 0 "
                                                  f"to {MAX_TURNS}")
        block.add(SiemensTurn(int(value.value)))
        return end

    def spindle_position(self, block: Block, code: str, pos: int, start: int) -> int:
        """``SPOS=90``: the spindle stops at 90 degrees, under position control: an oriented spindle stop
        (``SpindleOrientation``), the one a rigid tap's ``G331`` needs before it [K: SINUMERIK 840D sl
        Fundamentals, "Tapping without compensating chuck (G331, G332)": "the spindle must be switched to
        the position-controlled mode with SPOS" before G331, as quoted at
        https://en.cncforum.net/t/siemens-cnc-milling-g331-g332-codes-thread-interpolation/197]. A computed
        angle is kept as its expression; the positioning modes (``SPOS=DC(..)``, ``ACP(..)``, ``IC(..)``: the
        way round) and ``SPOS[n]`` (another spindle) are not modelled."""
        if SpindleOrientation.KEY in block.sections:
            raise self.error(block.line, pos + 1, "SPOS appears twice in one block")
        at = skip_blanks(code, start)
        if code[at:at + 3].upper() in ("DC(", "ACP", "ACN", "IC(", "AC("):
            raise Unmodelled("SPOS= with a positioning mode (DC, ACP, ACN, AC, IC)", pos)
        end, value = parse_expr(code, at)
        block.add(SpindleOrientation(value.value if isinstance(value, Num) else value))
        return end

    def opening_angle(self, block: Block, code: str, pos: int, start: int) -> int:
        """``AR=90``: the circle's opening angle (``arcs``), a number."""
        if SiemensArc.KEY in block.sections:
            raise self.error(block.line, pos + 1, "AR appears twice in one block")
        end, value = parse_expr(code, start)
        if not isinstance(value, Num):
            raise Unmodelled("AR= with a computed angle", pos)
        block.add(SiemensArc(value.value))
        return end

    def number(self, block: Block, code: str, pos: int, letter: str) -> int:
        n = len(code)
        start = pos + 1
        end = start
        if end < n and code[end] in "+-":
            end += 1
        digits = end
        end = decimal_end(code, end)
        number = code[start:end]
        if end == digits or number.lstrip("+-") == ".":
            raise self.error(block.line, pos + 1, f"address {letter.upper()} needs a value")
        block.words.append((letter, number))
        return end

    def value(self, block: Block, code: str, pos: int, start: int, letter: str,
              modes: list[tuple[str, str, int]]) -> int:
        """``X=10``, ``X=R1*2``, ``X=AC(10)``; ``T="DRILL"`` (``tool``); any other ``"string"`` is not
        modelled."""
        at = skip_blanks(code, start)
        if code[at:at + 1] == '"':
            if letter.upper() == "T":
                return self.tool(block, code, at)
            raise Unmodelled(f"{letter.upper()}=\"..\" (a name as the value)", pos)
        head = code[at:at + 3].upper()
        mode = ""
        if head in ("AC(", "IC("):
            mode = head[:2]
            modes.append((letter.upper(), mode, pos))
            at += 2
        if code[at:at + 3].upper() in ("DC(", "ACP", "ACN"):
            raise Unmodelled(f"{letter.upper()}={code[at:at + 3].upper().rstrip('(')}() (rotary positioning)", pos)
        end, value = parse_expr(code, at)
        text = code[at:end].strip()
        if mode:
            text = text[1:-1].strip() if text.startswith("(") and text.endswith(")") else text
        if isinstance(value, Num) and plain_number(text):
            block.words.append((letter, text))
        else:
            block.words.append((letter, text))
            block.values[letter.upper()] = value
        return end

    def distance_modes(self, block: Block, modes: list[tuple[str, str, int]]) -> None:
        """``=AC()``/``=IC()`` as plain values where the block's own G90/G91 means the same (and ``IC`` on a
        centre, incremental by default); else the per-address mode is not modelled."""
        codes = {num.lstrip("0") for letter, num in block.words if letter in "Gg"}
        for letter, mode, pos in modes:
            if letter in "IJK" and mode == "IC":
                continue
            if letter in "XYZABC" and (mode == "AC" and "90" in codes or mode == "IC" and "91" in codes):
                continue
            raise Unmodelled(f"{letter}={mode}(..) (a per-address distance mode; written plain in a block "
                             f"with the same G90/G91 it is read)", pos)


def _strip_comment(text: str) -> tuple[str, str | None]:
    """The code before ``;`` (outside a ``"string"``) blanked to the line's length, and the comment."""
    if ";" not in text:
        return text, None
    quoted = False
    for i, c in enumerate(text):
        if c == '"':
            quoted = not quoted
        elif c == ";" and not quoted:
            return text[:i] + " " * (len(text) - i), text[i + 1:]
    return text, None
