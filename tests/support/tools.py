"""Set-ups whose ``<Tools>`` give every register a value: the simulation refuses a tool length or cutter
radius it does not know, and most tests are about something else, so they run on a machine whose tools
are measured as zero (the programmed point is the controlled one) unless a test says otherwise."""

from __future__ import annotations

import copy

from postproc.setup.machine_setup import MachineSetup
from postproc.setup.machine import ToolData

REGISTERS = range(1, 100)


def with_tools(setup: MachineSetup | None = None, lengths: dict[int, float] | None = None,
               radii: dict[int, float] | None = None) -> MachineSetup:
    """A copy of ``setup`` (default: the default set-up) in which every register of ``REGISTERS`` the
    set-up leaves out has the length in ``lengths`` and the radius in ``radii``, zero when not given."""
    out = copy.copy(setup or MachineSetup())
    out.tools = dict(out.tools)
    lengths, radii = lengths or {}, radii or {}
    for n in REGISTERS:
        if str(n) not in out.tools:
            out.tools[str(n)] = ToolData(number=n, length=lengths.get(n, 0.0), radius=radii.get(n, 0.0))
    return out
