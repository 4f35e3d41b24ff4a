"""``--renumber START[,STEP]`` into the set-up, for one program and for a batch alike.

In its own dialect the writer renumbers the blocks it normalises (``Writer.normalized``: the option implies
``--normalize``). Between two dialects no block is normalised, every one is generated, so the writer's
renumbering would never run and the option would be ignored with exit 0: there it numbers the written
lines instead (``<Output blockNumbers="all">``, ``postproc.output.line_format``), from START by STEP (as a
set-up's ``renumberStart`` alone does there, ``line_format.numbering``). In its own dialect the references to
block numbers follow their blocks (``postproc.output.block_renumbering``); between two, a program that names
block numbers is refused, located (``postproc.output.block_references``).
"""

from __future__ import annotations

from ..setup.groups import OutputSettings


def apply_renumber(output: OutputSettings, renumber: tuple[int, int | None], source: str, target: str) -> None:
    """Set ``output`` to renumber as ``--renumber`` asks, translating from ``source`` to ``target``."""
    start, step = renumber
    output.renumber_start = start
    if step is not None:
        output.renumber_step = step
    if source != target:
        output.block_numbers = "all"
