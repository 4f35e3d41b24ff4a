"""verify's arcs as ``postproc.geometry.arc_paths`` paths: a pair of normalised arc moves (``Move``, each run of arcs on
one circle merged) compared by the largest distance between the paths their controllers cut. Interpreted (the
comparison, compiled, calls it only for a pair of arcs whose centres differ)."""

from __future__ import annotations

from ..geometry.arc_paths import arc_path, deviation
from ..geometry.arcs import PLANE_INDEX
from .normal_move import Move


def arc_deviation(a: Move, b: Move, floor: float) -> float:
    """The largest distance between the arc paths ``a`` and ``b`` (same plane and direction: the comparison has
    checked), or some value of at most ``floor`` where it is at most that (``postproc.geometry.arc_paths.deviation``)."""
    plane = a.plane or "XY"
    i, j, _ = PLANE_INDEX[plane]
    inside = ("xyz"[i], "xyz"[j])
    off = sorted({k for k in (*a.start, *a.end, *b.start, *b.end) if k not in inside})
    assert a.centre is not None and b.centre is not None
    return deviation(arc_path(a.start, a.end, a.centre, plane, a.sweep, a.kind == "cw", off),
                     arc_path(b.start, b.end, b.centre, plane, b.sweep, b.kind == "cw", off), floor)
