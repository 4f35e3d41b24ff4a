"""``CYCLE84`` (tapping without a compensating chuck, a rigid tap) read as Fanuc's rigid tap (``M29 S..`` then
``G84``/``G74``) exactly where the two move alike, else kept verbatim.

Its parameters [K: PGZ cycles manual 11/2006 6FC5398-3BP20-0BA0 2.1.5 "Rigid tapping - CYCLE84", as a
Polish 810D/840D course quotes them (zanotowane.pl/933/9458) and the Autodesk ``siemens-840d.cps``
``onCycle`` writes them]: ``RTP, RFP, SDIS, DP, DPR`` as every drilling cycle, ``DTB`` the dwell at the
thread's depth in seconds, ``SDAC`` the spindle's direction after the cycle (3: M3, 4: M4, 5: M5), ``MPIT``
the pitch as a metric thread size (3 for M3 ... 48 for M48) or ``PIT`` the pitch as a value, each signed
(positive: right-hand thread, negative: left-hand), ``POSS`` the spindle position of the oriented stop
before tapping (degrees), ``SST`` the spindle speed tapping in, ``SST1`` the speed of the way out, ``_AXN``
the tool axis; then ``_PTAB`` (the unit of PIT), ``_TECHNO``, ``_VARI`` (0: tap to the depth in one go;
1 and 2: chip breaking or removal, by ``_DAM`` and ``_VRT``) of newer cycles. The Autodesk post writes a
plain tap as ``CYCLE84(RTP, RFP, SDIS, DP, , DTB, SDAC, , PIT, 0, S, S)``: SDAC the direction the spindle
turned before, PIT signed by the tap's hand, POSS 0, SST = SST1 = the spindle speed in force, and with
chip breaking ``_AXN 0, _PTAB 0, _TECHNO 0, _VARI 1`` after them.

What it does [K: PGZ 2.1.5, sequence of motions]: G0 to RFP+SDIS; oriented spindle stop at POSS, the spindle
changed to axis mode; tapping to the final depth at the speed SST, synchronised with the spindle at the
pitch, the spindle's direction that of the thread's hand; dwell DTB; back to RFP+SDIS at the speed SST1 with
the direction reversed; G0 to RTP; the spindle back in speed mode at the speed in force before the call and
in the direction SDAC. That is Fanuc's rigid ``G84`` (``G74`` for a left-hand thread) with R = RFP+SDIS, P =
DTB in ms and the pitch PIT [K: Fanuc 0i-MF operator's manual, rigid tapping: rapid to R, tap to Z, dwell P,
spindle reversed, tap back to R, G98 rapid to the initial level; the spindle turns the tap's direction
after it], when:

* ``PIT`` is given and ``MPIT`` is empty (the metric size's table is not modelled here), ``_PTAB`` empty or 0
  (PIT in the program's unit [?: the other values' units are not confirmed here]);
* ``SDAC`` is the tap's own direction: 3 for a right-hand thread, 4 for a left-hand one (Fanuc's spindle
  turns that way after its rigid tap); 5, or the other direction, is kept verbatim;
* ``SST`` is the spindle speed in force at each hole (Fanuc's rigid tap runs at the S in force, and
  SINUMERIK restores the speed before the call afterwards), ``SST1`` empty, 0 or SST [?: that an empty or 0
  SST1 returns at SST is not confirmed here, and SINUMERIK does not run the way out at another speed than
  the way in where they are the same];
* ``POSS`` empty or 0: the oriented stop moves no axis, and the thread's start on the spindle is where the
  cycle puts it whatever Fanuc does [?: whether Fanuc's rigid tap orients the spindle is a machine parameter];
  another angle is kept verbatim, so a program that re-cuts a thread at its own angle is never read as one
  that does not;
* ``_AXN`` empty or 3 (the tool along Z), ``_TECHNO`` empty or 0 and ``_VARI`` empty or 0 (one pass to the
  depth: Fanuc's peck rigid tap returns per a machine parameter);
* DTB is a whole number of milliseconds (``cycles.cycle_words``).

``CYCLE840`` (tapping with a compensating chuck) [K: PGZ 11.02 p.2-86 (manual.onestart.ai) and 11/2006
2.1.6]: ``RTP, RFP, SDIS, DP, DPR, DTB``, then ``SDR`` the direction of the way out (0: reversed by the cycle,
with an encoder only), ``SDAC`` the direction for the next threads of a modal call, "the direction of rotation
programmed before the first call", ``ENC`` 1 to tap without the encoder (``G63``: the feed in force, the chuck
taking up the difference), ``MPIT``/``PIT`` a lead from which the cycle computes the feed (SW 6.2 on). Without
an encoder it moves: G0 to RFP+SDIS; G63 to the depth at the F in force; dwell DTB; G63 back to RFP+SDIS with
the spindle turning SDR; G0 to RTP; the spindle in SDAC again. That is Fanuc's (floating) ``G84``/``G74`` under
G99 [K: Fanuc 0i-MF, tapping cycle: feed to Z, dwell P, spindle reversed, feed back to R, the spindle turning
the tapping direction again], read so only where:

* ``ENC`` is 1 and ``MPIT``/``PIT`` are empty (the F in force; a lead's computed feed, and what F is in force
  after it, are not confirmed here [?]), ``_PTAB``/``_TECHNO`` empty or 0, ``_AXN`` empty or 3;
* ``SDAC`` is 3 or 4 and ``SDR`` the other (the way out reversed), and the spindle turns SDAC at the call (the
  first thread is tapped in the direction in force);
* RTP is RFP+SDIS (whether the spindle turns back to SDAC before or after the G0 to RTP is not confirmed [?]),
  G94 is in force (whether G63 runs under G95 is not confirmed [?]) (``cycles.SiemensCycleRules``).

The meaning then is a ``CannedCycle`` of kind ``tap``/``tap_left`` with ``pitch`` PIT (``RigidTap`` in every
expansion: ``postproc.lowering.synchronised_tap``), so LinuxCNC gets ``G33.1`` and the Fanuc family its ``M29`` tap
cycle, and a target that cannot synchronise the spindle (grbl) refuses it by name.
"""

from __future__ import annotations

from .deep_hole import Unconfirmed

SAME = 1e-9
"""Speeds closer than this (rev/min) are the same."""
RIGHT, LEFT = 3.0, 4.0
"""SDAC's codes of the spindle's directions (M3, M4) [K: PGZ 2.1.5]."""


def rigid_tap(given: dict[str, float | None]) -> tuple[str, float, float]:
    """The kind (``tap`` or ``tap_left``), the pitch (no sign) and the tapping speed SST of ``CYCLE84`` with
    parameters ``given``; ``Unconfirmed`` names what is not read (the module docstring)."""
    if given.get("MPIT") is not None:
        raise Unconfirmed("CYCLE84 with MPIT (the pitch of a metric thread size is not modelled: give PIT)")
    pit = given.get("PIT")
    if pit is None or pit == 0:
        raise Unconfirmed("CYCLE84 without its pitch PIT")
    if given.get("_PTAB") not in (None, 0):
        raise Unconfirmed("CYCLE84 with _PTAB other than 0 (the unit of PIT is not confirmed here)")
    kind, own = ("tap", RIGHT) if pit > 0 else ("tap_left", LEFT)
    sdac = given.get("SDAC")
    if sdac != own:
        shown = "empty" if sdac is None else f"{sdac:g}"
        raise Unconfirmed(f"CYCLE84 with SDAC {shown} (read with SDAC={own:g}, the direction a "
                          f"{'right' if own == RIGHT else 'left'}-hand tap turns: Fanuc's spindle keeps it after "
                          "its rigid tap)")
    sst = given.get("SST")
    if sst is None or sst <= 0:
        raise Unconfirmed("CYCLE84 without its tapping speed SST")
    sst1 = given.get("SST1")
    if sst1 not in (None, 0) and abs(float(sst1 or 0.0) - sst) > SAME:
        raise Unconfirmed("CYCLE84 with SST1 other than SST (Fanuc's rigid tap returns at the speed it taps at)")
    if given.get("POSS") not in (None, 0):
        raise Unconfirmed("CYCLE84 with POSS other than 0 (the thread's start at an angle of its own)")
    if given.get("_AXN") not in (None, 3):
        raise Unconfirmed("CYCLE84 with _AXN other than 3 (read with the tool along Z)")
    for name in ("_TECHNO", "_VARI"):
        if given.get(name) not in (None, 0):
            raise Unconfirmed(f"CYCLE84 with {name} other than 0 (read as one pass to the depth: Fanuc's peck rigid "
                              "tap returns per a machine parameter)")
    return kind, abs(float(pit)), float(sst)


def floating_tap(given: dict[str, float | None]) -> str:
    """The kind (``tap`` or ``tap_left``) of ``CYCLE840`` with parameters ``given``, tapping without the
    encoder at the F in force; ``Unconfirmed`` names what is not read (the module docstring)."""
    if given.get("ENC") != 1:
        raise Unconfirmed("CYCLE840 with ENC other than 1 (with the encoder it taps by G33 at a lead, not confirmed "
                          "against Fanuc's G84 here)")
    if given.get("MPIT") is not None or given.get("PIT") is not None:
        raise Unconfirmed("CYCLE840 with a lead MPIT/PIT (its computed feed, and the F in force after it, are not "
                          "confirmed here)")
    for name in ("_PTAB", "_TECHNO"):
        if given.get(name) not in (None, 0):
            raise Unconfirmed(f"CYCLE840 with {name} other than 0")
    if given.get("_AXN") not in (None, 3):
        raise Unconfirmed("CYCLE840 with _AXN other than 3 (read with the tool along Z)")
    sdac, sdr = given.get("SDAC"), given.get("SDR")
    if sdac not in (RIGHT, LEFT) or sdr != (LEFT if sdac == RIGHT else RIGHT):
        raise Unconfirmed(f"CYCLE840 with SDR {_shown(sdr)} and SDAC {_shown(sdac)} (read with SDAC 3 or 4 and SDR the "
                          "other: the way out reversed)")
    return "tap" if sdac == RIGHT else "tap_left"


def _shown(value: float | None) -> str:
    return "empty" if value is None else f"{value:g}"
