"""A reference return (Fanuc ``G28``) towards SINUMERIK as a fixed-point approach, ``G75 FP=1 Z1=0``.

Why ``G75`` and not ``G53``/``G153``/``SUPA``: those suppress the frames for one block, but whether they
suppress the tool length and radius too is machine data (``$MN_G53_TOOLCORR``) [V: SINUMERIK 802D sl/840D
ISO Milling programming manual 04.07, 3.1.1 "Machine coordinate system (G53)"], so their meaning is not
certain from the program. ``G75`` is [K: SINUMERIK ONE NC programming, Programming Manual 12/2019
6FC5398-2EP40-0BA0, 2.14 p.361; 840D sl Fundamentals "Fixed point approach (G75)", as quoted on
en.cncforum.net/t/196]:

* non-modal, in a block of its own; the group-1 code in force before it (G0, G1...) is in force after it;
* it moves the named axes as machine axes at rapid (internally ``SUPA`` with ``G0 RTLIOF``) to fixed point
  ``FP=<n>`` (1 when no FP is written), a position in machine data (``MD30600 $MA_FIX_POINT_POS``): all
  active frames are ignored and no offset is in effect, so no tool length either: the slide goes where
  Fanuc's G28 puts the spindle, at its reference point (a parameter too). An external work offset, DRF and
  ``$AA_OFF`` still shift it [K: p.361]: machine state a translation never sets;
* each axis is written by its machine axis name with any value (ignored), e.g. ``Z1=0``. ``X1``/``Y1``/``Z1``
  are the default machine axis names [?: MD10000 ``AXCONF_MACHAX_NAME_TAB``; a machine builder may rename
  them], and the spelling shop programs use (``G75 FP=1 Z1=0 Y1=0 X1=0``) [K].

So fixed point 1 is the set-up's ``<Axis home>`` (where a reference return goes, as on ISG): the writer
writes the intermediate point as a ``G0`` move, then ``G75 FP=1``; the reader reads ``G75 FP=1`` back as a
rapid move in machine coordinates to the set-up's home, which is how the simulator runs Fanuc's ``G28``
(the spindle at the home position, the tool's length below it). A set-up with no home for an axis is a
located error naming the element, on both sides; a return to the second reference point (``G30``) is
refused (the set-up has no element for fixed point 2), as is any ``FP`` other than 1 when reading.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING

from postproc.errors import ProgramError
from postproc.ir.expr import Expr
from postproc.ir import MachineCoordinates, Motion, Section
from postproc.output.home_position import SECOND_RETURN, add_home, home_position
from postproc.output.home_position import reference_problem as home_problem
from postproc.xmlio import XAttr

if TYPE_CHECKING:
    from postproc.context import Context
    from postproc.ir import Block
    from postproc.setup.machine_setup import MachineSetup

MACHINE_AXES = {"X": "X1", "Y": "Y1", "Z": "Z1"}
"""Geometry axis -> its machine axis name in a G75 block (the 840D defaults [?], module docstring)."""
_GEOMETRY = {machine: axis for axis, machine in MACHINE_AXES.items()}
_BLOCK = re.compile(r"G0*75(?:\s+FP\s*=\s*(\d+))?((?:\s+[XYZ]1\s*=\s*[-+]?(?:\d+\.?\d*|\.\d+))+)\s*$", re.IGNORECASE)
"""``G75 FP=<n>`` and its machine axes, alone in the block (after a skip, a block number or a label)."""
_AXIS = re.compile(r"([XYZ]1)\s*=", re.IGNORECASE)


class SiemensFixedPoint(Section):
    """A ``G75 FP=<n>`` block as read: the fixed point and the geometry axes it moves, in order
    (``resolve`` turns it into a move in machine coordinates)."""

    XNAME = KEY = "SiemensFixedPoint"
    __slots__ = ("number", "axes")
    XATTRS = (XAttr("number", int), XAttr("axes", str))
    number: int
    axes: str

    def __init__(self, number: int, axes: str) -> None:
        self.number = number
        self.axes = axes


def read_fixed_point(code: str, pos: int) -> SiemensFixedPoint | None:
    """The fixed-point approach of a block's words from ``pos``, or None when they are no plain
    ``G75 FP=<n> Z1=0`` (any other G75 block is read as before: kept verbatim)."""
    found = _BLOCK.match(code, pos)
    if found is None:
        return None
    axes = "".join(_GEOMETRY[name.upper()] for name in _AXIS.findall(found.group(2)))
    if len(set(axes)) != len(axes):
        return None
    return SiemensFixedPoint(int(found.group(1) or 1), axes)


def reference_problem(setup: MachineSetup, motion: Motion, inch: bool) -> str | None:
    """Why a reference return cannot be written as ``G75 FP=1``, or None when it can."""
    for axis in motion.axes:
        if axis not in MACHINE_AXES:
            return f"a reference return of axis {axis} (G75 is written for X, Y and Z)"
    return home_problem(setup, motion, inch, "SINUMERIK writes it as G75 FP=1, fixed point 1 being the set-up's "
                        "home position", SECOND_RETURN + " (G30)")


def resolve(block: Block, ctx: Context, point: SiemensFixedPoint) -> None:
    """``G75 FP=1``: a rapid move in machine coordinates to the set-up's home of each named axis."""
    text = (block.text or "").upper()
    if point.number != 1:
        raise ProgramError(f"G75 FP={point.number}: only fixed point 1 is known (the set-up's <Axis home>); "
                           "the set-up has no element for the others", ctx.at(block, text.find("FP") + 1 or 1))
    inch = ctx.state.units == "inch"
    axes: dict[str, float | Expr] = {}
    for axis in point.axes:
        value = home_position(ctx.setup, axis, inch)
        if value is None:
            raise ProgramError(f"G75 FP=1 moves axis {axis} to fixed point 1, taken as the set-up's home "
                               f"position, which it does not give ({add_home(axis)})",
                               ctx.at(block, text.find(MACHINE_AXES[axis]) + 1 or 1))
        axes[axis] = value
    block.add(MachineCoordinates())
    block.add(Motion("rapid", axes))


def g75_line(axes: list[str]) -> str:
    """The fixed-point approach of ``axes`` (geometry names), without its end of line."""
    return "G75 FP=1 " + " ".join(MACHINE_AXES[axis] + "=0" for axis in axes)

