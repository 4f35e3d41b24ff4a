"""ISG ``#`` commands: kept verbatim as ``NativeCode`` tagged ``isg``, named for messages.

A ``#`` command is alone in its block (only a block number may precede it). Its text, bracketed
``key=value`` arguments included, travels unchanged: written back byte for byte in ISG, refused by
every other dialect's writer and by the simulator, each naming the command. The machine
transformations (``#CYL``, ``#FACE``, ``#CAX``, ``#TRAFO``) map the programmed contour onto other axes,
and ``#CONTOUR MODE``, ``#CS`` and ``#SLOPE`` change the path or its timing: nothing here computes
their geometry, so no toolpath is ever made of a program under them.
"""

from __future__ import annotations

COMMANDS: dict[str, str] = {
    "#CYL": "cylinder surface transformation",
    "#FACE": "face machining transformation",
    "#CAX": "C axis transformation",
    "#TRAFO": "kinematic transformation",
    "#CS": "coordinate system",
    "#ACS": "coordinate system",
    "#SLOPE": "acceleration profile",
    "#CONTOUR": "contour blending mode",
    "#MSG": "message",
    "#FILE": "implicit subroutine files",
    "#TOOL": "tool data",
    "#TIME": "dwell",
    "#SET": "setting",
}
"""What each command does, for messages; any other ``#`` command is named by its word alone."""

_WORD = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_")


def command_name(code: str, pos: int) -> str:
    """``#CYL``, ``#CONTOUR MODE``, ``#MC_..``: the command word, and a second upper-case word
    (``MODE``, ``OFF``) when one follows before any argument."""
    end = pos + 1
    n = len(code)
    while end < n and code[end] in _WORD:
        end += 1
    name = code[pos:end].upper()
    after = end
    while after < n and code[after] in " \t":
        after += 1
    second = after
    while second < n and code[second] in _WORD:
        second += 1
    word = code[after:second]
    if word and word.isupper() and (second >= n or code[second] in " \t["):
        return f"{name} {word}"
    return name


def describe_command(name: str) -> str:
    """``#CYL OFF (cylinder surface transformation)``."""
    what = COMMANDS.get(name.split(" ", 1)[0])
    if what is None and name.startswith("#MC_"):
        what = "motion control command"
    return f"{name} ({what})" if what else name


OPENING: dict[str, str] = {"#VAR": "#ENDVAR", "#COMMENT BEGIN": "#COMMENT END"}
"""A ``#`` command whose following lines are read otherwise (declarations, comment lines) -> the one
that closes them."""


def command_line(text: str) -> str | None:
    """The ``#`` command a line holds (upper case, single blanks, without its block number), or None."""
    words = text.replace("\u00a0", " ").upper().split()
    if words and words[0][:1] == "N" and words[0][1:].isdigit():
        words = words[1:]
    if not words or not words[0].startswith("#"):
        return None
    return " ".join(words)
