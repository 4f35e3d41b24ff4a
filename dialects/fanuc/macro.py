"""Fanuc calls and returns: ``M98 P L`` (and the packed ``P``), ``M99 [P]``, ``G65 P L <arguments>``,
``G66``/``G67``, read from a lexed block's words into ``Call``/``Return``/``ModalCall``/``ModalCallCancel``.

The call's words leave ``block.words`` (the section holds them; the block's text still has them for a
lossless copy), so what stays is what runs before the call (``G01 X10. M98 P2000``: the move).

Choices where the manuals leave room (documented, tested):
- ``M98 P`` with more than 4 digits and no ``L`` is the packed form of the 0-series: the last 4 digits
  are the program, the ones before the repeat count (``P00032100`` = 3 x O2100).
- A ``G65``/``G66`` argument without a decimal point on an address that follows the decimal-point rule
  (X, Y, Z, ... R, Q) would be least input increments, whose size depends on the machine: it is an
  error unless it is 0 or the set-up says calculator input. Other addresses (D, E, F, H, M, S, T) take
  the value as written. Macro expressions count as having a decimal point.
"""

from __future__ import annotations

from postproc.context import Context
from postproc.interp.control import CONTROL, Call, ModalCall, ModalCallCancel, Return
from postproc.errors import ParseError
from postproc.ir.expr import Expr, Num
from postproc.ir import Block, Section
from postproc.rs274.block_syntax import DECIMAL_LETTERS

from .arguments import LETTER_LOCALS, LOCAL_LETTERS
from .call_codes import CALL_CODES as _CALL_CODES, makes_call

__all__ = ["LETTER_LOCALS", "LOCAL_LETTERS", "makes_call", "read_call"]


def _code(letter: str, num: str) -> tuple[str, str] | None:
    up = letter.upper()
    if up not in "GM" or not num.isdigit():
        return None
    key = (up, num.lstrip("0") or "0")
    return key if key in _CALL_CODES else None


def read_call(block: Block, ctx: Context) -> None:
    """Turn the block's call or return words into its control section (nothing if it has none)."""
    found: list[tuple[int, str]] = []
    for i, (letter, num) in enumerate(block.words):
        key = _code(letter, num)
        if key is not None:
            found.append((i, key[0] + key[1]))
    if not found:
        return
    if len(found) > 1:
        i = found[1][0]
        letter, num = block.words[i]
        raise ParseError(f"{letter}{num}: one call or return per block",
                         ctx.at(block, ctx.column_of(block, letter, num)))
    if CONTROL in block.sections:
        raise ParseError("a call and a macro statement in one block", ctx.at(block))
    at, code = found[0]
    words = block.words
    taken: dict[str, tuple[str, Expr]] = {}
    keep: list[tuple[str, str]] = []
    takes = _TAKES[code]
    for i, (addr, num) in enumerate(words):
        up = addr.upper()
        if i == at:
            continue
        if up in takes or (takes == "*" and up not in "NGO"):
            if up in taken:
                raise ParseError(f"address {up} appears twice in one block",
                                 ctx.at(block, ctx.column_of(block, up, nth=2)))
            taken[up] = (num, _value(block, ctx, up, num, code))
        elif takes == "*" and up == "G":
            raise ParseError(f"G{num} cannot share a block with {code}", ctx.at(block, ctx.column_of(block, "G", num)))
        else:
            keep.append((addr, num))
    for up in taken:
        block.values.pop(up, None)
    block.words = keep
    block.canonical = False  # its text is no longer its words (``Block.canonical``)
    block.add(_section(block, ctx, code, taken))


_TAKES = {"M98": "PL", "M99": "P", "G65": "*", "G66": "*", "G67": ""}
"""The words each code takes with it (``*``: every address but N, G, O: its arguments)."""


def _value(block: Block, ctx: Context, up: str, num: str, code: str) -> Expr:
    value = block.values.get(up)
    if isinstance(value, Expr):
        return value
    if up in "PL":
        if "." in num or num[:1] in "+-":
            raise ParseError(f"address {up} of {code} takes a whole number ({up}{num})",
                             ctx.at(block, ctx.column_of(block, up, num)))
        return Num(float(int(num)))
    if "." not in num and up in DECIMAL_LETTERS and float(num) != 0.0 \
            and ctx.setup.input.decimal_point != "calculator":
        raise ParseError(f"{code} argument {up}{num} has no decimal point: its value would be least input "
                         f"increments, which depend on the machine (write {up}{num}.)",
                         ctx.at(block, ctx.column_of(block, up, num)))
    return Num(float(num))


def _section(block: Block, ctx: Context, code: str, taken: dict[str, tuple[str, Expr]]) -> Section:
    if code == "M99":
        return Return(target=taken["P"][1] if "P" in taken else None)
    if code == "G67":
        return ModalCallCancel()
    if "P" not in taken:
        raise ParseError(f"{code} needs a program number P", ctx.at(block, ctx.column_of(block, code[0], code[1:])))
    p_text, p_value = taken.pop("P")
    repeat = taken.pop("L")[1] if "L" in taken else None
    name: str | Expr = p_value
    if isinstance(p_value, Num):
        digits = p_text.lstrip("+")
        if code == "M98" and repeat is None and len(digits) > 4:
            count = int(digits[:-4])
            repeat = Num(float(count)) if count > 1 else None  # P0000nnnn: once
            digits = digits[-4:]
        name = str(int(digits))
    if code == "M98":
        return Call(name, repeat=repeat)
    args = {LETTER_LOCALS[up]: value for up, (_, value) in taken.items()}
    if code == "G65":
        return Call(name, args, repeat, kind="macro")
    return ModalCall(name, args, repeat)
