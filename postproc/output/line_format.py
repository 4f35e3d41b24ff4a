"""The set-up's line formatting (``<Output>``): block numbers, letter case, line ending, line length.

Applied to the written text, line by line, after the writer (so every writer honours it alike), and
only when the set-up asks for one of them: ``LineFormat.for_run`` returns None otherwise and the writer
emits with no step per block. Settings are read once per translation.

* ``blockNumbers``: ``keep`` (as written), ``all`` (every line with words, from ``renumberStart`` by
  ``renumberStep``), ``tool-changes`` (only the tool-change block, or the first line the tool-change
  template writes), ``none``. A number past ``numberMax`` wraps to ``renumberStart`` (the N address of
  Fanuc 0i and LinuxCNC takes five digits: a sixth is an alarm, so posts wrap; a block number is a
  label, repeated numbers only matter to jumps). A target that refuses a number the set-up's numbering
  can reach (``Writer.MAX_BLOCK_NUMBER``: grbl's 10,000,000) refuses the set-up, located at its setting,
  before anything is written: ``numberMax`` is the set-up's statement of the largest number its controller
  takes, so wrapping elsewhere would be a numbering it did not ask for, and a program would fail or pass by
  its length. A program that jumps to block numbers cannot be
  renumbered here: its targets would change (a located error; the writer's ``--renumber`` in the program's own
  dialect rewrites them, ``postproc.output.block_renumbering``). Between two dialects a ``renumberStart`` alone
  means ``all`` (``numbering``). Comment lines, ``%`` and program-number,
  O-word, ``$`` and label lines get no number.
* ``case``: ``upper``, or ``lower`` where the target's reader accepts lower case (``LOWER_CASE``);
  comments keep their text.
* ``lineEnding``: ``lf`` or ``crlf`` for every line (``keep``: as read, LF for generated lines).
* ``maxLineLength``: a longer line (without its line ending) is a located error; nothing is split.

The target's own rules for a line (``Dialect.LINE_RULE``: grbl's line buffer and real-time characters)
apply here too, to every line written - blocks, templates' output, whatever a writer emits - so no path
around them exists: a line is rewritten as the rule says (with a warning), or refused, located.
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, Callable

from mypy_extensions import mypyc_attr

from ..errors import ConfigError, Location, ProgramError
from ..ir import Block
from .block_references import names_block_numbers

if TYPE_CHECKING:
    from ..context import Context
    from ..setup.groups import OutputSettings

_NUMBER = re.compile(r"(/\d?\s*)?[Nn]\d+\s*")
"""A block number at the start of a line, after an optional block delete."""
_SLASH = re.compile(r"/\d?\s*")
_UNNUMBERED = ("(", ";", "%", "O", "o", "$", "[", "#", "'")
"""Lines that start so carry no block number (comments, tape marks, program numbers, O-words, ISG
statements and labels, macro assignments stay as written)."""
_COMMENT = re.compile(r"\([^)]*\)?|;.*")


@mypyc_attr(allow_interpreted_subclasses=True)
class LineRule:
    """A controller's rules for every line written to it (``Dialect.LINE_RULE``): a rule subclasses it. A
    class, not a protocol: ``LineFormat.line`` calls ``fits`` on every text written, natively when compiled
    (through a protocol the call was a Python method call: ~250 instructions a line, callgrind)."""

    def fits(self, text: str) -> bool:
        """Every line of ``text`` passes as it is (a quick test of the whole; False: ``fit`` each line)."""
        raise NotImplementedError

    def fit(self, line: str, eol: str) -> tuple[str, str | None, str | None]:
        """``line`` (without its end ``eol``) as the controller must receive it, a warning when that changed
        its text, and why the line cannot be sent at all (None: it can)."""
        raise NotImplementedError


@mypyc_attr(allow_interpreted_subclasses=True)
class LineFormat:
    """One translation's line formatting, wrapped around the writer's ``emit``."""

    def __init__(self, ctx: "Context", target: str | None, lower_case: bool, rule: LineRule | None = None,
                 max_number: int = 0, between: bool = False) -> None:
        """``target``: the dialect written (None: the source's own); ``lower_case``: its reader takes
        lower-case addresses (the dialect's ``LOWER_CASE``); ``rule``: its ``LINE_RULE``; ``max_number``: the
        largest block number it takes (0: any; ``Writer.MAX_BLOCK_NUMBER``); ``between``: the run translates
        between two dialects (``renumberStart`` alone then numbers the lines: ``numbering``)."""
        out = ctx.setup.output
        self.rule = rule
        self.warned = False
        """The rule's warning has been given (once a run)."""
        self.mode = numbering(out, between)
        self.formats = not (self.mode == "keep" and out.case == "keep" and out.line_ending == "keep"
                            and not out.max_line_length)
        """The set-up asks for a format (otherwise only the rule applies)."""
        self.ctx = ctx
        self.start = out.renumber_start or out.renumber_step
        self.step = out.renumber_step
        self.max = out.number_max
        self.next = self.start
        self.case = out.case
        self.eol = {"keep": None, "lf": "\n", "crlf": "\r\n"}[out.line_ending]
        self.max_length = out.max_line_length
        self.block: Block | None = None
        """The block whose text is being written (None: a template's)."""
        self.template: str | None = None
        setup = ctx.setup
        if self.case == "lower" and target is not None and not lower_case:
            raise ConfigError(f"<Output case=\"lower\">: the {target} reader takes upper-case addresses only",
                              setup.setting_at("Output", "case"))
        if max_number and self.mode in ("all", "tool-changes") and max(self.start, self.max) > max_number:
            name, value = ("renumberStart", self.start) if self.start > max_number else ("numberMax", self.max)
            raise ConfigError(f"<Output {name}=\"{value}\">: the {target or 'target'} controller refuses a block "
                              f"number above {max_number} (the line is not run): set {name} to {max_number} or less",
                              setup.setting_at("Output", name))

    @classmethod
    def for_run(cls, ctx: "Context", target: str | None, lower_case: bool,
                rule: LineRule | None = None, max_number: int = 0, between: bool = False) -> "LineFormat | None":
        out = ctx.setup.output
        if (out.block_numbers == "keep" and out.case == "keep" and out.line_ending == "keep"
                and not out.max_line_length and rule is None and not (between and out.renumber_start)):
            return None
        return cls(ctx, target, lower_case, rule, max_number, between)

    def wrap(self, emit: Callable[[str], object]) -> Callable[[str], object]:
        """``emit`` of each text as ``line`` has it."""
        line = self.line

        def formatted(text: str) -> object:
            return emit(line(text))
        return formatted

    def line(self, text: str) -> str:
        """``text`` (a block's, or a template's lines) formatted, and as the target's rule has it. With only the
        rule to apply, most text passes its quick test as it is."""
        rule = self.rule
        if rule is not None and not self.formats and rule.fits(text):
            return text
        return self.format(text)

    def format(self, text: str) -> str:
        rule = self.rule
        block = self.block
        if block is not None and self.mode != "keep":
            if names_block_numbers(block):
                self._error("block numbers cannot be rewritten in a program that jumps to block numbers or "
                            "names them (a return to one, a lathe cycle's profile range): the numbers it names "
                            "would change")
        number_first = self.mode == "all" or (self.mode == "tool-changes" and (
            self.template == "tool_change" or (block is not None and "ToolChange" in block.sections)))
        out: list[str] = []
        for line in text.splitlines(keepends=True):
            body = line.rstrip("\r\n")
            eol = line[len(body):]
            if self.mode != "keep":
                body, number_first = self._number(body, number_first)
            if self.case != "keep":
                body = _recase(body, self.case)
            if rule is not None:
                body = self._ruled(rule, body, self.eol if self.eol is not None and eol else eol)
            if self.max_length and len(body) > self.max_length:
                self._error(f"a written line is {len(body)} characters long, more than <Output maxLineLength="
                            f"\"{self.max_length}\">: {body[:40]}...")
            if self.eol is not None and eol:
                eol = self.eol
            out.append(body + eol)
        return "".join(out)

    def _number(self, body: str, number: bool) -> tuple[str, bool]:
        """Drop the line's block number; give it the next one when ``number`` and it takes one. Returns
        the line and whether the next line is still to be numbered (``all``: always)."""
        head = body.lstrip()
        if not head or head.startswith(_UNNUMBERED):
            return body, number
        match = _NUMBER.match(head)
        slash = ""
        if match is not None:
            slash = (match.group(1) or "").strip()
            head = head[match.end():]
            if not head.strip() and not number:
                return (slash + " " if slash else ""), number
        else:
            slash_match = _SLASH.match(head)
            if slash_match is not None:
                slash, head = slash_match.group(0).strip(), head[slash_match.end():]
        if not number:
            return (f"{slash} " if slash else "") + head, False
        text = f"N{self.next}"
        self.next += self.step
        if self.next > self.max:
            self.next = self.start
        return (f"{slash} " if slash else "") + text + (" " + head if head else ""), self.mode == "all"

    def _ruled(self, rule: LineRule, body: str, eol: str) -> str:
        line, warning, problem = rule.fit(body, eol)
        if problem is not None:
            self._error(problem)
        elif warning is not None and not self.warned:
            self.warned = True
            self.ctx.diagnostics.warn(warning, self._where())
        return line

    def _error(self, message: str) -> None:
        self.ctx.diagnostics.error(ProgramError(message, self._where()))

    def _where(self) -> Location:
        if self.block is not None:
            return self.ctx.at(self.block)
        setup = self.ctx.setup
        return Location(setup.source or "<set-up>", setup.template_lines.get(self.template or "", 1), 1)


def numbering(out: "OutputSettings", between: bool) -> str:
    """The ``blockNumbers`` a run follows: the set-up's, and ``all`` for a ``renumberStart`` between two dialects
    (``--renumber``'s meaning there, ``postproc.commands.renumbering``: the writer renumbers only the blocks it
    normalises, which a translation between two dialects has none of, so the setting was ignored, exit 0)."""
    if out.block_numbers == "keep" and out.renumber_start and between:
        return "all"
    return out.block_numbers


def _recase(body: str, case: str) -> str:
    """``body`` in upper or lower case outside its comments."""
    change = str.upper if case == "upper" else str.lower
    parts: list[str] = []
    at = 0
    for match in _COMMENT.finditer(body):
        parts.append(change(body[at:match.start()]))
        parts.append(match.group(0))
        at = match.end()
    parts.append(change(body[at:]))
    return "".join(parts)
