"""Programmable data input of the RS274 family (G10): ``G10 L2 P1 X.. Y..`` and the tool-offset forms read
into a ``DataSetting`` where the dialect's ``DATA_TABLES`` model them. Split out of the block syntax
(``WordBlockSyntax._data_setting`` calls it; a dialect overrides that method for forms of its own)."""

from __future__ import annotations

from typing import Any, ClassVar, Final, Mapping, Protocol

from postproc.context import Context
from postproc.errors import ProgramError
from postproc.ir.expr import Expr
from postproc.ir import Block, DataSetting, NativeCode

from .codes import CodeTable, g_key
from .lathe_offset_input import lathe_offset_setting
from .word_values import real, whole_index
from .words import AXIS_LETTERS, DATA_KEY, UPPER, col_of_word


class DataSyntax(Protocol):
    """What the reading asks of the block syntax (``WordBlockSyntax``, whose class attributes of these names
    say what they mean), named here so that this module does not import it back."""

    DIALECT: ClassVar[str]
    DATA_TABLES: ClassVar[Mapping[int, tuple[str, int, int]]]
    LATHE_OFFSET_INPUT: ClassVar[bool]
    DATA_INCREMENTAL: ClassVar[bool]
    DATA_P0_ACTIVE: ClassVar[bool]
    DATA_ROTATION: ClassVar[bool]

    def table(self, ctx: Context) -> CodeTable: ...

    def family(self) -> str: ...

_ROTATION: Final = frozenset("R")


def read_data_setting(syntax: DataSyntax, block: Block, ctx: Context, codes: dict[str, Any],
                      values: dict[str, Any], used: set[str]) -> bool:
    """``G10 L2 P1 X.. Y..`` and the tool-offset forms -> ``DataSetting``; False (the block kept as
    ``NativeCode``) for an L the dialect does not model, or a computed L or P (the table or entry it sets
    is known only when it runs: the interpreter reads the block again with numbers)."""
    number = next(n for l, n in block.words if UPPER[l] == "G" and g_key(n) == DATA_KEY)
    at = ctx.at(block, col_of_word(block, "G", number))
    ell = whole_index(values.get("L"))
    table = None if ell is None else syntax.DATA_TABLES.get(ell)
    native = f"G{number} ({syntax.table(ctx).native_g[DATA_KEY]})"
    if syntax.LATHE_OFFSET_INPUT and "L" not in values:
        distance = codes.get("03")
        lathe = lathe_offset_setting(block, ctx, number, values, used, syntax.family(), (
            distance[2] if distance is not None else ctx.state.distance) == "incremental", UPPER)
        if lathe is not None:
            block.add(lathe)
            return True
    if table is None or isinstance(values.get("P"), Expr):
        block.add(NativeCode(syntax.DIALECT, native, block.text or ""))
        return False
    name, first, last = table
    code = f"G{number} L{ell}"
    p = whole_index(values.get("P"))
    if p is None:
        raise ProgramError(f"{code} needs the entry it sets, P{first}-P{last}", at)
    if not first <= p <= last:
        raise ProgramError(f"{code} P{p}: the entry is P{first}-P{last}", ctx.at(block, ctx.column_of(block, "P")))
    letters = (AXIS_LETTERS | _ROTATION if syntax.DATA_ROTATION and name == "work_offset" else AXIS_LETTERS) \
        if name.startswith("work_offset") else frozenset("R")
    data = {k: real(v) for k, v in values.items() if k in letters}
    if set(values) - letters - {"L", "P", "N", "O"}:  # a word the IR does not model (LinuxCNC's R)
        block.add(NativeCode(syntax.DIALECT, native, block.text or ""))
        return False
    if not data:
        raise ProgramError(f"{code} P{p} sets nothing (no {'axis word' if 'R' not in letters else 'R'})", at)
    used.update(("L", "P", *data))
    distance = codes.get("03")
    incremental = syntax.DATA_INCREMENTAL and (
        distance[2] if distance is not None else ctx.state.distance) == "incremental"
    if p == 0 and name == "work_offset" and syntax.DATA_P0_ACTIVE:
        p = ctx.state.work_offset
    keep = {"L", "P", *data}
    text = " ".join(letter + num for letter, num in block.words
                    if UPPER[letter] in keep or UPPER[letter] == "G" and g_key(num) == DATA_KEY)
    block.add(DataSetting(syntax.family(), name, p, data, incremental, text))
    return True
