"""An arc carried by a linear map: one computation for a frame's evaluation (``postproc.frames.lowering``) and a
``--transform`` (``postproc.transforms.carry``), which each had a copy of it.

The arc's end point is carried as any point (by the caller). Its centre offsets I/J/K are a vector, carried by
the map's linear part alone; its radius R is scaled by the map's factor in the plane; a map that mirrors the
plane turns its direction over (G2 <-> G3). A map that takes the arc out of its plane or scales its two axes
unequally makes it no arc (``Affine.arc_factor``): the caller refuses it in its own words.
"""

from __future__ import annotations

from typing import Final

from ..ir.expr import Binary, Expr, Num
from ..ir import Motion
from .affine import EXACT, INDEX, Affine
from .frame import PLANE_AXES

TURNED: Final = {"cw": "ccw", "ccw": "cw"}
"""An arc's direction in a mirrored plane."""


def carried_arc(fmap: Affine, plane: str, m: Motion, out: dict[str, float | Expr], mode: str) -> Motion | None:
    """The arc ``m`` (direction ``mode``) in ``plane`` ("XY", "ZX", "YZ") under ``fmap``, its end ``out`` (carried
    by the caller); None where the map makes it no arc. A computed offset or radius stays an expression
    (``combination``)."""
    axes = PLANE_AXES[plane]
    found = fmap.arc_factor(axes)
    if found is None:
        return None
    factor, turned = found
    centre: dict[str, float | Expr] | None = None
    radius: float | Expr | None = None
    if m.center is not None:
        fm = fmap.m
        centre = {}
        for a in axes[:2]:
            i = INDEX[a]
            centre[a] = combination([(fm[3 * i + INDEX[b]], value) for b, value in m.center.items()
                                     if abs(fm[3 * i + INDEX[b]]) > EXACT], 0.0)
    elif m.radius is not None:
        radius = combination([(factor, m.radius)], 0.0)
    return Motion(TURNED[mode] if turned else mode, out, centre, radius)


def combination(terms: list[tuple[float, float | Expr]], constant: float) -> float | Expr:
    """``sum(c * x) + constant``: a number when every ``x`` is one, else the expression (a factor of 1 and
    a zero constant left out, so an unturned word stays as written)."""
    total = constant
    expr: Expr | None = None
    for c, x in terms:
        if not isinstance(x, Expr):
            total += c * x
            continue
        term: Expr = x if c == 1.0 else Binary("mul", Num(c), x)
        expr = term if expr is None else Binary("add", expr, term)
    if expr is None:
        return total
    return expr if total == 0.0 else Binary("add", expr, Num(total))
