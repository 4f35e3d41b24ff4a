"""Fanuc-family drilling cycles written as SINUMERIK modal cycle calls: ``MCALL CYCLE81(RTP, RFP, SDIS, DP)`` /
``MCALL CYCLE82(RTP, RFP, SDIS, DP, , DTB)`` and the others below, the holes as plain position blocks, a bare
``MCALL`` to end.

Exactly where the meanings match, which is where the reader (``cycles``) reads them back to the same cycle
[K: USERS-AND-SIEMENS.md 3.2, PGZ cycles manual 11/2006 p.2-86; the Autodesk ``siemens-840d.cps`` mapping]:

* Fanuc's R level is RFP+SDIS: written ``RFP = R``, ``SDIS = 0`` [?: whether a control objects to SDIS 0 is not
  confirmed; the cycle's approach is then RFP itself]; ``DP`` is Fanuc's Z (absolute); ``RTP`` is R under G99
  and the initial level under G98, which SINUMERIK takes as an absolute plane: a G98 block is native only where
  the tool stands at the initial level before it (true at a cycle's first block and after each G98 hole);
* G81 ``CYCLE81``; G82 ``CYCLE82`` (DTB the dwell in seconds, whole milliseconds); G83 ``CYCLE83`` with
  ``FDEP`` the first stroke's depth, ``VARI`` 1, no degression and no dwells, ``_DIS1`` the clearance d, where
  the depth is a whole number of pecks (``deep_hole`` says why); G85 ``CYCLE85`` with FFR = RFF = the feed;
  G89 ``CYCLE89``; G88 ``CYCLE88`` with SDIR 3 (Fanuc restarts the spindle clockwise); a rigid G84/G74 (after
  ``M29 S..``, which is left out) ``CYCLE84`` with SDAC the tap's direction, PIT the pitch signed by the hand,
  POSS 0, SST = SST1 = the S in force; a floating G84/G74 under G99 with the spindle turning the tap's way
  ``CYCLE840`` with ENC 1 (G63 at the F in force), SDR the reverse, SDAC the tap's direction, any other
  floating tap (G98, feed per revolution) its moves (``floating_call``) (``tapping`` reads both back).
  Expanded: G73 (chip breaking retracts at the feed on SINUMERIK [K: PGZ 2.1.4], Fanuc's G73 at rapid), G86 and G76
  (``CYCLE86`` orients the spindle and lifts off, and what it leaves the spindle doing is not confirmed), back boring (G87: no SINUMERIK call, the
  Autodesk post expands it too), and a block that repeats (K/L), has no new position in the plane (G88: its
  moves stop the program, so it is not written outside the call either), is not in G17, programs its levels
  incrementally (G91) or computes a word;
* the cycle runs after each block that moves [K: 3.2 "every later block that moves runs the cycle at its
  end"], so a hole is a position block with X/Y only, in G0 (written before each ``MCALL``), and anything that
  moves otherwise while the call is active (a motion code, an expansion, the cycle cancel, the program end)
  gets the bare ``MCALL`` first. A hole where the tool already stands is written as the cycle's own moves
  outside the call (``in_place_moves``; a tap as its call once, no plain move taps), the call taken up again
  at the next hole.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from postproc.cycles.section import CannedCycle

NAMES = {"drill": "CYCLE81", "drill_dwell": "CYCLE82", "peck_deep": "CYCLE83", "bore_feed": "CYCLE85",
         "bore_dwell_feed": "CYCLE89", "bore_manual": "CYCLE88", "tap": "CYCLE84", "tap_left": "CYCLE84"}
"""Neutral cycle kind -> the SINUMERIK cycle written for it."""
SAME = 1e-9
"""Levels closer than this (program units) are the same level."""
TAPS = frozenset(("tap", "tap_left"))
"""The kinds written as ``CYCLE84`` (a rigid tap: a record with its ``pitch``) or ``CYCLE840`` (a floating tap,
``floating_call``; another is written as its moves)."""
BORING = frozenset(("bore_feed", "bore_dwell_feed"))
"""The kinds written with their feed in and out (``CYCLE85``'s FFR and RFF, ``CYCLE89``'s F in force)."""


def moves_in_plane(cycle: CannedCycle) -> bool:
    """Whether the hole's block moves in the plane. One that does not (a hole where the tool stands: the
    cycle's first block after a positioning move, usually) is written as the cycle's moves, outside the
    call: whether a block that moves by nothing runs the modal call is not confirmed [?]."""
    for axis in ("X", "Y"):
        start = cycle.start.get(axis)
        if axis in cycle.words and (start is None or abs(start - cycle.position[axis]) > SAME):
            return True
    return False


def in_place_moves(cycle: CannedCycle, call: "Call") -> list[tuple[str, float]]:
    """The moves of Fanuc's G81/G82/G83 at the hole where the tool stands [K: Fanuc 0i-MF operator's manual,
    "Drilling cycle, spot drilling (G81)": rapid to R, feed to Z, (G82: dwell), rapid to the return level;
    "Peck drilling cycle (G83)": feed Q, rapid to R, rapid to d above the last depth, feed Q + d, ...];
    ``("dwell", seconds)`` for the dwell."""
    moves = [("rapid", call.rfp)]
    if call.stroke is not None:
        for k in range(1, strokes(call.rfp - call.dp, call.stroke)):
            depth = call.rfp - k * call.stroke
            moves += [("linear", depth), ("rapid", call.rfp), ("rapid", depth + call.clearance)]
    moves.append(("linear", call.dp))
    if call.dtb:
        moves.append(("dwell", call.dtb))
    if call.feed is not None:  # G85/G89: feed out to R [K: Fanuc 0i-MF, "Boring cycle (G85)", "(G89)"]
        moves.append(("linear", call.rfp))
    return moves + [("rapid", call.rtp)]


def floating_call(cycle: CannedCycle, feed_mode: str) -> bool:
    """Whether a floating tap is ``CYCLE840``'s (``tapping`` reads it back so): under G99 (whether the spindle
    turns back before or after the G0 to RTP is not confirmed [?]), in G94, the spindle turning the tap's
    direction at the call; else the writer writes its moves (``floating_tap_moves``)."""
    return cycle.return_level == "r" and feed_mode == "per_min" \
        and cycle.spindle == ("cw" if cycle.kind == "tap" else "ccw")


def floating_tap_moves(cycle: CannedCycle, call: "Call") -> list[tuple[str, float | str]]:
    """The moves of Fanuc's (floating) G84/G74 at its hole, for a tap that no ``CYCLE840`` writes
    (``floating_call``) [K: Fanuc 0i-MF, "Tapping cycle (G84)": rapid to R, feed to Z, dwell P, spindle reversed,
    feed back to R, G98 rapid to the initial level, the tapping direction again]; ``("spindle", direction)`` for
    a spindle code."""
    work, back = ("ccw", "cw") if cycle.kind == "tap_left" else ("cw", "ccw")
    moves: list[tuple[str, float | str]] = [("rapid", call.rfp), ("linear", call.dp)]
    if call.dtb:
        moves.append(("dwell", call.dtb))
    return moves + [("spindle", back), ("linear", call.rfp), ("rapid", call.rtp), ("spindle", work)]


def strokes(depth: float, stroke: float) -> int:
    """How many strokes of ``stroke`` drill ``depth`` (whole, or one when the stroke reaches the bottom)."""
    return max(1, round(depth / stroke))


def whole_strokes(cycle: CannedCycle) -> bool:
    """Whether a G83's depth is drilled in strokes of Q that are all the same (``CYCLE83`` is read only so:
    ``deep_hole``), or in one; and it has its clearance d and no dwell (Fanuc's G83 ignores P [?])."""
    assert cycle.r is not None and cycle.bottom is not None
    q, d, depth = cycle.q, cycle.clearance, cycle.r - cycle.bottom
    if q is None or q <= 0 or d is None or d <= 0 or cycle.dwell:
        return False
    if q >= depth - SAME:
        return True
    count = depth / q
    return abs(count - round(count)) <= 1e-9 * count


def writable(cycle: CannedCycle) -> bool:
    """Whether ``cycle``'s block is written natively (see the module docstring); else it is expanded."""
    if cycle.repeat != 1 or cycle.expand or not parameters_writable(cycle):
        return False
    if cycle.kind == "bore_manual" and not moves_in_plane(cycle):
        return False  # its moves where the tool stands stop the program: not written outside the call
    if cycle.return_level == "initial":
        z, initial = cycle.start.get("Z"), cycle.initial
        return z is not None and initial is not None and abs(z - initial) <= SAME
    return cycle.return_level == "r"


def parameters_writable(cycle: CannedCycle) -> bool:
    """Whether ``cycle``'s levels, dwell and strokes are a ``CYCLE8x`` call's parameters (``Call``), wherever
    the call stands: a G17 cycle of a kind in ``NAMES`` with absolute levels and position, a dwell of whole
    milliseconds, a deep hole of whole strokes, a bore with its feed."""
    if cycle.kind not in NAMES or cycle.plane != "XY":
        return False
    if cycle.r is None or cycle.bottom is None or cycle.initial is None:
        return False
    words = cycle.words
    if any(type(value) not in (int, float) for value in words.values()):
        return False
    if "Z" in words and abs(float(words["Z"]) - cycle.bottom) > SAME \
            or "R" in words and abs(float(words["R"]) - cycle.r) > SAME:
        return False  # incremental levels (G91)
    for axis in ("X", "Y"):
        if axis in words and abs(float(words[axis]) - cycle.position.get(axis, float("nan"))) > SAME:
            return False  # an incremental position
    if cycle.dwell is not None and abs(cycle.dwell * 1000 - round(cycle.dwell * 1000)) > 1e-6:
        return False
    if cycle.kind == "peck_deep" and not whole_strokes(cycle):
        return False
    if cycle.kind in TAPS and cycle.pitch is not None and cycle.pitch <= 0:
        return False
    return not (cycle.kind in BORING and (cycle.feed is None or cycle.feed <= 0))


@dataclass(frozen=True)
class Call:
    """The parameters of one ``MCALL CYCLE8x(..)``."""

    name: str
    rtp: float
    rfp: float
    dp: float
    dtb: float | None
    stroke: float | None = None
    """A deep hole's stroke (Fanuc's Q, at most the depth)."""
    clearance: float = 0.0
    """A deep hole's anticipation distance (Fanuc's d)."""
    feed: float | None = None
    """A bore that feeds out: the feed in and out (``CYCLE85``'s FFR and RFF)."""
    pitch: float | None = None
    """A rigid tap's pitch, signed by the thread's hand (``CYCLE84``'s PIT: negative for ``G74``)."""
    speed: float | None = None
    """A rigid tap's spindle speed (``CYCLE84``'s SST and SST1: the S in force, at which Fanuc's taps)."""
    left: bool = False
    """A floating tap of a left-hand thread (``CYCLE840`` with SDAC 4, SDR 3)."""

    @classmethod
    def of(cls, cycle: CannedCycle, rpm: float | None = None) -> "Call":
        """The call of ``cycle``; ``rpm`` the spindle speed in force (a rigid tap's SST)."""
        assert cycle.r is not None and cycle.bottom is not None and cycle.initial is not None
        rtp = cycle.r if cycle.return_level == "r" else cycle.initial
        if cycle.kind in TAPS and cycle.pitch is None:
            return cls("CYCLE840", rtp, cycle.r, cycle.bottom, cycle.dwell or None, left=cycle.kind == "tap_left")
        if cycle.kind in TAPS:
            assert cycle.pitch is not None
            return cls(NAMES[cycle.kind], rtp, cycle.r, cycle.bottom, cycle.dwell or None,
                       pitch=cycle.pitch if cycle.kind == "tap" else -cycle.pitch, speed=rpm)
        if cycle.kind == "peck_deep":
            assert cycle.q is not None and cycle.clearance is not None
            return cls(NAMES[cycle.kind], rtp, cycle.r, cycle.bottom, None, min(cycle.q, cycle.r - cycle.bottom),
                       cycle.clearance)
        if cycle.kind in BORING or cycle.kind == "bore_manual":
            dwell = cycle.dwell if cycle.kind != "bore_feed" else None
            return cls(NAMES[cycle.kind], rtp, cycle.r, cycle.bottom, dwell or None,
                       feed=cycle.feed if cycle.kind in BORING else None)
        dwell = cycle.dwell if cycle.kind == "drill_dwell" else None
        return cls(NAMES[cycle.kind], rtp, cycle.r, cycle.bottom, 0.0 if cycle.kind == "drill_dwell" and dwell is None
                   else dwell)

    def text(self, number: Callable[[float], str], feed: Callable[[float], str], once: bool = False) -> str:
        """``number`` spells a level as the writer spells a Z value, ``feed`` a feed as it spells F (so
        ``CYCLE85``'s FFR reads back as the F in force). A deep hole: ``FDEP`` the first stroke's depth,
        ``DAM``, ``DTB``, ``DTS`` 0, ``FRF`` 1, ``VARI`` 1 (swarf removal), ``_DTD`` 0 and ``_DIS1`` d
        (``deep_hole``, which reads it back). ``once``: the call alone, which drills where the tool stands and
        leaves no call active (``cycles``: how the reader reads it)."""
        params = [number(self.rtp), number(self.rfp), "0", number(self.dp)]
        dtb = "" if self.dtb is None else _seconds(self.dtb)
        if self.pitch is not None:
            # SDAC the tap's own direction (3: M3 right-hand, 4: M4 left-hand), MPIT empty, PIT, POSS 0, SST = SST1
            # [K: the Autodesk siemens-840d.cps onCycle writes a tap so; ``tapping`` reads it back]
            speed = "" if self.speed is None else _speed(self.speed)
            params += ["", dtb, "3" if self.pitch > 0 else "4", "", number(self.pitch), "0", speed, speed]
        elif self.name == "CYCLE840":
            # SDR the way out reversed, SDAC the tap's own direction, ENC 1: G63 at the F in force (``tapping``)
            params += ["", dtb, *(("3", "4") if self.left else ("4", "3")), "1"]
        elif self.stroke is not None:
            params += ["", number(self.rfp - self.stroke), "", "0", "0", "0", "1", "1", "", "", "", "0",
                       number(self.clearance)]
        elif self.name == "CYCLE85":
            assert self.feed is not None
            params += ["", dtb, feed(self.feed), feed(self.feed)]
        elif self.name == "CYCLE88":
            params += ["", dtb, "3"]
        elif self.dtb is not None:
            params += ["", dtb]
        return f"{'' if once else 'MCALL '}{self.name}({', '.join(params)})"


def _speed(value: float) -> str:
    return f"{value:.6f}".rstrip("0").rstrip(".")


def _seconds(value: float) -> str:
    text = f"{round(value * 1000) / 1000:.3f}".rstrip("0")
    return text + "0" if text.endswith(".") else text

