"""G92: the threading single cycle (Fanuc T / GSK 980TDc, G-code system A), with its chamfer pull-out."""

from __future__ import annotations

from postproc.errors import ProgramError

from .profile import Point, TurnMove, drop_still, finite, sign


def thread_end(cycle: str, x_start: float, z_start: float, x: float, z: float, x_out: float,
               lead: float, r: int) -> list[TurnMove]:
    """The threading feed from (x_start, z_start) to (x, z), ending with the 45-degree pull-out of
    ``r`` tenths of the lead when ``r`` > 0: from the thread line a distance g = r * lead / 10 before
    ``z`` to (x + g toward ``x_out``, z). Shared by G92 and G76."""
    if not 0 <= r <= 99:
        raise ProgramError(f"{cycle}: the chamfer {r} (tenths of the lead) must be 0 to 99")
    if r == 0:
        return [TurnMove("feed", x, z, feed=lead, note="thread")]
    g = r * lead / 10.0
    length = abs(z - z_start)
    out = sign(x_out - x)
    if g > length + 1e-9:
        raise ProgramError(f"{cycle}: the chamfer {g:g} is longer than the thread ({length:g})")
    if out == 0 or g > abs(x_out - x) + 1e-9:
        raise ProgramError(f"{cycle}: the chamfer {g:g} pulls out beyond the start point's X")
    t = 1.0 - g / length  # where the pull-out starts, as a fraction of the thread's length
    xc = x_start + t * (x - x_start)
    zc = z_start + t * (z - z_start)
    return [TurnMove("feed", xc, zc, feed=lead, note="thread"),
            TurnMove("feed", x + out * g, z, feed=lead, note="thread chamfer")]


def single_threading(start: Point, x: float, z: float, lead: float, r: float = 0.0,
                     chamfer: int = 0) -> list[TurnMove]:
    """The four sides of ``G92 X(U) Z(W) R F`` from ``start`` = (x0, z0), back to ``start``.

    ``x``, ``z``: the thread's end (radius, absolute). ``lead``: F, the lead per revolution (every
    ``thread`` move is spindle-synchronised at it). ``r``: R, the radius at the thread's start
    minus the radius at its end (signed). ``chamfer``: the pull-out in tenths of the lead (Fanuc
    parameter 5130 / GSK's thread chamfer with M23; 0 = square exit), at 45 degrees.

    Sequence (DIALECTS.md 2.2, [K]): 1 rapid X to x + r; 2 thread to (x, z), or with a chamfer
    g = chamfer * lead / 10: thread to where the thread line is g before z, then thread at 45 degrees
    to (x + g toward x0, z); 3 rapid X back to x0; 4 rapid Z back to z0.
    """
    x0, z0 = start
    finite("threading single cycle", x=x, z=z, lead=lead, r=r, x0=x0, z0=z0)
    if lead <= 0.0:
        raise ProgramError(f"threading single cycle: the lead F must be positive, not {lead:g}")
    u = x - x0
    if r and sign(r) != sign(u) and abs(r) > abs(u) + 1e-9:
        raise ProgramError(f"threading single cycle: the taper R{r:g} exceeds the X travel {abs(u):g} (radius) against "
                           "its direction")
    xs = x + r
    moves = [TurnMove("rapid", xs, z0, note="approach")]
    moves += thread_end("threading single cycle", xs, z0, x, z, x0, lead, chamfer)
    moves += [TurnMove("rapid", x0, z, note="pull out"), TurnMove("rapid", x0, z0, note="return")]
    return drop_still(moves, start)
