"""Tool length compensation: G43 adds the length of its register to Z, G44 subtracts it, G49 cancels it
([V] LinuxCNC: ``USE_TOOL_LENGTH_OFFSET`` with the table's length; [K] Fanuc: offset along Z, the sign by
G43/G44). The offset takes effect with the next move: a block that only changes it moves nothing here
([?] Fanuc: a controller that moves the axis at the changing block itself ends at the same point). A
controller that moves nothing until the axis is programmed (``Dialect.LENGTH_AT_PROGRAMMED_AXIS``: [V]
LinuxCNC, grbl) keeps the controlled point instead (``Moves.compensation``).

The simulator keeps the programmed point in its own frame and writes the controlled point (programmed +
offset) beside it; a reference return ends at the reference point with no offset ([V] LinuxCNC computes
the programmed point back from the machine position), so there the programmed point is moved instead.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from ..errors import ProgramError
from .tool_table import ToolTable

AXIS = "Z"
"""The axis the length is applied along (a mill's spindle axis)."""
SIGNS = {"positive": 1.0, "negative": -1.0, "cancel": 0.0, "dynamic": 1.0}


@mypyc_attr(allow_interpreted_subclasses=True)
class ToolLength:
    """The tool length offset in force, in mm along ``AXIS``."""

    def __init__(self, table: ToolTable) -> None:
        self.table = table
        self.offset = 0.0

    def change(self, mode: str, register: int | None, length: float | None = None, scale: float = 1.0) -> None:
        """Put a length offset in force (register values are read now: a later change of the register
        needs the offset programmed again, as on the controllers modelled). A ``dynamic`` offset carries
        its ``length`` in program units (``scale`` mm per unit): [V] grbl wiki "G43.1 Z.. dynamic tool
        length offset", LinuxCNC ``G43.1``."""
        sign = SIGNS.get(mode)
        if sign is None:
            raise ProgramError(f"tool length offset '{mode}' cannot be simulated")
        if sign == 0.0:
            self.offset = 0.0
            return
        if mode == "dynamic":
            if length is None:
                raise ProgramError("a dynamic tool length offset without its length cannot be simulated")
            self.offset = length * scale
            return
        if register is None:
            raise ProgramError("a tool length offset without its register cannot be simulated")
        self.offset = sign * self.table.length(register)
