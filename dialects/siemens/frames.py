"""SINUMERIK programmable frame statements read into the neutral ``FrameChange`` (``chain`` rules, whose
meaning is in ``postproc.frames.frame``): ``TRANS``/``ATRANS``, ``ROT``/``AROT``, ``SCALE``/``ASCALE``,
``MIRROR``/``AMIRROR``.

What each takes [K: SINUMERIK ONE NC programming 12/2019 p.309 and p.316; 808D programming manual 01/2014
p.56-58]:

* ``TRANS X.. Y.. Z..`` / ``ATRANS ..``: offsets (``X10`` or ``X=10``);
* ``ROT RPL=..`` / ``AROT RPL=..``: an angle in degrees in the active plane; ``ROT X..`` (or ``Y``, ``Z``):
  about that geometry axis. Angles about more than one axis turn in an order set by machine data
  (MD10600 FRAME_ANGLE_INPUT_MODE: RPY Z, Y', X'' or Euler Z, X', Z'') [K: ONE p.309]: not modelled;
* ``SCALE X.. Y.. Z..`` / ``ASCALE ..``: factors (an axis not named: 1); a negative factor is not
  modelled [?: whether it mirrors];
* ``MIRROR X0 ..`` / ``AMIRROR ..``: the axes whose direction turns over ("Value: freely selectable" [K]);
* the replacing statement alone (``TRANS``, ``ROT``, ``SCALE``, ``MIRROR``) clears the programmable frame
  [K: 808D p.56 "without values: clears old instructions for offset, rotation, scaling factor, mirroring"].

The first incremental move on an axis a statement moved is refused (``chain`` rules), naming the setting that
decides whether it also travels the change (``INCREMENT_SETTING``, ``FrameChange.increment_setting``).

A statement is alone in its block [K: ONE p.309 "Frame statements must be programmed in a separate NC
block"]. Computed values (``TRANS X=R1``), axes other than X, Y, Z, an additive statement without values
and what is listed as not modelled raise ``Unmodelled``: the block is kept verbatim, refused elsewhere by
name.
"""

from __future__ import annotations

from typing import Final

from postproc.errors import Location, ParseError
from postproc.ir.expr import Expr, Num
from postproc.frames.section import CHAIN, FrameChange
from postproc.isg_family.expressions import Unmodelled
from postproc.rs274.expressions import skip_blanks

from .expressions import parse_expr, plain_number

STATEMENTS: Final = {
    "TRANS": "local", "ATRANS": "local_add", "ROT": "rotate", "AROT": "rotate_add",
    "SCALE": "scale", "ASCALE": "scale_add", "MIRROR": "mirror", "AMIRROR": "mirror_add",
}
"""Frame statement -> the neutral kind it is read as."""
INCREMENT_SETTING: Final = "setting data SD42440 (FRAME_OFFSET_INCR_PROG)"
"""Whether the first incremental move on an axis a frame change moved also travels the change: SD42440
FRAME_OFFSET_INCR_PROG, 1 (the default) it does, 0 only the increment; so for a settable frame's change (G54...)
too [K: 840D Function Manual K2 08/2005 1.3 "Frames with G91"]. The setting is not in the set-up, so the
simulation refuses such a move (``postproc.frames.commands.pending``) and names it."""
_FACTOR: Final = {"X": "I", "Y": "J", "Z": "K"}
_ABOUT: Final = {"X": "A", "Y": "B", "Z": "C"}


def read_frame(word: str, code: str, pos: int, end: int, file: str, line: int) -> FrameChange:
    """The statement ``word`` at ``code[pos:end]`` and its values up to the end of the code."""
    kind = STATEMENTS[word]
    values: dict[str, float] = {}
    n = len(code)
    at = skip_blanks(code, end)
    while at < n:
        if code[at:at + 3].upper() == "RPL" and word in ("ROT", "AROT"):
            letter, start = "RPL", at + 3
        else:
            letter, start = code[at].upper(), at + 1
            if letter not in "XYZ" or code[start:start + 1].isalpha() or code[start:start + 1] == "_":
                raise Unmodelled(f"{word} with other than X, Y, Z" + (" or RPL" if kind.startswith("rot") else ""), at)
        if letter in values:
            raise ParseError(f"{letter} appears twice in {word}", Location(file, line, at + 1))
        equals = skip_blanks(code, start)
        if code[equals:equals + 1] == "=":
            start = equals
        elif letter == "RPL":
            raise ParseError("RPL takes '=': RPL=30", Location(file, line, start + 1))
        stop, value = parse_expr(code, start + 1 if code[start:start + 1] == "=" else start)
        if not isinstance(value, Num) or code[start:start + 1] != "=" and not plain_number(code[start:stop].strip()):
            raise Unmodelled(f"{word} with computed values", at)
        values[letter] = value.value
        at = skip_blanks(code, stop)
    return FrameChange(kind, _words(word, kind, values, pos), CHAIN, "siemens", code[pos:].strip(),
                       increment_setting=INCREMENT_SETTING)


def _words(word: str, kind: str, values: dict[str, float], pos: int) -> dict[str, float | Expr]:
    if not values and kind.endswith("_add"):
        raise Unmodelled(f"{word} without values", pos)
    if kind.startswith("local") or kind.startswith("mirror"):
        return dict(values)
    if kind.startswith("scale"):
        if any(v <= 0.0 for v in values.values()):
            raise Unmodelled(f"{word} with a factor of 0 or below", pos)
        return {_FACTOR[a]: v for a, v in values.items()}
    turning = {a: v for a, v in values.items() if v != 0.0}
    if "RPL" in values and len(values) > 1:
        raise Unmodelled(f"{word} with RPL and axis angles together", pos)
    if len(turning) > 1:
        raise Unmodelled(f"{word} about more than one axis (their order is machine data MD10600)", pos)
    if "RPL" in values:
        return {"R": values["RPL"]}
    return {_ABOUT[a]: v for a, v in turning.items()}


