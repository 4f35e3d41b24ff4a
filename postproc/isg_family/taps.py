"""The rigid tap strokes ``G331 Z.. K.. S..`` (in) and ``G332 Z.. [K..] [S..]`` (out) of ISG and SINUMERIK, read
into the neutral ``RigidTap`` with its ``stroke`` (``postproc.lowering.synchronised_tap``). Both spell and mean them
alike, so both readers share this (the ISG and SINUMERIK code tables map them to the motion modes
``tap_in``/``tap_out``).

[V] Beckhoff TF5200 programming manual, "Tapping (G331/G332)" (CNC build V3.1.3067.01 on): G331 taps to the
target point in step with a position-controlled spindle, K the pitch in mm (inch) per revolution, its
sign the thread's hand (negative: left-hand); G332 retracts to its target point, the spindle reversed by
the control; its K is optional (the G331's applies) and must be the G331's; both are modal. The spindle
speed word in the block is read as every S is. An axis-only block under G331/G332 is another stroke with
the pitch in force.

[K] SINUMERIK 840D sl Fundamentals, "Tapping without compensating chuck (G331, G332)", as quoted at
https://en.cncforum.net/t/siemens-cnc-milling-g331-g332-codes-thread-interpolation/197 (its example
``SPOS=0`` / ``G331 Z-25 K0.8 S600`` / ``G332 Z5 K0.8``): the same strokes, K (I, J for X, Y) the pitch whose
sign is the spindle's direction (positive as with M3), G332 with the G331's pitch and the direction reversed
by the control, S without M3/M4; the spindle put into position control by ``SPOS=`` before G331
(``dialects/siemens``). Only K (tapping along Z) is read here; I and J are not.

Both writers write a stroke alike too (``stroke_words``): the code, the axes, K the signed pitch, and on the in
stroke the S it taps at when the block sets none (ISG: G331 names the speed it taps at [V, the page above];
SINUMERIK: G331 is programmed with its S [K, the example above]).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, Final

from postproc.context import Context
from postproc.errors import ProgramError
from postproc.ir.expr import Expr
from postproc.ir import Block, Motion
from postproc.lowering.synchronised_tap import RigidTap

if TYPE_CHECKING:
    from postproc.rs274.writer import WordWriter

MODES: Final = {"tap_in": "in", "tap_out": "out"}
"""The code table's motion modes of G331/G332 -> the stroke."""
PITCH: Final = "isg_tap_pitch"
"""``ctx.state.extra`` key: the pitch of the last G331 (signed), for a G332 without K."""


def read_tap_stroke(block: Block, ctx: Context, motion: Motion, values: dict[str, Any], used: set[str],
                    codes: dict[str, str]) -> None:
    """Replace the block's ``Motion`` (mode ``tap_in``/``tap_out``) by its ``RigidTap`` stroke; K is taken.
    ``codes``: the stroke ("in", "out") -> its spelling, for messages (the dialect's code table)."""
    stroke = MODES[str(motion.mode)]
    code = codes[stroke]
    col = ctx.column_of(block, "G")
    del block.sections["Motion"]  # (first: a refused block leaves no motion the simulation cannot run)
    if not motion.axes:
        if "K" in values:
            raise ProgramError(f"{code} with K and no axis word: the target point of the stroke is missing",
                               ctx.at(block, col))
        return  # the mode alone (a modal G331/G332 block without a move)
    pitch = values.get("K")
    if isinstance(pitch, Expr):
        raise ProgramError(f"a computed K in {code} is not supported (write the number)",
                           ctx.at(block, ctx.column_of(block, "K")))
    if pitch is None:  # G332's K is optional; an axis-only block under G331 taps again with its pitch
        pitch = ctx.state.extra.get(PITCH) if stroke == "out" or ctx.state.motion == "tap_in" else None
        if pitch is None:
            raise ProgramError(f"{code} needs K, the thread pitch (distance per spindle revolution)", ctx.at(block, col))
    elif float(pitch) == 0.0:
        raise ProgramError(f"{code} K0: the thread pitch must not be zero", ctx.at(block, ctx.column_of(block, "K")))
    used.add("K")
    if stroke == "in":
        ctx.state.extra[PITCH] = float(pitch)
    elif PITCH in ctx.state.extra and float(pitch) != ctx.state.extra[PITCH]:
        raise ProgramError(f"{code} K{float(pitch):g}: the pitch must be the {codes['in']}'s "
                           f"(K{ctx.state.extra[PITCH]:g})",
                           ctx.at(block, ctx.column_of(block, "K")))
    block.add(RigidTap(dict(motion.axes), float(pitch), stroke=stroke))
    ctx.state.motion = str(motion.mode)


def stroke_words(writer: WordWriter, s: Any, block: Block, controller: str) -> list[str]:
    """A rigid tap stroke's words, ``G331 Z.. K.. [S..]`` in or ``G332 Z.. K..`` out (the module docstring), for
    the writer of ``controller`` (named in its refusal); a whole tap arrives split into strokes
    (``postproc.cycles.rigid_tap_lowering.as_strokes``), the pitch signed (the thread's hand: ISG; the spindle's
    direction: SINUMERIK, the same sign)."""
    if s.stroke is None or s.dwell or s.speedup is not None:
        writer.unsupported(f"a rigid tap as one move in and out ({controller} taps by two strokes, in and then out "
                           "with the spindle reversed)", block)
    words = [writer.code("motion", "tap_in" if s.stroke == "in" else "tap_out", "a rigid tap stroke", block)]
    incremental = writer.modal.distance == "incremental"
    for axis, value in s.axes.items():
        words.append(axis + (writer.expression(value, block) if isinstance(value, Expr)
                             else writer.position(axis, value, incremental)))
    words.append("K" + writer.length(s.pitch, block, "K"))
    rpm = writer.modal.spindle_rpm
    if s.stroke == "in" and "SpindleSpeed" not in block.sections and isinstance(rpm, (int, float)) and rpm:
        words.append("S" + writer.speed(rpm))
    return words
