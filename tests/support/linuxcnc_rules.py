"""LinuxCNC's acceptance rules, as a checker for every LinuxCNC program the suite writes: LinuxCNC's own
interpreter (``rs274``, see ``rs274.py``) runs the program, and whatever it refuses is a problem.

The machine is given a tool table holding every tool the program names (``T<n>``, ``H<n>``, ``D<n>``, with zero length
and diameter), and tools 1-99 when it computes one (``H#1``, ``T[#2+1]``): which tools a shop has is not the
writer's business. One error is not the writer's either: a program that ends with neither M2/M30 nor a closing ``%`` ("File ended
with no percent sign or program end") is what a source without an end translates to, so it is accepted
here (the writer warns about it). A ``%`` that does not close an opening one ("Bad character '%' used")
is the writer's and is reported.
"""

from __future__ import annotations

import re

from .rs274 import RS274Error, available, run_rs274

__all__ = ["available", "linuxcnc_problems"]

NO_END = "File ended with no percent sign or program end"
"""rs274's message for a program with no end: the source's own state, not a writing error."""


def linuxcnc_problems(text: str) -> list[str]:
    """What rs274 refuses in ``text`` (its error message and offending block), or nothing."""
    tools = {int(n) for n in re.findall(r"(?i)\b[THD]\s*(\d+)", text)} | {1}
    if re.search(r"(?i)\b[THD]\s*[-+]?\s*[#\[]", text):
        tools |= set(range(1, 100))  # a computed tool or register: any the program may name
    tools = sorted(tools)
    table = "".join(f"T{n} P{n} Z0 D0\n" for n in tools)
    try:
        run_rs274(text, tool_table=table)
    except RS274Error as err:
        if err.stderr.splitlines()[:1] == [NO_END]:
            return []
        return [err.stderr or str(err)]
    return []
