"""How grblHAL moves through its drilling cycles, as a judgement of one resolved cycle block: does the
native G81/G82 move as the source controller's cycle does (``native_motion_matches``)? A translation keeps
the block native where it does and expands it otherwise (``Grblhal.moves_like``); reading grblHAL refuses a
block it does not (``GrblhalCycleRules``), so what is read is simulated as grblHAL runs it.

grblHAL's drilling cycles, from ``motion_control.c`` ``mc_canned_drill`` and ``gcode.c`` (github.com/grblHAL/core,
stored commit f80fc34) [V]:

* below R, the tool first rises to R (rapid), then rapids to the hole in the plane at its level; each repeat
  rapids down to R when above it, feeds to the bottom, dwells P seconds (G82), and retracts (rapid) to the
  retract level: R under G99; under G98 the level the tool stood at when the block began (risen to R when
  below it), not a remembered initial level;
* R in G91 is measured from the tool's level at the block's start, Z in G91 from R; L repeats in G91 step by
  X/Y between holes, in G90 drill the same hole again; L <= 0 is an error;
* a block that changes the cycle code needs R and the drilling axis word (and P for G82): nothing carries
  over from another cycle; a block that only repeats the cycle keeps them;
* G73 and G83 dwell 0.25 s at each peck, G83 feeds down from the retract level each time (``pecking``): no
  other family's peck cycle moves so, so they are read (a grblHAL program keeps them) and never written from
  another dialect; G84 reverses a spindle with the at-speed capability (its moves and spindle events are not
  modelled: refused where read, expanded where written), G85/G86/G89 are parsed and not run.

The RS274/NGC family (LinuxCNC) and Fanuc differ from that only in the level a G98 block returns to (their
initial level, remembered from the block that started the cycle; rs274 takes R when it is higher) and, for
Fanuc, in positioning at the tool's level when it stands below R. So a G81/G82 block in absolute distances
in the XY plane moves alike when the retract level agrees: G99, or a G98 block that starts at the
source's clear level (the usual case: every hole after the first starts there), and for Fanuc a block that
starts at or above R.
"""

from __future__ import annotations

from typing import Final

from postproc.context import Context
from postproc.cycles.section import CannedCycle
from postproc.errors import ParseError
from postproc.ir import Block
from postproc.syntaxes.syntax import Syntax

NATIVE: Final = frozenset({"drill", "drill_dwell"})
"""The cycles grblHAL runs as another family does (G81, G82): kept native from another dialect."""
PECK: Final = frozenset({"peck_chip", "peck_deep"})
"""G73 and G83: grblHAL's own moves (``pecking``), which no other family makes."""
READ: Final = NATIVE | PECK
"""The cycles read from grblHAL."""
_SAME: Final = 1e-9


def native_motion_matches(cycle: CannedCycle) -> bool:
    """The native G81/G82 on grblHAL moves as ``cycle`` does under its source family's rules (module
    docstring); False for every other cycle."""
    return cycle.kind in NATIVE and positions_alike(cycle)


def positions_alike(cycle: CannedCycle) -> bool:
    """grblHAL positions for the hole, and retracts, as ``cycle``'s family does (module docstring): absolute
    distances, the XY plane, a retract level that agrees."""
    if cycle.plane != "XY" or cycle.step or cycle.repeat < 1:
        return False
    start, r, initial = cycle.start.get("Z"), cycle.r, cycle.initial
    if start is None or r is None or initial is None:
        return False
    if cycle.semantics == "fanuc":
        if start < r - _SAME:
            return False  # Fanuc positions at the tool's level, grblHAL rises to R first
        clear = initial
    elif cycle.semantics == "rs274":
        clear = max(initial, r)
    else:
        return False
    return cycle.return_level == "r" or abs(max(start, r) - clear) <= _SAME


class GrblhalCycleRules(Syntax):
    """Refuses a cycle block read from grblHAL whose motion the resolve step (RS274/NGC rules) would not
    simulate as grblHAL moves (module docstring): incremental distances, another plane, a G98 block that
    starts below the cycle's initial level, or a cycle other than G73/G81/G82/G83. A G73/G83 block, which
    only grblHAL runs so (``pecking``), is marked to be expanded for any other controller."""

    XNAME = "GrblhalCycleRules"
    __slots__ = ()

    def build(self, block: Block, ctx: Context) -> None:
        cycle = block.sections.get("CannedCycle")
        if not isinstance(cycle, CannedCycle):
            return
        if cycle.kind not in READ or not positions_alike(cycle):
            raise ParseError("this grblHAL cycle block moves by rules not modelled here (grblHAL retracts a G98 "
                             "block to the level it starts at and measures a G91 R from it): only absolute "
                             "G73/G81/G82/G83 blocks in the XY plane that start at the cycle's clear level are read",
                             ctx.at(block))
        if cycle.kind in PECK:
            cycle.expand = True
