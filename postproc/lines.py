"""The check every program line passes before a reader lexes it: what no controller reads is refused
here, once for every dialect, with the line and column.

* A line longer than the set-up's ``<Limits lineLength>`` (default 64 kB, more than any controller's
  buffer) is refused before anything scans it.
* Outside comments a program is ASCII (but for a UTF-8 byte order mark opening the file, which
  readers skip with ``lexable``, as they skip the DOS end-of-file byte): Python's ``\\d`` and ``str.isdigit`` accept Arabic-Indic or
  full-width digits, which no controller reads as numbers. Inside a comment - between ``(`` and ``)``,
  or after ``;`` - any character is text and is kept as it is (so Latin-1 bytes read as surrogates
  still round-trip).
* A number (digits and a decimal point) of more than ``MAX_DIGITS`` digits outside comments is refused: no controller register holds
  it, and it would overflow a float (or Python's int conversion limit) further down.

A refused line is reported to the run's diagnostics and replaced by an empty line with the same end
of line, so line numbers stay right and reading goes on to report every bad line.
"""

from __future__ import annotations

from itertools import chain, islice
from typing import Iterable, Iterator

from .context import Context
from .errors import Location, ParseError, character_name

MAX_DIGITS = 30
"""The most digits read in one number: more than any controller's registers hold, and within a float's
range and Python's int conversion limit by far."""
CHUNK = 1024
"""Lines checked at once on the fast path (a chunk is held while checked: a few dozen kilobytes)."""
_NUMBER_CHARS = bytes(1 if chr(i) in "0123456789." else 0 for i in range(256))
"""``bytes.translate`` table: digits and the point to 1, everything else to 0."""
_LONG_RUN = b"\x01" * (MAX_DIGITS + 1)
"""A candidate for a too-long number (``line_problem`` then counts its digits)."""


def checked_lines(lines: Iterable[str], ctx: Context) -> Iterator[str]:
    """``lines`` as they are; a line that fails a check (see the module docstring) as an empty line.

    Lines are checked a chunk at a time with a few C-speed calls (``isascii``, ``len``, one translate and
    one substring search over the joined chunk) and passed on by ``chain`` without a Python step per
    line; only a chunk that fails them is checked line by line. (A regex search per line cost 5 % of a
    copy-through translation.)"""
    return chain.from_iterable(_checked_chunks(iter(lines), ctx))


def _checked_chunks(lines: Iterator[str], ctx: Context) -> Iterator[list[str]]:
    limit = ctx.setup.limits.line_length
    number = 0
    while True:
        chunk = list(islice(lines, CHUNK))
        if not chunk:
            return
        text = "".join(chunk)
        if text.isascii() and (len(text) <= limit or max(map(len, chunk)) <= limit) \
                and _LONG_RUN not in text.encode("ascii").translate(_NUMBER_CHARS):
            number += len(chunk)
            yield chunk
            continue
        for line in chunk:
            number += 1
            bom = number == 1 and line[:1] == BOM
            problem = line_problem(line[1:] if bom else line, limit)
            if problem is not None and bom:
                problem = problem[0], problem[1] + 1
            if problem is None:
                yield [line]
                continue
            message, column = problem
            ctx.diagnostics.error(ParseError(message, Location(ctx.file, number, column)))
            yield [line[len(line.rstrip("\r\n")):]]


BOM = "\ufeff"
"""A UTF-8 byte order mark, which some editors write at the start of a file: accepted there."""
EOF_BYTE = "\x1a"
"""The DOS end-of-file byte (Ctrl-Z) that old DNC software appends to a program."""


def lexable(number: int, text: str) -> str:
    """The part of a line a reader lexes: without a byte order mark at the start of the file, and without
    the DOS end-of-file byte and whatever follows it on its line (the block keeps its text as written,
    so a program is still written back byte for byte)."""
    if number == 1 and text[:1] == BOM:
        text = text[1:]
    cut = text.find(EOF_BYTE)
    return text if cut < 0 else text[:cut]


def line_problem(line: str, limit: int) -> tuple[str, int] | None:
    """What is wrong with a line and its 1-based column, or None when it may be read."""
    text = line.rstrip("\r\n")
    if len(text) > limit:
        return (f"the line is {len(text)} characters long, more than the limit of {limit} "
                "(the set-up's <Limits lineLength>)", limit + 1)
    depth = 0  # inside ( ) comments
    run = 0  # digits in the current number
    start = 0  # where it starts
    for i, ch in enumerate(text):
        if depth:
            if ch == "(":
                depth += 1
            elif ch == ")":
                depth -= 1
            continue
        if ch == "(":
            depth = 1
            run = 0
        elif ch == ";":
            return None  # the rest of the line is a comment
        elif "0" <= ch <= "9":
            if run == 0:
                start = i
            run += 1
            if run > MAX_DIGITS:
                return (f"a number with more than {MAX_DIGITS} digits cannot be read", start + 1)
        elif ch == ".":
            continue  # one number: its digits on both sides of the point count together
        elif not ch.isascii():
            return (f"{character_name(ch)} is not ASCII: outside comments a program is ASCII", i + 1)
        else:
            run = 0
    return None
