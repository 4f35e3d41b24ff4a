"""Machine-specific codes towards a controller of another family: under ``--on-unsupported warn`` the
code alone is left out, with a warning and a comment in its block, and the rest of the block is kept
(``M31``: the part counter does not count). Under 'error' the block reaches the writer unchanged, which
reports the code with its location.

A code whose action is ``rigid-tap`` (Fanuc ``M29 S..``) is never left out here: it makes the tap cycles
after it follow the spindle, and the same cycle fed without the spindle in step breaks the tap. Towards a
target that writes a synchronised tap (LinuxCNC's G33.1) ``postproc.synchronised_tap`` has already taken it
(its taps carry its meaning); towards any other family it is refused in either mode, by
``refused_rigid_tap``'s message.
"""

from __future__ import annotations

from typing import Iterator

from ..context import Context
from ..dialect import Dialect
from ..errors import UnsupportedError
from ..ir import Block, Comments, MachineFunction

RIGID_TAP = "rigid-tap"
"""The action of a code that makes the following tap cycles spindle-synchronised."""


def refused_rigid_tap(code: MachineFunction, target: str) -> str:
    """Why a rigid-tapping code cannot go to ``target`` (a controller of another family)."""
    return (f"{code.describe()} of the {code.family} family makes the tap cycles after it follow the spindle; "
            f"this translation writes no spindle-synchronised tap for {target}, and fed "
            "without the spindle in step a tap breaks: refused, even with --on-unsupported warn")


def comment_out(block: Block, note: str) -> None:
    """The block's machine-specific code goes; ``note`` joins its comments, saying why or where its meaning went."""
    del block.sections["MachineFunction"]
    comments = block.sections.get("Comments")
    texts = list(comments.texts) if isinstance(comments, Comments) else []
    block.sections["Comments"] = Comments([*texts, note])
    block.changed()


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
        if isinstance(code, MachineFunction) and code.family != family and code.action == RIGID_TAP:
            ctx.diagnostics.error(UnsupportedError(refused_rigid_tap(code, target.NAME),
                                                   ctx.at(block, _column(block, code.code))))
            del block.sections["MachineFunction"]  # refused once, here: the writer would warn of it again
            block.changed()
        elif isinstance(code, MachineFunction) and code.family != family:
            note = f"{code.text} NOT WRITTEN: {code.describe()} of the {code.family} family has no equivalent"
            ctx.diagnostics.warn(f"{code.describe()}, a machine-specific code of the {code.family} family, has "
                                 f"no equivalent in {target.NAME}; left out, its block kept",
                                 ctx.at(block, _column(block, code.code)))
            comment_out(block, note)
        yield block


def _column(block: Block, code: str) -> int:
    i = (block.text or "").upper().find(code)
    return i + 1 if i >= 0 else 1
