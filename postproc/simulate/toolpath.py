"""Toolpath simulation: a block stream becomes a stream of motion and machine events (DESIGN.md,
"Toolpath JSON lines"), so two dialects' programs can be compared and drawn in one neutral frame.

Streaming: the simulator keeps the modal state and one position, never the program. It is a reading
"target" without native canned cycles: the blocks pass through the registered lowering transforms for
such a controller first, so cycles arrive expanded as ``CompoundMotion``.

Assumptions (a simulator knows no machine data):
- Positions are absolute work coordinates in mm from the set-up's start position (``Machine startX``...).
  A work offset the program sets (G10 L2: ``DataSetting``) shifts the absolute points programmed in its
  work system; the set-up's (``<WorkOffsets>``) do not (``postproc.simulate.work_offsets``).
- Tool length (G43/G44/G49) and, for a dialect with ``CUTTER_RULES``, cutter radius compensation move the
  controlled point (``postproc.compensation``); a move's event keeps the programmed point and carries the
  controlled one beside it (``controlled``) when they differ. Register values come from the program's own
  data settings, else the set-up's ``<Tools>``; a register with neither is a located error.
- Machine coordinates (G53, always absolute) are put in the work frame less the set-up's offset of the
  active work system (``Simulator.machine_to_frame``); a change of work system after the first move
  gives the point the machine stands at in the new system (``Moves.reframe``). Without ``<WorkOffsets>``
  in the set-up every offset is zero; a set-up that gives some but not the one needed is a located error.
- A reference return (G28/G30) rapids to the intermediate point, then to the reference point, machine
  zero on the axes named in the block; on a mill, G28 goes to the set-up's ``<Axis home>`` where it
  gives one (machine positions, put in the work frame as G53's are).
- Arc centres ``cx, cy, cz`` are absolute; on the axis normal to the plane the centre carries the arc's
  start value. ``plane`` is the IR's name of the plane: "XY", "ZX" or "YZ".
- Optional-skip blocks (``/``) are executed, as with the block-delete switch off.
- After the program end (M02/M30, or a closing ``%``) no more events are emitted; the rest is still
  read and checked, and the lines of live blocks there (``postproc.lowering.program_end``) are recorded in
  ``Simulator.live_after_end`` for ``verify``.
- A T word alone is a preselection on a mill (the ``tool`` event comes with the tool change, M06);
  on a lathe set-up T indexes the turret and emits the event itself.
- Zero-length moves (after rounding to 6 decimals) are dropped; a full circle is not zero-length.
"""

from __future__ import annotations

import io
from typing import Callable, Iterable, Iterator, Mapping, cast

from ..lowering.feed_first import check_blocks
from ..context import ASSUMED_START, Context
from ..dialect import Dialect
from ..errors import Diagnostics
from ..lowering.lower import lower_for
from ..lowering.units_at_start import write_units_at_start
from ..lowering.machine_functions import drop_foreign_machine_functions
from ..lowering.program_end import comment_after_end
from ..frames.measured_entries import write_measured_entries
from ..lowering.sideways_offsets import write_sideways_offsets
from ..lowering.tool_entries import write_tool_entries
from ..plugins import Registry, default_registry
from ..collector import gc_paused
from ..reading import macro_arguments, read_blocks
from ..setup.machine_setup import MachineSetup
from ..cycles.rigid_tap_lowering import resolve_rigid_taps
from ..lowering.deferred import resolve_dynamic_cutter_compensation
from ..lowering.length_timing import time_length_changes
from .events import MOVES_THE_TOOL, UNSIMULATED, Event, header, num, start_position
from .move_record import MoveRecord
from .simulator import Simulator
from .stream import simulate
from .travel import TravelError

__all__ = ["MOVES_THE_TOOL", "UNSIMULATED", "Event", "Simulator", "ToolpathTarget", "TRANSLATE_ONLY", "check_travel",
           "header", "num", "simulate", "start_position", "toolpath_events", "toolpath_stream"]

TRANSLATE_ONLY = (check_blocks, comment_after_end, drop_foreign_machine_functions, resolve_rigid_taps,
                  resolve_dynamic_cutter_compensation, time_length_changes, write_tool_entries,
                  write_sideways_offsets, write_measured_entries, write_units_at_start)
"""Generic lowering steps a simulation skips: it checks the feed itself, it must see the blocks after
the program end as they are written (to record the live ones), and it runs machine-specific codes,
rigid taps and compensation by a diameter (keeping the programmed point beside the controlled one), and
it applies a tool length change by the reading dialect's own rule (``time_length_changes``); it starts in the
units the translation writes for another dialect (``write_units_at_start``)."""


class ToolpathTarget(Dialect):
    """The simulator as a lowering target: it runs no canned cycle natively, everything else it reads.
    Never registered as a dialect; it only selects the lowering transforms the simulation needs."""

    NAME = "toolpath"
    DESCRIPTION = "toolpath simulation (not a dialect)"
    NATIVE_CYCLES = frozenset()
    MACHINE_TYPES = frozenset({"mill", "lathe"})
    INVERSE_TIME_FEED = True
    """It reports an inverse-time F as it is (``feed_mode`` says so); ``verify`` compares it per minute."""
    DIAMETER_PROGRAMMING = True
    """It reads the program's own X (a diameter stays a diameter: the simulator halves it itself)."""


def toolpath_events(lines: Iterable[str], *, file: str, dialect: str | type[Dialect],
                    setup: MachineSetup | None = None, registry: Registry | None = None,
                    diagnostics: Diagnostics | None = None, check: bool = True,
                    live_after_end: list[int] | None = None,
                    unsimulated: list[tuple[int, str, str]] | None = None,
                    on_unsupported: str = "error", compensate: bool = True,
                    arguments: Mapping[str, float] | None = None,
                    kept_native: Callable[[str], bool] | None = None, mark_held: bool = False,
                    assumed_start: bool = False) -> Iterator[Event]:
    """Read a program in ``dialect`` and yield its toolpath (header first). Raises ``ErrorList`` at the
    end when the program had errors (unless ``check`` is False: the caller then checks
    ``diagnostics``); events already yielded then belong to a failed run. ``live_after_end``, if given,
    receives the lines of live blocks after the program end; ``unsimulated`` the changes of settings
    the simulation does not apply (``Simulator.unsimulated``). ``on_unsupported="warn"`` makes a move
    beyond the travel a warning. ``compensate=False`` leaves cutter radius compensation unsimulated even
    where the dialect has rules for it (``verify`` against a dialect that has none). ``arguments``
    (``{"A": 30.0}``): the program is a macro file run on its own, as called with these arguments
    (``postproc.reading.macro_arguments``). ``kept_native``: which stretches of cutter compensation stay
    settings while the others are simulated (``Moves.kept_native``, for ``verify``). ``mark_held``: a reference
    return's move to the reference point names the axes it put at a machine position (``"held": "xz"``;
    ``verify --transform``). ``assumed_start``: a read of the current position before the program places the
    axis is the set-up's start, which the simulation assumes (``verify`` runs a translation so: a translation
    writes such a read where the source keeps an axis it never placed, ``postproc.lowering.length_timing``);
    without it that read is the machine's, an error."""
    diagnostics = diagnostics or Diagnostics()
    with gc_paused():
        yield from cast(Iterator[Event], toolpath_stream(lines, file=file, dialect=dialect, setup=setup, registry=registry,
                                   diagnostics=diagnostics, live_after_end=live_after_end, unsimulated=unsimulated,
                                   on_unsupported=on_unsupported, compensate=compensate, arguments=arguments,
                                   kept_native=kept_native, mark_held=mark_held, assumed_start=assumed_start,
                                   records=False))  # (no records)
    if check:
        diagnostics.check()


def toolpath_stream(lines: Iterable[str], *, file: str, dialect: str | type[Dialect], diagnostics: Diagnostics,
                    setup: MachineSetup | None = None, registry: Registry | None = None,
                    live_after_end: list[int] | None = None,
                    unsimulated: list[tuple[int, str, str]] | None = None,
                    on_unsupported: str = "error", compensate: bool = True,
                    arguments: Mapping[str, float] | None = None,
                    kept_native: Callable[[str], bool] | None = None, mark_held: bool = False,
                    assumed_start: bool = False, records: bool = True,
                    tool_data: list[tuple[int, str, str, float]] | None = None) -> Iterator[Event | MoveRecord]:
    """``toolpath_events`` without its checks: the simulator's own (compiled) event stream, read and lowered
    as it is pulled, with no Python generator around it (``verify`` pulls every event of two programs: a
    Python ``yield from`` cost about 1,500 instructions an event there). The caller checks ``diagnostics``
    at the end and pauses the cyclic collector for the run (``postproc.collector.gc_paused``). The reading
    starts here, not at the first event. ``records``: a straight move comes as a ``MoveRecord`` (read by the
    JSON lines writer and verify's normalising; ``as_events`` gives any other reader the dictionaries), else
    every event as its dictionary. ``tool_data`` receives the changes of the tool data in force
    (``Position.tool_data``: ``verify`` names what a translation lost)."""
    setup = setup or MachineSetup()
    registry = registry or default_registry()
    if isinstance(dialect, str):
        dialect = registry.dialect(dialect)
    arguments_prepare = macro_arguments(dialect, arguments) if arguments else None

    def prepare(ctx: Context) -> None:
        """With ``assumed_start``, a position read before the program places an axis is the simulated start
        (``ASSUMED_START``)."""
        if assumed_start:
            ctx.run_data[ASSUMED_START] = True
        if arguments_prepare is not None:
            arguments_prepare(ctx)

    # a simulation runs the program's loops, jumps and calls
    from ..fast.reading import install_reading  # the reading lanes (postproc.fast), as a translation has
    ctx, blocks = read_blocks(lines, file, dialect, setup, diagnostics, program_mode="execute",
                              prepare=prepare, lanes=install_reading)
    steps = [step for step in registry.lowerings if step not in TRANSLATE_ONLY]
    lowered = lower_for(blocks, ctx, ToolpathTarget, "error", steps)
    return simulate(lowered, ctx, live_after_end, unsimulated, on_unsupported == "warn",
                    ctx.cutter_rules if compensate else None, kept_native, mark_held, records, tool_data)


def check_travel(lines: Iterable[str], *, file: str, dialect: type[Dialect], setup: MachineSetup,
                 diagnostics: Diagnostics, on_unsupported: str, registry: Registry | None = None) -> None:
    """A translation's travel check: the source program simulated against the set-up's limits; each
    problem goes to ``diagnostics`` (a warning under ``on_unsupported="warn"``). Where the simulation
    itself fails (a construct it cannot run), the travel from there on cannot be known: one error says
    so, and nothing after it is checked."""
    private = Diagnostics(max_errors=1_000_000, warn_stream=io.StringIO())
    with gc_paused():  # the compiled stream pulled here, without ``toolpath_events``' Python generator around it
        for _ in toolpath_stream(lines, file=file, dialect=dialect, setup=setup, registry=registry,
                                 diagnostics=private):
            pass
    for err in private.errors:
        stopped = not isinstance(err, TravelError)
        if stopped:
            err = TravelError(f"the travel cannot be checked from here on: {err.message}", err.location)
        if on_unsupported == "warn":
            diagnostics.warn(err.message, err.location)
        else:
            diagnostics.error(err)
        if stopped:
            return
