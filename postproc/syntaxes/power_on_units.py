"""The units a controller is in at power-on, carried by the program's first block that reads a length.

A program that programs no ``G20``/``G21`` before its first length runs in its controller's power-on units, a
setting of the machine (Fanuc parameter 0000#2 INI [K]; Haas Setting 9 "Dimensioning", INCH or MM [K: Haas
lathe and mill operator's manuals, settings list, as known, not re-read here]), which a copy of the program does
not carry. Read as millimetres such a program is scaled by 25.4 on an inch machine. The set-up's
``<Controller startUnits>`` says what the machine's setting is: the reading starts in those units, and the first
block that reads a length gets them as a ``Units`` section, as if the program had programmed them there. Its text
is kept, so a copy for the same controller is the program as written; every other consumer (the simulation, a
writer for another controller, ``verify``) sees the units where they take effect, and a target gets them written
(``G20`` in that block). Without the attribute the program starts in millimetres
(``postproc.lowering.units_at_start``).
"""

from __future__ import annotations

from typing import Final

from postproc.context import Context
from postproc.interp.control import ASSIGN, CONTROL, SubStart
from postproc.errors import UnsupportedError
from postproc.ir import Block, Units

KEY: Final = "power_on_units"
"""``ModalState.extra`` key: the power-on units, until the block that reads a length first takes them."""
HEADER: Final = frozenset(("ProgramStart", "TapeMark", "Comments", "Sequence"))
"""Sections of a block that read no length: the units may come after them."""
PLAIN: Final = frozenset(("Comments", "Coolant", "CutterCompensation", "CycleCancel", "DistanceMode", "Dwell", "Feed",
                          "FeedMode", "MachineCoordinates", "MachineFunction", "Motion", "PathControl", "Plane",
                          "ProgramControl", "ReturnLevel", "Sequence", "SpindleControl", "SpindleOrientation",
                          "SpindleSpeed", "ToolChange", "ToolLengthOffset", "ToolSelect", "WorkOffset", "DataSetting",
                          "CycleCall", "CompoundMotion"))
"""Sections of a plain block (modal words, motion, a data setting): the units can join them (``G21 G90 G54``)."""


def take_power_on_units(block: Block, ctx: Context) -> None:
    """Give ``block`` the power-on units if it is the first to read a length (see the module docstring). A control
    statement or an assignment before it reads no length (``#100=1.``, ``WHILE``): the units wait for the block
    after it that does, in the order the blocks are read, which for a program kept as written is its text's and for
    a run its execution's (the same block, both times, unless a jump skips it). A subprogram defined before the
    program (LinuxCNC ``o<name> sub``) is refused by name: its blocks run only where it is called, after the
    program's own first moves."""
    keys = block.sections.keys()
    if not keys or ("Units" not in keys and HEADER.issuperset(keys)):
        return
    if "Units" not in keys and (CONTROL in keys or ASSIGN in keys):
        if isinstance(block.sections.get(CONTROL), SubStart):
            raise UnsupportedError(f"the machine's power-on units (<Controller startUnits=\"{ctx.state.extra[KEY]}\">) "
                                   "would go into a subprogram defined before the program, which runs where it is "
                                   "called: program the units before it", ctx.at(block))
        return  # a statement reads no length itself: the units go with the next block that does
    units = ctx.state.extra.pop(KEY)
    if "Units" in keys:
        return
    block.add(Units(str(units)))
