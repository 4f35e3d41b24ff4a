"""Whether a block names block numbers: the reason a program cannot be renumbered as it is written.

A renumbering gives every block a new number; a word that names a block by its number (a jump to it, a
return to it in the caller, a lathe cycle's profile range from its first to its last block) would then
name another block, or none, and the program would run other moves with no error. The writer's renumbering
(``--renumber`` in the program's own dialect) rewrites such a block's literal references to their targets'
new numbers (``postproc.output.block_renumbering``: it numbers the whole program before writing it) and
refuses the rest, located; ``blockNumbers`` (``postproc.output.line_format``) numbers the lines after they
are written, references included, and refuses such a block.
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
