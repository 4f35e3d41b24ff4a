"""LinuxCNC's acceptance rules, as a checker for every LinuxCNC program the suite writes: LinuxCNC's own
interpreter (``rs274``, see ``rs274.py``) runs the program, and whatever it refuses is a problem.

The machine is given a tool table holding every tool the program names (``T<n>``, ``H<n>``, ``D<n>``, with zero length
and diameter): which tools a shop has is not the writer's business. Everything else rs274 refuses is the
writer's, a program that runs out without an end ("File ended with no percent sign or program end") too:
the writer ends a source without one with M2.
"""

from __future__ import annotations

import re

from .rs274 import RS274Error, available, run_rs274

__all__ = ["available", "linuxcnc_problems"]


def linuxcnc_problems(text: str) -> list[str]:
    """What rs274 refuses in ``text`` (its error message and offending block), or nothing."""
    tools = sorted({int(n) for n in re.findall(r"(?i)\b[THD]\s*(\d+)", text)} | {1})
    table = "".join(f"T{n} P{n} Z0 D0\n" for n in tools)
    try:
        run_rs274(text, tool_table=table)
    except RS274Error as err:
        return [err.stderr or str(err)]
    return []
