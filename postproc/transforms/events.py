"""A toolpath moved by a program transform: what ``verify --transform`` compares a transformed output with.

Each move's programmed end point and arc centre go through the map; an arc whose plane the map turns over
changes direction. The controlled point (``controlled``: where tool length and cutter radius put the tool)
is the moved programmed point plus the tool's own offset, which the map does not scale or move: the
length along Z stays as it is, the cutter's offset in XY turns with the plane (a rotation or mirror) and
keeps its length (a uniform scaling in XY does not widen the cutter). Events other than moves pass as
they are.

Machine positions are not moved (``translate --transform`` keeps them: ``postproc.transforms.carry``): on each
axis the map changes, the start, and a reference return's move to the reference point (marked ``"held"`` by the
simulator: ``toolpath_events(..., mark_held=True)``), stay where they are, and so does every later point that
leaves that axis where it was, until a block programs it absolutely (``"programmed"``, marked by the
simulator likewise) or a move changes it (the translation refuses a move that would change it from there other
than to a programmed absolute point).
"""

from __future__ import annotations

import math
from typing import Any, Iterable, Iterator

from ..frames.affine import INDEX, XYZ, Affine
from .carry import untouched
from .spec import ProgramTransform

Event = dict[str, Any]
_POINT = (("x", "y", "z"), ("cx", "cy", "cz"))
_PLANES = {"XY": (0, 1), "ZX": (2, 0), "YZ": (1, 2)}
_TURNED = {"cw": "ccw", "ccw": "cw"}


def moved_events(events: Iterable[Event], transform: ProgramTransform,
                 start: dict[str, float] | None = None) -> Iterator[Event]:
    """``events`` moved by ``transform``; ``start``: the machine's start position (mm, by axis letter), held
    on the axes the map changes (the module docstring)."""
    fmap = transform.map
    m = fmap.m
    xy_factor = math.sqrt(abs(m[0] * m[4] - m[1] * m[3])) or 1.0
    touched = {a.lower() for a in XYZ if not untouched(fmap, INDEX[a])}
    holding = {a.lower(): v for a, v in (start or {}).items() if a.lower() in touched}
    """Held axis -> the machine position it stands at (mm)."""
    here = {a.lower(): v for a, v in (start or {}).items()}
    """Where the moved path stands (a move that went nowhere and still goes nowhere is dropped)."""
    for ev in events:
        if "move" not in ev:
            yield ev
            continue
        out = dict(ev)
        still = bool(out.pop("still", False))
        marked = str(out.pop("held", ""))
        programmed = str(out.pop("programmed", ""))
        for key in [k for k, v in holding.items() if k in programmed or k not in ev or abs(float(ev[k]) - v) > 1e-6]:
            del holding[key]  # programmed, or moved away: a point of the program again
        for key in marked:
            if key in touched:
                holding[key] = float(ev[key])
        held = set(holding) | set(marked)
        for keys in _POINT:
            if keys[0] in ev:
                out.update(zip(keys, fmap.point([float(ev.get(k, 0.0)) for k in keys])))
        for key in held:
            out[key] = ev[key]
        if still and all(abs(float(out[k]) - here.get(k, float("nan"))) <= 1e-6 for k in ("x", "y", "z") if k in ev):
            continue
        here.update((k, float(out[k])) for k in ("x", "y", "z") if k in ev)
        kind = ev["move"]
        if kind in _TURNED and _turns_over(fmap, str(ev.get("plane", "XY"))):
            out["move"] = _TURNED[kind]
        controlled = ev.get("controlled")
        if isinstance(controlled, dict):
            moved: Event = {}
            for keys in _POINT:
                if keys[0] not in controlled and keys[0] not in ev:
                    continue
                d = [float(controlled.get(k, ev.get(k, 0.0)) or 0.0) - float(ev.get(k, 0.0) or 0.0) for k in keys]
                turned = fmap.linear((d[0] / xy_factor, d[1] / xy_factor, 0.0))
                for i, k in enumerate(keys):
                    if k in controlled or k in ev:
                        moved[k] = out.get(k, 0.0) + turned[i] + (d[2] if i == 2 else 0.0)
            out["controlled"] = {k: controlled[k] if k in held else v for k, v in moved.items() if k in controlled}
        yield out


def _turns_over(fmap: Affine, plane: str) -> bool:
    i, j = _PLANES.get(plane, (0, 1))
    m = fmap.m
    return m[3 * i + i] * m[3 * j + j] - m[3 * i + j] * m[3 * j + i] < 0.0
