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
from postproc.cycles.lathe_expansion import to_sections
from postproc.cycles.turning.profile import TurnMove
from postproc.errors import ProgramError
from postproc.expr import Expr
from postproc.ir import Block, CompoundMotion, Feed, Motion
from postproc.thread_lead import lead_along_major

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
    col = ctx.column_of(block, "G")
    state = ctx.state
    del block.sections["Motion"]  # replaced by the moves; a refused block keeps none

    def refuse(message: str, letter: str | None = None) -> ProgramError:
        return ProgramError(message, ctx.at(block, ctx.column_of(block, letter) if letter else col))

    given = {letter: values[letter] for letter in WORDS if letter in values}
    if any(isinstance(v, Expr) for v in [*given.values(), *motion.axes.values()]):
        raise refuse("a computed word in G76 is not supported (write the numbers)")
    words: dict[str, float] = {letter: float(v) for letter, v in given.items()}
    axes: dict[str, float] = {axis: float(v) for axis, v in motion.axes.items() if not isinstance(v, Expr)}
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
    if angle == -1.0:
        angle = 0.0  # rs274 reads a Q of -1 as none
    if not -90.0 < angle < 90.0:
        raise refuse(f"G76 Q{angle:g}: a compound angle of 90 degrees or more is not modelled", "Q")
    spring = words.get("H", 0.0)
    if spring != int(spring) or spring < 0:
        raise refuse("G76 H must be a whole number of spring passes, 0 or more", "H")
    if spring >= ctx.setup.limits.moves_per_block:
        raise refuse(f"G76 H{spring:g} makes more moves than <Limits movesPerBlock> "
                     f"({ctx.setup.limits.moves_per_block})", "H")
    r = words.get("R")
    degression = max(r, 1.0) if r is not None else 1.0  # rs274: below 1, or left out, is 1
    turning = _spindle_of(block) or state.spindle  # (LinuxCNC starts or stops the spindle before the motion)
    if turning not in ("cw", "ccw"):
        raise refuse("G76 with the spindle stopped (rs274: \"Chosen spindle (0) not turning in G76\")")
    x0, z0 = state.position.get("X"), state.position.get("Z")
    if x0 is None or z0 is None:
        raise refuse("G76: the tool's position before the cycle is unknown (program an absolute X and Z first)")
    scale = 2.0 if ctx.diameter else 1.0
    incremental = state.distance == "incremental"
    distance = block.sections.get("DistanceMode")
    if distance is not None:
        incremental = distance.mode == "incremental"  # type: ignore[attr-defined]

    def end(axis: str, known: float) -> float:
        value = axes.get(axis)
        if value is None:
            return known
        return known + value if incremental else value

    start = (float(x0) / scale, float(z0))
    finish = (end("X", float(x0)) / scale, end("Z", float(z0)))
    moves = g76_moves(start, finish, pitch, i / scale, j / scale, k / scale, degression, angle,
                      int(spring), taper, int(ends), ctx.setup.limits.moves_per_block)
    if len(moves) > ctx.setup.limits.moves_per_block:
        raise refuse(f"G76 makes {len(moves)} moves, more than <Limits movesPerBlock> "
                     f"({ctx.setup.limits.moves_per_block})")
    items = to_sections(moves, start, ctx)
    feed = block.sections.get("Feed")
    after = feed.value if isinstance(feed, Feed) else state.feed
    if after is not None:
        items.append(Feed(after))  # the cycle leaves the feed rate as it was
    ctx.moves_made += len(moves)
    block.add(CompoundMotion("G76", items))
    used.update(words)
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
