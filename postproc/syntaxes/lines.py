"""The check every program line passes before a reader lexes it: what no controller reads is refused
here, once for every dialect, with the line and column.

* A line longer than the set-up's ``<Limits lineLength>`` (default 64 kB, more than any controller's
  buffer) is refused before anything scans it, and before it is read whole: a text stream is read a
  piece of at most ``PIECE`` characters at a time (``pieces``), a longer line is counted piece by piece
  and dropped, and one that has not ended after ``MAX_SKIPPED`` more characters ends the reading
  (``/dev/zero`` is one endless line). What is held is at most ``CHUNK`` pieces.
* Outside comments a program is ASCII (but for the reader's ``BLANKS``, and a UTF-8 byte order mark opening the file, which
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

import io
from functools import partial
from itertools import chain, islice, repeat
from typing import Callable, Final, Generator, Iterable, Iterator, TextIO, Union

from ..context import Context
from ..errors import Location, ParseError, character_name
from ..numbers import MAX_DIGITS as NUMBER_DIGITS

MAX_DIGITS: Final = NUMBER_DIGITS
"""The most digits read in one number: more than any controller's registers hold, and within a float's
range and Python's int conversion limit by far (``postproc.numbers.MAX_DIGITS``: no writer writes more)."""
CHUNK = 1024
"""Lines checked at once on the fast path (a chunk is held while checked: a few dozen kilobytes of a
program, at most ``CHUNK`` pieces of ``PIECE`` characters of anything)."""
PIECE = 1 << 12
"""Most characters ``pieces`` reads at once: longer lines (rare, and checked line by line) are joined."""
MAX_SKIPPED = 1 << 26
"""Characters of a too-long line read past its limit before reading stops: the line's length is then
reported as at least this much, and the rest of the input is not read."""
_NUMBER_CHARS = bytes(1 if chr(i) in "0123456789." else 0 for i in range(256))
"""``bytes.translate`` table: digits and the point to 1, everything else to 0."""
_LONG_RUN = b"\x01" * (MAX_DIGITS + 1)
"""A candidate for a too-long number (``line_problem`` then counts its digits)."""
_CHECKED_CHARS = bytes(1 if chr(i) in "0123456789." else 2 if chr(i) in "\v\f\x1c\x1d\x1e" else 0 for i in range(256))
"""``_NUMBER_CHARS``, and the ASCII characters ``str.splitlines`` ends a line at that a text stream does not, to 2."""
_SEPARATOR = b"\x02"


def pieces(lines: Iterable[str], limit: int) -> Iterable[str]:
    """A text stream's lines read at most ``piece_size(limit)`` characters at a time, so that no line is
    ever read whole before its length is known (``checked_lines`` joins the pieces of a line within the
    limit, and counts and drops those of a longer one); ``lines`` as they are when they are not a stream.
    All C calls: no Python step per line."""
    read = getattr(lines, "readline", None)
    if read is None:
        return lines
    return iter(partial(read, piece_size(limit)), "")


def piece_size(limit: int) -> int:
    """Characters ``pieces`` reads at once: a line within ``limit`` and its end of line, up to ``PIECE``."""
    return min(limit + 2, PIECE)


Run = tuple[Iterable[str], Union[str, None], bytes]
"""A run of checked lines (``CheckedLines.runs``): a list of their texts without their ends, the end of line they
all have (the last line of a program may have none: a run of its own, with "") and their ASCII bytes, ends and all
(the check's copy, which a reader may read them from: ``rs274.canonical_line.scan_marks``; or b""); or the lines
with their ends, None and b""."""


def checked_lines(lines: Iterable[str], ctx: Context, blanks: str = "") -> CheckedLines:
    """``lines`` as they are; a line that fails a check (see the module docstring) as an empty line.
    ``blanks``: the non-ASCII characters the reader reads as blanks (``Reader.BLANKS``).

    Lines are checked a chunk at a time with a few C-speed calls (``len``, ``isascii``, one translate and
    one substring search over the joined chunk) and passed on by ``chain`` without a Python step per
    line; only a chunk that fails them is checked line by line. (A regex search per line cost 5 % of a
    copy-through translation.)"""
    return CheckedLines(lines, ctx, blanks)


class CheckedLines:
    """The checked lines of a program (``checked_lines``), read once: iterated, each line with its end of line
    (what ``Reader.read`` takes); or as ``runs``, the same lines and errors, where a stream's piece of many lines
    all ending alike is passed on split from their ends by one C call (``str.split``): a reader that takes runs
    makes no string a line to cut its end off (~400 instructions a CAM line: callgrind)."""

    def __init__(self, lines: Iterable[str], ctx: Context, blanks: str) -> None:
        self.lines = lines
        self.ctx = ctx
        self.blanks = blanks

    def __iter__(self) -> Iterator[str]:
        return chain.from_iterable(lines for lines, _, _ in self._chunks(False))

    def runs(self) -> Iterator[Run]:
        """The lines, a run at a time (``Run``), in order."""
        return self._chunks(True)

    def _chunks(self, split: bool) -> Iterator[Run]:
        lines, ctx, blanks = self.lines, self.ctx, self.blanks
        limit = ctx.setup.limits.line_length
        if getattr(lines, "read", None) is not None and getattr(lines, "readline", None) is not None:
            return _read_chunks(lines, ctx, limit, blanks, split)  # type: ignore[arg-type]
        read = pieces(lines, limit)
        return zip(_checked_chunks(iter(read), ctx, limit, blanks, read is not lines), repeat(None), repeat(b""))


def line_runs(lines: Iterable[str]) -> Iterable[Run]:
    """``lines`` as runs (``Run``): ``CheckedLines.runs`` where they are checked lines, else one run of the lines
    with their ends, as they come."""
    if isinstance(lines, CheckedLines):
        return lines.runs()
    return ((lines, None, b""),)


def one_end(text: str) -> str | None:
    """The end of line that ends every line of ``text`` where its lines are split at CR, LF and CR LF (the
    last line may have none): LF where it holds no CR, CR LF where every CR and LF stand in one; else None."""
    if "\r" not in text:
        return "\n"
    pairs = text.count("\r\n")
    return "\r\n" if pairs == text.count("\r") and pairs == text.count("\n") else None


class _Resumed:
    """What is left of a stream after ``_read_chunks`` read ``held`` (the start of a line, with no end of line
    in it but maybe a CR last) past its last whole line, read as ``readline(size)`` reads it: the pieces
    ``pieces`` takes (``_checked_chunks`` goes on with them)."""

    def __init__(self, held: str, stream: TextIO) -> None:
        self.held = held
        self.stream = stream

    def readline(self, size: int) -> str:
        held = self.held
        if not held:
            return self.stream.readline(size)
        if len(held) >= size:
            self.held = held[size:]
            return held[:size]
        self.held = ""
        if held[-1] == "\r":  # the line ends, with a CR LF if an LF follows and the size leaves room for it
            after = self.stream.read(1)
            if after == "\n":
                return held + after
            self.held = after
            return held
        return held + self.stream.readline(size - len(held))


def _read_chunks(stream: TextIO, ctx: Context, limit: int, blanks: str, split: bool) -> Iterator[Run]:
    """``_checked_chunks`` of a text stream, read in pieces of many lines (``read``) and split here: the same
    lines and errors, without a ``readline`` call a line (~1,000 instructions a CAM line: callgrind).

    Where the stream splits lines as ``str.splitlines`` does on the ASCII text without its other separators
    (universal newlines: CR, LF, CR LF, which its ``newlines`` shows once a line end was read; not a stream
    opened with ``newline="\\n"``, nor a ``readline``-only one), its first line is read by ``readline`` and
    the rest ``fast`` characters at a time: every line after a chunk's first then fits the fast check, and
    the first (the line a read cut, joined) is measured. A line not ended within ``fast`` characters
    (longer than the limit, or than ``PIECE``) goes back to ``_checked_chunks`` with the rest of the stream
    (``_Resumed``), as does a stream that splits lines another way. ``split``: a piece whose lines all end alike
    (``one_end``) is passed on as their texts and that end (``Run``)."""
    piece = piece_size(limit)
    fast = min(limit, piece - 1)
    first = stream.readline(piece)
    if not first:
        return
    if first[-1] not in "\r\n" or getattr(stream, "newlines", None) is None:
        for lines in _checked_chunks(chain((first,), iter(partial(stream.readline, piece), "")), ctx, limit, blanks,
                                     True):
            yield lines, None, b""
        return
    read = stream.read
    number = 0
    held = first  # read, and not passed on yet
    while True:
        data = read(fast)
        text = held + data if held else data
        if data:
            end = max(text.rfind("\n"), text.rfind("\r")) + 1
            if end == len(text) and text[-1] == "\r":  # maybe the CR of a CR LF: kept for the next read
                end = max(text.rfind("\n", 0, end - 1), text.rfind("\r", 0, end - 1)) + 1
            whole, held = text[:end], text[end:]
            if len(held) > fast:  # a line this long is read in pieces, and maybe never whole
                if whole:  # (never: only a line begun in an earlier read can be this long)
                    number = yield from _checked_text(whole, ctx, limit, blanks, number, fast, None)
                for lines in _checked_chunks(iter(partial(_Resumed(held, stream).readline, piece), ""), ctx, limit,
                                             blanks, True, number):
                    yield lines, None, b""
                return
            if not whole:
                continue
        elif not text:
            return
        else:
            whole, held = text, ""  # the last line, without an end of line
        number = yield from _checked_text(whole, ctx, limit, blanks, number, fast, one_end(whole) if split else None)


def _checked_text(text: str, ctx: Context, limit: int, blanks: str, number: int, fast: int,
                  end: str | None) -> Generator[Run, None, int]:
    """Yield the whole lines ``text`` holds (lines ``number + 1`` on), checked as ``_checked_chunks`` checks
    them, as one chunk; returns the number of the last. Every line but the first is at most ``fast`` long.
    ``end``: the end of line every line of ``text`` has (``one_end``): lines that pass the checks are passed on
    as their texts (split at it, a C call) and that end, the last as a run of its own where it has none."""
    if text.isascii():
        data = text.encode("ascii")
        coded = data.translate(_CHECKED_CHARS)
        if end is not None:  # (``split`` at it splits where the stream does: no other separator counts)
            texts = text.split(end)
            last = texts.pop()  # "" where the last line has its end
            if (len(texts[0]) + len(end) if texts else len(last)) <= fast and _LONG_RUN not in coded:
                if texts:
                    yield texts, end, data
                if last:
                    yield [last], "", b""
                return number + len(texts) + (1 if last else 0)
            lines = io.StringIO(text, newline="").readlines()  # (it may hold another separator: not ``splitlines``)
        elif _SEPARATOR not in coded:  # ``splitlines`` splits where the stream does
            lines = text.splitlines(True)
            if len(lines[0]) <= fast and _LONG_RUN not in coded:
                yield lines, None, b""
                return number + len(lines)
        else:
            lines = io.StringIO(text, newline="").readlines()
    else:
        lines = io.StringIO(text, newline="").readlines()
    checked: list[str] = []
    for line in lines:
        number += 1
        bom = number == 1 and line[:1] == BOM
        problem = line_problem(line[1:] if bom else line, limit, blanks)
        if problem is None:
            checked.append(line)
        else:
            message, column = problem
            ctx.diagnostics.error(ParseError(message, Location(ctx.file, number, column + bom)))
            checked.append(line[len(line.rstrip("\r\n")):])
    yield checked, None, b""
    return number


def _checked_chunks(lines: Iterator[str], ctx: Context, limit: int, blanks: str,
                    streamed: bool, number: int = 0) -> Iterator[list[str]]:
    piece = piece_size(limit)  # a piece this long that does not end its line was cut by ``pieces``
    fast = min(limit, piece - 1)
    # A piece ``pieces`` read holds at most one LF, at its end; where pieces are shorter than the limit
    # (the usual limit), a piece ending with LF is a whole line within it. So a chunk of as many LFs as
    # pieces holds no cut piece and no long line, which one count finds (``max(map(len, ...))`` cost
    # ~180 instructions a line: callgrind).
    whole_lines_fit = streamed and piece < limit
    pending: list[str] = []
    while True:
        chunk = pending + list(islice(lines, CHUNK - len(pending)))
        pending = []
        if not chunk:
            return
        text = "".join(chunk)
        if (whole_lines_fit and text.count("\n") == len(chunk)) or max(map(len, chunk)) <= fast:
            # no cut piece and no long line
            if text.isascii() and _LONG_RUN not in text.encode("ascii").translate(_NUMBER_CHARS):
                number += len(chunk)
                yield chunk
                continue
        rest = iter(chunk)
        for line in rest:
            number += 1
            cut = len(line) == piece and not line.endswith("\n")
            if cut:
                bom = number == 1 and line[:1] == BOM  # not counted in the line's length
                whole, length, eol, pending, ended = _whole_line(
                    line, lambda: next(rest, None) or next(lines, None), piece, limit + bom)
                pending.extend(rest)
                if whole is None:
                    _too_long(ctx, Location(ctx.file, number, limit + 1 + bom), length - bom, limit, ended)
                    yield [eol]
                    if not ended:
                        return
                    break
                line = whole
            bom = number == 1 and line[:1] == BOM
            problem = line_problem(line[1:] if bom else line, limit, blanks)
            if problem is not None and bom:
                problem = problem[0], problem[1] + 1
            if problem is None:
                yield [line]
            else:
                message, column = problem
                ctx.diagnostics.error(ParseError(message, Location(ctx.file, number, column)))
                yield [line[len(line.rstrip("\r\n")):]]
            if cut:
                break  # on with what was read past the line


def _whole_line(first: str, take: Callable[[], str | None], piece: int,
                limit: int) -> tuple[str | None, int, str, list[str], bool]:
    """Read a cut line (``first`` is its first piece) to its end, keeping its pieces only while they are
    within the limit: (the line with its end of line, or None when it is longer than ``limit``; its
    length without the end of line; its end of line; the piece read past it, if any; whether it ended
    within ``MAX_SKIPPED`` characters past the limit)."""
    kept: list[str] | None = [first]
    part, total = first, len(first)
    while True:
        eol, after = "", []
        if part.endswith("\n"):
            eol = "\r\n" if part.endswith("\r\n") else "\n"
        elif part.endswith("\r"):  # a CR LF may have been cut between its two characters
            following = take() if len(part) == piece else None
            if following == "\n":
                eol, total = "\r\n", total + 1
                if kept is not None:
                    kept.append(following)
            else:
                eol, after = "\r", [following] if following else []
        if eol:
            length = total - len(eol)
            return ("".join(kept) if kept is not None and length <= limit else None), length, eol, after, True
        if total > limit + MAX_SKIPPED:
            return None, total, "", [], False
        following = take()
        if following is None:  # the input ends on this line
            return ("".join(kept) if kept is not None and total <= limit else None), total, "", [], True
        part = following
        total += len(part)
        if kept is not None:
            if total <= limit + 2:
                kept.append(part)
            else:
                kept = None


def _too_long(ctx: Context, at: Location, length: int, limit: int, ended: bool) -> None:
    if ended:
        message = (f"the line is {length} characters long, more than the limit of {limit} (the set-up's "
                   "<Limits lineLength>)")
    else:
        message = (f"the line is more than {length} characters long, more than the limit of {limit} (the "
                   "set-up's <Limits lineLength>): the rest of the input is not read")
    ctx.diagnostics.error(ParseError(message, at))


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


def line_problem(line: str, limit: int, blanks: str = "") -> tuple[str, int] | None:
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
        elif not ch.isascii() and ch not in blanks:
            return (f"{character_name(ch)} is not ASCII: outside comments a program is ASCII", i + 1)
        else:
            run = 0
    return None
