"""GrblFamily: what the dialects of the grbl family (grbl 1.1, grblHAL) share as a class, for the family's
steps to ask a target. A build of a grbl-family controller chooses its features when it is compiled
(grblHAL's ``N_TOOLS``, ``NGC_EXPRESSIONS_ENABLE``), so some capabilities depend on the set-up's
``<Controller>``: the family's steps ask the dialect with the set-up in hand."""

from __future__ import annotations

from postproc.dialect import Dialect
from postproc.setup.machine_setup import MachineSetup


class GrblFamily(Dialect):
    """A grbl-family dialect (subclassed by each; it registers none itself)."""

    LENGTH_AT_PROGRAMMED_AXIS = True
    """[V] grbl ``gcode.c``: ``G43.1``/``G49`` change ``tool_length_offset`` and move nothing; an axis without
    a word keeps ``gc_state.position`` (machine), an absolute word adds the offset, an incremental one adds
    to the machine position. [K] grblHAL ``gcode.c``: the same (``gc_get_block_offset`` adds the length to
    absolute words only)."""

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
