"""Machine-specific codes towards a controller of another family: under ``--on-unsupported warn`` the
code alone is left out, with a warning and a comment in its block, and the rest of the block is kept
(``M29 S500``: the tap still runs at S500). Under 'error' the block reaches the writer unchanged, which
reports the code with its location.
"""

from __future__ import annotations

from typing import Iterator

from .context import Context
from .dialect import Dialect
from .ir import Block, Comments, MachineFunction


def drop_foreign_machine_functions(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Leave out (with a warning and a comment) each machine-specific code of another family (with
    ``--on-unsupported warn``; otherwise the writer refuses it, and the blocks pass with no step each)."""
    if ctx.on_unsupported != "warn":
        return blocks
    return _drop(blocks, ctx, target)


def _drop(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    family = target.family()
    for block in blocks:
        code = block.sections.get("MachineFunction")
        if isinstance(code, MachineFunction) and code.family != family:
            note = f"{code.text} NOT WRITTEN: {code.describe()} of the {code.family} family has no equivalent"
            ctx.diagnostics.warn(f"{code.describe()}, a machine-specific code of the {code.family} family, has "
                                 f"no equivalent in {target.NAME}; left out, its block kept",
                                 ctx.at(block, _column(block, code.code)))
            del block.sections["MachineFunction"]
            comments = block.sections.get("Comments")
            texts = list(comments.texts) if isinstance(comments, Comments) else []
            block.sections["Comments"] = Comments([*texts, note])
            block.changed()
        yield block


def _column(block: Block, code: str) -> int:
    i = (block.text or "").upper().find(code)
    return i + 1 if i >= 0 else 1
