"""SINUMERIK drilling cycles on the neutral cycle IR: ``MCALL CYCLE81(..)`` / ``MCALL CYCLE82(..)`` and the bare
``MCALL`` that deselects them.

Parameters, positional, comma-separated [K: USERS-AND-SIEMENS.md 3.2: Autodesk ``siemens-840d.cps``
``onCycle``; PGZ cycles manual 11/2006 p.2-86]: ``CYCLE81(RTP, RFP, SDIS, DP, DPR)``, ``CYCLE82(RTP, RFP,
SDIS, DP, DPR, DTB)``. RTP retraction plane, RFP reference plane, DP final depth (absolute), SDIS safety
distance and DPR depth relative to RFP (no sign), DTB dwell at the depth in seconds. The cycle: rapid to
RFP+SDIS, feed (the F in force) to the depth, dwell DTB (CYCLE82), rapid to RTP [K: same sources].

Modal call [K: 3.2]: ``MCALL CYCLE8x(..)`` drills nothing itself; every later block that moves runs the cycle
at its end, until a bare ``MCALL``. That is Fanuc's ``G81``/``G82`` data block with no hole (``K0``) and its
hole blocks, exactly when:

* RTP is RFP+SDIS (Fanuc's R level, ``G99``), or the tool's Z when ``MCALL`` is read (Fanuc's initial level,
  ``G98``): otherwise the retraction plane has no Fanuc level (a located error);
* G0 is in force at ``MCALL`` and the positioning blocks carry no motion code and no Z (Fanuc positions at
  rapid, a motion code would cancel its cycle, and its Z is the cycle's depth): located errors otherwise;
* G17 and G90 are in force (the parameters are absolute Z levels);
* only one of DP and DPR is given (which wins is not confirmed here [?]), and RTP, RFP, SDIS are given
  (their defaults for an empty position are not confirmed [?]); DTB is a whole number of milliseconds.

A one-shot ``CYCLE81(..)``, the other cycles and computed parameters are kept verbatim (``reader``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar

from postproc.errors import ProgramError
from postproc.ir import Section
from postproc.xmlio import XAttr

if TYPE_CHECKING:
    from postproc.context import Context
    from postproc.ir import Block

KINDS = {"CYCLE81": "drill", "CYCLE82": "drill_dwell"}
"""Cycle name -> the neutral cycle kind (Fanuc G81, G82)."""
PARAMETERS = {"CYCLE81": ("RTP", "RFP", "SDIS", "DP", "DPR"), "CYCLE82": ("RTP", "RFP", "SDIS", "DP", "DPR", "DTB")}
LEVEL_TOLERANCE = 1e-9
MCALL_KEY = "siemens_mcall"
"""``ctx.state.extra`` key: True while a modal cycle call is active."""


class CycleLevels(Section):
    """The levels of a ``MCALL CYCLE8x`` the block syntax still has to check against the tool's Z (then it
    becomes the block's return level and leaves the block)."""

    XNAME = KEY = "SiemensCycleLevels"
    __slots__ = ("retract", "r")
    XATTRS = (XAttr("retract", float), XAttr("r", float))
    retract: float
    r: float

    def __init__(self, retract: float, r: float) -> None:
        self.retract = retract
        self.r = r


def cycle_words(name: str, params: list[float | None], at: int) -> tuple[list[tuple[str, str]], CycleLevels]:
    """The Fanuc-family words (``R``, ``Z``, ``P`` in ms, ``K0``) of ``MCALL name(params)``; a ``ValueError``
    names what is missing or ambiguous."""
    names = PARAMETERS[name]
    if len(params) > len(names):
        raise ValueError(f"{name} takes {len(names)} parameters here ({', '.join(names)}), not {len(params)}")
    given = dict(zip(names, params))
    for required in ("RTP", "RFP", "SDIS"):
        if given.get(required) is None:
            raise ValueError(f"{name}: {required} is empty (its default is not confirmed here [?])")
    dp, dpr = given.get("DP"), given.get("DPR")
    if (dp is None) == (dpr is None):
        raise ValueError(f"{name}: give exactly one of DP and DPR (which wins when both are given is not "
                         "confirmed here [?])")
    rtp, rfp, sdis = float(given["RTP"] or 0.0), float(given["RFP"] or 0.0), float(given["SDIS"] or 0.0)
    if sdis < 0 or dpr is not None and dpr < 0:
        raise ValueError(f"{name}: SDIS and DPR have no sign")
    bottom = dp if dp is not None else rfp - float(dpr or 0.0)
    words = [("R", _spell(rfp + sdis)), ("Z", _spell(float(bottom))), ("K", "0")]
    dtb = given.get("DTB")
    if dtb is not None:
        ms = dtb * 1000.0
        if dtb < 0 or abs(ms - round(ms)) > 1e-6:
            raise ValueError(f"{name}: DTB is a dwell of whole milliseconds here, not {dtb}")
        words.append(("P", str(int(round(ms)))))
    return words, CycleLevels(rtp, rfp + sdis)


def _spell(value: float) -> str:
    return repr(float(value))


class SiemensCycleRules:
    """The block syntax's checks of a modal cycle call and its positioning blocks (see the module)."""

    EXTRA: ClassVar[str] = MCALL_KEY

    @staticmethod
    def call(block: Block, ctx: Context, levels: CycleLevels) -> str:
        """The return level of ``MCALL CYCLE8x`` ('initial' or 'r'), or a located error."""
        state = ctx.state
        at = ctx.at(block)
        if state.plane != "XY" or state.distance != "absolute":
            raise ProgramError("MCALL CYCLE8x is read in G17 and G90 only (its levels are absolute Z values)", at)
        if state.motion != "rapid":
            raise ProgramError("MCALL moves to each hole in the motion mode in force: program G0 before it (Fanuc's "
                               "cycles position at rapid)", at)
        state.extra[MCALL_KEY] = True
        if abs(levels.retract - levels.r) <= LEVEL_TOLERANCE:
            return "r"
        z = state.position.get("Z")
        if z is not None and abs(z - levels.retract) <= LEVEL_TOLERANCE:
            return "initial"
        raise ProgramError(f"RTP {levels.retract:g} is neither RFP+SDIS ({levels.r:g}) nor the tool's Z at MCALL "
                           f"({'unknown' if z is None else f'{z:g}'}): no Fanuc level retracts there", at)

    @staticmethod
    def position(block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any]) -> None:
        """A block under ``MCALL``: no motion code, no Z."""
        if "01" in codes:
            raise ProgramError(f"G{codes['01'][3]} under MCALL: SINUMERIK runs the cycle after this move, a Fanuc "
                               "cycle would be cancelled (program the position without a motion code)", ctx.at(block))
        if "Z" in values:
            raise ProgramError("Z under MCALL: SINUMERIK moves Z before the cycle, Fanuc's Z is the cycle's depth "
                               "(not read)", ctx.at(block, ctx.column_of(block, "Z")))
