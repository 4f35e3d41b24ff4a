"""Fagor 8070 codes: one table, read by the block syntax and inverted by the writer.

Rows are ``(spelling, modal group, kind, argument)`` (``postproc.rs274.codes``). What each collision
with Fanuc's numbers means here (DIALECTS.md 1.4, 2.3, 3.4):

* ``G70``/``G71`` are inch/mm (Fanuc ``G20``/``G21``) [K].
* ``G98``/``G99`` return to the initial / reference plane after a hole cycle, as on Fanuc [V].
* ``G159=n`` selects zero offset n [V for the syntax]: ``G159=1``-``G159=6`` are ``G54``-``G59``
  (the writer spells those as ``G54``-``G59``); a higher n is kept verbatim (``native_g``).
* ``G81`` drills with a dwell ``K`` at the bottom (Fanuc's ``G82``; without ``K`` it is ``G81``) and
  ``G89`` bores with a dwell and a withdrawal at the work feed (Fanuc's ``G89``; ``G85`` without the
  dwell) [K: the 8055 family's words ``Z I K``].
* ``G82``-``G88`` are kept verbatim: the words of G82 (variable peck), G83 (peck) and G84 (tapping) and
  the motion of G85 (reaming) and G86 (boring, rapid withdrawal) are not confirmed [?], and ``G87``/
  ``G88`` are the rectangular and circular pockets, not Fanuc's back and manual boring. So a Fanuc
  ``G73``, ``G74``, ``G76``, ``G83``, ``G84``, ``G86``, ``G87`` or ``G88`` reaches Fagor expanded, never
  as the Fagor code of the same number.
* A rigid (spindle-synchronised) tap is refused by name (``Fagor`` has neither ``TAP_STROKES`` nor
  ``SYNCHRONISED_TAP``): the 8070's ``G84`` takes an ``R`` word that selects normal or rigid tapping [?:
  DIALECTS.md 2.3; Autodesk's post for a Fagor 8065 writes ``G84 .. Z I K R0 F``], and ``G63`` is named a
  rigid tap in Fagor's lists [?], but neither's words nor how the feed follows the pitch are confirmed.
* ``G04 K`` dwells, ``K`` in the unit of the cycle dwell (the set-up's ``fagorDwellUnit``) [?: the 8055
  family's form; the 8070's unit is not confirmed, as for the cycle ``K``].
* ``M19`` orients the spindle to the machine's angle (the set-up's ``orientAngle``) [?: the ISO M code;
  an expansion writes it only when the set-up says ``<Cycles orientation="m19"/>``].
* ``G160``-``G165`` (multiple machining) are routed by the block syntax to its hook, not read here.
* ``M17``/``M29`` end a local subroutine [?]: kept verbatim.
* Corners [V: 8070 programming manual REF 1709 p.197, "Controlled corner rounding, radius blend
  (G05/G61)"]: ``G05`` (modal) and ``G61`` (one block) round each corner along a curve, not an arc, whose
  shape the ``#ROUNDPAR`` type in force and the axes' feed and acceleration set; ``G05`` excludes ``G07``,
  ``G50``, ``G60`` and ``G61``, and at power-up, ``M02``/``M30`` or a reset the CNC takes ``G05``, ``G07`` or
  ``G50`` as the OEM's parameter ICORNER says. ``G05`` is read and written as the cutting mode (Fanuc's
  ``G64``, LinuxCNC's ``G64`` without ``P``): the path runs through each corner without an exact stop, the
  deviation left to the machine (its ``#ROUNDPAR``), as every dialect that writes no blending tolerance
  leaves it (``WordWriter.note_unwritten_tolerance`` warns where a program gave one) [K: the p.197 text
  against Fanuc's cutting mode]. A ``#ROUNDPAR`` line is kept verbatim, so a Fagor program that sets the
  rounding is refused elsewhere, never read as the default. ``G07`` is the square corner (each block ends in
  position) and ``G60`` its one-block form [K: the 8055 family's G07; G60's one-block meaning from the 8070's
  list; the 8060/8065 ISO lists "G07 square corner (modal), see G60"]: Fanuc's ``G61``/``G09`` are written so.
  ``G50`` and ``G61`` are kept verbatim: ``G61`` rounds one block (Fanuc has no such one-shot mode) and
  ``G50``'s rounding is not confirmed [?]; Fanuc's ``G61`` is never written ``G61``.
* ``G53`` (one block) moves to coordinates referred to machine zero, without the zero offsets and the
  tool length and radius compensation [K: the 8055 family's "programming with respect to machine zero
  (G53)", not modal, which cancels the compensations for its block; the 8065/8070 language keeps G53 for
  machine-coordinate moves (Autodesk's post for a Fagor 8065 retracts with ``G53``)]. A reference return
  (Fanuc ``G28``) is written as its intermediate point and a ``G53`` rapid to the set-up's home position of
  each axis it names (``FagorWriter.machine_move``); Fagor's own home search ``G74`` (which references the
  axes against their switches) is not written [?].
* ``G43`` applies the length of the selected tool offset ``D``; ``G44`` **cancels** it [V: 8055 programming
  manual 8.2, "G44: cancellation of tool length compensation"; [K] the 8070 keeps them]. Fanuc's ``G44`` is a
  negative offset: it is never written as Fagor's ``G44`` (refused, ``postproc.isg_family.tool_data``), and
  Fagor's ``G44`` is read as a cancel (written ``G49`` for Fanuc).
"""

from __future__ import annotations

from postproc.rs274.codes import CodeTable

ROWS = (
    ("G00", "01", "motion", "rapid"),
    ("G01", "01", "motion", "linear"),
    ("G02", "01", "motion", "cw"),
    ("G03", "01", "motion", "ccw"),
    ("G04", "00", "dwell", None),
    ("G17", "02", "plane", "XY"),
    ("G18", "02", "plane", "ZX"),
    ("G19", "02", "plane", "YZ"),
    ("G40", "07", "cutter", "off"),
    ("G41", "07", "cutter", "left"),
    ("G42", "07", "cutter", "right"),
    ("G43", "08", "length", "positive"),
    ("G44", "08", "length", "cancel"),
    ("G54", "14", "offset", 1),
    ("G55", "14", "offset", 2),
    ("G56", "14", "offset", 3),
    ("G57", "14", "offset", 4),
    ("G58", "14", "offset", 5),
    ("G59", "14", "offset", 6),
    ("G07", "15", "path", "exact_stop"),
    ("G05", "15", "path", "cutting"),
    ("G53", "00", "machine", None),
    ("G60", "00", "path_once", "exact_stop"),
    *((f"G159={n}", "14", "offset", n) for n in range(1, 7)),
    ("G70", "06", "units", "inch"),
    ("G71", "06", "units", "mm"),
    ("G80", "09", "cycle_cancel", None),
    ("G81", "09", "cycle", "drill_dwell"),
    ("G89", "09", "cycle", "bore_dwell_feed"),
    ("G90", "03", "distance", "absolute"),
    ("G91", "03", "distance", "incremental"),
    ("G94", "05", "feed_mode", "per_min"),
    ("G95", "05", "feed_mode", "per_rev"),
    ("G98", "10", "return", "initial"),
    ("G99", "10", "return", "r"),
    ("M00", "", "program", "stop"),
    ("M01", "", "program", "optional_stop"),
    ("M02", "", "program", "end"),
    ("M03", "", "spindle", "cw"),
    ("M04", "", "spindle", "ccw"),
    ("M05", "", "spindle", "stop"),
    ("M06", "", "tool_change", None),
    ("M07", "", "coolant", "mist"),
    ("M08", "", "coolant", "flood"),
    ("M09", "", "coolant", "off"),
    ("M19", "", "orient", None),
    ("M30", "", "program", "end_rewind"),
)
"""Codes whose meaning the IR models."""

CODES_OF_DWELLING = {str(arg): spelling for spelling, _, kind, arg in ROWS if kind == "cycle"}
"""The dwelling cycles' codes (``G81``, ``G89``)."""

CYCLE_ALIASES = {"drill": "drill_dwell", "bore_feed": "bore_dwell_feed"}
"""Neutral cycles Fagor writes as a dwelling cycle with no dwell (``K0`` when one is in force): ``G81``/``G89``
with ``K`` absent or 0 drill/bore without a dwell [V: Fagor 8055-M programming manual p.162 (G81), "[K5]
Dwell ... If not programmed, the CNC will take the value of K0"; [K] the same ``K`` for the 8070 and for G89].
The table writes them with those codes (``aliases``); reading, ``G81``/``G89`` are the dwelling rows and the
cycle resolution makes them these where no ``K`` is in force (``dialects.fagor.cycle_words.UNDWELLED``)."""

PATTERN_CODES = frozenset({"160", "161", "162", "163", "164", "165"})
"""Multiple machining: G160 line, G161 parallelogram, G162 grid, G163 full circle, G164 arc, G165 chord."""

MAX_OFFSET = 99
"""The highest ``G159=n`` read (kept verbatim above 6) [?: the 8070's table size is not known]."""

CODES = CodeTable(
    ROWS,
    native_g={
        "82": "drilling with variable peck [?]", "83": "deep-hole drilling with constant peck [?]",
        "84": "tapping [?]", "85": "reaming [?]", "86": "boring with rapid withdrawal [?]",
        "87": "rectangular pocket", "88": "circular pocket",
        "50": "controlled corner rounding",
        "61": "corner rounding for one block",
        # radius compensation's modes (cutter_rules.py: their constructions are in figures only [?])
        "136": "circular transitions between radius-compensated paths",
        "137": "linear transitions between radius-compensated paths",
        "138": "direct start and end of radius compensation", "139": "indirect start and end of radius compensation",
        **{f"159={n}": f"zero offset {n}" for n in range(7, MAX_OFFSET + 1)},
    },
    native_m={17: "end of a local subroutine [?]", 29: "end of a local subroutine [?]"},
    aliases={("cycle", plain): CODES_OF_DWELLING[dwelling] for plain, dwelling in CYCLE_ALIASES.items()},
)
"""Fagor's code table. ``native_g``/``native_m``: kept verbatim (they round-trip to Fagor, are refused
anywhere else and are never simulated)."""
