"""Machine-specific codes of one run: the family's defaults for the set-up's controller variant, then
what the set-up declares (``<MachineCodes>``), which wins.

A dialect gives its defaults as data (``WordBlockSyntax.MACHINE_DEFAULTS``: variant -> codes, the
family's common list under the dialect's base variant); the table is resolved once per run and kept in
``ctx.run_data``.
"""

from __future__ import annotations

from typing import Mapping

from postproc.context import Context
from postproc.setup.machine_setup import CodeAction, MachineCode

Defaults = Mapping[str, tuple[MachineCode, ...]]
"""Controller variant -> the machine codes it has besides its family's common ones."""

_KEY = "machine_codes"


def machine_table(ctx: Context, defaults: Defaults, base: str) -> dict[tuple[str, str], MachineCode]:
    """``(letter, number key)`` -> the code's declaration, for this run's set-up."""
    table: dict[tuple[str, str], MachineCode] | None = ctx.run_data.get(_KEY)
    if table is None:
        table = {}
        variant = ctx.setup.controller.variant or base  # None: the dialect's own controller, the family's base
        for source in (defaults.get(base, ()), defaults.get(variant, ()) if variant != base else (),
                       ctx.setup.machine_codes):
            for code in source:
                table[code.key()] = code
        ctx.run_data[_KEY] = table
    return table


def m(number: int, name: str, action: CodeAction = "none", words: str = "") -> MachineCode:
    """A default M code declaration (dialects' tables read better with it)."""
    return MachineCode(letter="M", number=str(number), action=action, name=name, words=words)


def g(number: str, name: str, words: str = "") -> MachineCode:
    """A default machine G code declaration."""
    return MachineCode(letter="G", number=number, name=name, words=words)
