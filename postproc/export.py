"""Exporting a toolpath: JSON lines, or a backplot drawn as SVG or PNG."""

from __future__ import annotations

import json
from typing import Any, Iterable, TextIO

from .errors import UsageError
from .setup import MachineSetup
from .dialect import Dialect
from .backplot import Backplot
from .toolpath import Event, start_position, toolpath_events


def export_toolpath(lines: Iterable[str], out: Any, *, file: str, dialect: str | type[Dialect],
                    setup: MachineSetup | None = None, fmt: str = "jsonl") -> None:
    """Write a program's toolpath to ``out``: JSON lines or SVG (text streams), PNG (a binary stream)."""
    setup = setup or MachineSetup()
    events = toolpath_events(lines, file=file, dialect=dialect, setup=setup)
    if fmt == "jsonl":
        write_jsonl(events, out)
    elif fmt in ("svg", "png"):
        plot = Backplot(start_position(setup))
        plot.add_all(events)
        if fmt == "svg":
            plot.write_svg(out)
        else:
            plot.write_png(out)
    else:
        raise UsageError(f"unknown toolpath format {fmt!r} (jsonl, svg or png)")


def write_jsonl(events: Iterable[Event], out: TextIO) -> None:
    write = out.write
    encode = json.JSONEncoder().encode
    for ev in events:
        write(encode(ev) + "\n")
