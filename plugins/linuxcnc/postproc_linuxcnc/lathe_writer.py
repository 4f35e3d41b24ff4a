"""LinuxCNC's writer of a lathe program: the RS274/NGC lathe words (``postproc.rs274.ngc_lathe_writer``: the
mode line, G96 with its clamp, G33 with K, each rule checked with rs274 2.9) on LinuxCNC's writer. Its own class
(``Linuxcnc.writer_class``), so a mill program keeps the fast lane.

A Fanuc T or GSK ``G76`` (two-block form) is written as its passes in ``G33``, never as LinuxCNC's own ``G76 P J
R K Q H E L``: the two cycles never move alike, so a native cycle would change the toolpath [V: LinuxCNC
``src/emc/rs274ngc/interp_convert.cc`` ``convert_threading_cycle``/``threading_pass``, checked with rs274 2.9]:

* LinuxCNC retracts each pass to X = start + (full depth - this pass's depth) and goes back to the next pass
  in one diagonal rapid (X and Z together); Fanuc retracts every pass to the start point's X and rapids back
  along Z alone (``postproc.cycles.turning.threading``). Only a cycle of one depth would agree, and LinuxCNC's
  needs K > J (at least two depths);
* LinuxCNC ends at (the start X, the thread's Z end), Fanuc back at the start point;
* LinuxCNC's depths are J * n^(1/R) with no minimum step and no finishing allowance, Fanuc's Δd * sqrt(n) with
  its minimum Δdmin and its allowance d.
"""

from __future__ import annotations

from typing import ClassVar

from postproc.rs274.ngc_lathe_writer import NgcLatheWriting, feed_apart

from .writer import LinuxcncWriter

__all__ = ["LinuxcncLatheWriter", "feed_apart"]


class LinuxcncLatheWriter(NgcLatheWriting, LinuxcncWriter):
    """LinuxCNC's writer for a lathe program: the mode line, G96 with its clamp, G33 with K."""

    MODE_LINES: ClassVar[dict[str, str]] = {"diameter": "G18 G7", "radius": "G18 G8"}
    """The ZX plane and how X reads, first in a program translated here."""
    X_MODE_CODES: ClassVar[dict[str, str]] = {"diameter": "G7", "radius": "G8"}
    """A switch inside the program [V: rs274 2.9.0~pre1 run here: tests/test_linuxcnc_x_mode_switch.py]."""
