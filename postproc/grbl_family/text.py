"""What the serial and protocol layers of the grbl family (grbl 1.1, grblHAL) do to a line before the parser
sees it, as the rules every written line obeys (``GrblLines``, through ``postproc.output.line_format``) and
the family's comment syntax (``COMMENTS``). Each dialect makes its ``GrblLines`` with its line buffer.

From ``grbl/serial.c`` and ``grbl/protocol.c`` (github.com/gnea/grbl, stored commit bfb67f0) [V]:

* the serial layer acts on ``?`` (status), ``!`` (feed hold), ``~`` (cycle start) and Ctrl-X wherever
  they stand, comments included, and bytes above 0x7F are real-time commands (grbl 1.1's extended
  set: feed and spindle overrides, ...): no written line holds one. Text is written in ASCII without
  them (``Ø`` as ``DIA``, ``°`` as ``DEG``, accents dropped, anything else ``_``), with one warning.
* ``protocol_main_loop`` keeps a line in ``line[LINE_BUFFER_SIZE]`` (80, ``protocol.h``) without spaces,
  control characters, ``/`` and comments (``( )`` to the first ``)``, ``;`` to the end of the line);
  the 80th character kept sets the overflow flag: error 11, "Max characters per line exceeded". A
  longer line has its numbers written shorter where that is exact (``X10.500`` as ``X10.5``, ``-0.5``
  as ``-.5``: grbl's ``read_float`` reads both alike); one still too long is refused, located.

grblHAL (github.com/grblHAL/core, stored commit f80fc34) keeps the real-time characters and the extended
set above 0x7F [V: ``protocol.c`` ``protocol_enqueue_realtime_command``, ``stream.h``; inside ``( )`` a
driver may keep them for messages, so the rule stays the safe one], and its ``protocol_main_loop`` keeps
every character of a line but control characters and leading blanks, comments and spaces included, in
``line[LINE_BUFFER_SIZE]`` (257, ``protocol.h``) [V]: ``kept_whole``.
"""

from __future__ import annotations

import re
import unicodedata
from typing import Callable, Final

from mypy_extensions import mypyc_attr

from postproc.output.line_format import LineRule
from postproc.syntaxes.comments import CommentSyntax

GRBL_LINE_BUFFER_SIZE: Final = 80
"""grbl 1.1's ``LINE_BUFFER_SIZE`` (``protocol.h``): at most 79 characters of a line are kept [V]."""
GRBL_KEPT: Final = GRBL_LINE_BUFFER_SIZE - 1

REALTIME = re.compile(r"[?!~\x00-\x08\x0b\x0c\x0e-\x1f\x7f]")
"""Characters grbl acts on (or that have no place in a line): replaced in what is written."""
_SYMBOLS = {"\u00d8": "DIA", "\u00f8": "DIA", "\u2300": "DIA", "\u00b0": "DEG", "\u00b1": "+/-", "\u00b5": "U",
            "\u2013": "-", "\u2014": "-", "\u2018": "'", "\u2019": "'", "\u201c": '"', "\u201d": '"'}
_MARKED: Final = bytes(code if code < 128 and not REALTIME.match(chr(code)) else code ^ 0x80 for code in range(256))
"""``bytes.translate`` table: the ASCII characters grbl takes as they are (those ``REALTIME`` does not
match) to themselves, every other byte to another: a text of plain bytes translates to itself."""
_NUMBER = re.compile(r"([-+]?)(\d*)\.?(\d*)")
_WORD_NUMBER = re.compile(r"(?<=[A-Za-z])\s*[-+]?(?:\d+\.?\d*|\.\d+)")
_COMMENT = re.compile(r"\([^)]*\)?|;.*")


def plain_ascii(text: str) -> bool:
    """``text`` is ASCII without a character of ``REALTIME``: its bytes translate to themselves (a byte loop
    in C; a translation that changes nothing is the bytes themselves, so the comparison is one of identity:
    ~125 instructions a line fewer than testing the translation for a marked byte, callgrind). Deleting the
    plain bytes instead, ``translate(None, delete)``, builds a table of 256 entries a call: 1,500
    instructions. Text beyond ASCII fails its encoding (a comment's rare accent or a lone surrogate: an
    exception, a few thousand instructions): ``str.isascii`` first was a generic method call compiled, and
    ``encode("ascii", "replace")`` mypyc's general ``CPy_Encode``; the strict ASCII encoding is a direct call
    (-256 instructions a call, callgrind of a mypyc build of the three forms)."""
    try:
        data = text.encode("ascii")
    except UnicodeEncodeError:
        return False
    return data.translate(_MARKED) == data


def grbl_safe(text: str) -> str:
    """``text`` in ASCII without grbl's real-time characters (see the module docstring)."""
    out: list[str] = []
    for ch in text:
        if ch.isascii():
            out.append("_" if REALTIME.match(ch) else ch)
        elif ch in _SYMBOLS:
            out.append(_SYMBOLS[ch])
        else:
            plain = unicodedata.normalize("NFKD", ch).encode("ascii", "ignore").decode()
            out.append("_" if not plain or REALTIME.search(plain) else plain)
    return "".join(out)


COMMENTS: Final = CommentSyntax(parens=True, nested=False, semicolon=True, clean=grbl_safe)
"""``( )`` to the first ``)`` and ``;`` to the end of the line (``protocol.c``) [V]; no real-time
character inside."""


def kept(line: str) -> int:
    """How many characters of ``line`` grbl 1.1's protocol layer keeps (see the module docstring)."""
    return sum(1 for ch in _COMMENT.sub("", line) if ch > " " and ch != "/")


def kept_whole(line: str) -> int:
    """How many characters of ``line`` grblHAL's protocol layer keeps: all but control characters and
    leading blanks, comments and spaces included [V: grblHAL core ``protocol.c``, ``protocol_main_loop``]."""
    return sum(1 for ch in line.lstrip(" ") if ch >= " ")


def _shorter(match: re.Match[str]) -> str:
    """A word's number in its shortest exact spelling (no sign '+', leading or trailing zero, or point)."""
    text = match.group(0).strip()
    parts = _NUMBER.fullmatch(text)
    if parts is None:
        return text
    sign, whole, frac = parts.group(1), parts.group(2).lstrip("0"), parts.group(3).rstrip("0")
    if not whole and not frac:
        return "0"
    return ("-" if sign == "-" else "") + (whole or "") + ("." + frac if frac else "")


def shortened(line: str) -> str:
    """``line`` with every word's number shortest, its comments as they are."""
    out: list[str] = []
    at = 0
    for match in _COMMENT.finditer(line):
        out.append(_WORD_NUMBER.sub(_shorter, line[at:match.start()]))
        out.append(match.group(0))
        at = match.end()
    out.append(_WORD_NUMBER.sub(_shorter, line[at:]))
    return "".join(out)


def short(text: str, size: int) -> bool:
    """Every piece of ``text`` between two LFs (or its ends) is shorter than ``size``: no ``size`` characters in a
    row without an LF. From a piece's start, the last LF among the next ``size`` characters ends every piece that
    starts there or before it (each then shorter than ``size``), none ends the piece that starts there too late;
    so an expanded hole's text of ten short lines takes two searches (splitting it into pieces and taking the
    longest's length cost ~4k instructions compiled, a generic call of ``max``)."""
    at = 0
    length = len(text)
    while length - at >= size:
        end = text.rfind("\n", at, at + size)
        if end < 0:
            return False
        at = end + 1
    return True


@mypyc_attr(allow_interpreted_subclasses=True)
class GrblLines(LineRule):
    """The rules of every line written for a controller of the family (``postproc.output.line_format.LineRule``):
    ``name`` and ``controller`` name it in messages (``grbl``, ``grbl 1.1``), ``buffer_size`` is its ``LINE_BUFFER_SIZE`` (the characters kept,
    and a terminator), ``count`` says which characters of a line its protocol layer keeps, ``counted``
    says it in words."""

    def __init__(self, name: str, controller: str, buffer_size: int, count: Callable[[str], int],
                 counted: str) -> None:
        self.name = name
        self.controller = controller
        self.buffer_size = buffer_size
        self.limit = buffer_size - 1
        self.count = count
        self.counted = counted

    def fits(self, text: str) -> bool:
        """Every line of ``text`` is plain ASCII and short enough, as it is (the test of a usual block, and
        of an expanded cycle's many lines). Plain ASCII has no line break but CR and LF, so each line lies
        within a piece between two LFs, and a piece shorter than the buffer holds a line ``fit`` keeps: ``short``."""
        return plain_ascii(text) and short(text, self.buffer_size)

    def fit(self, line: str, eol: str) -> tuple[str, str | None, str | None]:
        """``line`` as the controller must receive it, a warning when its text changed, and why it cannot be
        sent."""
        warning = None
        if not plain_ascii(line):
            line = grbl_safe(line)
            warning = (f"{self.name} acts on '?', '!', '~' and bytes above 0x7F even inside a comment: text "
                       "is written without them")
        if len(line) < self.buffer_size or self.count(line) <= self.limit:
            return line, warning, None
        short = shortened(line)
        count = self.count(short)
        if count <= self.limit:
            return short, warning, None
        return line, warning, (f"the line keeps {count} characters{self.counted}, more than the {self.limit} "
                               f"{self.controller} holds (LINE_BUFFER_SIZE {self.buffer_size}, error 11): split "
                               "the block, or write its numbers with fewer digits")
