"""SiemensBlockSyntax: the SINUMERIK reading of a block's words, the family's word rules with the 840D table.

* A number without a decimal point is in mm/inch (``X10`` = 10 mm) [K: SINUMERIK has no least-increment
  input], whatever the set-up's ``Input`` says.
* ``G4 F2.5`` dwells 2.5 seconds: that F is the time, not a feed (the feed in force stays) [K: 840D
  Fundamentals "Dwell time (G4)"; Autodesk post ``onDwell``]; ``G4 S`` (revolutions) is not modelled.
* ``G70``/``G71`` set the units of lengths only: an F in a program under them is in the basic system's
  unit (the set-up's machine units) [K: Fundamentals "Inch/metric dimensions"], so an F where they differ
  is a located error (G700/G710 say it without doubt).
* ``D<n>`` selects cutting edge n of the tool: its length applies (``D0``: none) and G41/G42 take its
  radius (``postproc.isg_family.tool_data``, as on ISG).
* ``G331``/``G332`` are the rigid tap's strokes, read as ISG's (``postproc.isg_family.taps``).
"""

from __future__ import annotations

from typing import Any, ClassVar

from postproc.context import Context
from postproc.errors import ProgramError
from postproc.ir.expr import Expr
from postproc.ir import Block, Dwell, MachineCoordinates, Motion, ReturnLevel
from postproc.isg_family.taps import MODES, read_tap_stroke
from postproc.isg_family.tool_data import read_tool_data
from postproc.rs274.block_syntax import WordBlockSyntax, col_of_word
from postproc.rs274.codes import CodeTable, g_key
from postproc.ir.state import PLANE_AXES

from . import frame_suppression, helix
from .arcs import CIP_KEY, SiemensArc, SiemensCip, arc_words, cip_words
from .codes import CODES, GEOMETRY_UNITS
from .fixed_point import SiemensFixedPoint
from .fixed_point import resolve as resolve_fixed_point
from .cycles import DIS1_KEY, MCALL_KEY, TAP_KEY, CycleLevels, SiemensCycleRules, keep_verbatim
from .helix import SiemensTurn
from .holes import SiemensHoles
from .holes import resolve as resolve_holes

TAP_CODES = {"in": "G331", "out": "G332"}
"""The rigid tap strokes' spelling, for the messages of ``read_tap_stroke``."""

_MOTION = frozenset(("", "1", "2", "3", "33", "331", "332"))
"""Group-1 codes (G0 ... G3, G33, G331, G332; ``lstrip("0")`` of G0 is empty) that end ``CIP``."""
GEOMETRY_KEY = "siemens_geometry_units"
"""``ctx.state.extra`` key: True while G70/G71 (lengths only) is the units code in force."""


def _centre_in_plane(block: Block, ctx: Context) -> None:
    """An arc's centre offset along the axis normal to its plane (``K`` in G17: ``G2 X0 Y0 Z10 I0 J-25 K5``)
    is a component of the centre point, which SINUMERIK takes "in Cartesian coordinates" beside I and J
    [V: SINUMERIK ONE NC programming manual 12/2019 6FC5398-2EP40-0BA0, 2.9.7 "Helical interpolation":
    ``G2/G3 X... Y... Z... I... J... K... TURN=``, "I J K: circle center point in Cartesian coordinates"].
    The circle turns in the plane about the centre's projection and the normal axis moves linearly to its end
    point [V: same, "a vertical linear motion is superimposed"; 2.9.6: start and end apart along the normal
    make a helix], so that component moves nothing: it leaves the neutral arc, whose centre lies in the plane."""
    motion = block.sections.get("Motion")
    if not isinstance(motion, Motion) or motion.mode not in ("cw", "ccw") or not motion.center:
        return
    plane = block.sections.get("Plane")
    name = getattr(plane, "plane", None) or ctx.state.plane
    normal = PLANE_AXES[name][2]
    if normal in motion.center:
        motion.center = {a: v for a, v in motion.center.items() if a != normal}


class SiemensBlockSyntax(WordBlockSyntax):
    """Words -> neutral sections, for SINUMERIK 840D sl / 828D mills."""

    XNAME = "SiemensBlockSyntax"
    __slots__ = ()
    DIALECT: ClassVar[str] = "siemens"
    TITLE: ClassVar[str] = "SINUMERIK"
    CODES: ClassVar[CodeTable] = CODES
    POINTLESS_IN_UNITS: ClassVar[bool] = True

    def build(self, block: Block, ctx: Context) -> None:
        point = block.sections.pop(SiemensFixedPoint.KEY, None)
        if isinstance(point, SiemensFixedPoint):
            resolve_fixed_point(block, ctx, point)
            return
        arc = block.sections.pop(SiemensArc.KEY, None)
        if isinstance(arc, SiemensArc):
            arc_words(block, ctx, arc)
        if not self.circle_through(block, ctx):
            return  # kept verbatim (``arcs``)
        turn = block.sections.pop(SiemensTurn.KEY, None)
        start = None
        if isinstance(turn, SiemensTurn):
            start = helix.before(block, ctx, turn)
            if "NativeCode" in block.sections:
                return  # kept verbatim (``helix``)
        holes = block.sections.pop(SiemensHoles.KEY, None)
        if isinstance(holes, SiemensHoles):
            resolve_holes(block, ctx, holes)
            if "NativeCode" in block.sections:
                return  # kept verbatim (``holes``)
        suppression = frame_suppression.take(block)
        if suppression is not None:
            why = frame_suppression.problem(block, ctx)
            if why is not None:
                keep_verbatim(block, f"{suppression} (frame suppression) {why}")
                return
            frame_suppression.kept_length(block, ctx)
            block.add(MachineCoordinates())
        frame_suppression.note_cutter(block, ctx)
        levels = block.sections.pop(CycleLevels.KEY, None)
        if isinstance(levels, CycleLevels):
            level = SiemensCycleRules.call(block, ctx, levels)
            if level is None:
                return  # kept verbatim (``cycles.keep_verbatim``)
            block.add(ReturnLevel(level))
        elif "CycleCancel" in block.sections:
            ctx.state.extra.pop(MCALL_KEY, None)
            ctx.state.extra.pop(DIS1_KEY, None)
            ctx.state.extra.pop(TAP_KEY, None)
        super().build(block, ctx)
        _centre_in_plane(block, ctx)
        if isinstance(turn, SiemensTurn) and start is not None:
            helix.after(block, ctx, turn, start)

    @staticmethod
    def circle_through(block: Block, ctx: Context) -> bool:
        """``CIP`` (``arcs.cip_words``), and the blocks while it is the motion code in force: one that moves
        with no motion code of its own is kept verbatim (each CIP block names its intermediate point).
        False when the block was kept verbatim."""
        extra = ctx.state.extra
        cip = block.sections.pop(SiemensCip.KEY, None)
        if isinstance(cip, SiemensCip):
            if not cip_words(block, ctx, cip):
                keep_verbatim(block, "CIP off the XY plane, in G91 or without its intermediate point I1, J1")
                extra[CIP_KEY] = True
                return False
            extra[CIP_KEY] = True
            return True
        if CIP_KEY not in extra:
            return True
        if any(letter in "Gg" and num.lstrip("0") in _MOTION for letter, num in block.words):
            del extra[CIP_KEY]
            return True
        if any(letter.upper() in "XYZ" for letter, _ in block.words):
            keep_verbatim(block, "a move under CIP without its own intermediate point")
            return False
        return True

    def g_sections(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                   used: set[str], cycle_block: bool) -> None:
        if "CycleCall" in block.sections:
            used.update("RZKPQ")  # the words of ``MCALL CYCLE8x`` (``cycles``), read by the resolve step
        elif ctx.state.extra.get(MCALL_KEY) and ctx.state.cycle is not None:
            SiemensCycleRules.position(block, ctx, codes, values)
        units = codes.get("06")
        extra = ctx.state.extra
        if units is not None:
            extra[GEOMETRY_KEY] = g_key(units[3]) in GEOMETRY_UNITS
        dwell = any(kind == "dwell" for _, kind, _, _ in codes.values())
        if "F" in values and not dwell and extra.get(GEOMETRY_KEY):
            selected = units[2] if units is not None else ctx.state.units
            if selected != ctx.setup.machine.units:
                raise ProgramError(f"F under G70/G71 is in the basic system's unit ({ctx.setup.machine.units}), not "
                                   f"the program's {selected}: write G700/G710 to program the feed in {selected}",
                                   ctx.at(block, ctx.column_of(block, "F")))
        super().g_sections(block, ctx, codes, values, used, cycle_block)
        read_tool_data(block, ctx, values, used, toggles=False, first=0)
        motion = block.sections.get("Motion")
        if isinstance(motion, Motion) and motion.mode in MODES:
            read_tap_stroke(block, ctx, motion, values, used, TAP_CODES)

    def _dwell(self, block: Block, ctx: Context, values: dict[str, Any], used: set[str], num: str) -> None:
        """``G4 F<seconds>``; the F is popped so no feed is made of it."""
        at = ctx.at(block, col_of_word(block, "G", num))
        if "S" in values:
            raise ProgramError("G4 S (a dwell in spindle revolutions) is not modelled", at)
        if "F" not in values:
            raise ProgramError("G4 needs its time in F (seconds): G4 F2.5", at)
        time = values.pop("F")
        if isinstance(time, Expr):
            block.add(Dwell(time))
            return
        if time < 0:
            raise ProgramError("a dwell time cannot be negative", at)
        block.add(Dwell(float(time)))
