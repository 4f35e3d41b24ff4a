"""``HOLES1`` (a row of holes) and ``HOLES2`` (a circle of holes): the modal cycle of ``MCALL`` run at each point.

Parameters [K: PGZ cycles manual 11/2006 6FC5398-3BP20-0BA0, 2.2 "Drilling patterns"; USERS-AND-SIEMENS.md 3.2]:

* ``HOLES1(SPCA, SPCO, STA1, FDIS, DBH, NUM)``: reference point (SPCA, SPCO), absolute in the plane; the row's
  angle STA1 to the abscissa (degrees); FDIS the distance from the reference point to the first hole and DBH
  between neighbouring holes (both without sign); NUM holes. Hole k (k = 0 ... NUM-1) lies at
  reference + (FDIS + k*DBH) * (cos STA1, sin STA1).
* ``HOLES2(CPA, CPC, RAD, STA1, INDA, NUM)``: centre (CPA, CPC), absolute; radius RAD (no sign); the first
  hole at the angle STA1 from the abscissa; INDA the angle from hole to hole (0: the NUM holes share the full
  circle, 360/NUM apart); NUM holes. Hole k lies at centre + RAD * (cos, sin)(STA1 + k*INDA).

The tool goes to each hole at rapid in the plane, at the level the cycle left it, and the cycle runs there
[K: the PGZ: the holes are approached with G0]; it ends over the last hole. ``HOLES1`` picks from which end
it starts by the tool's position [?: PGZ 2.2.1 says the order avoids idle travel; the exact rule is not
confirmed here]: read only when the tool stands nearer its first hole (every such rule then starts there),
kept verbatim otherwise, as a pattern without an active ``MCALL`` cycle is (what it does then is not
confirmed here [?]).

Read on the neutral IR as the active cycle's record made at each point (``postproc.patterns.resolve.cycle_at``,
the neutral hole pattern's own step), the points' expansions as the block's motion. The block carries the
first point's record marked ``expand``: every other dialect gets the exact moves, and the rest of the modal
cycle after it is expanded too (a native cycle there would have been cancelled by those moves).
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

from postproc.cycles.expansion import TooManyMoves
from postproc.cycles.resolve import active_cycle
from postproc.errors import ProgramError
from postproc.ir import CompoundMotion, Section
from postproc.patterns.resolve import cycle_at
from postproc.patterns.section import HolePattern
from postproc.xmlio import XAttr

from .cycles import MCALL_KEY, keep_verbatim

if TYPE_CHECKING:
    from postproc.context import Context
    from postproc.ir import Block

PARAMETERS = {"HOLES1": ("SPCA", "SPCO", "STA1", "FDIS", "DBH", "NUM"),
              "HOLES2": ("CPA", "CPC", "RAD", "STA1", "INDA", "NUM")}
MAX_HOLES = 10000
"""More holes in one call is a located error (hostile input; the set-up's movesPerBlock bounds the moves)."""
NEARER = 1e-9


class SiemensHoles(Section):
    """A ``HOLES1``/``HOLES2`` call as read, resolved against the modal state by the block syntax (``resolve``),
    which removes it."""

    XNAME = KEY = "SiemensHoles"
    __slots__ = ("name", "a", "b", "c", "d", "e", "num")
    XATTRS = (XAttr("name"), XAttr("a", float), XAttr("b", float), XAttr("c", float), XAttr("d", float),
              XAttr("e", float), XAttr("num", int))
    name: str
    a: float
    b: float
    c: float
    d: float
    e: float
    num: int

    def __init__(self, name: str, a: float, b: float, c: float, d: float, e: float, num: int) -> None:
        self.name, self.a, self.b, self.c, self.d, self.e, self.num = name, a, b, c, d, e, num


def read_holes(name: str, params: list[float | None]) -> SiemensHoles:
    """The call's section; a ``ValueError`` names a missing or wrong parameter."""
    names = PARAMETERS[name]
    if len(params) != len(names) or any(p is None for p in params):
        raise ValueError(f"{name} takes its {len(names)} parameters, each given: {name}({', '.join(names)})")
    a, b, c, d, e, num = (float(p or 0.0) for p in params)
    if not num.is_integer() or not 1 <= num <= MAX_HOLES:
        raise ValueError(f"{name}: NUM is a whole number of holes from 1 to {MAX_HOLES}, not {num:g}")
    if name == "HOLES1" and (d < 0 or e < 0):
        raise ValueError("HOLES1: FDIS and DBH have no sign")
    if name == "HOLES2" and c <= 0:
        raise ValueError("HOLES2: the radius RAD is positive")
    return SiemensHoles(name, a, b, c, d, e, int(num))


def hole_points(holes: SiemensHoles) -> list[tuple[float, float]]:
    """The holes in the order the parameters number them (the module's formulas)."""
    if holes.name == "HOLES1":
        u = _direction(holes.c)
        return [(holes.a + (holes.d + k * holes.e) * u[0], holes.b + (holes.d + k * holes.e) * u[1])
                for k in range(holes.num)]
    step = holes.e if holes.e != 0 else 360.0 / holes.num
    points = []
    for k in range(holes.num):
        u = _direction(holes.d + k * step)
        points.append((holes.a + holes.c * u[0], holes.b + holes.c * u[1]))
    return points


def resolve(block: Block, ctx: Context, holes: SiemensHoles) -> None:
    """Give ``block`` the active cycle's record and its motion at every hole (module docstring), or keep it
    verbatim; a located error for what cannot run."""
    state = ctx.state
    at = ctx.at(block)
    active = active_cycle(state) if state.extra.get(MCALL_KEY) else None
    if active is None:
        keep_verbatim(block, f"{holes.name} without an active MCALL cycle")
        return
    cycle, expansion = active
    if cycle.plane != "XY":
        raise ProgramError(f"{holes.name} is read in G17 only", at)
    x, y = state.position.get("X"), state.position.get("Y")
    if x is None or y is None:
        raise ProgramError(f"{holes.name}: the tool's X and Y are unknown (position them absolutely first)", at)
    points = hole_points(holes)
    if holes.name == "HOLES1" and len(points) > 1 and \
            math.dist((x, y), points[0]) >= math.dist((x, y), points[-1]) - NEARER:
        keep_verbatim(block, "HOLES1 with the tool not nearer its first hole than its last (which end it starts "
                             "at is not confirmed here)")
        return
    limit = ctx.setup.limits.moves_per_block
    grid = HolePattern("line", 1, 0.0)  # the plane and distance mode ``cycle_at`` reads: XY, absolute
    pos = {axis: value for axis, value in state.position.items() if axis in "XYZ" and value is not None}
    previous = (x, y)
    items: list[Section] = []
    first = None
    for point in points:
        here = cycle_at(grid, cycle, pos, point, previous)
        try:
            made, end = expansion.expand(here, max(limit - len(items), 0))
        except TooManyMoves:
            made, end = None, {}
        if made is None or len(items) + len(made) > limit:
            raise ProgramError(f"{holes.name}: {holes.num} holes make more than {limit} moves in one block (the "
                               "set-up's <Limits movesPerBlock>)", at)
        items.extend(made)
        first = here if first is None else first
        previous, pos = point, dict(end)
    assert first is not None
    first.expand = True  # the record is the first hole's; the block's motion makes every hole
    ctx.moves_made += len(items)
    block.add(first)
    block.add(CompoundMotion(cycle.kind, items))
    for axis, value in pos.items():
        state.position[axis] = value


def _direction(degrees: float) -> tuple[float, float]:
    """The unit vector at ``degrees``; exact on the axes (cos 90 is 0, not 6e-17)."""
    quarter, rest = divmod(degrees, 90.0)
    if rest == 0.0:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[int(quarter) % 4]
    t = math.radians(degrees)
    return math.cos(t), math.sin(t)
