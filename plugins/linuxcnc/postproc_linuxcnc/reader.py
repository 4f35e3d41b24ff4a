"""LinuxCNC reader: the RS274/NGC family reader with o-words, parameters and expressions, naming
LinuxCNC in its messages."""

from __future__ import annotations

from postproc.rs274.ngc_lexer import NgcReader


class LinuxcncReader(NgcReader):
    DIALECT = "linuxcnc"
    PARAMETRIC = True
