"""The Fanuc family's machine-specific codes: what most Fanuc-controlled mills have beyond the
standard M codes, and what each variant adds or means otherwise (a set-up's ``<MachineCodes>`` wins).

Machine builders choose these numbers, so the lists keep to the common ones: rigid tapping M29, gear
ranges M41-M44, through-spindle coolant M88/M89 (M50 on many Japanese builders' machines), the part
counter M31; Haas's own (its Operator's Manual M-code list: chip auger M31/M33, pallet change M50,
automatic door M80/M81, air blast M83/M84, 4th/5th axis brakes M10-M13, G103 block look-ahead limit,
G187 smoothness). What an M code does for the simulation is its action; the rest moves no axis.
"""

from __future__ import annotations

from postproc.rs274.machine_codes import Defaults, g, m

FANUC = (
    m(29, "rigid tapping", "rigid-tap"),
    m(31, "part counter"),
    *(m(n, f"gear range {n - 40}", "gear") for n in range(41, 45)),
    m(50, "through-spindle coolant on", "coolant-on"),
    m(88, "through-spindle coolant on", "coolant-on"),
    m(89, "through-spindle coolant off", "coolant-off"),
    g("5.1", "AI contour control", "QR"),
    g("8", "look-ahead control", "P"),
)
"""Every Fanuc-family variant's defaults."""

HAAS = (
    m(10, "4th axis brake on"), m(11, "4th axis brake release"),
    m(12, "5th axis brake on"), m(13, "5th axis brake release"),
    m(31, "chip auger forward"), m(33, "chip auger stop"),
    m(50, "pallet change"),
    m(80, "automatic door open"), m(81, "automatic door close"),
    m(83, "air blast on"), m(84, "air blast off"),
    g("103", "block look-ahead limit", "P"),
    g("187", "smoothness and corner rounding", "PE"),
)
"""Haas mills (NGC and classic control), over the family's list."""

DEFAULTS: Defaults = {"fanuc": FANUC, "haas": HAAS}
"""Controller variant -> its machine codes ('fanuc' is the family's base; 'fanuc-0m' has no others)."""

HAAS_LATHE = (
    m(21, "tailstock advance"), m(22, "tailstock retract"),
    m(23, "thread pull-out chamfer on", "thread-chamfer-on"),
    m(24, "thread pull-out chamfer off", "thread-chamfer-off"),
    m(31, "chip auger forward"), m(33, "chip auger stop"),
)
"""Haas lathes [K: Haas lathe operator's manual, M-code list, as known, not re-read here: M21 tailstock advance
and M22 tailstock retract (the public Haas programs of tests/heldout write M21 then G04 P3. "WAIT FOR TAILSTOCK",
and M22 at the end), M23 "Angle Out of
Thread On", M24 "Angle Out of Thread Off" (the G76/G92 pull-out of Setting 95), M31 chip auger forward, M33
chip auger stop; the public Haas programs of tests/heldout write M24 before a G76 whose pull-out would
otherwise leave the start point's X]."""

LATHE_DEFAULTS: Defaults = {"haas": HAAS_LATHE}
"""A Fanuc T lathe's defaults by variant (the mill list's codes are the machine builder's for mills)."""
