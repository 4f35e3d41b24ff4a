"""Machine-specific codes of one run: the family's defaults for the set-up's controller variant, then
what the set-up declares (``<MachineCodes>``), which wins; and the family's word rules that follow the
variant (``dwell_in_seconds``, ``cutter_register_from_h``: the Fanuc family's controllers, so here and not in
the neutral set-up, which only holds what the set-up says).

A dialect gives its defaults as data (``WordBlockSyntax.MACHINE_DEFAULTS``: variant -> codes, the
family's common list under the dialect's base variant); the table is resolved once per run and kept in
``ctx.run_data``.
"""

from __future__ import annotations

from typing import Mapping

from postproc.context import Context
from postproc.setup.groups import ControllerSettings
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


def dwell_in_seconds(controller: ControllerSettings) -> bool:
    """A dwell P written with a decimal point is in seconds (``G04 P0.5``): as ``dwellSeconds`` says, else as
    the variant does (a Haas: yes; Fanuc: the point-less number of milliseconds)."""
    return controller.variant == "haas" if controller.dwell_seconds is None else controller.dwell_seconds


def cutter_register_from_h(controller: ControllerSettings) -> bool:
    """G41/G42 may take the radius register from H (Fanuc 0M ``G42 H19``): as ``cutterRegisterH`` says, else as
    the variant does (0M: yes)."""
    return controller.variant == "fanuc-0m" if controller.cutter_register_h is None else controller.cutter_register_h
