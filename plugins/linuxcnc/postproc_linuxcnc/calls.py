"""LinuxCNC's Fanuc-style subprogram calls: ``M98 P<n> [L<k>]`` and ``M99``, read from a lexed line into a
``Call(kind="sub")`` or a ``Return()`` (the program start ``O<n>`` is read by ``oword``).

What rs274 (LinuxCNC 2.9) does, checked line by line with the packaged interpreter:

- ``M98 P<n> L<k>`` runs the subprogram ``O<n>`` k times (``L0``: not at all, the program need not exist),
  sharing the caller's ``#1``-``#30``; blanks anywhere (``M 9 8 P 1``) and leading zeros (``P0001``) read.
  There is no packed ``P`` form: ``P00032100`` is program 32100.
- ``M98`` stands alone on its line (with its P and L, after an N): ``G0 X1 M98 P1``, ``F10 M98 P1``,
  ``G91 M98 P1`` are "Unknown m code used: M98". Without P: "Found 'm98' code with no P-word"; a P or L
  that is not a whole number: "Non integer value for integer"; ``L-1``: "Negative l word used".
- ``M99`` stands alone too: ``M99 P5`` is refused ("Unexpected character after O-word" in a subprogram,
  "P word with no ... to use it" in the main program), ``G0 X1 M99`` in a subprogram is an rs274 error
  ("Reached convert_stop() from M99"); a comment may follow.

So the words leave ``block.words`` (the section holds them) and every other word on such a line is a
located error. A computed ``M#1`` is not a call: the block syntax refuses an M98/M99 it meets.
"""

from __future__ import annotations

from postproc.interp.control import Call, Return
from postproc.errors import Location, ParseError
from postproc.ir.expr import Expr, Num
from postproc.ir import Block

INTEGER_TOLERANCE = 0.0001
"""How far from a whole number rs274 still reads an integer word (``read_integer_value``)."""


def _code(letter: str, num: str) -> str | None:
    if letter not in "Mm" or not num.isdigit():
        return None
    value = num.lstrip("0")
    return value if value in ("98", "99") else None


def read_call(block: Block, file: str, code: str) -> None:
    """Turn an ``M98``/``M99`` line's words into its control section (nothing for other lines).
    ``code`` is the line with its comments blanked out (for columns)."""
    found = [(i, c) for i, (letter, num) in enumerate(block.words) if (c := _code(letter, num)) is not None]
    if not found:
        return
    where = _Columns(file, block.line, code)
    at, number = found[0]
    name = "M" + number
    if len(found) > 1:
        raise ParseError(f"one M98 or M99 per line ({'M' + found[1][1]} follows {name})", where.of("M", 2))
    if "Control" in block.sections or "Assign" in block.sections or "BlockDelete" in block.sections:
        raise ParseError(f"{name} stands alone on its line in LinuxCNC", where.of("M"))
    taken: dict[str, tuple[str, Expr]] = {}
    for i, (letter, num) in enumerate(block.words):
        up = letter.upper()
        if i == at or (up == "N" and i == 0):
            continue
        if number == "98" and up in "PL":
            if up in taken:
                raise ParseError(f"address {up} appears twice in one block", where.of(up, 2))
            taken[up] = (num, _whole(block, up, num, where))
            continue
        if number == "99" and up == "P":
            raise ParseError("M99 P (a return to a block number) is not LinuxCNC: rs274 refuses it",
                             where.of("P"))
        raise ParseError(f"{name} stands alone on its line in LinuxCNC: {up}{num} cannot share it "
                         f"(rs274: Unknown m code used: M98)" if number == "98" else
                         f"M99 stands alone on its line in LinuxCNC: {up}{num} cannot share it", where.of(up))
    for up in taken:
        block.values.pop(up, None)
    block.words = [w for i, w in enumerate(block.words) if i == 0 and w[0] in "Nn" and i != at]
    if number == "99":
        block.add(Return())
        return
    if "P" not in taken:
        raise ParseError("M98 needs a program number P (rs274: Found 'm98' code with no P-word)", where.of("M"))
    program = taken["P"][1]
    repeat = taken["L"][1] if "L" in taken else None
    block.add(Call(str(int(program.value)) if isinstance(program, Num) else program, repeat=repeat))


def _whole(block: Block, up: str, num: str, where: "_Columns") -> Expr:
    value = block.values.get(up)
    if isinstance(value, Expr) and not _is_number(num):
        return value
    number = float(num)
    nearest = round(number)
    if abs(number - nearest) > INTEGER_TOLERANCE:
        raise ParseError(f"{up}{num} of M98 is not a whole number", where.of(up))
    if nearest < 0:
        what = "program number" if up == "P" else "repeat count"
        raise ParseError(f"M98 {up}{num}: a negative {what}", where.of(up))
    return Num(float(nearest))


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


class _Columns:
    """Columns of letters in a line, computed only when an error is raised."""

    __slots__ = ("file", "line", "code")

    def __init__(self, file: str, line: int, code: str) -> None:
        self.file = file
        self.line = line
        self.code = code

    def of(self, letter: str, nth: int = 1) -> Location:
        upper = self.code.upper()
        at = -1
        for _ in range(nth):
            at = upper.find(letter, at + 1)
            if at < 0:
                return Location(self.file, self.line, 1)
        return Location(self.file, self.line, at + 1)
