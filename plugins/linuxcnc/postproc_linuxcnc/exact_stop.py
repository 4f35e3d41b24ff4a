"""A one-shot exact stop (Fanuc ``G09``, ISG/Fagor ``G60``, SINUMERIK ``G9``) for LinuxCNC, which has none: rs274
refuses ``G9`` ("Unknown g code used" [V: /usr/bin/rs274]). The block is written in exact-stop mode (``G61``)
and the path mode in force before it follows on a line of its own (``G64`` with its tolerances, or ``G61``), so
the stop holds for that block only, as the source's does.

Where the program has set no path mode, the one after the block is cutting mode without tolerances (``G64``):
the mode both a Fanuc [K: 0i-F G code list, G64 is group 15's power-on state] and LinuxCNC [K: rs274ngc
``init``, ``CANON_CONTINUOUS``] start in, and the one the simulation takes back to after the source's one-shot
stop (``postproc.simulate.simulator``). Under an exact-stop mode the block already stops: the one-shot is left
out. In a program kept with its control flow (o-words), the mode in force at a block depends on the way the
run took: a one-shot there, with a path mode change anywhere in that flow, is a located error.

The step is the core's ``postproc.lowering.exact_stop`` (compiled: it sees every block), with LinuxCNC's words
for the refusal.
"""

from __future__ import annotations

from postproc.lowering import exact_stop

REFUSAL = ("a one-shot exact stop in a program whose path mode changes inside its control flow: LinuxCNC has no "
           "one-shot stop, and the mode to take back to after the block depends on the way the run takes")


exact_stop_for_one_block = exact_stop.ExactStopForOneBlock(REFUSAL)
"""Lowering step: each one-shot exact stop as exact-stop mode for its block, then the mode before (the module
docstring)."""
