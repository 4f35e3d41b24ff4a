"""grblHAL reader: the grbl family's reader (``%`` as an inert comment), naming grblHAL in errors. ``/`` at the
start of a block skips it when the operator's block delete switch is on [V: grblHAL core ``gcode.c``
``gc_normalize_block``, ``sys.flags.block_delete_enabled``], as RS274/NGC reads it."""

from __future__ import annotations

from postproc.grbl_family.reader import GrblFamilyReader


class GrblhalReader(GrblFamilyReader):
    DIALECT = "grblHAL"
