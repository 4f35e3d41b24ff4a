"""LinuxCNC's tool table file (``tool.tbl``): read into the set-up's ``<Tool>`` entries (``<Tools table="tool.tbl">``,
``postproc.setup.load``) and written from them, for a LinuxCNC machine or for rs274 (``rs274 -t``). A set-up data
file like the XML, not a G-code spelling: the set-up's loader reads it, so it lives beside it, below every family.

The format [K: LinuxCNC docs, "Tool Compensation", 2.1 "Tool Table Format": one tool a line, ``T# P# X Y Z A B C U V
W Dia FA BA Ori Rem``, the remark after ``;``; the values in the machine's units, ``[TRAJ] LINEAR_UNITS``] as
LinuxCNC reads it [V: ``src/emc/rs274ngc/tool_parse.cc`` ``loadToolTable``: words split at spaces, the letter in
either case, ``T`` and ``P`` and ``Q`` whole numbers, the others decimal numbers; the remark is the rest of the
line after the first ``;``; a line with any other word is skipped with "Unrecognized line skipped"]:

    T1 P1 Z0.511 D0.125 ;1/8 end mill

Here ``T`` is the entry's ``number`` (LinuxCNC's ``H`` and ``D`` registers are its tool numbers), ``P`` its
``pocket``, ``Z`` its ``length``, ``D`` (a diameter) twice its ``radius``, the remark its ``comment``. The values
are the set-up's ``<Machine units>``: a table is in the machine's units, and so are ``<Tools>``. Stricter than
LinuxCNC where it would lose data silently: a line it skips, an old-style line of bare numbers, a tool twice, a
line without ``T`` or ``P`` (LinuxCNC then files it in the pocket of the line before [V: ``pocket`` is kept from
line to line]) are errors at their line. Not read yet (an error at the column naming what to write instead): the
lathe's ``X`` and orientation ``Q`` (``<Tool x z tip>``), the front and back angles ``I``/``J``, offsets along
``Y``, ``A``-``C``, ``U``-``W``; a zero there is accepted, as it changes nothing.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Iterable

from ..errors import ConfigError, ErrorList, Location
from .machine import ToolData

__all__ = ["read_tool_table", "parse_tool_table", "tool_table_text"]

_INT = re.compile(r"[+-]?\d+\Z")
_REAL = re.compile(r"[+-]?(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?\Z")
_WHOLE = frozenset("TPQ")
_READ = {"T": "number", "P": "pocket", "Z": "length", "D": "radius"}
_NOT_READ = {
    "X": "a lathe tool's X offset, is not read from a tool table yet: give the lathe offsets as <Tool x z>",
    "Q": "a lathe tool's orientation, is not read from a tool table yet: give it as <Tool tip>, in Fanuc's numbering",
    "I": "the front angle", "J": "the back angle",
    "Y": "an offset along Y", "A": "an offset along A", "B": "an offset along B", "C": "an offset along C",
    "U": "an offset along U", "V": "an offset along V", "W": "an offset along W",
}


def read_tool_table(path: str | Path) -> list[tuple[int, ToolData]]:
    """The entries of the tool table file ``path`` with their lines; every problem raised at once, located in the
    file (``ConfigError``, or an ``ErrorList`` of them); a file that cannot be read is one ``ConfigError`` the
    caller locates."""
    try:
        text = Path(path).read_text(encoding="utf-8", errors="surrogateescape")
    except OSError as exc:
        raise ConfigError(f"cannot read the tool table {path}: {exc.strerror}") from None
    return parse_tool_table(text, str(path))


def parse_tool_table(text: str, file: str) -> list[tuple[int, ToolData]]:
    """``read_tool_table`` of a file's text."""
    from ..setup.validate import Invalid, validate
    entries: list[tuple[int, ToolData]] = []
    problems: list[ConfigError] = []
    seen: dict[int, int] = {}
    pockets: dict[int, tuple[int, int]] = {}
    for n, line in enumerate(text.split("\n"), start=1):  # (LinuxCNC's fgets ends a line at a newline only)
        code, semicolon, remark = line.rstrip("\r").partition(";")
        words = code.split()
        if not words:  # a blank line, or a remark alone: no tool
            continue
        raw: dict[str, object] = {}
        letters: set[str] = set()
        problem: ConfigError | None = None
        column = 1
        for word in words:
            column = code.index(word, column - 1) + 1
            letter, number = word[0].upper(), word[1:]
            if letter in letters:
                problem = ConfigError(f"{letter} appears twice on the line", Location(file, n, column))
                break
            letters.add(letter)
            if word[0].isdigit() or word[0] in "+-.":
                problem = ConfigError("an old-style tool table line (numbers without letters) is not read: write it "
                                      "as T.. P.. Z.. D..", Location(file, n, column))
                break
            if letter not in _READ and letter not in _NOT_READ:
                problem = ConfigError(f"'{word}' is no word of a LinuxCNC tool table (T P X Y Z A B C U V W D I J Q, "
                                      "a remark after ';')", Location(file, n, column))
                break
            if not (_INT if letter in _WHOLE else _REAL).match(number):
                kind = "a whole number" if letter in _WHOLE else "a number"
                problem = ConfigError(f"{letter} needs {kind}, got '{number}'", Location(file, n, column))
                break
            if letter in _NOT_READ:
                if float(number) != 0.0:
                    what = _NOT_READ[letter]
                    what += "" if "," in what else ", is not read from a tool table yet (a set-up has no such tool data)"
                    problem = ConfigError(f"{letter}, {what}", Location(file, n, column))
                    break
                continue
            value: object = int(number) if letter in _WHOLE else float(number)
            if letter == "D":
                value = float(number) / 2.0  # a diameter: the entry keeps the radius
            raw[_READ[letter]] = value
        if problem is None:
            missing = [letter for letter in "TP" if _READ[letter] not in raw]
            if missing:
                problem = ConfigError(f"a tool table line needs {' and '.join(missing)} (LinuxCNC files a line "
                                      "without P in the pocket of the line before)", Location(file, n, 1))
        if problem is None:
            tool = raw["number"]
            assert isinstance(tool, int)
            if tool in seen:
                problem = ConfigError(f"tool T{tool} appears twice (line {seen[tool]} and here)", Location(file, n, 1))
            seen[tool] = n
        if problem is None:
            pocket, tool = raw["pocket"], raw["number"]
            assert isinstance(pocket, int) and isinstance(tool, int)
            if pocket in pockets:
                problem = ConfigError(f"pocket P{pocket} holds tool T{pockets[pocket][0]} too (line {pockets[pocket][1]}; "
                                      "a pocket holds one tool)", Location(file, n, 1))
            pockets.setdefault(pocket, (tool, n))
        if problem is None:
            comment = remark.rstrip()
            if semicolon and comment:
                raw["comment"] = comment
            try:
                entries.append((n, validate(ToolData, raw)))
            except Invalid as exc:
                for name, msg in exc.problems:
                    problems.append(ConfigError(f"T{raw['number']} {name}: {msg}" if name else f"T{raw['number']} {msg}",
                                                Location(file, n, 1)))
        if problem is not None:
            problems.append(problem)
    if len(problems) == 1:
        raise problems[0]
    if problems:
        raise ErrorList(list(problems))
    return entries


def _number(value: float) -> str:
    """A value as the table writes it: the shortest text that reads back as the same float (``0.511``, ``25.4``,
    ``-3``), never an exponent (``tool_parse.cc`` reads one, a person reading the table may not)."""
    text = repr(float(value))
    if "e" in text or "E" in text:
        plain = f"{value:.20f}".rstrip("0").rstrip(".")
        text = plain if float(plain) == value else text
    if text.endswith(".0"):
        text = text[:-2]
    return "0" if text in ("-0", "") else text


def tool_table_text(tools: Iterable[ToolData]) -> str:
    """The LinuxCNC tool table of ``tools`` (the set-up's ``<Tools>``, in its machine units), one line each in
    the order given: ``T<number> P<pocket> Z<length> D<diameter> ;<comment>``, the length and radius with their
    wear (the table holds one value each; LinuxCNC's wear entries are tools of their own [K]). A tool without a
    pocket goes in the pocket of its number. Raises ``ConfigError`` for an entry a LinuxCNC table cannot hold:
    a lathe offset (not written yet, as not read) or a Fanuc memory A/B entry, whose one value is both."""
    lines: list[str] = []
    pockets: dict[int, int] = {}
    for tool in tools:
        if tool.lathe() is not None or tool.tip is not None:
            raise ConfigError(f"<Tool number=\"{tool.number}\">: a lathe offset is not written into a LinuxCNC tool "
                              "table yet")
        if tool.shared():
            raise ConfigError(f"<Tool number=\"{tool.number}\">: offset/offsetWear (one value for H and D: Fanuc "
                              "memory A/B) has no LinuxCNC tool table column; give length and radius")
        pocket = tool.number if tool.pocket is None else tool.pocket
        if pocket in pockets:
            raise ConfigError(f"<Tool number=\"{tool.number}\">: pocket {pocket} holds tool {pockets[pocket]} too")
        pockets[pocket] = tool.number
        words = [f"T{tool.number}", f"P{pocket}"]
        length = tool.geometry("length")
        if length is not None or tool.length_wear is not None:
            words.append("Z" + _number((length or 0.0) + tool.wear("length")))
        radius = tool.geometry("radius")
        if radius is not None or tool.radius_wear is not None or tool.diameter_wear is not None:
            words.append("D" + _number(2.0 * ((radius or 0.0) + tool.wear("radius"))))
        line = " ".join(words)
        if tool.comment is not None:
            line += " ;" + tool.comment
        lines.append(line + "\n")
    return "".join(lines)
