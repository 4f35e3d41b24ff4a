"""LinuxCNC's ``G76 P- Z- I- J- R- K- Q- H- E- L-`` threading cycle, read on a lathe set-up into the moves it makes
(a ``CompoundMotion``: the simulation runs them, another controller gets them written as its thread moves; a
LinuxCNC program keeps its G76 line).

The moves follow LinuxCNC's ``src/emc/rs274ngc/interp_convert.cc`` ``convert_threading_cycle`` and
``threading_pass`` [V: read there, and checked move by move against rs274 2.9 in ``tests/test_linuxcnc_lathe.py``]:

* the drive line is the X the tool stands at (``safe_x``); I is the thread's crest from it (negative: an
  outside thread, cut towards -X; positive: a bore), J the first pass's depth beyond the crest, K the full
  thread depth; in diameter mode (G7) I, J and K are diameters (halved);
* pass n cuts at depth |I| + |J| * n^(1/R) (R, the degression, at least 1; 1 when not given) while that is
  short of |I| + |K|; then one pass at full depth and H spring passes more;
* every pass: rapid to X = drive line -+ (depth - full depth) at Z = start - zoff (one move from where the
  tool is, both axes at once), rapid in X to the pass's depth, feed spindle-synchronised, P per revolution,
  to Z = the end + |K| tan Q - zoff, rapid out to the X the pass came in at; zoff = (depth - |I|) tan Q, Q the
  compound angle in degrees (negated when the thread runs towards +Z; Q left out is 0);
* E, with L 1 (entry), 2 (exit) or 3 (both): the pass's ends are tapered over E along Z, synchronised at
  P * hypot(E, K) / E along the path: at the entry a feed in X from the rapid's X to the crest, then to the
  pass's depth E further along; at the exit, from E short of the end, out to the crest at the end (E
  negated when the thread runs towards +Z); E left out, 0 or below, or L 0, none;
* at the end, a rapid to the block's end point (its X, or the drive line, and its Z).

G76 needs a turning spindle and cutter compensation off, I not 0, J above 0, K above J, and P (rs274: "P word
missing with G76"). G76 stays the motion mode: a later block with axis words alone runs it again; such a block is
refused here (program G0 or G1 first). The cycle sets no feed rate: the feed in force before it is in force
after it (the moves end by saying it again).

Not modelled, so refused where read: a computed word, a Q of 90 degrees or more, H not a whole number at least
0, L above 3 (rs274 reads its bits; 4 and more are not documented).
"""

from __future__ import annotations

import math
from typing import Any, Final

from postproc.context import Context
from postproc.cycles.turning.profile import TurnMove
from postproc.errors import ProgramError
from postproc.ir import Block, Motion
from postproc.rs274.lathe_threading import (compound_angle, place_thread_moves, spring_passes, thread_refusal,
                                            thread_start, thread_words)
from postproc.geometry.thread_lead import lead_along_major

from .codes import CODES

MODE: Final = "ngc_thread_cycle"
"""The motion kind the code table gives G76 on a lathe (replaced by its moves where read)."""
WORDS: Final = "PIJKRQHEL"
"""The cycle's words besides the axes."""


def g76_moves(start: tuple[float, float], end: tuple[float, float], pitch: float, i: float, j: float, k: float,
              degression: float = 1.0, angle: float = 0.0, spring: int = 0, taper: float = 0.0, ends: int = 0,
              limit: int = 100_000) -> list[TurnMove]:
    """The moves of ``G76`` from ``start`` (x radius, z) to ``end`` (module docstring): ``i``, ``j``, ``k`` as
    radii, ``angle`` in degrees as programmed, ``taper`` E and ``ends`` L. At most ``limit`` passes."""
    safe_x, start_z = start
    end_x, end_z = end
    toward = 1.0 if i > 0.0 else -1.0  # +X for a bore
    crest, first, height = abs(i), abs(j), abs(k)
    full = height + crest
    q = math.radians(angle)
    if end_z > start_z:
        q = -q
    tan_q = math.tan(q)
    target_z = end_z + height * tan_q
    taper = max(taper, 0.0)
    taper_pitch = pitch * math.hypot(taper, height) / taper if taper > 0.0 else pitch
    if end_z > start_z:
        taper = -taper
    entry = taper != 0.0 and ends > 0 and bool(ends & 1)
    exit_ = taper != 0.0 and ends > 0 and bool(ends & 2)
    moves: list[TurnMove] = []

    def thread(x: float, z: float, along_path: float) -> None:
        """A synchronised feed to (x, z), ``along_path`` per revolution along it (its lead along the major axis)."""
        last = moves[-1]
        lead = lead_along_major(along_path, x - last.x, z - last.z)
        moves.append(TurnMove("feed", x, z, feed=lead, note="thread"))

    def cut(depth: float) -> None:
        zoff = (depth - crest) * tan_q
        back = safe_x + toward * (depth - full)
        bottom = safe_x + toward * depth
        crest_x = safe_x + toward * (depth - height)
        moves.append(TurnMove("rapid", back, start_z - zoff, note="back"))
        if entry:
            thread(crest_x, start_z - zoff, taper_pitch)
            thread(bottom, start_z - zoff - taper, taper_pitch)
        else:
            moves.append(TurnMove("rapid", bottom, start_z - zoff, note="in"))
        if exit_:
            thread(bottom, target_z - zoff + taper, pitch)
            thread(crest_x, target_z - zoff, taper_pitch)
        else:
            thread(bottom, target_z - zoff, pitch)
        moves.append(TurnMove("rapid", back, target_z - zoff, note="out"))

    depth, passes = crest + first, 1
    while depth < full:
        cut(depth)
        passes += 1
        if passes > limit:
            raise ProgramError(f"G76 makes more than {limit} passes (J is too small for K at this degression R)")
        depth = crest + first * passes ** (1.0 / degression)
    for _ in range(spring + 1):
        cut(full)
    last = moves[-1]
    if (last.x, last.z) != (end_x, end_z):  # (rs274 prints a move to where the tool stands: it moves nothing)
        moves.append(TurnMove("rapid", end_x, end_z, note="end"))
    return moves


def read_g76(block: Block, ctx: Context, motion: Motion, values: dict[str, Any], used: set[str]) -> None:
    """The block's G76 (``motion``, read with the code table's ``MODE``) -> its ``CompoundMotion``; the tool
    where the cycle leaves it, and no motion mode a later block may repeat (module docstring)."""
    state = ctx.state
    refuse = thread_refusal(block, ctx)
    words, axes = thread_words(block, motion, values, WORDS, "G76", refuse)
    if "P" not in words:
        raise refuse("G76 needs P, the thread pitch (rs274: \"P word missing with G76\")")
    for letter in ("I", "J", "K"):
        if letter not in words:
            raise refuse(f"G76 needs {letter} (rs274: I must not be 0, J must be above 0, K above J)")
    pitch, i, j, k = (words[letter] for letter in "PIJK")
    if pitch <= 0.0:
        raise refuse(f"G76 P{pitch:g}: the pitch must be positive", "P")
    if i == 0.0:
        raise refuse("In G76, I must not be 0 (rs274)", "I")
    if j <= 0.0:
        raise refuse("In G76, J must be greater than 0 (rs274)", "J")
    if k <= j:
        raise refuse("In G76, K must be greater than J (rs274)", "K")
    taper = words.get("E", 0.0)
    ends = words.get("L", -1.0)
    if ends != int(ends) or ends > 3:
        raise refuse("G76 L says which ends are tapered: 0 to 3", "L")
    angle = words.get("Q", -1.0)
    angle = compound_angle(0.0 if angle == -1.0 else angle, refuse, "G76")  # rs274 reads a Q of -1 as none
    spring = spring_passes(words, ctx, refuse, "G76")
    r = words.get("R")
    degression = max(r, 1.0) if r is not None else 1.0  # rs274: below 1, or left out, is 1
    turning = _spindle_of(block) or state.spindle  # (LinuxCNC starts or stops the spindle before the motion)
    if turning not in ("cw", "ccw"):
        raise refuse("G76 with the spindle stopped (rs274: \"Chosen spindle (0) not turning in G76\")")
    start, scale, incremental = thread_start(block, ctx, refuse, "G76")

    def end(axis: str, known: float) -> float:
        value = axes.get(axis)
        if value is None:
            return known
        return known + value if incremental else value

    finish = (end("X", start[0] * scale) / scale, end("Z", start[1]))
    moves = g76_moves(start, finish, pitch, i / scale, j / scale, k / scale, degression, angle,
                      spring, taper, int(ends), ctx.setup.limits.moves_per_block)
    place_thread_moves(block, ctx, moves, start, words, used, refuse, "G76")
    state.position["X"] = finish[0] * scale
    state.position["Z"] = finish[1]
    state.motion = None  # G76 stays in force on LinuxCNC: a block of axis words alone is refused


def _spindle_of(block: Block) -> str | None:
    """What the block's own M3/M4/M5 does to the spindle (its M codes are read after its G codes), or None."""
    for letter, num in block.words:
        if letter.upper() == "M" and num.isdigit():
            entry = CODES.m.get(int(num))
            if entry is not None and entry[0] == "spindle":
                return str(entry[1])
    return None
