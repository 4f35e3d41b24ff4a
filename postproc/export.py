"""Exporting a toolpath: JSON lines, or a backplot drawn as SVG or PNG."""

from __future__ import annotations

import json
import math
from typing import Any, Callable, Iterable, Mapping, TextIO

from .errors import Diagnostics, Location, ProgramError, UsageError
from .setup import MachineSetup
from .dialect import Dialect
from .backplot import Backplot
from .toolpath import Event, start_position, toolpath_events


def export_toolpath(lines: Iterable[str], out: Any, *, file: str, dialect: str | type[Dialect],
                    setup: MachineSetup | None = None, fmt: str = "jsonl",
                    diagnostics: Diagnostics | None = None, on_unsupported: str = "error",
                    arguments: Mapping[str, float] | None = None) -> None:
    """Write a program's toolpath to ``out``: JSON lines or SVG (text streams), PNG (a binary stream).
    ``on_unsupported="warn"``: a move beyond the set-up's travel is a warning. ``arguments``: a macro
    file's call arguments (``toolpath_events``)."""
    setup = setup or MachineSetup()
    events = toolpath_events(lines, file=file, dialect=dialect, setup=setup, diagnostics=diagnostics,
                             on_unsupported=on_unsupported, arguments=arguments)
    if fmt == "jsonl":
        write_jsonl(events, out, file)
    elif fmt in ("svg", "png"):
        from .plugins import default_registry
        reading = default_registry().dialect(dialect) if isinstance(dialect, str) else dialect
        write_backplot(events, out, fmt, start_position(setup), reading.reads_lathe(setup))
    else:
        raise UsageError(f"unknown toolpath format {fmt!r} (jsonl, svg or png)")


def write_backplot(events: Iterable[Event], out: Any, fmt: str, start: dict[str, float], lathe: bool) -> None:
    """Draw a toolpath as SVG (a text stream) or PNG (a binary one), in memory that does not grow with
    the program (the points wait in a spill file until the picture is written)."""
    with Backplot(start, lathe=lathe) as plot:
        plot.add_all(events)
        if fmt == "svg":
            plot.write_svg(out)
        else:
            plot.write_png(out)


FLOATS_KEPT = 4096
"""Spellings of floats ``event_encoder`` keeps at most (then it starts again)."""


def event_encoder() -> Callable[[Event], str]:
    """``json.JSONEncoder(allow_nan=False).encode`` for a toolpath's events, faster on what they hold.

    Writing a float's shortest spelling (``float.__repr__``, as json does) is most of a toolpath's cost
    (3,500 instructions a float, six floats a move under a tool length: callgrind), yet a path repeats
    its numbers: the controlled point shares X and Y with the programmed one, Z stays through a pass. So
    the spelling of each float is kept (by value; zero, whose two signs compare equal, is spelled every
    time). An event is an object of string keys whose values are strings, ints, floats, booleans, None
    or such an object; anything else (a list, a subclass) is left to json's encoder, whose text this
    is, byte for byte (``tests/test_toolpath_numbers.py`` compares the two on random events). A float
    that is not finite raises ``ValueError``, as json's does under ``allow_nan=False``."""
    fallback = json.JSONEncoder(allow_nan=False).encode
    string = json.encoder.encode_basestring_ascii  # json's spelling of a string (ensure_ascii)
    spelled: dict[float, str] = {}
    names: dict[str, str] = {}
    float_repr, int_repr = float.__repr__, int.__repr__

    def encode(ev: Event) -> str:
        parts: list[str] = []
        for key, value in ev.items():
            kind = type(value)
            if kind is float:
                text = spelled.get(value)
                if text is None:
                    if value - value != 0.0:  # inf or nan
                        raise ValueError(f"Out of range float values are not JSON compliant: {value!r}")
                    text = float_repr(value)
                    if value:
                        if len(spelled) >= FLOATS_KEPT:
                            spelled.clear()
                        spelled[value] = text
            elif kind is int:
                text = int_repr(value)
            elif kind is str:
                text = string(value)
            elif kind is dict:
                text = encode(value)
            elif value is None:
                text = "null"
            elif value is True:
                text = "true"
            elif value is False:
                text = "false"
            else:
                raise _Unusual
            name = names.get(key) if type(key) is str else None
            if name is None:
                if type(key) is not str:
                    raise _Unusual
                name = names[key] = string(key) + ": "
            parts.append(name + text)
        return "{" + ", ".join(parts) + "}"

    def event(ev: Event) -> str:
        try:
            return encode(ev)
        except _Unusual:
            return fallback(ev)

    return event


class _Unusual(Exception):
    """An event holds what ``event_encoder`` leaves to json's encoder."""


def write_jsonl(events: Iterable[Event], out: TextIO, file: str = "<toolpath>") -> None:
    """One JSON object a line; strict JSON (no ``NaN``/``Infinity``): a non-finite value is an error
    at the event's source line."""
    write = out.write
    encode = event_encoder()
    for ev in events:
        try:
            text = encode(ev)
        except ValueError:
            bad = ", ".join(k for k, v in ev.items() if isinstance(v, float) and not math.isfinite(v))
            raise ProgramError(f"the toolpath has a value beyond the range of a float ({bad})",
                               Location(file, int(ev.get("line", 1)), 1)) from None
        write(text + "\n")
