"""The ``--transform`` text: a strict little language for moving a whole program, read into one affine map.

Operations, applied in the order written and separated by ``;``::

    translate DX,DY[,DZ]
    rotate DEG [about C1,C2] [in xy|zx|yz]      counter-clockwise in the plane (default xy)
    mirror AXES [about V[,V...]]                 AXES is x, y, z or several (xy): each coordinate turns over
    scale S[,SY,SZ] [about X,Y[,Z]]              one factor, or one per axis (no zero; a negative one mirrors)

Lengths are millimetres (the unit of ``toolpath`` and ``verify``), angles degrees. Anything else (an unknown
word, a missing or extra number, a non-finite number) is a ``UsageError`` naming the operation: the text
never reaches a program, only the numbers read from it do.
"""

from __future__ import annotations

import math
import re
from typing import Final

from ..errors import UsageError
from ..frames.affine import INDEX, XYZ, Affine, about, diagonal, rotation, translation
from ..records import record

_NUMBER: Final = r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?\Z"
"""Compiled where first used (``--transform``), not at every start."""
_PLANES: Final = {"xy": ("X", "Y"), "zx": ("Z", "X"), "yz": ("Y", "Z")}
SYNTAX: Final = ("translate DX,DY[,DZ] | rotate DEG [about C1,C2] [in xy|zx|yz] | mirror x|y|z|xy.. [about V,..] | "
                 "scale S[,SY,SZ] [about X,Y[,Z]], joined by ';'")


@record(frozen=True, slots=True)
class ProgramTransform:
    """A parsed ``--transform``: the map from the program's work coordinates to the output's (mm)."""

    text: str
    """As the user wrote it (for messages and the output's comment)."""
    map: Affine


def parse_transform(text: str) -> ProgramTransform:
    """Read ``text`` (see the module docstring) into one map; a ``UsageError`` for anything else."""
    result = Affine()
    steps = [part.strip() for part in text.split(";")]
    if not any(steps):
        raise UsageError(f"--transform is empty: expected {SYNTAX}")
    for step in steps:
        if not step:
            raise UsageError(f"--transform {text!r}: an empty operation between ';' (expected {SYNTAX})")
        result = result.then(_operation(step))
    return ProgramTransform(text, result)


def _operation(step: str) -> Affine:
    words = step.split()
    verb, args = words[0].lower(), words[1:]
    if verb == "translate":
        values = _numbers(_only(args, 1, step)[0], 2, 3, step)
        return translation((*values, 0.0)[:3] if len(values) == 2 else values)
    if verb == "rotate":
        return _rotate(args, step)
    if verb == "mirror":
        return _mirror(args, step)
    if verb == "scale":
        return _scale(args, step)
    raise UsageError(f"--transform: unknown operation {words[0]!r} in {step!r} (expected {SYNTAX})")


def _rotate(args: list[str], step: str) -> Affine:
    if not args:
        raise UsageError(f"--transform {step!r}: rotate needs an angle in degrees")
    degrees = _numbers(args[0], 1, 1, step)[0]
    options = _options(args[1:], ("about", "in"), step)
    plane = options.get("in", "xy").lower()
    if plane not in _PLANES:
        raise UsageError(f"--transform {step!r}: the plane is xy, zx or yz, not {options['in']!r}")
    first, second = _PLANES[plane]
    centre = [0.0, 0.0, 0.0]
    if "about" in options:
        c1, c2 = _numbers(options["about"], 2, 2, step)
        centre[INDEX[first]], centre[INDEX[second]] = c1, c2
    return about(centre, rotation((first, second), degrees))


def _mirror(args: list[str], step: str) -> Affine:
    if not args:
        raise UsageError(f"--transform {step!r}: mirror needs the axes it turns over (x, y, z or several: xy)")
    axes = args[0].upper()
    if not axes or any(a not in XYZ for a in axes) or len(set(axes)) != len(axes):
        raise UsageError(f"--transform {step!r}: mirror takes the axes x, y and z, each once, not {args[0]!r}")
    options = _options(args[1:], ("about",), step)
    lines = _numbers(options["about"], len(axes), len(axes), step) if "about" in options else (0.0,) * len(axes)
    centre = [0.0, 0.0, 0.0]
    for axis, line in zip(axes, lines):
        centre[INDEX[axis]] = line
    return about(centre, diagonal(tuple(-1.0 if a in axes else 1.0 for a in XYZ)))


def _scale(args: list[str], step: str) -> Affine:
    if not args:
        raise UsageError(f"--transform {step!r}: scale needs a factor (or one per axis: SX,SY,SZ)")
    factors = _numbers(args[0], 1, 3, step)
    if len(factors) == 2:
        raise UsageError(f"--transform {step!r}: scale takes one factor or three (SX,SY,SZ), not two")
    if any(f == 0.0 for f in factors):
        raise UsageError(f"--transform {step!r}: a scale factor of 0 flattens the program")
    per_axis = factors * 3 if len(factors) == 1 else factors
    options = _options(args[1:], ("about",), step)
    centre = (0.0, 0.0, 0.0)
    if "about" in options:
        given = _numbers(options["about"], 2, 3, step)
        centre = (given[0], given[1], given[2] if len(given) == 3 else 0.0)
    return about(centre, diagonal(per_axis))


def _options(args: list[str], allowed: tuple[str, ...], step: str) -> dict[str, str]:
    """``about 10,20 in xy`` -> {"about": "10,20", "in": "xy"}: each keyword once, each with one value."""
    options: dict[str, str] = {}
    for i in range(0, len(args), 2):
        key = args[i].lower()
        if key not in allowed or key in options:
            expected = " or ".join(repr(a) for a in allowed)
            raise UsageError(f"--transform {step!r}: unexpected {args[i]!r} (expected {expected}, each once)")
        if i + 1 >= len(args):
            raise UsageError(f"--transform {step!r}: {args[i]!r} needs a value")
        options[key] = args[i + 1]
    return options


def _only(args: list[str], count: int, step: str) -> list[str]:
    if len(args) != count:
        raise UsageError(f"--transform {step!r}: expected {SYNTAX}")
    return args


def _numbers(text: str, least: int, most: int, step: str) -> tuple[float, ...]:
    """``least`` to ``most`` comma-separated finite numbers."""
    parts = text.split(",")
    if not least <= len(parts) <= most:
        many = str(least) if least == most else f"{least} to {most}"
        raise UsageError(f"--transform {step!r}: {text!r} should be {many} comma-separated numbers")
    values = []
    for part in parts:
        if not re.match(_NUMBER, part):
            raise UsageError(f"--transform {step!r}: {part!r} is not a number")
        value = float(part)
        if not math.isfinite(value) or abs(value) > 1e9:
            raise UsageError(f"--transform {step!r}: {part!r} is out of range")
        values.append(value)
    return tuple(values)


def transform_argument(text: str) -> ProgramTransform:
    """``parse_transform`` as an argparse ``type``: bad text is a usage error before any file is opened."""
    import argparse
    try:
        return parse_transform(text)
    except UsageError as err:
        raise argparse.ArgumentTypeError(err.message) from None
