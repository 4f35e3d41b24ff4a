"""Values a template writes never become code: each stands, made safe, inside a passive comment.

A template is the integrator's code; what its ``{{ ... }}`` write comes from elsewhere - the input
file's name, ``--define`` values, a comment of the program, the set-up's name - and is text, not code
(a file named ``x) G0 X-999. (.nc`` in ``(PROGRAM {{ program }})`` must not move the machine). So
the sandbox's ``finalize`` (``mark``) wraps the text of every ``{{ ... }}`` in two private-use
characters, and ``seal`` then, knowing the target's comment syntax (``postproc.syntaxes.comments``):

* makes each marked text safe inside a comment (``CommentSyntax.inside``: no parenthesis, line break
  or character the controller acts on);
* checks that it stands inside a comment of the written line, and not one the controller acts on
  (LinuxCNC's ``(MSG,`` ``(LOGOPEN,`` ...): anywhere else it is a located ``ConfigError``; a comment
  that acts only because of its value gets a ``-`` at its head and stays a comment;
* removes the marks.

A plain number (``T{{ tool }}``, ``{{ value|int }}``: digits, a sign, a decimal point) is no text and
stands anywhere. Values reach the renderer with the marks' characters replaced (``scrub``), so no
value can forge a mark.
"""

from __future__ import annotations

import re
from typing import Any

from ..syntaxes.comments import CommentSyntax
from ..errors import ConfigError, Location

OPEN = "\ue000"
CLOSE = "\ue001"
"""Private-use characters around a written value's text while a template renders."""
_PLAIN_NUMBER = re.compile(r"-?\d+(?:\.\d+)?\Z")
_MARK_SPLIT = re.compile(f"([{OPEN}{CLOSE}])")
_MARKS = str.maketrans({OPEN: "?", CLOSE: "?"})
_GENERIC = CommentSyntax()
"""Used where no target is known (``config check`` of a set-up naming no dialect): values are made
safe for parentheses and lines, and their places are not checked."""


def mark(value: Any) -> Any:
    """The sandbox's ``finalize``: a plain number as it is, any other value's text between the marks
    (text that already holds marks - a macro's output, a ``{% filter %}`` block - as it is)."""
    if isinstance(value, (int, float)) and not isinstance(value, bool) and _PLAIN_NUMBER.match(str(value)):
        return value
    text = str(value)
    if OPEN in text or CLOSE in text:
        return text
    return OPEN + text + CLOSE


def scrub(value: Any) -> Any:
    """``value`` (a variable passed to a template) with the marks' characters replaced in every text."""
    if isinstance(value, str):
        return value.translate(_MARKS)
    if isinstance(value, dict):
        return {k: scrub(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [scrub(v) for v in value]
    return value


def seal(name: str, text: str, comments: CommentSyntax | None, where: Location) -> str:
    """The rendered ``text`` without marks, each value made safe and checked to stand inside a passive
    comment of ``comments`` (see the module docstring); ``comments`` None: no target known, values are
    made safe and not placed. A value outside a comment is a ``ConfigError`` at ``where``."""
    if OPEN not in text and CLOSE not in text:
        return text
    syntax = comments or _GENERIC
    out: list[str] = []
    spans: list[tuple[int, int]] = []
    size = 0
    first_close = text.find(CLOSE)
    first_open = text.find(OPEN)
    # an end before any start (a filter cut a value apart): the text before it counts as a value
    start: int | None = 0 if first_close >= 0 and (first_open < 0 or first_close < first_open) else None
    for part in _MARK_SPLIT.split(text):
        if part == OPEN:
            if start is None:
                start = size
        elif part == CLOSE:
            if start is not None:
                spans.append((start, size))
                start = None
        elif part:
            safe = syntax.inside(part) if start is not None else part
            out.append(safe)
            size += len(safe)
    if start is not None:
        spans.append((start, size))
    sealed = "".join(out)
    if comments is not None:
        sealed = _check_places(name, sealed, spans, comments, where)
    return sealed


def _check_places(name: str, text: str, spans: list[tuple[int, int]], comments: CommentSyntax,
                  where: Location) -> str:
    """Every span lies inside one comment of its line, and one the controller does not act on: a comment
    that acts only because of a value (``({{ name }})`` with the name ``MSG, hi``) gets a ``-`` at its head,
    as a comment from another dialect does (``CommentSyntax.text``); one that acts whatever the value is
    refused. Returns ``text`` with those heads."""
    line_start = 0
    found: list[tuple[int, int, bool]] = []
    for line in text.splitlines(keepends=True):
        found.extend((line_start + a, line_start + b, passive) for a, b, passive in comments.comments(line))
        line_start += len(line)
    heads: set[int] = set()
    for a, b in spans:
        if a == b:
            continue  # an empty value writes nothing
        home = next((c for c in found if c[0] < a and b <= c[1]), None)
        if home is not None and not home[2] and not _acts_without_values(text, home, spans, comments):
            heads.add(home[0] + 1)
        elif home is None or not home[2]:
            row = text.count("\n", 0, a) + 1
            shown = text[a:b] if b - a <= 40 else text[a:a + 37] + "..."
            place = "outside a comment" if home is None else "inside a comment the controller acts on"
            raise ConfigError(f"template {name} writes the value {shown!r} {place} (output line {row}): "
                              "values (file names, --define, set-up and program text) are written only "
                              "inside a plain comment, or as a plain number (|int, |float)", where)
    for at in sorted(heads, reverse=True):
        text = text[:at] + "-" + text[at:]
    return text


def _acts_without_values(text: str, comment: tuple[int, int, bool], spans: list[tuple[int, int]],
                         comments: CommentSyntax) -> bool:
    """The comment acts with each value in it written as ``_``: the template wrote an active comment."""
    a, b, _ = comment
    inner = [(x, y) for x, y in spans if a < x and y <= b]
    parts: list[str] = []
    at = a
    for x, y in inner:
        parts.append(text[at:x] + "_")
        at = y
    parts.append(text[at:b])
    body = "".join(parts)
    return not any(passive for _, _, passive in comments.comments(body)[:1])
