"""A program's physical lines split from their ends of line, kept exactly (``\\n``, ``\\r\\n``, ``\\r`` or none):
the readers of the ISO lexer's dialects and of RS274/NGC (``postproc.rs274.lexer``, ``postproc.rs274.ngc_lexer``)
take the text to lex and write the end back as it was.

Compiled (``pyproject.toml [tool.postproc] compiled``): a reader's loop calls ``split_line`` natively for every
line. As the Python generator ``split_lines`` alone, it cost the LinuxCNC reading ~3.5k instructions a line
(callgrind, ``verify`` of a CAM program translated to LinuxCNC: a generator resumed through Python a line)."""

from __future__ import annotations

from typing import Iterable, Iterator


def split_line(raw: str) -> tuple[str, str]:
    """A physical line as (text, end of line)."""
    if raw.endswith("\n"):
        if raw.endswith("\r\n"):
            return raw[:-2], "\r\n"
        return raw[:-1], "\n"
    if raw.endswith("\r"):
        return raw[:-1], "\r"
    return raw, ""


def split_lines(lines: Iterable[str]) -> Iterator[tuple[int, str, str]]:
    """Yield (line number, text, end of line) for each physical line, keeping the exact terminator."""
    number = 0
    for raw in lines:
        number += 1
        text, eol = split_line(raw)
        yield number, text, eol
