"""Exporting a toolpath: JSON lines, or a backplot drawn as SVG or PNG."""

from __future__ import annotations

import json
import math
from typing import Any, Callable, Iterable, Mapping, TextIO

from ..errors import Diagnostics, Location, ProgramError, UsageError
from ..setup.machine_setup import MachineSetup
from ..dialect import Dialect
from ..simulate.event_text import EventValueError, write_lines
from ..simulate.move_record import MoveRecord, as_events
from ..collector import gc_paused
from ..simulate.toolpath import Event, start_position, toolpath_stream


def export_toolpath(lines: Iterable[str], out: Any, *, file: str, dialect: str | type[Dialect],
                    setup: MachineSetup | None = None, fmt: str = "jsonl",
                    diagnostics: Diagnostics | None = None, on_unsupported: str = "error",
                    arguments: Mapping[str, float] | None = None) -> None:
    """Write a program's toolpath to ``out``: JSON lines or SVG (text streams), PNG (a binary stream).
    ``on_unsupported="warn"``: a move beyond the set-up's travel is a warning. ``arguments``: a macro
    file's call arguments (``postproc.simulate.toolpath.toolpath_events``)."""
    setup = setup or MachineSetup()
    if fmt not in ("jsonl", "svg", "png"):
        raise UsageError(f"unknown toolpath format {fmt!r} (jsonl, svg or png)")
    diagnostics = diagnostics or Diagnostics()
    # ``toolpath_events`` without its Python generator: the writer pulls the simulator's compiled stream
    # itself (a ``yield from`` in interpreted code cost ~3,300 instructions an event: callgrind,
    # ``benchmarks/callgrind.sh fanuc toolpath 0``); its checks are made here, as it makes them at the end
    with gc_paused():
        events = toolpath_stream(lines, file=file, dialect=dialect, setup=setup, diagnostics=diagnostics,
                                 on_unsupported=on_unsupported, arguments=arguments)
        if fmt == "jsonl":
            write_jsonl(events, out, file)
        else:
            from ..plugins import default_registry
            reading = default_registry().dialect(dialect) if isinstance(dialect, str) else dialect
            write_backplot(as_events(events), out, fmt, start_position(setup), reading.reads_lathe(setup))
    diagnostics.check()


def write_backplot(events: Iterable[Event], out: Any, fmt: str, start: dict[str, float], lathe: bool) -> None:
    """Draw a toolpath as SVG (a text stream) or PNG (a binary one), in memory that does not grow with
    the program (the points wait in a spill file until the picture is written). The drawing's modules (with
    lxml, tempfile and shutil) are imported here: JSON lines, the default, has no use for them (~15 ms of a
    one-line toolpath's start)."""
    from ..drawing.backplot import Backplot
    with Backplot(start, lathe=lathe) as plot:
        plot.add_all(events)
        if fmt == "svg":
            plot.write_svg(out)
        else:
            plot.write_png(out)


def _bytes_write(out: TextIO) -> Callable[[bytes], object]:
    """How ``write_jsonl`` writes a chunk of ASCII bytes to the text stream ``out``: to its binary buffer, after what
    it holds as text (a text file), else decoded (a stream of text alone: ``io.StringIO``)."""
    buffer = getattr(out, "buffer", None)
    if buffer is not None:
        out.flush()
        write: Callable[[bytes], object] = buffer.write
        return write
    return lambda chunk: out.write(chunk.decode("ascii"))


def event_encoder() -> Callable[[Event], str]:
    """``json.JSONEncoder(allow_nan=False).encode`` for one event, made once: ``encode`` makes json's C
    encoder anew at every call, so the C encoder it would make is made here and kept (a fifth less CPU a
    toolpath event; writing each event's own floats with a kept spelling, in Python, cost more than it
    saved). Where json has none (not CPython), ``encode`` itself. Its text is json's
    (``tests/test_toolpath_numbers.py`` compares the two on random events)."""
    encoder = json.JSONEncoder(allow_nan=False)
    make = getattr(json.encoder, "c_make_encoder", None)
    if make is None:
        return encoder.encode
    # the arguments JSONEncoder.iterencode passes its C encoder, but no markers: an event holds no cycle
    chunks = make(None, encoder.default, json.encoder.encode_basestring_ascii, encoder.indent,
                  encoder.key_separator, encoder.item_separator, encoder.sort_keys, encoder.skipkeys,
                  encoder.allow_nan)
    join = "".join
    return lambda ev: join(chunks(ev, 0))


def write_jsonl(events: Iterable[Event | MoveRecord], out: TextIO, file: str = "<toolpath>") -> None:
    """One JSON object a line; strict JSON (no ``NaN``/``Infinity``): a non-finite value is an error
    at the event's source line. The text is json's (``postproc.simulate.event_text``, which hands what it
    does not write itself to json's encoder), in ASCII bytes: written to ``out``'s binary buffer where it has one
    (a file: no encoder's copy of each chunk), else as text."""
    try:
        write_lines(events, _bytes_write(out), event_encoder())
    except EventValueError as err:
        ev = err.event
        bad = ", ".join(k for k, v in ev.items() if isinstance(v, float) and not math.isfinite(v))
        raise ProgramError(f"the toolpath has a value beyond the range of a float ({bad})",
                           Location(file, int(ev.get("line", 1)), 1)) from None
