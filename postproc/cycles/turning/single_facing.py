"""G94: the facing single cycle (Fanuc T / GSK 980TDc, G-code system A): G90 with X and Z swapped."""

from __future__ import annotations

from postproc.errors import ProgramError

from .profile import Point, TurnMove, drop_still, finite, sign


def single_facing(start: Point, x: float, z: float, r: float = 0.0,
                  feed: float | None = None) -> list[TurnMove]:
    """The four sides of ``G94 X(U) Z(W) R F`` from ``start`` = (x0, z0), back to ``start``.

    ``x``, ``z``: the cut's end point (radius, absolute). ``r``: taper in Z, the Z at the start of the
    cut (at x0) minus the Z at its end (at x), signed, so the cut runs from (x0, z + r) to (x, z).
    ``feed``: F of the cycle (None: the modal feed).

    Sequence (DIALECTS.md 2.2, [K]): 1 rapid Z to z + r; 2 feed to (x, z); 3 feed Z back to z0;
    4 rapid X back to x0. Moves of zero length are left out. R against the direction of W with
    |R| > |W| is refused, as for G90.
    """
    x0, z0 = start
    finite("facing single cycle", x=x, z=z, r=r, feed=feed, x0=x0, z0=z0)
    w = z - z0
    if r and sign(r) != sign(w) and abs(r) > abs(w) + 1e-9:
        raise ProgramError(f"facing single cycle: the taper R{r:g} exceeds the Z travel {abs(w):g} against its direction")
    moves = [
        TurnMove("rapid", x0, z + r, note="approach"),
        TurnMove("feed", x, z, feed=feed, note="cut"),
        TurnMove("feed", x, z0, feed=feed, note="turn out"),
        TurnMove("rapid", x0, z0, note="return"),
    ]
    return drop_still(moves, start)
