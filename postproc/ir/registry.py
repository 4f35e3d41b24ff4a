"""Every core section, for the XML registry (``register_sections``) and the steps that treat the simple
ones alike (``SIMPLE_SECTIONS``)."""

from __future__ import annotations

from typing import Iterator, Final

from ..xmlio import XFactory
from .modal import (BlockDelete, Comments, Coolant, CutterCompensation, CycleCall, CycleCancel, DistanceMode,
                    Dwell, Feed, FeedMode, MachineCoordinates, PathControl, Plane, ProgramControl, ProgramStart,
                    ReturnLevel, Sequence, SpindleControl, SpindleOrientation, SpindleSpeed, TapeMark,
                    ToolChange, ToolLengthOffset, ToolSelect, Units, WorkOffset)
from .motion import CompoundMotion, Motion
from .section import Section
from .verbatim import DataSetting, MachineFunction, NativeCode


SIMPLE_SECTIONS: Final[tuple[type[Section], ...]] = (
    Sequence, BlockDelete, ProgramStart, TapeMark, Units, Plane, DistanceMode, WorkOffset, FeedMode, Feed,
    SpindleSpeed, SpindleControl, SpindleOrientation, ToolSelect, ToolChange, ToolLengthOffset,
    CutterCompensation, Coolant, Dwell, ProgramControl, PathControl, ReturnLevel, CycleCancel,
    MachineCoordinates, CycleCall, MachineFunction,
)




def register_sections(factory: XFactory | None = None) -> None:
    """Register every core section with ``factory``; idempotent."""
    for cls in iter_sections():
        cls.reg(factory)


def iter_sections() -> Iterator[type[Section]]:
    yield from (*SIMPLE_SECTIONS, Comments, Motion, NativeCode, CompoundMotion, DataSetting)
