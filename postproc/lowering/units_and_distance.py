"""The units and the distance mode in force where a lowering step stands: the one tracker the steps that convert a
length or read a position by them follow (a block's ``Units`` and ``DistanceMode`` sections), where each had its own
copy of the same lines (the tool length timing, the machine positions, the sideways offsets, the cutter resolver,
an ISG-family target's tool data, a grbl-family target's tool lengths, a lathe's tool offsets written into the
coordinates, the inverse-time feeds).

Each step holds its own tracker: a step sees the blocks as the steps before it leave them (a resolved cutter
compensation stretch adds its own G90/G91), so the modes in force are the step's. A program starts in millimetres
and absolute, as ``ModalState`` and the simulation start, unless the step says otherwise (the inverse-time feeds
start from the reading's state at the program start, with its plane and feed mode: ``postproc.lowering.inverse_time``).
"""

from __future__ import annotations

from typing import Final

from mypy_extensions import mypyc_attr

from ..ir import DistanceMode, Section, Units

MM_PER_INCH: Final = 25.4


@mypyc_attr(allow_interpreted_subclasses=True)
class UnitsAndDistance:
    """The units (``inch``) and the distance mode (``absolute``) the blocks followed so far leave in force."""

    def __init__(self, inch: bool = False, absolute: bool = True) -> None:
        self.inch = inch
        """Inches in force (else millimetres)."""
        self.absolute = absolute
        """Absolute positions in force (G90; else increments, G91)."""
        self.scale = MM_PER_INCH if inch else 1.0
        """Millimetres per program unit."""

    def absolute_in(self, sections: dict[str, Section]) -> bool:
        """Whether a block runs in absolute positions: its own distance mode, else the one in force (asked before
        ``follow`` takes the block)."""
        distance = sections.get("DistanceMode")
        return distance.mode != "incremental" if isinstance(distance, DistanceMode) else self.absolute

    def follow(self, sections: dict[str, Section]) -> bool:
        """Take a block's units and distance mode; True where its units are not the ones in force before it. (A
        ``dict``, not a ``Mapping``: compiled, a ``Mapping``'s ``get`` is a method call, ~45 instructions a block
        more over the steps, callgrind.)"""
        distance = sections.get("DistanceMode")
        if isinstance(distance, DistanceMode):
            self.absolute = distance.mode != "incremental"
        units = sections.get("Units")
        if not isinstance(units, Units):
            return False
        inch = units.system == "inch"
        if inch == self.inch:
            return False
        self.inch = inch
        self.scale = MM_PER_INCH if inch else 1.0
        return True
