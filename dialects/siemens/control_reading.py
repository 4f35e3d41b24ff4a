"""Reading SINUMERIK control statements for the reader's per-file state (``reader._State``, which inherits
them): loops, conditions and jumps, with the checks made when the file ends.

``IF``/``ELSE``/``ENDIF``, ``WHILE``/``ENDWHILE``, ``FOR``/``TO``/``ENDFOR``, ``REPEAT``/``UNTIL``,
``LOOP``/``ENDLOOP`` (liufang-robot SPEC; Job planning p.107 [K]); ``GOTOF``/``GOTOB``/``GOTO``/``GOTOC``
to a label or a block number, alone or after ``IF cond``. A label must be unique in its file and a
``GOTOF``/``GOTOB`` target must lie in its direction (checked when the file ends): the neutral jump
searches forward, then from the start, which is then each of them exactly. The block number may be
written bare (``GOTOF 90``): the jump destination is "a main block or subblock number (e.g.: 200, N300)"
[K: SINUMERIK 840D sl Programming Manual Fundamentals, "Program jumps to jump markers"; main blocks are
numbered ``:200``, so the bare form names one; wording recalled, not re-read here]. ``GOTOC`` jumps as
``GOTO`` but suppresses alarm 14080 (jump destination not found): a missing target goes on with the
next block [K: same section] (the neutral jump's ``fallthrough``).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING

from postproc.interp.control import Do, Else, EndFor, EndIf, EndWhile, For, Goto, GotoLabel, If, Until, While
from postproc.errors import ParseError
from postproc.ir.expr import Expr, Num
from postproc.ir import Section
from postproc.isg_family.expressions import Unmodelled
from postproc.rs274.expressions import skip_blanks

from .call_reading import NAME_START
from .expressions import name_at, parse_expr, parse_variable

OPENERS = {"IF": "ENDIF", "WHILE": "ENDWHILE", "FOR": "ENDFOR", "REPEAT": "UNTIL", "LOOP": "ENDLOOP"}
"""The words that open a construct, and the word that closes each."""
CLOSERS = {close: open_ for open_, close in OPENERS.items()}
JUMPS = ("GOTOF", "GOTOB", "GOTOC", "GOTO")


@dataclass
class Jump:
    """A jump as read, checked against the file's labels when it ends (``finish``)."""

    word: str
    target: str
    """A label's name (lower case) or ``N<number>``."""
    line: int
    col: int


class ControlReading:
    """The control-statement methods of the reader's state; it supplies the attributes and ``error``."""

    stack: list[tuple[str, str, int]]
    count: int
    labels: dict[str, list[int]]
    jumps: list[Jump]

    if TYPE_CHECKING:  # the reader's state defines it
        def error(self, line: int, col: int, message: str) -> ParseError: ...

    def open(self, word: str, line: int) -> str:
        self.count += 1
        label = str(self.count)
        self.stack.append((word, label, line))
        return label

    def close(self, word: str, line: int, col: int) -> str:
        opener = CLOSERS[word]
        if not self.stack or self.stack[-1][0] != opener:
            found = f" (the innermost open construct is {self.stack[-1][0]} from line {self.stack[-1][2]})" \
                if self.stack else ""
            raise self.error(line, col, f"{word} does not close an open {opener}{found}")
        return self.stack.pop()[1]

    def statement(self, code: str, pos: int, end: int, word: str, line: int) -> Section:
        col = pos + 1
        n = len(code)

        def done(at: int, section: Section) -> Section:
            at = skip_blanks(code, at)
            if at < n:
                raise self.error(line, at + 1, f"unexpected {code[at:].strip()[:20]!r} after {word}")
            return section

        if word in JUMPS:
            return done(*self.jump(code, end, word, line, None))
        if word == "IF":
            at, cond = parse_expr(code, end)
            after = skip_blanks(code, at)
            jump_end = name_at(code, after)
            jump = code[after:jump_end].upper()
            if jump in JUMPS:
                return done(*self.jump(code, jump_end, jump, line, cond))
            return done(at, If(self.open("IF", line), cond))
        if word == "ELSE":
            if not self.stack or self.stack[-1][0] != "IF":
                raise self.error(line, col, "ELSE outside IF ... ENDIF")
            return done(end, Else(self.stack[-1][1]))
        if word == "ENDIF":
            return done(end, EndIf(self.close(word, line, col)))
        if word == "WHILE":
            at, cond = parse_expr(code, end)
            return done(at, While(self.open(word, line), cond))
        if word == "ENDWHILE":
            return done(end, EndWhile(self.close(word, line, col)))
        if word == "LOOP":
            return done(end, While(self.open(word, line), Num(1.0)))
        if word == "ENDLOOP":
            return done(end, EndWhile(self.close(word, line, col)))
        if word == "REPEAT":
            if skip_blanks(code, end) < n:
                raise Unmodelled("REPEAT of a program section (REPEAT label P=n)", pos)
            return done(end, Do(self.open(word, line)))
        if word == "UNTIL":
            at, cond = parse_expr(code, end)
            return done(at, Until(self.close(word, line, col), cond))
        if word == "FOR":
            return self.for_loop(code, end, line)
        return done(end, EndFor(self.close(word, line, col)))  # ENDFOR

    def for_loop(self, code: str, end: int, line: int) -> Section:
        """``FOR R1=0 TO 10`` / ``FOR I=1 TO R2``: counting up by 1 while the counter is at most the end
        value [K: Job planning "FOR counter loop"; the counter is a variable or an R parameter]."""
        start = skip_blanks(code, end)
        at, counter = parse_variable(code, start)
        if counter.name is not None and counter.name.startswith("$"):
            raise self.error(line, start + 1, "a FOR counter is an R parameter or a user variable")
        at = skip_blanks(code, at)
        if code[at:at + 1] != "=":
            raise self.error(line, at + 1, "FOR needs '=': FOR R1=0 TO 10")
        at, first = parse_expr(code, at + 1)
        to = skip_blanks(code, at)
        if code[to:to + 2].upper() != "TO" or code[to + 2:to + 3] not in ("", " ", "\t", "(", "R", "r") \
                and code[to + 2:to + 3].isalnum():
            raise self.error(line, to + 1, "FOR needs TO: FOR R1=0 TO 10")
        at, last = parse_expr(code, to + 2)
        rest = skip_blanks(code, at)
        if rest < len(code):
            raise self.error(line, rest + 1, f"unexpected {code[rest:].strip()[:20]!r} after FOR")
        return For(self.open("FOR", line), counter, first, last, Num(1.0))

    def jump(self, code: str, end: int, word: str, line: int, cond: Expr | None) -> tuple[int, Section]:
        at = skip_blanks(code, end)
        stop = name_at(code, at)
        target = code[at:stop]
        if not target:
            raise self.error(line, at + 1, f"{word} needs a label or a block number")
        fallthrough = word == "GOTOC"  # alarm 14080 suppressed: a missing target goes on with the next block
        digits = target[1:] if target[:1] in "Nn" else target
        if digits.isdigit():  # N300 or a bare 200: a block number (main block ``:200`` or ``N200``) [K]
            key = f"N{int(digits)}"
            section: Section = Goto(Num(float(int(digits))), cond, fallthrough)
        elif target[:1] in NAME_START:
            key = target.lower()
            section = GotoLabel(key, cond, fallthrough)
        else:
            raise self.error(line, at + 1, f"{word} needs a label or a block number, not {target!r}")
        self.jumps.append(Jump(word, key, line, at + 1))
        return stop, section

    def finish(self) -> list[ParseError]:
        """The constructs left open and the jumps whose target is missing, twice there or the wrong way."""
        errors = [self.error(line, 1, f"{word} is never closed ({OPENERS[word]} missing)")
                  for word, _, line in self.stack]
        for jump in self.jumps:
            lines = self.labels.get(jump.target, [])
            shown = jump.target.upper() if jump.target.startswith("N") else jump.target
            if len(lines) > 1:
                errors.append(self.error(jump.line, jump.col, f"{jump.word} {shown}: the target is on more than "
                                                              f"one line ({', '.join(map(str, lines))})"))
            elif not lines and jump.word == "GOTOC":
                continue  # GOTOC: the control suppresses alarm 14080 and goes on with the next block
            elif not lines:
                errors.append(self.error(jump.line, jump.col, f"{jump.word} {shown}: no such target in this file"))
            elif jump.word == "GOTOF" and lines[0] <= jump.line:
                errors.append(self.error(jump.line, jump.col, f"GOTOF {shown}: the target (line {lines[0]}) is not "
                                                              f"after the jump (GOTOF searches forward)"))
            elif jump.word == "GOTOB" and lines[0] > jump.line:
                errors.append(self.error(jump.line, jump.col, f"GOTOB {shown}: the target (line {lines[0]}) is not "
                                                              f"before the jump (GOTOB searches backward)"))
        return errors
