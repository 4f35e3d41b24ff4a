"""A toolpath moved by a program transform: what ``verify --transform`` compares a transformed output with.

Each move's programmed end point and arc centre go through the map; an arc whose plane the map turns over
changes direction. The controlled point (``controlled``: where tool length and cutter radius put the tool)
is the moved programmed point plus the tool's own offset, which the map does not scale or move: the
length along Z stays as it is, the cutter's offset in XY turns with the plane (a rotation or mirror) and
keeps its length (a uniform scaling in XY does not widen the cutter). Events other than moves pass as
they are.

A reference return's move to the reference point (marked ``"held"`` by the simulator: ``toolpath_events(...,
mark_held=True)``) keeps the axes it names where they are: they are machine positions, which the transform
does not move (``translate --transform`` keeps the return as written: ``postproc.transforms.carry``).
"""

from __future__ import annotations

import copy
import dataclasses
import math
from typing import Any, Iterable, Iterator

from ..frames.affine import Affine
from ..setup.machine_setup import MachineSetup
from .spec import ProgramTransform

Event = dict[str, Any]
_POINT = (("x", "y", "z"), ("cx", "cy", "cz"))
_PLANES = {"XY": (0, 1), "ZX": (2, 0), "YZ": (1, 2)}
_TURNED = {"cw": "ccw", "ccw": "cw"}


def moved_events(events: Iterable[Event], transform: ProgramTransform) -> Iterator[Event]:
    fmap = transform.map
    m = fmap.m
    xy_factor = math.sqrt(abs(m[0] * m[4] - m[1] * m[3])) or 1.0
    for ev in events:
        if "move" not in ev:
            yield ev
            continue
        out = dict(ev)
        held = str(out.pop("held", ""))
        for keys in _POINT:
            if keys[0] in ev:
                out.update(zip(keys, fmap.point([float(ev.get(k, 0.0)) for k in keys])))
        for key in held:
            out[key] = ev[key]
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


def moved_setup(setup: MachineSetup, transform: ProgramTransform) -> MachineSetup:
    """``setup`` with the tool starting at its start position's image: the transformed program is run
    from where the moved source would stand (a first move to the start, dropped as zero-length in the
    source's path, is dropped in the output's too). Not on a lathe: there the start is where the machine
    stands, held like a reference point (``postproc.transforms.carry``), so the caller keeps ``setup``."""
    machine = setup.machine
    mm = machine.mm()
    x, y, z = transform.map.point((machine.start_x * mm, machine.start_y * mm, machine.start_z * mm))
    moved = copy.copy(setup)
    moved.machine = dataclasses.replace(machine, start_x=x / mm, start_y=y / mm, start_z=z / mm)
    return moved


def _turns_over(fmap: Affine, plane: str) -> bool:
    i, j = _PLANES.get(plane, (0, 1))
    m = fmap.m
    return m[3 * i + i] * m[3 * j + j] - m[3 * i + j] * m[3 * j + i] < 0.0
