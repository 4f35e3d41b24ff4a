"""The intermediate representation: a program is a stream of ``Block``s.

A block keeps its source line, its raw text and words (so unchanged blocks are written back byte for
byte) and a dict of typed, dialect-neutral sections. No dialect's spelling lives here: a section says
"rapid motion" or "return to the initial level", never "G00" or "G98". Dialect-specific constructs with
no neutral meaning travel as ``NativeCode`` tagged with their dialect.

Blocks are plain ``__slots__`` objects without reference cycles and sections are created only for what a
block actually programs: a million-block program must stream without pressure on the garbage collector.

``section`` holds the base of every section, ``modal`` the simple ones, ``motion`` the moves, ``verbatim``
what travels verbatim for its own family, ``block`` the block, ``registry`` the list of them all; the
names a step or a plugin uses are these, from ``postproc.ir``.
"""

from .block import Block, decode_eol, encode_eol, one_line
from .modal import (BlockDelete, Comments, Coolant, CutterCompensation, CycleCall, CycleCancel, DistanceMode,
                    Dwell, Feed, FeedMode, MachineCoordinates, PathControl, Plane, ProgramControl, ProgramStart,
                    ReturnLevel, Sequence, SpindleControl, SpindleOrientation, SpindleSpeed, TapeMark,
                    ToolChange, ToolLengthOffset, ToolSelect, Units, WorkOffset)
from .motion import CompoundMotion, Motion
from .registry import SIMPLE_SECTIONS, iter_sections, register_sections
from .section import AXES, Section, axes_from_xml, axes_to_xml
from .verbatim import DataSetting, MachineFunction, NativeCode

__all__ = [
    "AXES", "SIMPLE_SECTIONS", "Block", "BlockDelete", "Comments", "CompoundMotion", "Coolant", "CutterCompensation",
    "CycleCall", "CycleCancel", "DataSetting", "DistanceMode", "Dwell", "Feed", "FeedMode", "MachineCoordinates",
    "MachineFunction", "Motion", "NativeCode", "PathControl", "Plane", "ProgramControl", "ProgramStart",
    "ReturnLevel", "Section", "Sequence", "SpindleControl", "SpindleOrientation", "SpindleSpeed", "TapeMark",
    "ToolChange", "ToolLengthOffset", "ToolSelect", "Units", "WorkOffset", "axes_from_xml", "axes_to_xml",
    "decode_eol", "encode_eol", "iter_sections", "one_line", "register_sections",
]
