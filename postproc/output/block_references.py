"""Whether a block names block numbers: the reason a program cannot be renumbered as it is written.

A renumbering gives every block a new number; a word that names a block by its number (a jump to it, a
return to it in the caller, a lathe cycle's profile range from its first to its last block) would then
name another block, or none, and the program would run other moves with no error. Both renumberings
(``--renumber`` in the writer, ``blockNumbers`` in ``postproc.output.line_format``) refuse such a block,
located, rather than write it: a rewrite of the references needs every target's new number before the
reference is written (a lathe cycle names blocks that follow it), and a computed target cannot be mapped.
"""

from __future__ import annotations

from ..interp.control import CONTROL
from ..ir import Block

PROFILE_RANGE = ("ns", "nf")
"""The ``LatheCycle`` parameters that are block numbers: the first and the last block of its profile."""


def names_block_numbers(block: Block) -> bool:
    """The block jumps to, returns to, or reads a profile between block numbers."""
    sections = block.sections
    control = sections.get(CONTROL)
    if control is not None and getattr(control, "target", None) is not None:
        return True
    cycle = sections.get("LatheCycle")
    params = getattr(cycle, "params", None)
    return isinstance(params, dict) and any(name in params for name in PROFILE_RANGE)
