"""``CYCLE83`` (deep-hole drilling) read as Fanuc's ``G83`` exactly where the two move alike, else kept verbatim.

What the cycle does with swarf removal (``VARI=1``) [K: PGZ cycles manual 11/2006 6FC5398-3BP20-0BA0 2.1.4
"Deep-hole drilling - CYCLE83", sequence of motions; known, not verified here: the search corpora hold only
excerpts of it]: G0 to RFP+SDIS; G1 to the first drilling depth at the feed in force times FRF; dwell DTB; G0
back to RFP+SDIS to remove the swarf; dwell DTS; G0 down to the depth last reached less the anticipation
distance; G1 to the next depth at the feed in force; and so on to the final depth; G0 to RTP. The
anticipation distance is ``_DIS1`` where it is positive, computed by the cycle where it is 0.

That is Fanuc's G83 (rapid to R, feed Q, rapid to R, rapid to d above the last depth, feed, ... rapid out)
with R = RFP+SDIS, Q the stroke, d = ``_DIS1`` and no dwells, when every stroke is the same: ``DAM`` 0 is
no degression [K: the Autodesk ``siemens-840d.cps`` ``onCycle`` writes a constant-peck deep drilling as
``FDEP = stock - incrementalDepth`` with ``_DAM`` = the peck reduction (0 for a constant peck), ``FRF`` 1 and
``VARI`` 1; a second CAM post's comment, after the job-planning manual 10/2015 pp. 651-663, writes G83 as
``CYCLE83`` with degression 0, FRF 1 and VARI 1, and G73 as VARI 0].

Read natively only where nothing unconfirmed is involved; kept verbatim (``Unconfirmed``) otherwise:

* ``VARI`` 1 only: chip breaking (``VARI`` 0) retracts by ``_VRT`` (1 mm in older cycles) with G1 at the
  feed [K: PGZ 2.1.4], where Fanuc's G73 retracts at rapid; an empty ``VARI`` has no confirmed default [?];
* ``SDIS`` 0: whether the later strokes are measured from RFP or from RFP+SDIS is not confirmed [?] (the
  two agree when SDIS is 0);
* a whole number of strokes: how the cycle shares out a remainder (the manual's "the last two strokes are
  of equal length" is said of the degression) is not confirmed for DAM 0 [?]; a remainder within the
  written numbers' rounding (``WRITTEN``: an inch program's 8 decimals) is none, the stroke the depth's share;
* ``FRF`` 1 as written (an empty FRF's default is not confirmed [?]); ``DAM``, ``DTB``, ``DTS`` and ``_DTD``
  empty or 0 (Fanuc's G83 has no dwells); ``_AXN`` empty or 3 (the tool along Z); ``_DIS1`` positive (0 is
  the distance the cycle computes [?]); ``_MDEP`` (the least stroke under degression) empty or not above the
  stroke; ``_VRT`` is chip breaking's and is not read;
* exactly one of ``FDEP`` (absolute) and ``FDPR`` (below RFP, no sign), the first depth not below the final
  one.

``_DIS1`` is each hole's own d (``cycles.deep_hole_clearance``). Fanuc's G83 takes its d from a machine
parameter, the set-up's ``<Cycles peckClearance>``: where ``_DIS1`` is another, every other dialect gets the
holes' exact moves instead of a native G83.
"""

from __future__ import annotations

SAME = 1e-9
"""Lengths closer than this (program units) are the same."""
WRITTEN = 1e-8
"""How far one written number may be from the length it stands for (program units): 8 decimals of an inch
(the writers' places) round by up to 5e-9, so a depth of n strokes converted to inches and written reads
back up to (n + 1) * 1e-8 off n times its stroke (RFP, FDEP, DP each rounded); that is no remainder."""


class Unconfirmed(Exception):
    """A ``CYCLE83`` whose motion is not confirmed as Fanuc's G83: kept verbatim, named by ``what``."""

    def __init__(self, what: str) -> None:
        super().__init__(what)
        self.what = what


def deep_hole(given: dict[str, float | None], r: float, bottom: float) -> tuple[float, float]:
    """The stroke (Fanuc's Q) and the anticipation distance (Fanuc's d) of ``CYCLE83`` with parameters
    ``given``, whose R level is ``r`` and final depth ``bottom``; ``Unconfirmed`` names what is not read."""
    vari = given.get("VARI")
    if vari != 1:
        shown = "empty" if vari is None else f"{vari:g}"
        raise Unconfirmed(f"CYCLE83 with VARI {shown} (read with VARI=1, swarf removal: chip breaking retracts at "
                          "the feed, Fanuc's G73 at rapid)")
    if given.get("SDIS"):
        raise Unconfirmed("CYCLE83 with SDIS other than 0 (whether its strokes are measured from RFP or from "
                          "RFP+SDIS is not confirmed here)")
    if given.get("FRF") != 1:
        raise Unconfirmed("CYCLE83 with FRF other than 1 (Fanuc's G83 drills its first peck at the feed in force)")
    for name in ("DAM", "DTB", "DTS", "_DTD"):
        if given.get(name):
            raise Unconfirmed(f"CYCLE83 with {name} (read with DAM, DTB, DTS and _DTD 0: Fanuc's G83 has no "
                              "degression and no dwells)")
    if given.get("_AXN") not in (None, 3):
        raise Unconfirmed("CYCLE83 with _AXN other than 3 (read with the tool along Z)")
    fdep, fdpr = given.get("FDEP"), given.get("FDPR")
    if (fdep is None) == (fdpr is None):
        raise Unconfirmed("CYCLE83 without exactly one of FDEP and FDPR (the first depth)")
    first = float(fdep) if fdep is not None else float(given.get("RFP") or 0.0) - float(fdpr or 0.0)
    stroke = r - first
    depth = r - bottom
    if stroke <= SAME or first < bottom - SAME:
        raise Unconfirmed("CYCLE83 whose first depth is not between RFP and the final depth")
    strokes = max(1, round(depth / stroke))
    if abs(depth - strokes * stroke) > WRITTEN * (strokes + 1):
        raise Unconfirmed(f"CYCLE83 whose depth {depth:g} is not a whole number of strokes of {stroke:g} (how it "
                          "shares out a remainder is not confirmed here)")
    stroke = depth / strokes  # the strokes, all the same, that make the depth (the written numbers' rounding out)
    mdep = given.get("_MDEP")
    if mdep is not None and mdep > stroke + SAME:
        raise Unconfirmed("CYCLE83 with _MDEP above its stroke")
    dis1 = given.get("_DIS1")
    if dis1 is None or dis1 <= 0:
        raise Unconfirmed("CYCLE83 with _DIS1 empty or 0 (the anticipation distance the cycle computes is not "
                          "confirmed here)")
    return stroke, float(dis1)
