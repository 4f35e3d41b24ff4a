"""LinuxCNC's ``G10 L1 P- Z- R-``, ``G10 L10 P- Z- R-`` and ``G10 L11 P- Z- R-``: set a tool table entry from
the program (L1: the values; L10: the length that makes the current point read Z in the active work system;
L11: the same in work system 9, G59.3).

[V] LinuxCNC ``docs/src/gcode/g-code.adoc`` "G10 L1 Set Tool Table": P is the tool number, R the radius,
the axis words the offsets, each word left out keeps its value; checked with rs274, which prints
``SET_TOOL_TABLE_ENTRY`` with the new length (``G10 L1 P3 Z12.5 R2`` then ``G41 D3`` offsets the path by 2).
A length or radius in force does not change with the entry: ``G43``/``G41`` read the table when they are
programmed [V: rs274 prints no ``USE_TOOL_LENGTH_OFFSET`` at the G10], as the simulation reads it.

The entry becomes a ``DataSetting`` of the neutral table ``tool_entry`` (``Z`` the length, ``R`` the radius,
entry P: LinuxCNC's H and D registers are tool numbers), or for L10/L11 ``tool_entry_at_point`` /
``tool_entry_at_point_9``, whose length only the simulation can work out (where the tool is): [V] rs274 with
G54 Z3, G59.3 Z-4, tool 3 of length 0 at Z5: ``G10 L10 P3 Z7`` sets the length -2 (5 + 0 - 7: the active
offset cancels), then at Z6 with that length ``G10 L11 P3 Z2`` sets 9 (machine 6 + 3 - 2 = 7, minus 2 - 4);
G91 changes neither (the values are absolute). On a mill, ``G10 L1`` also sets the entry's X and Y
offsets, which ``G43`` applies to X and Y as it applies Z [V: rs274 prints ``USE_TOOL_LENGTH_OFFSET(1 2 3,
...)`` after ``G10 L1 P1 X1 Y2 Z3`` and ``T1 M6 G43``; after ``G49`` and ``G0 X0`` the canonical point reads
Y2 Z3: like Z, X and Y keep the machine position until programmed]; ``G10 L10``/``L11`` X and Y are
measured as Z is, each word alone keeping the entry's other one [V: ``interp_convert.cc``
``convert_setup_tool``; rs274 with seeded programs, ``tests/test_tool_entry_at_point_26.py``]. The other
words (the offsets of the other axes, a lathe tool's X and its I, J, Q) are not modelled: such a block is kept
verbatim (``NativeCode``), which translates to LinuxCNC alone and is refused by the simulation. Like every
G10 L1, the values are absolute whatever the distance mode.
"""

from __future__ import annotations

from typing import Any, Final

from postproc.context import Context
from postproc.errors import ProgramError
from postproc.ir.expr import Expr
from postproc.ir import Block, DataSetting

TABLE: Final = "tool_entry"
"""The neutral table (``postproc.compensation.tool_table``)."""
TABLES: Final = {1: TABLE, 10: "tool_entry_at_point", 11: "tool_entry_at_point_9"}
"""G10's L -> the neutral table it writes."""
L: Final = 1
MODELLED: Final = frozenset("ZR")
"""The words of G10 L1/L10/L11 the IR models (everywhere)."""
MILL_ENTRY: Final = frozenset("XYZR")
"""The words of a mill's G10 L1/L10/L11 the IR models (its X and Y offsets too)."""
NOT_VALUES: Final = frozenset("GLPN")


def read_tool_entry(block: Block, ctx: Context, number: str, values: dict[str, Any], ell: int = L) -> bool:
    """The block's ``DataSetting``; False (the caller keeps the block verbatim) when it sets a word the IR
    does not model or its P is computed."""
    words = set(values) - NOT_VALUES
    p = values.get("P")
    modelled = MODELLED if ctx.lathe else MILL_ENTRY
    if words - modelled or isinstance(p, Expr) or not words:
        return False
    if p is None or isinstance(p, float) and not p.is_integer() or int(p) < 1:
        raise ProgramError(f"G{number} L{ell} needs the tool number it sets (P1 or more)",
                           ctx.at(block, ctx.column_of(block, "P") if p is not None else 1))
    data: dict[str, float | Expr] = {k: v if isinstance(v, Expr) else float(v) for k, v in values.items() if k in modelled}
    text = " ".join(letter + num for letter, num in block.words if letter.upper() in "GLP" or letter.upper() in modelled)
    block.add(DataSetting("linuxcnc", TABLES[ell], int(p), data, False, text))
    return True
