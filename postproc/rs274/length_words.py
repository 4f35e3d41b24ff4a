"""The tool length words of an RS274-family block beside the usual G43/G44/G49 H: a dynamic length
(``G43.1 Z<length>``), an H without a length code in its block, and G43/G44 without H. Split out of the
block syntax (``WordBlockSyntax``), whose methods of the same names call these."""

from __future__ import annotations

from typing import Any, ClassVar, Final, Protocol

from postproc.context import Context
from postproc.errors import ProgramError
from postproc.ir.expr import Expr
from postproc.ir import Block, ToolLengthOffset

from .words import AXIS_LETTERS, UPPER, col_of_word


class LengthSyntax(Protocol):
    """What these readings ask of the block syntax (``WordBlockSyntax``), named here so that this module
    does not import it back."""

    DYNAMIC_LENGTH_BARE: ClassVar[bool]

    def spell(self, kind: str, arg: object = None) -> str: ...

    @staticmethod
    def _word_text(block: Block, up: str) -> str: ...

LENGTH_REGISTER: Final = "rs274.length_register"
"""``ctx.run_data`` key: an H has been programmed (``bare_length``)."""


def dynamic_length(syntax: LengthSyntax, block: Block, ctx: Context, num: str, codes: dict[str, Any],
                   values: dict[str, Any], used: set[str]) -> None:
    """``G43.1 Z<length>``: every axis word of the block is the offset's, none a move [V: grbl ``gcode.c``
    "[G43.1 Errors]", an axis word other than Z or a missing Z is ``STATUS_GCODE_G43_DYNAMIC_AXIS_ERROR``;
    V: rs274 2.9 run here, ``G43.1 X1 Z3`` is ``USE_TOOL_LENGTH_OFFSET(1 0 3, ...)``, and an axis the block
    does not name keeps its offset: ``G43.1 Z3`` then ``G43.1`` or ``G43.1 X0`` leaves Z at 3]. Only a length
    along Z is modelled: an offset along another axis is refused by
    name, never read as a move. A motion or cycle code in the block is refused: rs274 then takes the Z word
    as the length and as the move's end too (``G91 G43.1 Z4 G1`` moves Z by 4 [V: rs274 2.9 run here]),
    grbl refuses it (an axis command conflict [V: grbl ``gcode.c``])."""
    motion = codes.get("01")
    if motion is not None and motion[1] in ("motion", "cycle"):
        raise ProgramError(f"G{num} with G{motion[3]} in one block: the Z word would be the tool length and the "
                           "move's too (write the motion in a block of its own)",
                           ctx.at(block, col_of_word(block, "G", motion[3])))
    other = next((letter for letter, _ in block.words if UPPER.get(letter, "") in AXIS_LETTERS
                  and UPPER[letter] != "Z"), None)
    if other is not None:
        up = UPPER[other]
        raise ProgramError(f"G{num} with an {up} word: only a tool length along Z is modelled (an offset "
                           f"along {up} is not; the {up} word is the offset's, not a move)",
                           ctx.at(block, ctx.column_of(block, up)))
    if "Z" not in values:
        if not syntax.DYNAMIC_LENGTH_BARE:
            raise ProgramError(f"G{num} needs the tool length as its Z word",
                               ctx.at(block, col_of_word(block, "G", num)))
        return  # the offsets in force stay: nothing changes
    used.add("Z")
    block.add(ToolLengthOffset("dynamic", None, values["Z"]))


def length_register(syntax: LengthSyntax, block: Block, ctx: Context, values: dict[str, Any],
                    used: set[str]) -> None:
    """An offset register H without G43/G44/G49 in its block (``G53 G0 Z0 H0``): while a tool length
    offset is in force it selects that register's offset [V: Fanuc 0i-MB operator's manual 14.1.2,
    "independent specification of the H command"]; under G49 H0 (whose offset is always zero) leaves
    the length offset cancelled [K: Fanuc 0i-F operator's manual, offset number 0; Haas mill operator's
    manual, H00]; another register there takes effect only with a later G43/G44 and is refused."""
    register = values["H"]
    ctx.run_data[LENGTH_REGISTER] = True
    mode = ctx.state.length
    if mode != "cancel":
        block.add(ToolLengthOffset(mode, register))
    elif not isinstance(register, Expr) and int(register) == 0:
        block.add(ToolLengthOffset("cancel"))
    else:
        raise ProgramError(f"H{syntax._word_text(block, 'H')} with no tool length offset in force: a register "
                           f"takes effect with {syntax.spell('length', 'positive')} or "
                           f"{syntax.spell('length', 'negative')} (write it in their block)",
                           ctx.at(block, ctx.column_of(block, "H")))
    used.add("H")


def bare_length(block: Block, ctx: Context, num: str) -> None:
    """G43/G44 without H takes the register in force, the H last programmed (modal) [K: Fanuc 0i-F
    operator's manual, tool length offset]; at a program's start the machine's (the last program's H, or
    H0 after a reset that clears it: parameter 5003#6 LVK [K]). Haas taken as Fanuc; whether its Setting
    15 (H & T code agreement) gives the spindle tool's register is not confirmed [?]. Not carried over
    here (after a jump the last H in the text need not be the last run): refused, saying which case."""
    at = ctx.at(block, col_of_word(block, "G", num))
    if ctx.run_data.get(LENGTH_REGISTER):
        raise ProgramError(f"G{num} without an offset register H: it takes the H last programmed, which "
                           f"this reader does not carry over (write the H in this block)", at)
    raise ProgramError(f"G{num} without an offset register H, and no H programmed before it: the register "
                       f"in force is the machine's, known only to it (program G{num} H..)", at)
