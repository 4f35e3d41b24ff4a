"""``postproc dialects``: the installed dialects' capabilities, as a table a person reads or as JSON.

Every row comes from the dialect classes (``Dialect.capabilities()``, the UPPER_CASE flags each dialect
declares and the code reads), never from a hand-written list: a flag a plugin adds appears here by
itself. The table puts one dialect in each column and one capability in each row; a list too long for
its column (the native cycles) is counted there and spelt out below the table.
"""

from __future__ import annotations

import argparse
import sys
from typing import Any, Mapping

from ..dialect import Dialect, Lazy
from ..plugins import installed_dialects
from . import command_line
from ..collector import gc_paused



def cmd_dialects(args: argparse.Namespace) -> int:
    """``postproc dialects [--format table|json]``."""
    with gc_paused(freeze=command_line.FREEZE_IMPORTS):  # the plugins load (``command_line.FREEZE_IMPORTS``)
        info = dialect_info(installed_dialects())
    if args.format == "json":
        import json
        print(json.dumps(info, indent=2))
    else:
        sys.stdout.write(render_table(info))
    return 0


COLUMN = 16
"""Widest a value may be in its column; a longer list is counted and listed below the table."""


def dialect_info(dialects: Mapping[str, type[Dialect]]) -> dict[str, dict[str, Any]]:
    """name -> description, whether it reads and writes, and its capability table (JSON-ready)."""
    return {name: {"description": cls.DESCRIPTION, "reads": declared(cls, "READER"),
                   "writes": declared(cls, "WRITER"), "capabilities": cls.capabilities()}
            for name, cls in sorted(dialects.items())}


def declared(cls: type[Dialect], name: str) -> bool:
    """Whether the dialect has a ``READER`` or ``WRITER``, without importing it: reading the attribute would
    load a ``Lazy`` one, and with it every dialect's reader and writer modules (lexers, macro languages,
    cycle writers), which made listing the dialects cost more than a translation (measured with callgrind)."""
    for klass in cls.__mro__:
        if name in vars(klass):
            value = vars(klass)[name]
            return isinstance(value, Lazy) or value is not None
    return False


def _cell(value: object) -> str:
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, list):
        return ",".join(str(v) for v in value) or "-"
    if isinstance(value, dict):
        return ",".join(f"{k}={v}" for k, v in value.items()) or "-"
    return str(value) if value != "" and value is not None else "-"


def render_table(info: dict[str, dict[str, Any]]) -> str:
    """The capability matrix (rows: read, write, then every capability any dialect declares), each
    dialect's description above it and the long lists below it."""
    names = list(info)
    rows: list[tuple[str, list[object]]] = [("read", [info[n]["reads"] for n in names]),
                                            ("write", [info[n]["writes"] for n in names])]
    keys: list[str] = []
    for name in names:
        keys.extend(k for k in info[name]["capabilities"] if k not in keys)
    for key in keys:
        rows.append((key, [info[n]["capabilities"].get(key, "") for n in names]))
    long_lists: list[str] = []
    cells: list[tuple[str, list[str]]] = []
    for key, values in rows:
        shown = []
        for name, value in zip(names, values):
            text = _cell(value)
            if len(text) > COLUMN and isinstance(value, list):
                long_lists.append(f"  {name} {key}: {', '.join(str(v) for v in value)}")
                text = f"{len(value)} (below)"
            shown.append(text)
        cells.append((key, shown))
    first = max(len(key) for key, _ in cells) + 2
    widths = [max(len(name), *(len(row[i]) for _, row in cells)) + 2 for i, name in enumerate(names)]
    lines = [f"{name}: {info[name]['description']}" for name in names]
    lines.append("")
    lines.append("capability".ljust(first) + "".join(n.ljust(w) for n, w in zip(names, widths)).rstrip())
    for key, shown in cells:
        lines.append(key.ljust(first) + "".join(t.ljust(w) for t, w in zip(shown, widths)).rstrip())
    if long_lists:
        lines.append("")
        lines.append("lists:")
        lines.extend(long_lists)
    return "\n".join(lines) + "\n"
