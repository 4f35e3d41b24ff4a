"""The finishing shape of a roughing cycle whose profile compensates the tool nose: the imaginary tool tip's
path while the nose runs along the profile under the controller's compensation, which the cycle roughs to
(plus its finishing allowance).

A profile that turns tool nose radius compensation on in its first block and off in its last (``G42`` in
the P block, ``G40`` in the Q block: the Haas form) is a finished shape the tool's round nose must touch.
The cycle then roughs along the shape offset by the nose, not along the programmed one: it applies the
compensation to the finishing shape and roughs along the offset shape [?: Fanuc 0i-TC B-64114EN / 0i-TF
B-64604EN, "tool nose radius compensation in multiple repetitive canned cycle", as the task that asked
for this cites them; the manuals' text was not reached in this session (the search corpora hold none of
it)]. The form itself is the Haas one [K: Haas lathe operator's manual, G71 with TNC: G41/G42 in the P
block, G40 in the Q block, as known, not re-read here].

The offset shape is the path the controller's own compensation makes of the profile, by one algorithm:
the profile's blocks run through the compensation the simulation runs G70 with (``CutterRules``, a Haas
lathe's ``cutter_rules.HAAS_T``: Fanuc T's start-up, corners and cancel; ``compensation.extended_corners``), so
the roughing leaves the allowance beside the very path the finishing pass takes. Of that path the shape
is the part between the approach (the first block, whose end the start-up rule places) and the departure
(the last block, no part of the shape): every point the imaginary tool tip, the nose centre moved by the
radius in the tip's direction (``postproc.compensation.nose``).

Coordinates are the turning library's: radii (x) and z in program units, arcs in the (z, x) frame.
"""

from __future__ import annotations

import math
from typing import Sequence

from postproc.compensation.cutter_radius import CutterRadius, Item, Segment
from postproc.compensation.extended_corners import ExtendedCorners
from postproc.compensation.rules import CutterRules
from postproc.errors import PostprocError, ProgramError

from .profile import EPS, Seg

Vec = tuple[float, float]
"""(z, x): the plane's first axis, then its second."""


def nose_path(profile: Sequence[Seg], side: str, radius: float, tip: tuple[int, int], name: str,
              rules: CutterRules) -> list[Seg]:
    """The imaginary tip's path along the blocks of ``profile`` between its first (the approach, which turns
    compensation on) and its last (the departure, which turns it off), compensated under ``rules`` for a
    nose of ``radius`` (program units, > 0) on ``side`` ('left' or 'right'); ``tip``: the (Z, X) signs from
    the nose centre to the imaginary tip (``nose.TIPS``). What the compensation refuses (a concave arc no
    wider than the nose, a block shorter than its corner takes, a reversal) is refused here, named."""
    if side not in ("left", "right"):
        raise ProgramError(f"{name}: tool nose radius compensation {side!r} is not left or right")
    if not radius > 0.0 or not math.isfinite(radius):
        raise ProgramError(f"{name}: the tool nose radius must be positive, not {radius:g}")
    if len(profile) < 3:
        raise ProgramError(f"{name}: the compensated profile has no block between its first and its last")
    released: list[Item] = []
    engine: CutterRadius = ExtendedCorners(rules, released.append) if rules.outside_corner == "extend" \
        else CutterRadius(rules, released.append)
    segments = [_segment(seg) for seg in profile]
    try:
        engine.start(side, radius, "ZX", (float(tip[0]), float(tip[1])))
        for seg, segment in zip(profile[:-1], segments):
            _run(engine, seg, segment)
        engine.cancel()
        _run(engine, profile[-1], segments[-1])
        engine.finish()
    except PostprocError as err:
        raise type(err)(f"{name}: {err.message}") from None
    return _tip_path(released, profile, segments)


def _segment(seg: Seg) -> Segment:
    """A profile block as a move of the compensation (plane points (z, x))."""
    kind = ("rapid" if seg.rapid else "feed") if seg.kind == "line" else seg.kind
    segment = Segment(kind, {"line": seg.line}, {"Z": seg.z1, "X": seg.x1})
    if seg.kind != "line":
        assert seg.cx is not None and seg.cz is not None
        segment.centre = segment.ccentre = (seg.cz, seg.cx)
        segment.turn = 1 if seg.kind == "ccw" else -1
    return segment


def _run(engine: CutterRadius, seg: Seg, segment: Segment) -> None:
    start = (seg.z0, seg.x0)
    if segment.turn:
        engine.arc(segment, start)
    else:
        engine.line(segment, start)


def _tip_path(released: list[Item], profile: Sequence[Seg], segments: list[Segment]) -> list[Seg]:
    """The released moves from the approach's end to the departure, as profile segments: each block at its
    compensated end (an arc about its compensated centre), a corner's straight moves with the block before
    them."""
    source = {id(segment): seg for seg, segment in zip(profile, segments)}
    moves = [item for item in released if isinstance(item, Segment)]
    approach, departure = segments[0], segments[-1]
    at = next(i for i, item in enumerate(moves) if item is approach)
    last = moves[at]
    path: list[Seg] = []
    owner = profile[0]
    for item in moves[at + 1:]:
        if item is departure:
            break
        if last.xy is None or item.xy is None:
            raise ProgramError("a compensated block has no compensated end")  # the engine sets every one
        owner = source.get(id(item), owner)
        (z0, x0), (z1, x1) = last.xy, item.xy
        if math.hypot(z1 - z0, x1 - x0) <= EPS and item.turn == 0:
            last = item
            continue
        if item.turn:
            assert item.ccentre is not None
            path.append(Seg("ccw" if item.turn > 0 else "cw", x0, z0, x1, z1, item.ccentre[1], item.ccentre[0],
                            owner.feed, owner.line, owner.rapid))
        else:
            path.append(Seg("line", x0, z0, x1, z1, None, None, owner.feed, owner.line, owner.rapid))
        last = item
    return path
