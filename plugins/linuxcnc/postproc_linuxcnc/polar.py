"""PolarSyntax: LinuxCNC's polar coordinates (``@`` radius, ``^`` angle in degrees) read into X and Y.

rs274 turns them into the XY end point of the block before it moves, about the origin of the active
coordinate system, so after this step a polar block is an ordinary block (its text kept: LinuxCNC gets
it back as written, another target its X and Y). The rules, from LinuxCNC's interpreter [V: LinuxCNC
src/emc/rs274ngc/interp_find.cc find_ends, interp_cycles.cc convert_cycle_xy and the CYCLE_MACRO of
interp_internal.hh, interp_internal.cc enhance_block; and rs274 2.9 run here]:

* Only in G17, never with an X or Y word in the block, never with G53; never with G92 ("Polar
  coordinates can only be used for motion"), nor with G10, G28, G30 or G52 (refused here: axis words
  mean other things there).
* G90: ``@`` and ``^`` are the end point's radius and angle; one alone keeps the other of the point
  where the tool is (``@`` alone at the origin is an error: no angle).
* G91: ``@`` is added to the radius of the point where the tool is, ``^`` to its angle (the radius
  first); at the origin either is an error ("indeterminate").
* A canned cycle in G90 takes a missing radius or angle from where the tool is (no origin check); in
  G91 each of its ``L`` repeats turns and stretches the last hole about the origin, so a polar G91
  cycle with ``L`` > 1 becomes ``L`` blocks of one hole each (rs274 moves the same: each next hole
  block starts at the clear level the last hole left, and R and the bottom stay the first block's as
  the initial level stays while the cycle is active).

A computed ``@`` or ``^`` (``@[#1]``) is known only when the program runs: a program that has one is
flattened for another target. In a copy to LinuxCNC itself (``program_mode`` 'keep', nothing run, no dry run of
``postproc.api._keep_check``: ``_copied``) a line whose end point is not computed here is kept as written
(``_kept_as_written``), as rs274 reads it where the program runs: one with a computed word, a G91 cycle whose
``L`` repeats turn each hole further (one line of the source, several holes), or one that keeps or adds to a
tool position not known here. Every other polar line of a copy is still read into X and Y (the later steps
check and follow it) and written as read (``postproc_linuxcnc.writer``).
"""

from __future__ import annotations

import re
from typing import Callable, Final, Iterable, Iterator

from postproc.context import Context, word_columns
from postproc.errors import Location, ProgramError
from postproc.ir.expr import Expr, Num
from postproc.interp import spell_number
from postproc.ir import Block, NativeCode
from postproc.interp.variables import RUN_INTERPRETER_KEY
from postproc.geometry.polar import clean as _clean, polar_absolute as _absolute, polar_turned as _turned
from postproc.syntaxes.syntax import Syntax

POLAR: Final = ("@", "^")
"""The polar addresses: radius, angle."""
_CYCLES: Final = frozenset((73.0, 74.0, 76.0, 81.0, 82.0, 83.0, 84.0, 85.0, 86.0, 87.0, 88.0, 89.0))
_MOTION: Final = frozenset((0.0, 1.0, 2.0, 3.0, 33.0, 33.1, 38.2, 38.3, 38.4, 38.5, 5.0, 5.1, 5.2))
"""Group-01 codes but the cycles: a block with one is no cycle block."""
_NOT_MOTION: Final = {10.0: "G10", 28.0: "G28", 28.1: "G28.1", 30.0: "G30", 30.1: "G30.1", 52.0: "G52",
                      53.0: "G53", 92.0: "G92", 92.1: "G92.1", 92.2: "G92.2", 92.3: "G92.3"}
_COMPUTED: Final = {"G": "G code beside polar coordinates", "L": "repeat count (L) beside polar coordinates"}
"""A computed word besides ``@``/``^`` that decides where the polar point is, as the refusal names it."""
_PLANES: Final = {17.0: "XY", 18.0: "ZX", 19.0: "YZ"}


class PolarSyntax(Syntax):
    """Rewrites a block's ``@``/``^`` words into the X and Y that rs274 computes (module docstring)."""

    XNAME = "PolarSyntax"
    __slots__ = ()

    def build(self, block: Block, ctx: Context) -> None:
        """Unused: the step streams (``process``), as a G91 cycle with L repeats becomes several blocks."""

    def process(self, blocks: Iterable[Block], ctx: Context) -> Iterator[Block]:
        for block in blocks:
            text = block.text
            if text is not None and "@" not in text and "^" not in text:
                yield block  # the common block (cheap: two scans in C)
                continue
            if not any(letter == "@" or letter == "^" for letter, _ in block.words):
                yield block
                continue
            try:
                extra = list(self._rewrite(block, ctx))
            except ProgramError as err:
                ctx.diagnostics.error(err, block.text)
                yield Block(block.line, block.text, block.eol)  # kept as text, as every refused line
                continue
            yield block
            yield from extra

    def _rewrite(self, block: Block, ctx: Context) -> Iterator[Block]:
        """Give ``block`` X and Y for its polar words; yield the blocks of the further holes of a G91
        cycle with L repeats."""
        words = block.words
        state = ctx.state
        column = _columns(block, ctx)
        values = block.values
        computed = [letter for letter in (*POLAR, "G", "L") if isinstance(values.get(letter), Expr)]
        copied = _copied(ctx)
        if computed and not copied:  # (a G code or a repeat count turns or places the point too)
            what = _COMPUTED.get(computed[0], f"polar coordinate ({computed[0]})")
            raise ProgramError(f"a computed {what} is known only when the program runs (it is read where the "
                               "program is run, not kept as it is)", column(computed[0]))
        polar: dict[str, float] = {}
        kept: dict[str, Expr] = {}
        """The polar words as expressions (a number a ``Num``), for a line kept as written."""
        codes: list[float] = []
        repeat = 1
        for letter, num in words:
            up = letter.upper()
            if up in POLAR:
                if up in kept:
                    raise ProgramError(f"address {up} appears twice in one block", column(up, 2))
                value = values.get(up)
                kept[up] = value if isinstance(value, Expr) else Num(float(num))
                if not isinstance(value, Expr):
                    polar[up] = float(num)
            elif up == "X" or up == "Y":
                raise ProgramError(f"cannot use both polar coordinates and an {up} word (rs274)", column(up))
            elif up == "G" and not isinstance(values.get("G"), Expr):
                codes.append(round(float(num), 1))
            elif up == "L" and not isinstance(values.get("L"), Expr):
                repeat = int(float(num))
        first = next(letter for letter, _ in words if letter in POLAR)
        for code in codes:
            if code in _NOT_MOTION:
                name = _NOT_MOTION[code]
                raise ProgramError(f"polar coordinates cannot be used with {name} (rs274: only for motion)",
                                   column(first))
        if state.plane != "XY":
            raise ProgramError("polar coordinates are used only in the G17 (XY) plane (rs274)", column(first))
        distance = state.distance
        for code in codes:
            if code == 90.0:
                distance = "absolute"
            elif code == 91.0:
                distance = "incremental"
        known_x, known_y = state.position.get("X"), state.position.get("Y")
        cycle = any(code in _CYCLES for code in codes) or (
            state.cycle is not None and not any(code in _MOTION or code == 80.0 for code in codes))
        if copied and (computed or known_x is None or known_y is None
                       or distance == "incremental" and cycle and repeat != 1):
            _kept_as_written(block, ctx, kept)  # (rs274's rules above were checked: they need no number)
            return
        if known_x is None or known_y is None:
            if distance == "incremental" or len(polar) < 2:
                raise ProgramError("the tool's X and Y are unknown before a polar coordinate that keeps or "
                                   "adds to where it is (program X and Y first)", column(first))
            known_x = known_y = 0.0  # both given absolutely: where the tool is plays no part
        x, y = known_x, known_y
        radius, angle = polar.get("@"), polar.get("^")
        holes: list[tuple[float, float]]
        if distance == "absolute":
            holes = [_absolute(x, y, radius, angle, cycle, column(first))]
        elif not cycle:
            holes = [_turned(x, y, radius, angle, column(first))]
        else:
            holes = []
            a, b = x, y
            for _ in range(max(repeat, 0)):
                a, b = _turned(a, b, radius, angle, column(first))
                holes.append((a, b))
        if not holes:  # L0: no hole, no move
            holes = [(x, y)]
        incremental = distance == "incremental"
        hx, hy = holes[0]
        block.words = _replaced(words, _clean(hx - x) if incremental else _clean(hx),
                                _clean(hy - y) if incremental else _clean(hy), drop_repeat=len(holes) > 1)
        for letter in POLAR:
            block.values.pop(letter, None)
        block.canonical = False
        if len(holes) == 1:
            return
        block.changed()  # one block of the source becomes several: written from its words everywhere
        for (ax, ay), (bx, by) in zip(holes, holes[1:]):
            yield Block(block.line, None, block.eol, [("X", spell_number(_clean(bx - ax))),
                                                      ("Y", spell_number(_clean(by - ay)))])


def _copied(ctx: Context) -> bool:
    """The program goes to LinuxCNC itself as written: a copy (``program_mode`` 'keep') in which nothing runs and
    which is no dry run of a translation elsewhere (``postproc.api._keep_check``, which must find that another
    target cannot take a computed polar word)."""
    return (ctx.program_mode == "keep" and RUN_INTERPRETER_KEY not in ctx.run_data
            and not ctx.run_data.get("dry_run"))


def _kept_as_written(block: Block, ctx: Context, kept: dict[str, Expr]) -> None:
    """A polar line of a copy whose end point is known only where LinuxCNC runs it (module docstring): its text
    goes out as written (``NativeCode``, which only LinuxCNC writes), and its polar pair is read as X and Y
    words whose values are the polar words' expressions (``kept``; X the first, Y the last): every later step
    sees an end point computed when the program runs, as for ``X[#1]`` (the tool's X and Y unknown after it, a
    cycle's holes kept verbatim), and the line's other words are read as ever. Nothing evaluates those values:
    the program is kept, not run."""
    given = [kept[letter] for letter, _ in block.words if letter in kept]
    texts = [num for letter, num in block.words if letter in kept]
    out: list[tuple[str, str]] = []
    for letter, num in block.words:
        if letter not in POLAR:
            out.append((letter, num))
        elif num == texts[0] and not any(a == "X" for a, _ in out):
            out.extend((("X", texts[0]), ("Y", texts[-1])))
    block.words = out
    values = block.values
    for letter in POLAR:
        values.pop(letter, None)
    values["X"], values["Y"] = given[0], given[-1]
    block.add(NativeCode(ctx.dialect, "a polar end point known only when the program runs", block.text or ""))


def _replaced(words: list[tuple[str, str]], x: float, y: float, drop_repeat: bool) -> list[tuple[str, str]]:
    """The words with the polar pair replaced by X and Y where the first of them stood."""
    out: list[tuple[str, str]] = []
    placed = False
    for letter, num in words:
        if letter in POLAR:
            if not placed:
                out.append(("X", spell_number(x)))
                out.append(("Y", spell_number(y)))
                placed = True
        elif not (drop_repeat and letter.upper() == "L"):
            out.append((letter, num))
    return out


def _columns(block: Block, ctx: Context) -> Callable[..., Location]:
    """``column(letter, nth=1)``: where a word of ``block`` is, for errors (worked out only then)."""
    def column(letter: str, nth: int = 1) -> Location:
        if letter in POLAR:
            code = _code(block.text or "")
            at = -1
            for _ in range(nth):
                at = code.find(letter, at + 1)
            return ctx.at(block, at + 1 if at >= 0 else 1)
        return ctx.at(block, ctx.column_of(block, letter, nth=nth))
    return column


def has_polar_words(text: str) -> bool:
    """The line has a polar word outside its comments (``_code``), where rs274 reads one; an ``@`` or ``^`` in a
    comment is text (``LinuxcncWriter.normalized``)."""
    code = _code(text)
    return "@" in code or "^" in code


def renumbered(text: str, number: int) -> str:
    """``text`` (a polar line written as read) with block number ``number`` in place of its own, or before its
    first word after a block delete ``/`` where it has none (rs274 reads N first only)."""
    own = next(((col, num) for col, letter, num in word_columns(text) if letter in "Nn"), None)
    if own is not None:
        found = re.compile(r"[Nn][ \t]*" + re.escape(own[1])).match(text, own[0] - 1)
        if found is not None:
            return text[:found.start()] + f"N{number}" + text[found.end():]
    lead = 1 if text.startswith("/") else 0
    return text[:lead] + (" " if lead else "") + f"N{number} " + text[lead:].lstrip()


def _code(text: str) -> str:
    """``text`` with its comments blanked (columns kept): a ``@`` in a comment is no word."""
    out: list[str] = []
    inside = False
    for n, ch in enumerate(text):
        if ch == ";" and not inside:
            return "".join(out) + " " * (len(text) - n)
        if ch == "(":
            inside = True
        out.append(" " if inside else ch)
        if ch == ")":
            inside = False
    return "".join(out)
