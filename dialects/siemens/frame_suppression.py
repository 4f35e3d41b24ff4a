"""``G53``, ``G153`` and ``SUPA``: a block without frames, read as a move in machine coordinates where that is
all it is, kept verbatim where its meaning depends on what is not confirmed here.

The facts [K: SINUMERIK 840D sl Fundamentals, "Frame suppression (G53, G153, SUPA, G500)"; ONE NC programming
12/2019 p.309 lists the frame statements]: each acts for its own block only; ``G53`` suppresses the settable
and programmable frames, ``G153`` the basic frames too, ``SUPA`` besides them the handwheel (DRF) offsets,
external zero offsets and PRESET; the block moves in the motion mode in force. Whether they suppress the tool
length and radius too is machine data ``$MN_G53_TOOLCORR`` [V: SINUMERIK 802D sl/840D ISO Milling
programming manual 04.07, 3.1.1].

postproc models no basic frame, handwheel or external offset, so all three are its machine coordinates (the
neutral ``MachineCoordinates``: the work offset and the programmable frame left out, as Fanuc's ``G53``)
exactly where the machine data cannot matter and the move is the neutral one (``problem`` says which):

* no tool length (``D0`` selected, or the set-up's tool of the selected D has length 0), or one the set-up's
  ``<Controller g53ToolCorr>`` settles (``$MN_G53_TOOLCORR``): 1 (true) suppresses it, the neutral move; 0
  (false) keeps it, so the block's Z is the tool tip's and the machine's is that plus the length (``kept_length``:
  Z is read that much higher, a number only); and no radius compensation (G40) in force, the block selecting
  neither;
* G0 in force or in the block (the neutral machine-coordinate move is at rapid);
* G90 (machine positions are absolute); the block's axes any of the channel's, geometry (X, Y, Z) or special
  (A, B, C, U, V, W): a frame carries offsets of both ("The rough and fine offsets, scaling and mirroring can
  be programmed for geometry and special axes" [V: SINUMERIK 840D sl Function Manual Basic Functions K2, 08/2005
  6FC5397-0BP10-0BA0, 1.3 "Frames", "Features in relation to axes"]), and the settable zero offsets G54.. are
  settable frames [V: same manual; SINUMERIK ISO Milling 04.07 3.1, "adjustable Frame G54 - G59"], so the
  block without frames puts a rotary axis at its machine position as it does X, Y, Z (issue 26, haasfacts:
  a Haas program's ``G53 Y0. A0.`` is ``SUPA G0 Y0. A0.``). ``I``, ``J``, ``K`` are no axes: a block of
  them is kept.

Anything else is kept verbatim, named (copied to SINUMERIK, refused elsewhere by name).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from postproc.compensation.tool_table import ToolTable
from postproc.errors import PostprocError
from postproc.isg_family.tool_data import SELECTED_KEY
from postproc.ir import Section

if TYPE_CHECKING:
    from postproc.context import Context
    from postproc.ir import Block

CUTTER_KEY = "siemens_cutter_on"
"""``ctx.state.extra`` key: True while G41/G42 is in force (``note_cutter``)."""
CODES = frozenset(("53", "153"))
"""The G numbers (leading zeros stripped) that suppress frames."""
_MOTION = {"": "rapid", "1": "linear", "2": "cw", "3": "ccw", "33": "thread"}
_CUTTER = {"40": False, "41": True, "42": True}


class SiemensSupa(Section):
    """``SUPA`` in a block, from the reader to the block syntax (``take``)."""

    XNAME = KEY = "SiemensSupa"
    __slots__ = ()


def take(block: Block) -> str | None:
    """Remove the block's frame suppression (``G53``/``G153`` words, the ``SUPA`` marker) and name it; None
    when the block has none."""
    names = [f"G{num}" for letter, num in block.words if letter in "Gg" and num.lstrip("0") in CODES]
    if block.sections.pop(SiemensSupa.KEY, None) is not None:
        names.append("SUPA")
    if not names:
        return None
    block.words[:] = [(letter, num) for letter, num in block.words
                      if not (letter in "Gg" and num.lstrip("0") in CODES)]
    return " ".join(names)


def problem(block: Block, ctx: Context) -> str | None:
    """Why the block's frame suppression is not read as a rapid move in machine coordinates (see the module
    docstring), or None."""
    state = ctx.state
    codes = {num.lstrip("0"): num for letter, num in block.words if letter in "Gg"}
    letters = {letter.upper() for letter, _ in block.words}
    motion = next((_MOTION.get(code, code) for code in codes if code in _MOTION), state.motion)
    if motion != "rapid":
        return (f"in G{codes_of(motion)} (read in G0 only: the neutral move in machine coordinates is at "
                "rapid)")
    if "91" in codes or state.distance != "absolute" and "90" not in codes:
        return "in G91 (read in G90 only)"
    if letters & set("IJK"):
        return "with interpolation parameters I, J, K (no axes)"
    if "D" in letters or any(code in _CUTTER for code in codes):
        return "selecting tool data (read with no tool length and no radius compensation in force)"
    if state.extra.get(CUTTER_KEY):
        return "under radius compensation (whether it stays is machine data $MN_G53_TOOLCORR)"
    selected = state.extra.get(SELECTED_KEY, 0)
    if not isinstance(selected, (int, float)) or selected != int(selected):
        return "with a computed D in force"
    if selected:
        try:
            length = ToolTable(ctx.setup).length(int(selected))
        except PostprocError:
            length = None
        suppressed = ctx.setup.controller.g53_tool_corr
        if length != 0.0 and (suppressed is None or length is None):
            return (f"with the length of D{int(selected)} in force (whether it stays is machine data "
                    "$MN_G53_TOOLCORR: the set-up's <Controller g53ToolCorr=\"0\"/> or \"1\" says; read with D0 or a "
                    "tool of length 0)")
        if length and not suppressed and not _plain_z(block):
            return f"with the length of D{int(selected)} kept in force (g53ToolCorr 0) and a Z not a number"
    return None


def _plain_z(block: Block) -> bool:
    """The block's Z, if any, is a plain number (``Z0``, ``Z-10.5``)."""
    for letter, num in block.words:
        if letter in "Zz":
            try:
                float(num)
            except ValueError:
                return False
    return True


def kept_length(block: Block, ctx: Context) -> None:
    """Under ``g53ToolCorr`` 0 the length of the selected D stays in force in a block without frames: its Z (the
    tool tip's, in machine coordinates) is read as the machine's, the length higher (program units), so the
    neutral machine-coordinate move goes where the machine does. After ``problem`` said None."""
    if ctx.setup.controller.g53_tool_corr is not False:
        return
    selected = ctx.state.extra.get(SELECTED_KEY, 0)
    if not selected:
        return
    length = ToolTable(ctx.setup).length(int(selected))  # (given: ``problem``)
    if ctx.state.units == "inch":
        length /= 25.4
    block.words[:] = [(letter, _number(float(num) + length) if letter in "Zz" else num)
                      for letter, num in block.words]


def _number(value: float) -> str:
    return repr(round(value, 9))


def codes_of(motion: str | None) -> str:
    """The G number of a motion mode (for messages)."""
    return next((code or "0" for code, mode in _MOTION.items() if mode == motion), "?")


def note_cutter(block: Block, ctx: Context) -> None:
    """Track G41/G42 being in force (``CUTTER_KEY``) from the block's words."""
    for letter, num in block.words:
        if letter in "Gg" and num.lstrip("0") in _CUTTER:
            ctx.state.extra[CUTTER_KEY] = _CUTTER[num.lstrip("0")]
