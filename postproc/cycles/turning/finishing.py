"""G70: the finishing cycle, once along the profile ns..nf with the profile's own F."""

from __future__ import annotations

from dataclasses import replace
from typing import Sequence

from .profile import Point, Seg, TurnMove, check_chain, contour_moves, drop_still, finite


def finishing(start: Point, profile: Sequence[Seg], feed: float | None = None) -> list[TurnMove]:
    """``G70 P(ns) Q(nf)`` from ``start`` (point A, where ns begins), back to ``start``.

    ``profile``: the blocks ns..nf, ns starting at ``start``. ``feed``: the F modal when G70 runs,
    used for a block that neither programs nor inherits an F inside ns..nf (``Seg.feed`` None).

    Sequence (DIALECTS.md 2.2 [V] for the F/S/T rule; the return [K], as GSK's manual describes G70):
    each block as programmed (G00 blocks rapid, G01/G02/G03 at the block's F), then a rapid to A.
    """
    finite("finishing cycle", x0=start[0], z0=start[1], feed=feed)
    check_chain(profile, start, "finishing cycle")
    own_feed = [seg if seg.feed is not None else replace(seg, feed=feed) for seg in profile]
    moves = contour_moves(own_feed, None, "finish")
    moves.append(TurnMove("rapid", start[0], start[1], note="return"))
    return drop_still(moves, start)

