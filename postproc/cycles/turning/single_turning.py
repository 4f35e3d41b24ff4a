"""G90: the OD/ID turning single cycle (Fanuc T / GSK 980TDc, G-code system A)."""

from __future__ import annotations

from postproc.errors import ProgramError

from .profile import Point, TurnMove, drop_still, finite, sign


def single_turning(start: Point, x: float, z: float, r: float = 0.0,
                   feed: float | None = None) -> list[TurnMove]:
    """The four sides of ``G90 X(U) Z(W) R F`` from ``start`` = (x0, z0), back to ``start``.

    ``x``, ``z``: the cut's end point (radius, absolute; the caller resolves U/W and diameters).
    ``r``: taper, the radius at the start of the cut minus the radius at its end (signed), so the cut
    runs from (x + r, z0) to (x, z). ``feed``: F of the cycle (None: the modal feed).

    Sequence (DIALECTS.md 2.2, [K]): 1 rapid X to x + r; 2 feed to (x, z); 3 feed X back to x0;
    4 rapid Z back to z0. Moves of zero length are left out.
    A taper against the direction of U (R and U of opposite signs) is refused when |R| > |U/2|
    (Fanuc manual's restriction: the cut would start beyond the start point's X).
    """
    x0, z0 = start
    finite("turning single cycle", x=x, z=z, r=r, feed=feed, x0=x0, z0=z0)
    u = x - x0
    if r and sign(r) != sign(u) and abs(r) > abs(u) + 1e-9:
        raise ProgramError(f"turning single cycle: the taper R{r:g} exceeds the X travel {abs(u):g} (radius) against its "
                           "direction")
    moves = [
        TurnMove("rapid", x + r, z0, note="approach"),
        TurnMove("feed", x, z, feed=feed, note="cut"),
        TurnMove("feed", x0, z, feed=feed, note="face out"),
        TurnMove("rapid", x0, z0, note="return"),
    ]
    return drop_still(moves, start)
