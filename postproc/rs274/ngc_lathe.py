"""The RS274/NGC lathe words, read into neutral sections: ``G7``/``G8``, ``G96 S.. D..``/``G97`` and ``G33 K``.
Shared by the controllers that spell them so (LinuxCNC, grblHAL in lathe mode): each passes what its own
interpreter says where it refuses a word (``Said``).

Each rule was checked with the packaged rs274 (2.9) [V], beside LinuxCNC ``docs/src/gcode/g-code.adoc``;
grblHAL's ``gcode.c`` (github.com/grblHAL/core, stored commit f80fc34) reads them alike [V] (its
differences are refused by its plugin, or read here more strictly than grblHAL: a G33 without K, which
grblHAL takes from the last G33, and an F beside G33, which it accepts):

* ``G7`` (diameter mode) and ``G8`` (radius mode) say how X reads. The IR keeps X as the set-up's
  ``xProgramming`` says (a mill's: radius). A controller whose reader passes ``switches`` (LinuxCNC's lathe
  block syntax, ``program_x_mode``) reads a program that switches mode: the words read in the other mode are
  converted to the set-up's before the block is read, and the switch becomes an ``XProgramming`` section. Its
  rules [V: rs274 2.9.0~pre1 run here, tests/test_linuxcnc_x_mode_switch.py]: the mode of a block's own G7/G8
  applies to that block's X; every X word (absolute or G91) is a diameter in G7; an arc's I and R stay radii;
  G33's K is a lead (no mode); G76's I, J and K are halved in G7 (``threading``); ``#5420`` reads the radius
  in either mode. Refused while the program's mode differs from the set-up's: an o-word line (a program kept
  as written is read in its text's order, not the order it runs in, so a subprogram or loop body could run in
  a mode other than the one it was read in), a computed X (or G76 I/J/K), and a G70-G72 cycle. Elsewhere
  (grblHAL) the mode that disagrees with the set-up is refused at its column.
* ``G96 S.. D..``: constant surface speed S (m/min under G21, ft/min under G20, as Fanuc's G96 S) with
  the spindle clamped at D rpm. G96 needs S ("S word missing with G96"); D is refused beside anything
  but G96 and cutter compensation ("D word with no G41 ... or G96 to use it"); a G96 without D lifts
  the clamp (rs274 prints ``SET_SPINDLE_MODE(0 1e30)``). A Fanuc-family clamp (``G50 S``) stays until the
  next, so a later G96 without D, after one with D, means what no other control here says: refused.
* ``G33 X.. Z.. K..``: a spindle-synchronised move, K the distance per revolution along the path
  ("K word missing with g33/g33.1"; an F beside it is refused: "F word used with a g33/g33.1"). It
  changes neither the feed rate nor the feed mode. K becomes the neutral lead along the major axis
  (``postproc.geometry.thread_lead``); a taper from a position not yet known is refused.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from postproc.context import Context
from postproc.errors import ProgramError, UnsupportedError
from postproc.interp.variables import RUN_INTERPRETER_KEY
from postproc.ir.expr import Expr
from postproc.ir import Block, Motion
from postproc.ir.lathe_sections import SpindleClamp, SpindleMode, ThreadLead, XProgramming
from postproc.rs274.codes import g_key
from postproc.geometry.thread_lead import lead_along_major

MODES = {"7": "diameter", "8": "radius"}
"""G7/G8 -> how X reads."""
LATHE_ONLY = frozenset(("33", "96", "97"))
"""Codes the table reads into lathe sections on a lathe set-up only; a mill keeps them verbatim."""
X_MODE_KEY = "ngc.x_mode"
"""``ctx.state.extra`` key: how the program writes X now (G7/G8), while that differs from the set-up's."""
_MODE_ENDS = frozenset("780.")
"""The last character of every spelling of G7/G8 (``07``, ``8.0``, ``7.``): most G words are no mode code,
and this skips their ``g_key`` (every lathe block passes ``program_x_mode``)."""
X_MODE_WORDS = frozenset("IJK")
"""The words besides X a G76 block reads as diameters in G7 (``threading``)."""
CLAMP_KEY = "ngc.spindle_clamp"
"""``ctx.state.extra`` key: the clamp of the last G96 (D), while one is in force."""


@dataclass(frozen=True)
class Said:
    """What a controller's interpreter says where it refuses a lathe word, quoted in the reader's message."""

    s_missing: str
    """G96 without S."""
    f_beside: str
    """F in a G33 block."""
    k_missing: str
    """G33 without K."""



def _col(block: Block, ctx: Context, num: str) -> int:
    return ctx.column_of(block, "G", num)


def read_x_mode(block: Block, ctx: Context, num: str, switches: bool = False) -> None:
    """G7/G8: refused where it disagrees with how X is read (a lathe: the set-up's ``xProgramming``; a
    mill: radius) unless the controller's reader ``switches`` (``program_x_mode`` read the block's mode
    before). Kept verbatim on a mill, a G7 would make the target read every later X as a diameter while the
    translation and the simulation read radii."""
    mode = MODES[g_key(num)]
    programmed = "diameter" if ctx.diameter else "radius"
    if mode != programmed and not ctx.lathe:
        raise ProgramError(f"G{num} ({mode} mode) on a mill set-up, which reads X as a radius (a lathe set-up "
                           "with <Input xProgramming=\"diameter\"> reads diameters)",
                           ctx.at(block, _col(block, ctx, num)))
    if mode != programmed and not switches:
        raise ProgramError(f"G{num} ({mode} mode) in a program read as {programmed}s: the set-up's "
                           f"<Input xProgramming=\"{programmed}\"> decides how X reads (set it to {mode}; a "
                           "program that switches mode is not read)", ctx.at(block, _col(block, ctx, num)))


def program_x_mode(block: Block, ctx: Context) -> list[tuple[str, str]] | None:
    """Before a lathe block is read (a reader that switches modes): the block's G7/G8 sets how the program
    writes X (an ``XProgramming`` section), and while it differs from the set-up's the
    block's X words (and a G76's I, J, K) become the set-up's numbers, halved or doubled (module docstring).
    Returns the words as written where it changed them (the caller puts them back once the block is read:
    ``values`` hold the set-up's numbers, ``words`` the text's), else None."""
    extra = ctx.state.extra
    current = extra.get(X_MODE_KEY)
    setup_mode = "diameter" if ctx.diameter else "radius"
    code: str | None = None
    for letter, num in block.words:
        if (letter == "G" or letter == "g") and num[-1:] in _MODE_ENDS and g_key(num) in MODES:
            if code is not None:
                raise ProgramError(f"G{code} and G{num} in one block, one modal group (rs274: \"Two g codes used "
                                   "from same modal group\"; grblHAL: error 21)", ctx.at(block, _col(block, ctx, num)))
            code = num
    if code is not None:
        mode = MODES[g_key(code)]
        block.add(XProgramming(mode))  # (also where it repeats the mode: a line written again keeps its code)
        current = None if mode == setup_mode else mode
        if current is None:
            extra.pop(X_MODE_KEY, None)
        else:
            extra[X_MODE_KEY] = current
    if current is None:
        return None
    if "Control" in block.sections:
        raise ProgramError(f"an o-word line while the program writes X as a {current} (G{'7' if current == 'diameter' else '8'}) "
                           f"and the set-up reads {setup_mode}s: a subprogram or loop could run in a mode other than "
                           "the one it is read in; switch back before it", ctx.at(block))
    factor = 2.0 if ctx.diameter else 0.5
    thread_cycle = any((letter == "G" or letter == "g") and g_key(num) == "76" for letter, num in block.words)
    letters = X_MODE_WORDS | {"X"} if thread_cycle else frozenset("X")
    values = block.values
    written = block.words
    words = list(written)
    for index, (letter, num) in enumerate(written):
        up = letter.upper()
        if up not in letters:
            continue
        if values and isinstance(values.get(up), Expr):
            raise ProgramError(f"a computed {up} while the program writes X as a {current} and the set-up reads "
                               f"{setup_mode}s is not supported (write the number)",
                               ctx.at(block, ctx.column_of(block, up)))
        try:
            value = float(num)
        except ValueError:
            continue  # (the block syntax refuses it)
        words[index] = (letter, repr(value * factor))
    if words == written:
        return None
    block.words = words
    block.canonical = False
    return written


def read_spindle_mode(block: Block, ctx: Context, mode: str, num: str, values: dict[str, Any],
                      used: set[str], said: Said) -> None:
    """``G96 S.. [D..]`` or ``G97``: the mode, and on G96 its clamp."""
    extra = ctx.state.extra
    block.add(SpindleMode(mode))
    if mode != "css":
        return
    if "S" not in values:
        raise ProgramError(f"G{num} needs S, the surface speed ({said.s_missing})",
                           ctx.at(block, _col(block, ctx, num)))
    clamp = values.get("D")
    if clamp is None:
        if extra.get(CLAMP_KEY) is not None:
            raise ProgramError(f"G{num} without D after one with D: the controller lifts the spindle clamp, which "
                               "the Fanuc family's clamp cannot say; write D again",
                               ctx.at(block, _col(block, ctx, num)))
        return
    if isinstance(clamp, Expr):
        raise ProgramError(f"a computed D in G{num} is not supported (write the number)",
                           ctx.at(block, ctx.column_of(block, "D")))
    if clamp <= 0:
        raise ProgramError(f"G{num} D{clamp:g}: the spindle clamp must be positive",
                           ctx.at(block, ctx.column_of(block, "D")))
    used.add("D")
    extra[CLAMP_KEY] = float(clamp)
    block.add(SpindleClamp(float(clamp)))


def read_thread(block: Block, ctx: Context, motion: Motion, values: dict[str, Any], used: set[str],
                said: Said) -> None:
    """``G33``'s K -> the block's ``ThreadLead``; K and the refusals as rs274 makes them."""
    code = next((num for letter, num in block.words if letter.upper() == "G" and g_key(num) == "33"), None)
    col = _col(block, ctx, code) if code is not None else 1
    name = f"G{code}" if code is not None else "the thread move"
    if "F" in values:
        raise ProgramError(f"F beside {name} ({said.f_beside}; set the feed rate in a block "
                           "before)", ctx.at(block, ctx.column_of(block, "F")))
    along = values.get("K")
    if along is None:
        raise ProgramError(f"{name} needs K, the distance per spindle revolution ({said.k_missing})",
                           ctx.at(block, col))
    used.add("K")
    if isinstance(along, Expr) or any(isinstance(v, Expr) for v in motion.axes.values()):
        if ctx.program_mode == "keep" and RUN_INTERPRETER_KEY not in ctx.run_data:
            return  # a plain copy to the dialect itself: the line goes as written, its lead known where it runs
        raise UnsupportedError(f"a computed word in {name} is not supported (write the numbers)", ctx.at(block, col))
        # (the program is valid NGC, LinuxCNC runs it: what is refused is this translation, not the source)
    if along <= 0:
        raise ProgramError(f"{name} K{along:g}: the distance per revolution must be positive",
                           ctx.at(block, ctx.column_of(block, "K")))
    dx, dz = _travel(block, ctx, motion, col, name)
    block.add(ThreadLead(lead_along_major(float(along), dx, dz)))


def _travel(block: Block, ctx: Context, motion: Motion, col: int, name: str) -> tuple[float, float]:
    """The move's X travel (a radius) and Z travel; a start not yet known matters only for a taper."""
    state = ctx.state
    incremental = state.distance == "incremental"
    distance = block.sections.get("DistanceMode")
    if distance is not None:
        incremental = distance.mode == "incremental"  # type: ignore[attr-defined]

    def travel(axis: str) -> float | None:
        value = motion.axes.get(axis)
        start = state.position.get(axis)
        if value is None:
            return 0.0
        if isinstance(value, Expr):
            return None  # (refused before: ``read_thread``)
        if incremental:
            return float(value)
        return None if start is None else float(value) - float(start)

    dx, dz = travel("X"), travel("Z")
    if dx is None or dz is None and dx != 0.0:
        axis = "X" if dx is None else "Z"
        raise ProgramError(f"{name} moving X from a {axis} not yet known (program an absolute {axis} first)",
                           ctx.at(block, col))
    return (dx / 2.0 if ctx.diameter else dx), (dz or 0.0)
