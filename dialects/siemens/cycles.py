"""SINUMERIK drilling cycles on the neutral cycle IR: ``CYCLE81`` ... ``CYCLE89``, ``CYCLE840`` called once
(``CYCLE81(..)`` alone in a block) or modally (``MCALL CYCLE81(..)``, deselected by a bare ``MCALL``).

Parameters are positional and comma-separated; an empty position is a parameter not given [K: USERS-AND-SIEMENS.md
3.2: Autodesk ``siemens-840d.cps`` ``onCycle``; PGZ cycles manual 11/2006 6FC5398-3BP20-0BA0 p.2-86]. The
leading five are common: RTP retraction plane and RFP reference plane (absolute), SDIS safety distance
(incremental, no sign), DP final depth (absolute) or DPR depth relative to RFP (no sign) [K: PGZ 2.1.2].
Every cycle starts where the tool stands: rapid to RFP+SDIS, work to the depth, back to RTP [K: PGZ 2.1.2].

=========  ==========================================================  =========================================
cycle      what the manual says it does [K: PGZ 2.1.2-2.1.10]         read as (Fanuc's kind)
=========  ==========================================================  =========================================
CYCLE81    G1 to the depth at the F in force, G0 to RTP                drill (G81)
CYCLE82    as CYCLE81, dwell DTB seconds at the depth                  drill_dwell (G82, P in ms)
CYCLE85    G1 to the depth at FFR, dwell DTB, G1 at RFF to RFP+SDIS,   bore_feed (G85), with DTB bore_dwell_feed
           G0 to RTP                                                   (G89), when FFR = RFF = the F in force
CYCLE87    G1 to the depth, M5, M0; on NC start G0 to RTP, spindle     bore_manual (G88) without dwell, SDIR 3
           in SDIR (3: M3, 4: M4)
CYCLE88    as CYCLE87 with a dwell DTB before M5                       bore_manual (G88), SDIR 3
CYCLE89    G1 to the depth, dwell DTB, G1 at the same F to RFP+SDIS,   bore_dwell_feed (G89)
           G0 to RTP
CYCLE83    deep hole: first depth FDEP/FDPR, degression DAM, dwells    peck_deep (G83, Q the stroke) with VARI=1,
           DTB/DTS, first-pass factor FRF, VARI 0 chip breaking / 1    DAM 0, no dwells, FRF 1, SDIS 0, a whole
           swarf removal, anticipation distance _DIS1 [K: 2.1.4]       number of strokes, d = _DIS1 (``deep_hole``);
                                                                       else kept verbatim
CYCLE84    rigid tap at SST (SST1 out) with pitch MPIT/PIT, spindle    tap / tap_left (rigid G84 / G74, the pitch
           oriented to POSS, direction SDAC after it [K: 2.1.5]       PIT) with SDAC the tap's own direction, SST
                                                                       the S in force, POSS 0 (``tapping``); else
                                                                       kept verbatim
CYCLE840   tap with a compensating chuck: reversal SDR, SDAC after,   tap / tap_left (G84 / G74 under G99) with
           with or without an encoder (ENC), feed from the pitch       ENC 1, no lead, SDR the reverse of SDAC,
           [K: 2.1.6]                                                  RTP = RFP+SDIS (``tapping``); else kept
                                                                       verbatim
CYCLE86    G1 to the depth, dwell DTB, oriented stop at POSS, G0       kept verbatim: the spindle's state after
           lift-off RPA/RPO/RPAP, G0 to RFP+SDIS, G0 to RTP back in    it (Fanuc's G76 ends turning clockwise)
           the plane [K: 2.1.8, as the Autodesk post writes G76]       and, at RTP above RFP+SDIS, the order of
                                                                       the rise and the way back in the plane
                                                                       are not confirmed [?]
=========  ==========================================================  =========================================

"Kept verbatim" is the reader's ``NativeCode`` named by the cycle: a Siemens program with it is copied byte
for byte, every other dialect and the simulator refuse it by name. So are parameters after the modelled
ones (``GMODE``, ``DMODE``, ``AMODE`` of newer software), computed parameters, a ``CYCLE87``/``CYCLE88``
with SDIR 4 (Fanuc's G88 restarts the spindle clockwise) or an empty SDIR (its default is not confirmed
here [?]), and a ``CYCLE85`` whose RFF differs from FFR. Empty RTP, RFP or SDIS, and both or neither of DP
and DPR, are located errors (their defaults, and which of DP and DPR wins, are not confirmed here [?]); an
empty DTB is no dwell [K: PGZ 2.1.3, DTB is the dwell "if programmed"].

Mapping onto Fanuc's words (``R`` RFP+SDIS, ``Z`` the depth, ``P`` DTB in ms, ``K0`` for the modal call that
drills nothing itself) is exact when [K]:

* under ``MCALL``, RTP is RFP+SDIS (Fanuc's R level, ``G99``) or the tool's Z at ``MCALL`` (the initial level,
  ``G98``): otherwise the retraction plane has no Fanuc level (a located error);
* G17 and G90 are in force (the parameters are absolute Z levels);
* under ``MCALL``, G0 is in force and the positioning blocks carry no motion code and no Z (Fanuc positions
  at rapid, a motion code would cancel its cycle, and its Z is the cycle's depth): located errors otherwise;
* DTB is a whole number of milliseconds.

A call once (``CYCLE81(..)`` alone in its block) drills where the tool stands, retracts to RTP whatever it is,
and leaves no cycle active (``SiemensCycleEnd``): its record is marked ``expand``, so every other dialect gets
its exact moves and no cycle stays active there either. The cycles are subprograms that restore the modal G functions they change
[K: the shipped cycles' ``PROC CYCLE8x(..) SAVE`` lines, as the PGZ quotes them [?]]: the motion mode after
one is the one before it. A one-shot call while a ``MCALL`` is active is kept verbatim (whether the modal
call then runs too is not confirmed here [?]).

A tap (``CYCLE84``, ``CYCLE840``: ``tapping`` has the facts) is Fanuc's tap cycle; a rigid one carries the
pitch PIT (``rigid_tap_pitch``) and is expanded for every other dialect, where the rigid-tap lowering writes a
synchronised move or the target's own rigid tap cycle. The cycle resolution asks every tap for a feed: a rigid
tap's block is given PIT x SST for it and loses it again (``tap_feed``), so the F in force stays SINUMERIK's.
Under a modal tap a hole block with another S than SST, or with a spindle code, is a located error (SINUMERIK
sets the spindle after each thread itself).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, ClassVar

from postproc.cycles.resolve import ACTIVE_KEY, STATE_KEY, peck_clearance_mm
from postproc.cycles.rigid_tap import end_rigid_mode
from postproc.cycles.section import CannedCycle
from postproc.errors import ProgramError
from postproc.ir import Feed, NativeCode, Section
from postproc.ir.state import MM_PER_INCH
from postproc.syntaxes.syntax import Syntax
from postproc.xmlio import XAttr

from .deep_hole import Unconfirmed, deep_hole
from .tapping import floating_tap, rigid_tap

if TYPE_CHECKING:
    from postproc.context import Context
    from postproc.ir import Block

COMMON = ("RTP", "RFP", "SDIS", "DP", "DPR")
DEEP_HOLE = (*COMMON, "FDEP", "FDPR", "DAM", "DTB", "DTS", "FRF", "VARI", "_AXN", "_MDEP", "_VRT", "_DTD", "_DIS1")
"""CYCLE83's parameters in order [K: USERS-AND-SIEMENS.md 3.2; the Autodesk ``siemens-840d.cps`` ``onCycle``
writes the same seventeen, in this order]."""
LEVEL_TOLERANCE = 1e-9
CLEARANCE_TOLERANCE = 1e-8
"""``_DIS1`` is the set-up's G83 clearance within this (program units): an inch program's ``_DIS1`` written
with 8 decimals (0.3 mm is 0.01181102 inch, 4e-9 off) reads back as the same clearance."""
MCALL_KEY = "siemens_mcall"
"""``ctx.state.extra`` key: True while a modal cycle call is active."""
DIS1_KEY = "siemens_dis1"
"""``ctx.state.extra`` key: a deep hole's anticipation distance ``_DIS1`` while its call is active, and whether
it differs from the set-up's G83 clearance (``SiemensCycleEnd`` gives it to each hole)."""
TAP_KEY = "siemens_rigid_tap"
"""``ctx.state.extra`` key: a ``CYCLE84`` call's (pitch, tapping speed SST) while it is active, and
``TAP_FEED_KEY`` the ``id`` of the block given the tap's feed for the cycle resolution (``SiemensCycleEnd``
takes it out again: the F in force stays SINUMERIK's)."""
TAP_FEED_KEY = "siemens_rigid_tap_feed"
ONCE_KEY = "siemens_cycle_once"
"""``ctx.state.extra`` key: (the ``id`` of the block calling a cycle once, its RTP), from the block syntax to
``SiemensCycleEnd``."""


@dataclass(frozen=True)
class CycleSpec:
    """One SINUMERIK cycle: its parameters in order, the neutral kind it is read as (None: kept verbatim)
    and why it is kept verbatim."""

    parameters: tuple[str, ...]
    kind: str | None = None
    verbatim: str = ""


CYCLES: dict[str, CycleSpec] = {
    "CYCLE81": CycleSpec(COMMON, "drill"),
    "CYCLE82": CycleSpec((*COMMON, "DTB"), "drill_dwell"),
    "CYCLE85": CycleSpec((*COMMON, "DTB", "FFR", "RFF"), "bore_feed"),
    "CYCLE87": CycleSpec((*COMMON, "SDIR"), "bore_manual"),
    "CYCLE88": CycleSpec((*COMMON, "DTB", "SDIR"), "bore_manual"),
    "CYCLE89": CycleSpec((*COMMON, "DTB"), "bore_dwell_feed"),
    "CYCLE83": CycleSpec(DEEP_HOLE, "peck_deep"),
    "CYCLE84": CycleSpec((*COMMON, "DTB", "SDAC", "MPIT", "PIT", "POSS", "SST", "SST1", "_AXN", "_PTAB", "_TECHNO",
                          "_VARI", "_DAM", "_VRT"), "tap"),
    "CYCLE840": CycleSpec((*COMMON, "DTB", "SDR", "SDAC", "ENC", "MPIT", "PIT", "_AXN", "_PTAB", "_TECHNO"), "tap"),
    "CYCLE86": CycleSpec((*COMMON, "DTB", "SDIR", "RPA", "RPO", "RPAP", "POSS"),
                         verbatim="its lift-off RPA/RPO/RPAP in three axes has no neutral cycle"),
}
"""Cycle name -> what is read of it [K: parameter orders from USERS-AND-SIEMENS.md 3.2]."""
class NotModelled(Exception):
    """A cycle call the IR does not model: the reader keeps its block verbatim, named by ``what``."""

    def __init__(self, what: str) -> None:
        super().__init__(what)
        self.what = what


class CycleLevels(Section):
    """What the block syntax still has to check of a cycle call against the modal state: the levels (the
    return level is the one RTP is), whether the call is once, and the feed it works at (None: the F in
    force) and a deep hole's anticipation distance (``_DIS1``, which must be the set-up's G83 clearance), a
    rigid tap's pitch and tapping speed (``CYCLE84``'s PIT and SST, which must be the S in force). It leaves
    the block there."""

    XNAME = KEY = "SiemensCycleLevels"
    __slots__ = ("retract", "r", "once", "feed", "name", "clearance", "pitch", "speed")
    XATTRS = (XAttr("retract", float), XAttr("r", float), XAttr("once", bool, False), XAttr("feed", float, None),
              XAttr("name", str, "CYCLE81"), XAttr("clearance", float, None), XAttr("pitch", float, None),
              XAttr("speed", float, None))
    retract: float
    r: float
    once: bool
    feed: float | None
    name: str
    clearance: float | None
    pitch: float | None
    speed: float | None

    def __init__(self, retract: float, r: float, once: bool = False, feed: float | None = None,
                 name: str = "CYCLE81", clearance: float | None = None, pitch: float | None = None,
                 speed: float | None = None) -> None:
        self.retract = retract
        self.r = r
        self.once = once
        self.feed = feed
        self.name = name
        self.clearance = clearance
        self.pitch = pitch
        self.speed = speed


def cycle_words(name: str, params: list[float | None], once: bool = False
                ) -> tuple[str, list[tuple[str, str]], CycleLevels]:
    """The neutral kind and the Fanuc-family words (``R``, ``Z``, ``P`` in ms, ``K0`` for a modal call) of
    ``name(params)``. A ``ValueError`` names what is missing or contradictory, a ``NotModelled`` what is
    kept verbatim."""
    spec = CYCLES[name]
    names = spec.parameters
    if len(params) > len(names):
        raise ValueError(f"{name} takes at most {len(names)} parameters ({', '.join(names)}), not {len(params)}")
    if spec.kind is None:
        raise NotModelled(f"{name} ({spec.verbatim})")
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
    bottom = float(dp) if dp is not None else rfp - float(dpr or 0.0)
    if bottom > rfp + sdis:
        raise ValueError(f"{name}: the final depth {bottom:g} is above RFP+SDIS ({rfp + sdis:g})")
    kind = spec.kind
    feed = None
    if name == "CYCLE85":
        feed, back = given.get("FFR"), given.get("RFF")
        if feed is None or back is None or feed <= 0:
            raise ValueError("CYCLE85 needs its feeds FFR (in) and RFF (out), both positive")
        if abs(feed - back) > LEVEL_TOLERANCE:
            raise NotModelled("CYCLE85 with RFF other than FFR (Fanuc's G85/G89 feed out at the feed in)")
    if name in ("CYCLE87", "CYCLE88"):
        sdir = given.get("SDIR")
        if sdir != 3:
            raise NotModelled(f"{name} with SDIR {'empty' if sdir is None else f'{sdir:g}'} (read with SDIR=3: "
                              "Fanuc's G88 restarts the spindle clockwise)")
    words = [("R", _spell(rfp + sdis)), ("Z", _spell(bottom))]
    clearance = pitch = speed = None
    try:
        if name == "CYCLE84":
            kind, pitch, speed = rigid_tap(given)
        elif name == "CYCLE840":
            kind = floating_tap(given)
    except Unconfirmed as err:
        raise NotModelled(err.what) from None
    if name == "CYCLE83":
        try:
            stroke, clearance = deep_hole(given, rfp + sdis, bottom)
        except Unconfirmed as err:
            raise NotModelled(err.what) from None
        words.append(("Q", _spell(stroke)))
    dtb = given.get("DTB")
    if dtb is not None and "DTB" in names and name != "CYCLE83":  # CYCLE83's DTB is 0 (``deep_hole``)
        ms = dtb * 1000.0
        if dtb < 0 or abs(ms - round(ms)) > 1e-6:
            raise ValueError(f"{name}: DTB is a dwell of whole milliseconds here, not {dtb:g}")
        if name == "CYCLE85" and dtb > 0:
            kind = "bore_dwell_feed"
        if kind != "bore_feed":
            words.append(("P", str(int(round(ms)))))
    if not once:
        words.append(("K", "0"))
    return kind, words, CycleLevels(rtp, rfp + sdis, once, feed, name, clearance, pitch, speed)


def _spell(value: float) -> str:
    return repr(float(value))


def keep_verbatim(block: Block, what: str) -> None:
    """Make ``block`` the reader's verbatim block (its comment kept), named by ``what``."""
    comments = block.sections.get("Comments")
    block.sections.clear()
    block.words.clear()
    block.values.clear()
    if comments is not None:
        block.add(comments)
    block.add(NativeCode("siemens", f"{what} (not modelled)", block.text or ""))


class SiemensCycleRules:
    """The block syntax's checks of a cycle call and of the positioning blocks under ``MCALL``."""

    EXTRA: ClassVar[str] = MCALL_KEY

    @staticmethod
    def call(block: Block, ctx: Context, levels: CycleLevels) -> str | None:
        """The return level of the cycle call ('initial' or 'r'), or None when the block is kept verbatim
        (``keep_verbatim``); a located error for what no Fanuc cycle means."""
        state = ctx.state
        at = ctx.at(block)
        name = levels.name
        if state.plane != "XY" or state.distance != "absolute":
            raise ProgramError(f"{name} is read in G17 and G90 only (its levels are absolute Z values)", at)
        if levels.once and state.extra.get(MCALL_KEY):
            keep_verbatim(block, f"{name} called once under MCALL")
            return None
        if not levels.once and state.motion != "rapid":
            raise ProgramError("MCALL moves to each hole in the motion mode in force: program G0 before it (Fanuc's "
                               "cycles position at rapid)", at)
        if levels.feed is not None and levels.feed != state.feed:
            keep_verbatim(block, f"{name} with FFR {levels.feed:g} other than the F in force (Fanuc's G85/G89 "
                                 "feed at it)")
            return None
        if name == "CYCLE840":
            why = floating_problem(levels, ctx, block)
            if why is not None:
                keep_verbatim(block, f"{name} {why}")
                return None
        if levels.pitch is not None and not same_speed(levels.speed, state.spindle_rpm):
            keep_verbatim(block, f"{name} with SST {levels.speed:g} other than the S in force "
                                 f"({'none' if state.spindle_rpm is None else f'{state.spindle_rpm:g}'}: SINUMERIK "
                                 "restores it after the tap, Fanuc's rigid tap runs at it)")
            return None
        if levels.pitch is not None:
            state.extra[TAP_KEY] = (levels.pitch, levels.speed)
            tap_feed(block, ctx)
        else:
            state.extra.pop(TAP_KEY, None)
        if levels.clearance is not None:
            d = peck_clearance_mm("peck_deep", ctx.peck_clearance_mm, ctx.setup.cycles)
            d = d if state.units == "mm" else d / MM_PER_INCH
            state.extra[DIS1_KEY] = (levels.clearance, abs(levels.clearance - d) > CLEARANCE_TOLERANCE)
        else:
            state.extra.pop(DIS1_KEY, None)
        if levels.once:
            state.extra[ONCE_KEY] = (id(block), levels.retract)
            return "r" if abs(levels.retract - levels.r) <= LEVEL_TOLERANCE else "initial"
        if abs(levels.retract - levels.r) <= LEVEL_TOLERANCE:
            level = "r"
        else:
            z = state.position.get("Z")
            if z is None or abs(z - levels.retract) > LEVEL_TOLERANCE:
                raise ProgramError(f"RTP {levels.retract:g} is neither RFP+SDIS ({levels.r:g}) nor the tool's Z at "
                                   f"MCALL ({'unknown' if z is None else f'{z:g}'}): no Fanuc level retracts there",
                                   at)
            level = "initial"
        state.extra[MCALL_KEY] = True
        return level

    @staticmethod
    def position(block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any]) -> None:
        """A block under ``MCALL``: no motion code, no Z."""
        if "01" in codes:
            raise ProgramError(f"G{codes['01'][3]} under MCALL: SINUMERIK runs the cycle after this move, a Fanuc "
                               "cycle would be cancelled (program the position without a motion code)", ctx.at(block))
        if "Z" in values:
            raise ProgramError("Z under MCALL: SINUMERIK moves Z before the cycle, Fanuc's Z is the cycle's depth "
                               "(not read)", ctx.at(block, ctx.column_of(block, "Z")))
        cycle = ctx.state.cycle
        if cycle is not None and cycle.kind in ("tap", "tap_left") and any(
                letter in "Mm" and num.isdigit() and int(num) in (3, 4, 5) for letter, num in block.words):
            raise ProgramError("a spindle code under MCALL CYCLE84/CYCLE840: the cycle sets the spindle's direction "
                               "after each thread (SDAC), Fanuc's tap cycle at its end (not read)", ctx.at(block))
        tap = ctx.state.extra.get(TAP_KEY)
        if tap is not None:
            rpm = values.get("S", ctx.state.spindle_rpm)
            if not same_speed(tap[1], rpm):
                raise ProgramError(f"S {rpm} under MCALL CYCLE84 with SST {tap[1]:g}: SINUMERIK taps at SST and "
                                   "restores the S in force after each hole, Fanuc's rigid tap runs at the S in "
                                   "force (not read)", ctx.at(block, ctx.column_of(block, "S")))
            if "F" not in values:
                tap_feed(block, ctx)


def floating_problem(levels: CycleLevels, ctx: Context, block: Block) -> str | None:
    """Why a ``CYCLE840`` call is not Fanuc's floating tap here (``tapping``), or None."""
    state = ctx.state
    if abs(levels.retract - levels.r) > LEVEL_TOLERANCE:
        return "with RTP other than RFP+SDIS (whether the spindle turns back to SDAC before or after the G0 to RTP " \
               "is not confirmed here)"
    if state.feed_mode != "per_min":
        return "outside G94 (whether its G63 runs in feed per revolution is not confirmed here)"
    cycle = block.sections.get("CycleCall")
    direction = "cw" if getattr(cycle, "kind", "tap") == "tap" else "ccw"
    if state.spindle != direction:
        return (f"with the spindle {state.spindle or 'unknown'}, not SDAC's {direction} (the first thread is tapped in "
                "the direction in force)")
    return None


def same_speed(speed: float | None, rpm: Any) -> bool:
    """Whether a tap's SST is the spindle speed ``rpm`` (None: not known)."""
    return speed is not None and isinstance(rpm, (int, float)) and abs(speed - float(rpm)) <= 1e-9


def tap_feed(block: Block, ctx: Context) -> None:
    """Give a ``CYCLE84`` block the tap's feed (pitch times SST), which the cycle resolution asks of every
    tap cycle; ``SiemensCycleEnd`` takes it out again."""
    pitch, speed = ctx.state.extra[TAP_KEY]
    block.add(Feed(pitch * speed))
    ctx.state.extra[TAP_FEED_KEY] = id(block)


class SiemensCycleEnd(Syntax):
    """After the cycle resolution: a cycle called once ends with its block (``ONCE_KEY``), and is written as
    its moves for every other dialect (its record's ``expand``: there no cycle may stay active after it)."""

    XNAME = "SiemensCycleEnd"
    __slots__ = ()

    def build(self, block: Block, ctx: Context) -> None:
        extra = ctx.state.extra
        if DIS1_KEY in extra:
            deep_hole_clearance(block, ctx)
        if TAP_KEY in extra:
            rigid_tap_pitch(block, ctx)
        if ONCE_KEY not in extra:
            return
        extra.pop(DIS1_KEY, None)
        extra.pop(TAP_KEY, None)
        called, retract = extra.pop(ONCE_KEY)
        if called != id(block):
            return  # the call's own block was refused before it came here
        state = ctx.state
        cycle = block.sections.get("CannedCycle")
        if isinstance(cycle, CannedCycle):
            cycle.expand = True
            cycle.initial, cycle.return_level = retract, "initial"  # straight back to RTP
            state.position["Z"] = retract
        end_rigid_mode(state)
        state.cycle = None
        extra.pop(STATE_KEY, None)
        extra.pop(ACTIVE_KEY, None)


def deep_hole_clearance(block: Block, ctx: Context) -> None:
    """Give the block's deep hole (and the active cycle's record, which hole patterns copy) the call's
    ``_DIS1`` as its clearance d; where it is not the set-up's G83 clearance, which every Fanuc-family
    target's G83 takes, the hole is expanded for every other dialect (``expand``), with that d."""
    extra = ctx.state.extra
    dis1, differs = extra[DIS1_KEY]
    active = extra.get(ACTIVE_KEY)
    for cycle in (block.sections.get("CannedCycle"), active[0] if isinstance(active, tuple) else None):
        if isinstance(cycle, CannedCycle) and cycle.kind == "peck_deep":
            cycle.clearance = dis1
            cycle.expand = cycle.expand or differs


def rigid_tap_pitch(block: Block, ctx: Context) -> None:
    """Give the block's tap (and the active cycle's record, which hole patterns copy) the call's pitch: a
    rigid tap (``tapping``); it is expanded for every other dialect (``expand``: the Fanuc family's tap cycle
    is rigid only after its code, which the rigid-tap lowering writes before each hole). The tap's feed goes
    from the block again (``tap_feed``)."""
    extra = ctx.state.extra
    pitch, _ = extra[TAP_KEY]
    if extra.pop(TAP_FEED_KEY, None) == id(block):
        block.sections.pop("Feed", None)
    active = extra.get(ACTIVE_KEY)
    for cycle in (block.sections.get("CannedCycle"), active[0] if isinstance(active, tuple) else None):
        if isinstance(cycle, CannedCycle) and cycle.kind in ("tap", "tap_left"):
            cycle.pitch = pitch
            cycle.expand = True
