"""What a running program reads of its own frame: the values behind a family's frame parameters (LinuxCNC's
``#5210``-``#5219``, a work system's offsets and rotation), as the frame evaluation has reached them.

The interpreter runs ahead of the lowering by one block at most: the blocks stream, so when it evaluates a
block, every block before it has been through ``evaluate_frames`` (``FrameRun``, ``ctx.frame_run``).
Where no evaluation runs (a program translated back to its own dialect keeps its frame commands for the
machine), or where the program has not set a value itself (a work offset from the set-up's table), the
value is known only to the machine: ``None``, which the family's table reports by name.

Lengths are in mm, angles in degrees; the family's table converts them to its own units.

The current position (LinuxCNC's ``#5420``-``#5428``) is the program position the frame evaluation follows
(``FrameRun.p``), in program units where the program stands: a read-only view, no second simulation. It
is known only where the machine's current point is what the simulation holds: every axis read was
programmed absolutely since the start (before that, ``p`` is the set-up's assumed start) and since the
last tool offset change, with no move in machine coordinates, reference return, cycle or change of work
system after it (those leave ``p`` unknown). In a simulation that assumes the machine starts where the set-up
says (``ASSUMED_START``: ``verify`` runs a translation so), an axis not programmed since the start reads that
start, as the simulated moves assume (``FrameReadings._at_start`` where no frame is evaluated, on a lathe).
"""

from __future__ import annotations

from typing import Callable, Hashable, Iterable

from ..context import ASSUMED_START, Context
from ..interp.numbers import COMPUTED, numbered_variables
from ..ir.state import LEFT_START, MM_PER_INCH
from ..ir import Block
from .run_state import FrameRun


class FrameReadings:
    """The frame values of one run (``ctx``), read where the program stands."""

    __slots__ = ("ctx",)

    def __init__(self, ctx: Context) -> None:
        self.ctx = ctx

    def _run(self) -> FrameRun | None:
        run = self.ctx.frame_run
        return run if isinstance(run, FrameRun) else None

    def origin_applied(self) -> bool | None:
        """The shared G52/G92 offset (shared_offset rules) is in force; None where the frame is not evaluated."""
        run = self._run()
        if run is None:
            return None
        return run.frame is not None and run.frame.rules == "shared_offset" and run.frame.applied

    def origin_parameter(self, axis: str) -> float | None:
        """The offset's stored value on ``axis`` (what G92.3 restores: kept by G92.2, cleared by G92.1)."""
        run = self._run()
        if run is None:
            return None
        if run.frame is None or run.frame.rules != "shared_offset":
            return 0.0
        return run.frame.saved.get(axis, 0.0)

    def work_system(self) -> int | None:
        """The work system the program selected last (1 = the first, G54); None before it selects one (the
        machine's, kept from its last program [K: LinuxCNC keeps #5220 between runs]) or where the frame is
        not evaluated."""
        run = self._run()
        return None if run is None else run.work

    def work_offset(self, index: int, axis: str) -> float | None:
        """Work system ``index``'s offset on ``axis`` where the program set it (a G10 before)."""
        run = self._run()
        if run is None:
            return None
        return run.g5x.get(index, {}).get(axis)

    def position(self, axis: str) -> float | None:
        """The current point on ``axis`` in program units (degrees on a rotary axis) where the simulation
        knows it (the module docstring); None where only the machine does. In a simulation (``ASSUMED_START``)
        an axis not programmed since the start reads where the simulation starts it (``_at_start``)."""
        run = self._run()
        if run is None:
            return self._at_start(axis)
        if axis in run.unsettled and not self.ctx.run_data.get(ASSUMED_START):
            return None
        here = run.point().get(axis)
        if here is None:
            return None
        return here / run.scale if axis in "XYZUVW" else here

    def _at_start(self, axis: str) -> float | None:
        """Where no frame is evaluated (a lathe), in a simulation only: an axis still at the simulation's start,
        in program units, while nothing can have moved it or the program's origin since the start (no axis
        placed, no reference return or machine-coordinate move, no tool offset or work system but the
        first, no cycle); X only from a start at 0 (a read X is a radius, a diameter program's X word not).
        None otherwise: only the machine knows."""
        ctx = self.ctx
        state = ctx.state
        if (not ctx.run_data.get(ASSUMED_START) or state.extra.get(LEFT_START) or state.length != "cancel"
                or state.work_offset != 1 or state.cycle is not None
                or any(value is not None for value in state.position.values())):
            return None
        machine = ctx.setup.machine
        if axis not in machine.axes:
            return None
        start = {"X": machine.start_x, "Y": machine.start_y, "Z": machine.start_z}.get(axis, 0.0)
        if axis == "X" and start != 0.0:
            return None
        if axis not in "XYZUVW":
            return float(start)
        mm = float(start) * machine.mm()
        return mm / MM_PER_INCH if state.units == "inch" else mm

    def compensating(self) -> bool:
        """Cutter radius compensation is on where the program stands (False where the frame is not
        evaluated: the read is then the machine's anyway)."""
        run = self._run()
        return run is not None and run.cutter

    def state(self) -> Hashable:
        """Everything the readings above can answer, as one comparable value (the interpreter's repeated-state
        check compares it between two passes of a loop head: a loop whose G10 or G92 changes what the
        program reads is not repeating itself, nor one whose moves change the current position)."""
        run = self._run()
        if run is None:
            return None
        frame = run.frame
        g5x = tuple(sorted((n, tuple(sorted(v.items()))) for n, v in run.g5x.items()))
        point = (tuple(sorted(run.point().items())), tuple(sorted(run.unsettled)), run.scale, run.cutter)
        if frame is None or frame.rules != "shared_offset":
            return (run.work, g5x, point)
        return (run.work, g5x, frame.applied, tuple(sorted(frame.saved.items())), tuple(sorted(frame.turns.items())),
                point)

    def work_rotation(self, index: int) -> float | None:
        """Work system ``index``'s XY rotation where the program set it (``G10 L2 R``)."""
        run = self._run()
        if run is None or run.frame is None or run.frame.rules != "shared_offset":
            return None
        return run.frame.turns.get(index)


def frame_parameter_read(blocks: Iterable[Block], reads_frame: Callable[[int], bool]) -> str | None:
    """The first frame parameter (``reads_frame``: the reading family's numbers) that ``blocks`` read, as
    ``#5211``; None when they read none. A program kept symbolically for a target whose frame is evaluated
    must not read one: the target's variable of that number holds no such frame (another dialect's
    numbering, or the frame the evaluation took out of the program), so such a program is flattened, and
    the flattening run reads the values here. Found through each section's XML (every section has one), so
    no construct's words are missed; a variable with a computed number is not decided here [?]."""
    for number in numbered_variables(blocks):
        if number != COMPUTED and reads_frame(number):
            return f"#{number}"
    return None
