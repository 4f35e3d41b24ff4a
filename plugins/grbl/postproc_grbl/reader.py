"""grbl reader: the family's reader (``postproc.grbl_family.reader``: ``%`` as an inert comment), naming grbl in
errors; ``/`` is ignored wherever it stands and the block runs, as grbl runs it (with a warning)."""

from __future__ import annotations

from postproc.grbl_family.reader import GrblFamilyReader


class GrblReader(GrblFamilyReader):
    DIALECT = "grbl"
    BLOCK_DELETE = False
    """grbl 1.1's protocol.c drops every '/' ("Block delete NOT SUPPORTED. Ignore character.")."""
