"""grblHAL's ``G76 P- Z- I- J- K- R- Q- H- E- L-`` threading cycle in lathe mode, read into the moves it makes (a
``CompoundMotion``: the simulation runs them, another controller gets them written as its thread moves; a grblHAL
program keeps its G76 line).

From grblHAL core (github.com/grblHAL/core, stored commit f80fc34) [V: read there]: ``gcode.c`` checks the words
and fills ``gc_thread_data``, ``motion_control.c`` ``mc_thread`` makes the moves:

* the drive line is the X the tool stands at; I is the crest's distance from it (negative: an outside thread,
  cut towards -X; ``cut_direction``), J the first pass's depth beyond the crest, K the full depth; under G7 I, J
  and K are diameters (halved); Z is where the thread ends;
* pass n cuts J * n^(1/R) beyond the crest (R the degression, 1 when not given), at most K (``calc_thread_doc``);
  the passes run until one reaches K, then H spring passes more at K;
* a pass: a rapid in X to its depth (from the drive line for the first, from the retract for the others), then
  spindle-synchronised at P per revolution along the path: to the end Z; then, unless it is the last, a rapid
  out to X = drive line -+ (K - the next pass's depth) (outwards from the drive line) and a rapid back to the
  start Z; the last pass leaves in a rapid to the drive line and the tool stays at the end Z;
* Q, the compound angle in degrees: every pass starts (K - its depth) tan Q further along +Z than the start
  (a first rapid in Z before the first pass); the sign does not follow the thread's direction;
* E with L 1 (entry), 2 (exit) or 3 (both): the ends are tapered over E along Z, synchronised as the rest
  (P along the path): the entry from K short of the pass's depth in X, the exit back out K in X; E left out or
  0, or L 0, none.

This reading refuses, where grblHAL errs: Z missing or none of P I J K (28, a value word missing), P, J or K
negative (50), I or J 0, K not above J, L above 3, R below 1 (33, out of range), a plane other than G18 (no
ZX plane), axis words other than X and Z (36), an end taper longer than half the thread (33), a spindle without
an encoder (20), G76 with the spindle stopped (``init_sync_motion``: no feed, error 41). And where its moves are
not modelled: an X word (grblHAL rescales the pitch by the taper it gives but moves no taper: ``mc_thread``'s
TODO), G20 (grblHAL converts I, J and K to mm but not P or E), G91 not needed (Z is an end point as any other),
a G76 right after a G76 (grblHAL keeps H, E, L, R and Q from the last one: ``gc_thread_data`` is cleared only
when the motion mode changes), a computed word, G76 under G96 (``init_sync_motion`` switches constant surface
speed off for the cycle: at what speed is not modelled), Z where the tool stands. G76 stays the motion mode on
grblHAL, where a later block of axis words alone errs (its I J K P missing): such a block is refused here too.
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

MODE: Final = "grblhal_thread_cycle"
"""The motion kind the code table gives G76 on a lathe (replaced by its moves where read)."""
WORDS: Final = "PIJKRQHEL"
"""The cycle's words besides the axes."""
IN_FORCE: Final = "grblhal_g76"
"""``ctx.state.extra`` key: G76 is the motion mode in force (its H, E, L, R, Q would carry over)."""
CSS: Final = "grblhal_css"
"""``ctx.state.extra`` key: G96 (constant surface speed) is in force."""


def g76_moves(start: tuple[float, float], end_z: float, pitch: float, i: float, j: float, k: float,
              degression: float = 1.0, angle: float = 0.0, spring: int = 0, taper: float = 0.0, ends: int = 0,
              limit: int = 100_000) -> list[TurnMove]:
    """The moves of ``G76`` from ``start`` (x radius, z) to ``end_z`` (module docstring): ``i``, ``j``, ``k`` as
    radii, ``angle`` in degrees, ``taper`` E and ``ends`` L. At most ``limit`` passes."""
    x0, z0 = start
    toward = -1.0 if i < 0.0 else 1.0
    peak = abs(i)
    tan_q = math.tan(math.radians(angle))
    start_z = z0 + k * tan_q
    entry_len = taper if ends & 1 and taper > 0.0 else 0.0
    exit_len = taper if ends & 2 and taper > 0.0 else 0.0
    length = end_z - z0
    if length > 0.0:
        entry_len, exit_len = -entry_len, -exit_len
    length += entry_len + exit_len
    passes = 1
    while j * passes ** (1.0 / degression) < k:
        passes += 1
        if passes > limit:
            raise ProgramError(f"G76 makes more than {limit} passes (J is too small for K at this degression R)")
    passes += spring
    moves: list[TurnMove] = []
    x, z = x0, z0

    def go(kind: str, nx: float, nz: float, note: str) -> None:
        nonlocal x, z
        if kind == "rapid":
            moves.append(TurnMove("rapid", nx, nz, note=note))
        else:  # P per revolution along the path
            moves.append(TurnMove("feed", nx, nz, feed=lead_along_major(pitch, nx - x, nz - z), note="thread"))
        x, z = nx, nz

    doc = j
    if tan_q != 0.0:
        go("rapid", x, start_z - doc * tan_q, "compound")
    for number in range(1, passes + 1):
        go("rapid", x0 + (peak + doc - (k if entry_len else 0.0)) * toward, z, "in")
        if entry_len:
            go("thread", x + k * toward, z - entry_len, "entry")
        go("thread", x, z + length, "cut")
        if exit_len:
            go("thread", x - k * toward, z - exit_len, "exit")
        if number < passes:
            doc = min(j * (number + 1) ** (1.0 / degression), k)
            go("rapid", x0 + (doc - k) * toward, z, "out")
            go("rapid", x, start_z - doc * tan_q, "back")
        else:
            go("rapid", x0, z, "out")
    return moves


def read_g76(block: Block, ctx: Context, motion: Motion, values: dict[str, Any], used: set[str]) -> None:
    """The block's G76 (``motion``, read with the code table's ``MODE``) -> its ``CompoundMotion``; the tool
    where the cycle leaves it, and no motion mode a later block may repeat (module docstring)."""
    state = ctx.state
    refuse = thread_refusal(block, ctx)
    if state.extra.get(IN_FORCE):
        del block.sections["Motion"]
        raise refuse("G76 right after a G76: grblHAL keeps the last one's H, E, L, R and Q where this one leaves "
                     "them out (not modelled); program G0 or G1 between them")
    words, axes = thread_words(block, motion, values, WORDS, "grblHAL's G76", refuse)
    other = next((axis for axis in axes if axis not in ("X", "Z")), None)
    if other is not None:
        raise refuse("grblHAL's G76 takes X and Z only (error 36, unused words)", other)
    if "X" in axes:
        raise refuse("an X word in grblHAL's G76 (a taper: grblHAL rescales the pitch by it but cuts no taper) is "
                     "not modelled", "X")
    if "Z" not in axes or not any(letter in words for letter in "PIJK"):
        raise refuse("grblHAL's G76 needs Z and its P, I, J and K (error 28, a value word missing)")
    units = block.sections.get("Units")
    if (getattr(units, "system", None) or state.units) == "inch":
        raise refuse("grblHAL's G76 under G20 (it converts I, J and K to mm but not P or E) is not modelled")
    plane = block.sections.get("Plane")
    if (getattr(plane, "plane", None) or state.plane) != "ZX":
        raise refuse("grblHAL's G76 needs the ZX plane, G18 (error 37, illegal plane)")
    if not ctx.setup.controller.spindle_sync:
        raise refuse("G76 needs a grblHAL spindle that reports its position (error 20 otherwise): a set-up with "
                     "<Controller spindleSync=\"true\"/> has one")
    pitch, i, j, k = (words.get(letter, 0.0) for letter in "PIJK")
    for letter, value in (("P", pitch), ("J", j), ("K", k)):
        if value < 0.0:
            raise refuse(f"G76 {letter}{value:g}: grblHAL refuses a negative {letter} (error 50)", letter)
    if i == 0.0 or j == 0.0 or k <= j:
        raise refuse("grblHAL's G76 needs I and J not 0 and K above J (error 33, value out of range)")
    if pitch == 0.0:
        raise refuse("grblHAL's G76 needs P, the pitch (with none, no feed: error 41)")
    ends = words.get("L", 0.0)
    if ends != int(ends) or not 0 <= ends <= 3:
        raise refuse("grblHAL's G76 L says which ends are tapered: 0 to 3 (error 33)", "L")
    r = words.get("R", 1.0)
    if r < 1.0:
        raise refuse(f"G76 R{r:g}: grblHAL's degression is 1 or more (error 33)", "R")
    angle = compound_angle(words.get("Q", 0.0), refuse, "G76")
    spring = spring_passes(words, ctx, refuse, "G76")
    control = block.sections.get("SpindleControl")
    if (getattr(control, "direction", None) or state.spindle) not in ("cw", "ccw"):
        raise refuse("grblHAL's G76 with the spindle stopped (no feed: error 41, spindle not running)")
    mode = block.sections.get("SpindleMode")
    if getattr(mode, "mode", None) == "css" or mode is None and state.extra.get(CSS, False):
        raise refuse("grblHAL's G76 under constant surface speed (G96): it turns G96 off for the cycle, at a "
                     "speed not modelled; program G97 before it")
    start, scale, incremental = thread_start(block, ctx, refuse, "G76")
    z0 = start[1]
    end_z = z0 + axes["Z"] if incremental else axes["Z"]
    if end_z == z0:
        raise refuse("grblHAL's G76 ends where the tool stands (Z): no thread", "Z")
    taper = words.get("E", 0.0)
    if ends and taper > 0.0 and taper > abs(end_z - z0) / 2.0:
        raise refuse(f"G76 E{taper:g}: an end taper longer than half the thread (error 33)", "E")
    moves = g76_moves(start, end_z, pitch, i / scale, j / scale, k / scale, r, angle, spring, taper,
                      int(ends), ctx.setup.limits.moves_per_block)
    place_thread_moves(block, ctx, moves, start, words, used, refuse, "G76")
    state.position["X"] = start[0] * scale
    state.position["Z"] = end_z
    state.motion = None  # G76 stays in force on grblHAL: a block of axis words alone is refused
    state.extra[IN_FORCE] = True
