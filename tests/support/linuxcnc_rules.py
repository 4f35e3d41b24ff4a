"""LinuxCNC's acceptance rules, as a checker for every LinuxCNC program the suite writes: LinuxCNC's own
interpreter (``rs274``, see ``rs274.py``) runs the program, and whatever it refuses is a problem.

The machine is given a tool table holding every tool the program names (``T<n>``, ``H<n>``, ``D<n>``, and the ``P<n>``
of a tool table write ``G10 L1``/``L10``/``L11``, which rs274 refuses for a tool its table lacks: "Requested tool 2 not
found in the tool table" [V: rs274], with zero length and diameter), and tools 1-99 when it computes one (``H#1``,
``T[#2+1]``, ``G10 L1 P#3``): which tools a shop has is not the writer's business. Everything else rs274 refuses is the writer's, a program that runs out without an end
("File ended with no percent sign or program end") too: the writer ends a source without one with M2.

A user M code (M100-M199) runs the machine's program file of that name; LinuxCNC's task registers each
executable file ``M1nn`` it finds under ``PROGRAM_PREFIX``/``USER_M_PATH`` with the interpreter, and a standalone
rs274 registers none, whatever its INI says ("Unknown m code used: M120" [V: rs274 with USER_M_PATH and -T;
saicanon.cc never calls USER_DEFINED_FUNCTION_ADD, emctaskmain.cc's emcTaskInit does]). Like the tools, the
machine is taken to have the files the program names: such a code alone in its word (no P or Q beside it) is
written as a comment before rs274 reads the program (``_USER_M``).
"""

from __future__ import annotations

import hashlib
import json
import os
import re
from pathlib import Path

from postproc.setup.tool_table_file import tool_table_text
from postproc.setup.machine import ToolData

from . import rs274
from .rs274 import RS274Error, RS274Timeout, available, run_rs274

__all__ = ["RS274_CACHE", "available", "linuxcnc_problems"]

RS274_CACHE = Path(os.environ.get("POSTPROC_RS274_CACHE")
                   or Path(__file__).resolve().parents[2] / ".rs274-cache")
"""rs274's answers, one small JSON file per program (``linuxcnc_problems``): a run of the suite asks rs274
only about programs no earlier run wrote. Remove the folder to ask again."""


_TABLE_WRITE = re.compile(r"(?i)(?=.*(?<![A-Z])G\s*0*10(?![.\d]))(?=.*(?<![A-Z])L\s*0*1[01]?(?![.\d]))")
"""A line that writes the tool table (``G10 L1``, ``L10``, ``L11``; its ``P`` names the tool)."""


_USER_M = re.compile(r"(?i)(?<![A-Z#\[])M\s*0*(1\d\d)(?![\d.])")
"""A user M code word M100-M199 (a literal, not a computed ``M#1``)."""


def _user_m_files(text: str) -> str:
    """``text`` with each user M code on a line without P or Q words written as a comment (the module's
    docstring: a standalone rs274 knows no user M code; the machine has the file)."""
    lines = text.splitlines(keepends=True)
    for i, line in enumerate(lines):
        end = min((k for k in (line.find("("), line.find(";")) if k >= 0), default=len(line))
        code = line[:end]
        if _USER_M.search(code) and not re.search(r"(?i)(?<![A-Z#])[PQ]\s*[-+#\[.\d]", code):
            lines[i] = _USER_M.sub(lambda m: f"(user M code M{m.group(1)})", code) + line[end:]
    return "".join(lines)


def linuxcnc_problems(text: str) -> list[str]:
    """What rs274 refuses in ``text`` (its error message and offending block), or nothing. Answered from
    ``RS274_CACHE`` when the same program, tool table and interpreter were run before."""
    tools = {int(n) for n in re.findall(r"(?i)\b[THD]\s*(\d+)", text)} | {1}
    if re.search(r"(?i)\b[THD]\s*[-+]?\s*[#\[]", text):
        tools |= set(range(1, 100))  # a computed tool or register: any the program may name
    for line in text.splitlines():
        if _TABLE_WRITE.search(line):
            tools |= {int(n) for n in re.findall(r"(?i)(?<![A-Z])P\s*(\d+)", line)}
            if re.search(r"(?i)(?<![A-Z])P\s*[-+]?\s*[#\[]", line):
                tools |= set(range(1, 100))
    tools = sorted(tools)
    # the set-up's tool table writer (postproc.setup.tool_table_file) gives rs274 its table: each tool in the pocket
    # of its number, length and diameter 0 ("T1 P1 Z0 D0", the text the cache is keyed by)
    table = tool_table_text(ToolData(number=n, pocket=n, length=0.0, radius=0.0) for n in tools)
    text = _user_m_files(text)
    path = RS274_CACHE / _key(text, table)
    try:
        return [str(p) for p in json.loads(path.read_text(encoding="utf-8"))]
    except (OSError, ValueError):
        pass
    try:
        run_rs274(text, tool_table=table)
        found: list[str] = []
    except RS274Timeout as err:
        return [str(err)]  # the machine may just have been busy: not kept
    except RS274Error as err:
        found = [err.stderr or str(err)]
    _keep(path, found)
    return found


def _key(text: str, table: str) -> str:
    """The program, its tool table and the interpreter's file (another rs274 may answer otherwise)."""
    binary = rs274.RS274 or ""
    try:
        info = os.stat(binary)
        binary += f":{info.st_size}:{info.st_mtime_ns}"
    except OSError:
        pass
    data = "\0".join((binary, table, text)).encode("utf-8", "surrogateescape")
    return hashlib.sha256(data).hexdigest()


def _keep(path: Path, found: list[str]) -> None:
    """Write the answer whole or not at all (a suite and ``make fuzz`` may run side by side)."""
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        part = path.with_name(f"{path.name}.{os.getpid()}.part")
        part.write_text(json.dumps(found), encoding="utf-8")
        os.replace(part, path)
    except OSError:
        pass
