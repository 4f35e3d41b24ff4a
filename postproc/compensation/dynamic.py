"""Cutter radius compensation by a diameter given in the program (LinuxCNC's G41.1/G42.1 D.. [L..]).

Unlike G41/G42 it names no register: the block carries the tool's diameter (and, on a lathe, its
orientation), so the simulation needs no tool table [V: LinuxCNC src/emc/rs274ngc/interp_convert.cc
convert_cutter_compensation_on: radius = D / 2, L only in G18, a negative radius swaps the side; and
rs274 2.9 run here]. A reader that meets it keeps its block verbatim (``NativeCode``, inert for the
simulation: this section says what it does) and adds this section only when the block does nothing
else, so the simulation never passes over another word of it. A target without the code refuses the
block (its ``NativeCode``) unless a lowering step resolves it into the compensated path first
(``lowering.cutter_compensation.resolve_dynamic_cutter_compensation``: every target but the source's
own dialect).
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from ..ir import Section
from ..xmlio import XAttr, XFactory


@mypyc_attr(allow_interpreted_subclasses=True)
class DynamicCutterCompensation(Section):
    """'left' or 'right' of the path, by ``diameter`` (program units; negative: the other side), with a
    lathe tool's ``orientation`` (None: 0, a mill's), numbered as LinuxCNC's L word numbers it (X mirrored
    from Fanuc's tip numbers: ``postproc.compensation.nose.mirrored``)."""

    XNAME = "DynamicCutterCompensation"
    KEY = "DynamicCutterCompensation"
    __slots__ = ("mode", "diameter", "orientation")
    XATTRS = (XAttr("mode", str), XAttr("diameter", float), XAttr("orientation", int, None))
    mode: str
    diameter: float
    orientation: int | None

    def __init__(self, mode: str, diameter: float, orientation: int | None = None) -> None:
        self.mode = mode
        self.diameter = diameter
        self.orientation = orientation

    def radius(self, scale: float) -> float:
        """The signed radius in mm (``scale``: mm per program unit); the compensation swaps the side of a
        negative one."""
        return self.diameter * scale / 2.0


def register(factory: XFactory | None = None) -> None:
    """Register the section with ``factory`` (the default one if None); idempotent."""
    DynamicCutterCompensation.reg(factory)

