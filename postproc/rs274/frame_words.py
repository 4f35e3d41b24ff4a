"""The RS274 family base's reading of frame codes: how its reader turns a frame code (its table's kind ``frame``) and the words it takes into a
``FrameChange``.

Words per kind (what is not taken stays for the rest of the block, which refuses a word nobody takes):
- ``local``, ``origin``, ``mirror``, ``mirror_off``: axis words (at least one);
- ``origin_clear``, ``origin_suspend``, ``origin_restore``, ``rotate_off``, ``scale_off``: none;
- ``rotate``: the centre on the active plane's two axes (either may be omitted: the current point) and
  ``R``, the angle. Fanuc: with a decimal point R is in degrees, without it in 0.001 degree [V: Fanuc
  15i/16i operator's manuals, "when a decimal fraction is used ... the 1s digit corresponds to degree
  units"; K: the least input increment 0.001 degree of parameter 5410];
- ``scale``: the centre (axis words, any omitted: the current point) and ``P``, or ``I J K`` per axis,
  in 0.001 (no decimal point) [K: Fanuc 0i-MF operator's manual, scaling; parameter 5400#7 SCR = 0].
"""

from __future__ import annotations

from typing import Any, Final

from ..context import Context
from ..errors import ProgramError
from ..ir.expr import Expr
from ..ir import AXES, Block
from ..frames.section import LAYERED, ROTATE_FIRST, FrameChange

AXIS_WORDS: Final = frozenset(AXES)
_NO_WORDS: Final = frozenset(("origin_clear", "origin_suspend", "origin_restore", "rotate_off", "scale_off", "polar",
                              "polar_off"))
_PER_THOUSAND: Final = 0.001
NO_ANGLE: Final = "parameter 5410"
"""Where a G68 without R takes its angle under Fanuc's rules (``LAYERED``) [K: Fanuc operator's manuals, coordinate
system rotation: an omitted R is the angle set in parameter 5410]: the simulation, which does not know it, names it
in its error (``FrameChange.omitted``, ``postproc.frames.commands``)."""


def read_frame(block: Block, ctx: Context, kind: str, code: str, values: dict[str, Any], used: set[str],
               rules: str, family: str, column: int) -> FrameChange:
    """The ``FrameChange`` of frame code ``code`` (as written, e.g. 'G68'); ``used`` gets the letters it
    takes. ``column`` locates the code for errors."""
    at = ctx.at(block, column)
    if ctx.state.cycle is not None:
        raise ProgramError(f"{code} while a canned cycle is active is not read [?]: cancel the cycle first", at)
    words: dict[str, float | Expr] = {}
    omitted = ""
    if kind in _NO_WORDS:
        pass
    elif kind in ("local", "origin", "mirror", "mirror_off"):
        words = {k: v for k, v in values.items() if k in AXIS_WORDS}
        if not words:
            raise ProgramError(f"{code} needs axis words", at)
    elif kind == "rotate":
        plane = ctx.state.plane
        words = {k: v for k, v in values.items() if k in plane}
        third = {"XY": "Z", "ZX": "Y", "YZ": "X"}[plane]
        if rules == ROTATE_FIRST and third in values:
            # [V] Beckhoff TF5200 diagnosis ID 22156: only the plane's two main axes give the centre
            raise ProgramError(f"{code} takes the centre on the plane's two axes: {third} belongs in the next block", at)
        if "R" in values:
            words["R"] = _angle(block, values["R"], rules)
        elif rules == LAYERED:
            omitted = NO_ANGLE
    elif kind == "scale":
        words = {k: v for k, v in values.items() if k in "XYZ"}
        for letter in "PIJK":
            if letter in values:
                words[letter] = _factor(block, ctx, letter, values[letter], rules)
        if "P" in words and any(k in words for k in "IJK"):
            raise ProgramError(f"{code} takes either P (every axis) or I, J, K (per axis)", at)
        if not any(k in words for k in "PIJK"):
            raise ProgramError(f"{code} without P or I, J, K takes its factor from a parameter, not known "
                               "here: program P", at)
    for letter in words:
        used.add(letter)
    text = " ".join(letter + number for letter, number in block.words
                    if letter.upper() in words or (letter.upper() == "G" and f"G{number}" == code))
    return FrameChange(kind, words, rules, family, text, omitted)


def _angle(block: Block, value: Any, rules: str) -> float | Expr:
    """G68's R in degrees."""
    if isinstance(value, Expr):
        return value
    if rules != LAYERED:
        return float(value)
    written = _text(block, "R")
    return float(written) if "." in written else int(written) * _PER_THOUSAND


def _factor(block: Block, ctx: Context, letter: str, value: Any, rules: str) -> float | Expr:
    """A scale factor: a whole number of 0.001."""
    if isinstance(value, Expr):
        return value
    written = _text(block, letter)
    if "." in written:
        raise ProgramError(f"a scale factor {letter} is written without a decimal point, in 0.001 [K: Fanuc "
                           "parameter 5400#7 SCR = 0]", ctx.at(block, ctx.column_of(block, letter)))
    return int(written) * _PER_THOUSAND


def _text(block: Block, up: str) -> str:
    for letter, number in block.words:
        if letter.upper() == up:
            return number
    return ""
