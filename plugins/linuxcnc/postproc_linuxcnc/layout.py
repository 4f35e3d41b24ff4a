"""Where another dialect's subprograms stand in a LinuxCNC file: each after every subprogram that calls it.

rs274 looks for the ``O<n>`` of an ``M98 P<n>`` from the call onward (``postproc.interp.rules``: an
``O<n>`` only before the call is "Failed to find sub 'O<n>' before EOF" [V: rs274 2.9]), where Fanuc
finds a program anywhere in memory. The main program comes first, so its calls find every subprogram;
a subprogram that calls one written before it does not. This lowering step writes the subprograms after
the main program's end in an order where every caller comes before the programs it calls (the source's
order where that holds already). Subprograms that call each other (``M98`` both ways) have no such
order: a located error (a program kept symbolically is then flattened).

The step is the RS274 family's ``postproc.rs274.subprogram_layout`` (compiled: it sees every block), with
LinuxCNC's words for the refusal.
"""

from __future__ import annotations

from postproc.rs274 import subprogram_layout


def _refusal(name: str, callee: str, left: int) -> str:
    return (f"subprograms O{name} and O{callee} call each other with M98 (through {left} programs): LinuxCNC "
            f"finds an O-number only after the M98 that calls it, so no order of them finds every call")


subprograms_after_callers = subprogram_layout.SubprogramsAfterCallers(_refusal)
"""Lowering step for LinuxCNC (see the module docstring), which also writes the return level a cycle needs as
the text comes (``postproc.rs274.return_level``: one loop for both); a LinuxCNC source is written as it is."""
