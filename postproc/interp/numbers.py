"""Numbered variables across dialect families: which numbers a program names, and whether a number is a
plain variable of a family.

A program kept symbolically carries its variable numbers to the target unchanged. A number means the same
on both controllers only where it is a plain variable (one the program holds its own values in) in both
families' tables: LinuxCNC's ``#3000`` is a global parameter, Custom Macro B's raises alarm 3000; Macro B's
``#5041`` is the current work position, LinuxCNC's ``#5041`` a parameter a program may set. Such a program
is flattened instead, where the source's table gives the values (or names what only the machine knows).
"""

from __future__ import annotations

from typing import Iterable, Iterator

from ..ir.expr import EvalError, Expr
from ..ir import Block
from .variables import VariablesFactory

COMPUTED = -1
"""What ``numbered_variables`` yields for a variable whose number is computed (``#[#1+100]``)."""


def numbered_variables(blocks: Iterable[Block]) -> Iterator[int]:
    """The variable numbers ``blocks`` name (``COMPUTED`` for a computed one), found through each section's
    XML (every section has one), so no construct's words are missed, and through each computed word's value
    (``Block.values``: the blocks a keep check sees are not yet read into sections, so ``G0 X#3000`` has its
    expression there only)."""
    for block in blocks:
        computed = [value for value in block.values.values() if isinstance(value, Expr)]
        for item in (*block.sections.values(), *computed):
            for var in item.make_xml_source().iter("Var"):
                if var.get("name") is not None:
                    continue
                kids = [kid for kid in var if isinstance(kid.tag, str)]
                if len(kids) != 1 or kids[0].tag != "Num":
                    yield COMPUTED
                    continue
                number = float(kids[0].get("value", "nan"))
                yield int(number) if number.is_integer() else COMPUTED


def plain_variable(family: VariablesFactory, number: int) -> bool:
    """``number`` is a variable the program holds its own values in under ``family``'s table: read,
    written and read back without an error (a system variable, an alarm or a number outside the table
    raises one)."""
    table = family(lambda: 0.001)
    try:
        table.read(number)
        table.write(number, 1.0)
        table.read(number)
    except EvalError:
        return False
    return True


def numbered_family(family: VariablesFactory) -> bool:
    """The family numbers its variables (``#1`` is one of them): the families whose numbers travel
    unchanged between dialects (ISG and Fagor name theirs; their writers spell each number)."""
    return plain_variable(family, 1)


def foreign_number(blocks: Iterable[Block], source: VariablesFactory, target: VariablesFactory,
                   names: tuple[str, str]) -> str | None:
    """Why ``blocks`` cannot carry their variable numbers from ``source``'s family to ``target``'s (None:
    they can): a number that is not plain in one of them, or a computed number that may be either;
    ``names``: the source's and the target's dialect, for the message."""
    if source is target or not (numbered_family(source) and numbered_family(target)):
        return None
    seen: set[int] = set()
    for number in numbered_variables(blocks):
        if number in seen or number == 0:
            continue  # #0: the vacant value, which each family's writer spells
        seen.add(number)
        if number == COMPUTED:
            return "it computes a variable number, which may name a variable of another meaning there"
        sides: tuple[tuple[VariablesFactory, str, str], ...] = ((source, names[0], names[1]),
                                                               (target, names[1], names[0]))
        for family, name, other in sides:
            if not plain_variable(family, number):
                return f"#{number} is no plain variable of {name}, so {other}'s #{number} would mean something else"
    return None
