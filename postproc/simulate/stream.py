"""The simulation's run: ``simulate`` drives a ``Simulator`` (``postproc.simulate.simulator``) over a lowered block
stream and turns what each block emits into the toolpath's stream (the header held until the first feed move fixes
its feed mode, a block that fails reported and skipped, the oriented stops a rigid tap prepares left out,
``verify --transform``'s marks). Compiled with the simulator (``pyproject.toml [tool.postproc] compiled``): it
runs a loop a block."""

from __future__ import annotations

from typing import Callable, Iterable, Iterator

from ..compensation.rules import CutterRules
from ..context import Context
from ..errors import PostprocError
from ..ir import Block, Motion
from .events import HEADER_LOOKAHEAD, header
from .move_record import Emitted, MoveRecord, move_kind
from .simulator import Simulator


def _mark_programmed(block: Block, sim: Simulator, out: list[Emitted], programmed: str) -> str:
    """``mark_held``: the axes a block programs absolutely in work coordinates (``"programmed": "xy"``) on the
    first move event it makes, or on a later block's where it makes none (a move to where the tool stands):
    ``verify --transform`` moves a held machine position from there (``postproc.transforms.events``). Returns
    what is still to be marked."""
    s = block.sections
    m = s.get("Motion")
    axes = ""
    if sim.modal.distance == "absolute" and "MachineCoordinates" not in s:
        if isinstance(m, Motion) and m.mode not in (None, "home", "home2"):
            axes = "".join(a.lower() for a in m.axes if a in "XYZ")
        cycle = s.get("CannedCycle")
        if cycle is not None:
            axes += "".join(a.lower() for a in str(getattr(cycle, "plane", "")) if a in getattr(cycle, "words", ()))
    programmed = "".join(sorted(set(programmed + axes)))
    for ev in out:
        if isinstance(ev, dict) and "move" in ev and programmed:  # (``mark_held`` runs emit no records)
            ev["programmed"] = programmed
            return ""
    return programmed


def prepared_taps(out: list[Emitted], held: Emitted | None) -> Emitted | None:
    """Leave out of ``out`` (a block's events, after ``held``, an orientation the block before ended with)
    each oriented spindle stop that a rigid tap follows at once: it is the tap's own preparation, the switch
    to position control a synchronised tap needs (SINUMERIK's ``SPOS`` before ``G331``, as Fanuc's ``M29``
    before ``G84``, which is no event either; ``dialects/siemens/tap_strokes.py``); the angle a tap starts at
    does not change the thread it cuts in a hole not yet threaded. Returns the orientation ``out`` ends with,
    held until the next block shows what follows it."""
    events = out if held is None else [held, *out]
    kept: list[Emitted] = []
    held = None
    for ev in events:
        if held is not None:
            if move_kind(ev) != "tap":
                kept.append(held)
            held = None
        if not isinstance(ev, MoveRecord) and ev.get("event") == "orient":
            held = ev
        else:
            kept.append(ev)
    out[:] = kept
    return held


def _has_move(out: list[Emitted]) -> bool:
    """A block's events hold a move."""
    for ev in out:
        if isinstance(ev, MoveRecord) or "move" in ev:
            return True
    return False


def simulate(blocks: Iterable[Block], ctx: Context, live_after_end: list[int] | None = None,
             unsimulated: list[tuple[int, str, str]] | None = None, travel_warn: bool = False,
             cutter_rules: CutterRules | None = None,
             kept_native: Callable[[str], bool] | None = None, mark_held: bool = False,
             records: bool = False, tool_data: list[tuple[int, str, str, float]] | None = None) -> Iterator[Emitted]:
    """Blocks (already lowered for ``ToolpathTarget``) -> the header, then events in execution order.
    ``records``: a straight move comes as its ``MoveRecord`` (not with ``mark_held``, which marks dictionaries),
    else as its dictionary. ``tool_data``: receives the changes of the tool data in force (``Position.tool_data``).

    Errors are reported to ``ctx.diagnostics`` with the block's location and the block is skipped;
    the caller raises them at the end (``Diagnostics.check``). Events are held back only until the
    first feed move fixes the header's feed mode (at most ``HEADER_LOOKAHEAD`` of them).
    """
    sim = Simulator(ctx, travel_warn, cutter_rules)
    sim.kept_native = kept_native  # verify's choice of the stretches compared as settings (``Moves.kept_native``)
    if live_after_end is not None:
        sim.live_after_end = live_after_end  # the caller reads the lines recorded there
    if unsimulated is not None:
        sim.unsimulated = unsimulated  # so does verify the settings the path does not show
    if tool_data is not None:
        sim.tool_data = tool_data  # and the tool data in force, to name what a translation lost
    sim.mark_held = mark_held
    sim.records = records and not mark_held
    report = ctx.diagnostics.error
    held: list[Emitted] = []
    holding = True
    units: str | None = None  # the program's units at its first move, for the header
    out: list[Emitted] = []
    sim.out = out  # where the simulator releases events: the block's own, as ``append`` emits them
    append = out.append  # one bound method for the run, not one a block
    programmed = ""
    orientation: Emitted | None = None  # an oriented stop held until what follows it is known (``prepared_taps``)
    for block in blocks:
        try:
            sim.block(block, append)
        except PostprocError as err:
            report(err.located(ctx.at(block)))
            out.clear()
            continue
        if sim.path_pending and out and _has_move(out):
            sim.path_at_first_move(block.line)
        if sim.oriented or orientation is not None and out:
            sim.oriented = False
            orientation = prepared_taps(out, orientation)
        if mark_held:
            programmed = _mark_programmed(block, sim, out, programmed)
        if not out:
            continue
        if holding:
            if units is None and _has_move(out):
                units = sim.modal.units
            held.extend(out)
            out.clear()
            if sim.header_mode is None and len(held) < HEADER_LOOKAHEAD:
                continue
            if sim.header_mode is None:
                sim.header_mode = "per_min"
            yield header(ctx, sim.header_mode, units or sim.modal.units)
            yield from held
            held, holding = [], False
        else:
            for ev in out:  # compiled, a loop over the list's items: ``yield from`` made an iterator a block
                yield ev
            out.clear()
    try:
        sim.finish()
    except PostprocError as err:
        report(err.located(ctx.at(sim.current)) if sim.current is not None else err)
        out.clear()
    if orientation is not None:
        out.insert(0, orientation)
    if out and not holding:
        yield from out
    elif out:
        held.extend(out)
    if holding:
        yield header(ctx, sim.header_mode, units or sim.modal.units)
        yield from held

