"""GrblFamily: what the dialects of the grbl family (grbl 1.1, grblHAL) share as a class, for the family's
steps to ask a target. A build of a grbl-family controller chooses its features when it is compiled
(grblHAL's ``N_TOOLS``, ``NGC_EXPRESSIONS_ENABLE``), so some capabilities depend on the set-up's
``<Controller>``: the family's steps ask the dialect with the set-up in hand."""

from __future__ import annotations

from postproc.geometry.arc_end import SPIRAL, ArcEndRule
from postproc.dialect import Dialect
from postproc.ir.state import MM_PER_INCH
from postproc.setup.machine_setup import MachineSetup


class GrblFamily(Dialect):
    """A grbl-family dialect (subclassed by each; it registers none itself)."""

    MAX_BLOCK_NUMBER = 10_000_000
    """[V] grbl 1.1 ``gcode.c``: ``MAX_LINE_NUMBER 10000000``; ``gc_execute_line`` refuses a line whose N is larger
    with error 27 (invalid line number) before it runs any of it; [V] grblHAL core ``gcode.c``: the same constant and
    error (``Status_GcodeInvalidLineNumber``). Both read N as a float truncated to an integer, and it only labels
    status reports. The family's reader refuses such a line (the source is invalid on its own controller), its
    writer drops such a number from a valid source with a warning, and generated numbering past it is refused."""

    LENGTH_AT_PROGRAMMED_AXIS = True
    """[V] grbl ``gcode.c``: ``G43.1``/``G49`` change ``tool_length_offset`` and move nothing; an axis without
    a word keeps ``gc_state.position`` (machine), an absolute word adds the offset, an incremental one adds
    to the machine position. [K] grblHAL ``gcode.c``: the same (``gc_get_block_offset`` adds the length to
    absolute words only)."""
    DYNAMIC_TOOL_LENGTH = True
    """``G43.1 Z..`` [V: grbl 1.1 ``gcode.c``; K: grblHAL ``gcode.c``]."""

    ARC_END = ArcEndRule(metric=0.005, inch=0.005 / MM_PER_INCH, relative=0.001, ceiling=100.0, of_start=True,
                         runs=SPIRAL)
    """[V] grbl 1.1 ``gcode.c`` (I/J/K already converted to mm): error 33 (invalid target) when the end radius
    differs from the start radius by more than 0.005 mm and either more than 0.5 mm or more than 0.001 of
    the start radius; inch programs are judged in mm. [K] grblHAL ``gcode.c``: the same check. grbl then runs
    the start radius about the programmed centre and a last segment to the end point (``mc_arc``) [V]; the
    simulation draws the spiral through the same end points, at most the accepted difference away [?]."""

    R_ARC_FLOAT_SLACK = 4 * 2.0 ** -23
    """[K] grbl 1.1 ``gcode.c`` (R arcs): ``h_x2_div_d = 4.0*r*r - x*x - y*y``, error 34 (arc radius error)
    when it is below 0, with no tolerance, in single-precision floats (``float``, 24-bit mantissa) [K: grbl
    ``nuts_bolts.h``/``gcode.c``]; grblHAL ``gcode.c``: the same check [K]. An exact semicircle by R (the
    chord 2R) passes or fails by rounding: four float32 steps of R are taken as that rounding [?]."""

    @classmethod
    def tool_table(cls, setup: MachineSetup) -> bool:
        """The controller under ``setup`` runs ``G43 H`` from its own tool table (else a length offset from a
        register is written as ``G43.1 Z<length>``, ``postproc.grbl_family.lengths``)."""
        return cls.TOOL_LENGTH_OFFSET

    @classmethod
    def expressions(cls, setup: MachineSetup) -> bool:
        """The controller under ``setup`` runs parameters, expressions and o-word flow control (else a program
        that computes reaches it flattened)."""
        return cls.PROGRAMS
