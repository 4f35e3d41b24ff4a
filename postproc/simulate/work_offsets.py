"""The work offsets between the toolpath's frame and the machine's (``postproc.setup.work_offsets``, where the
lowering reads them too): the simulation's names for them."""

from __future__ import annotations

from ..setup.work_offsets import declared_offsets, offset_beyond_frame

__all__ = ["declared_offsets", "offset_beyond_frame"]
