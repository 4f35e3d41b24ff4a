"""LinuxCNC writer: the RS274 word writer spelling every code from LinuxCNC's table (G0, M3, G4 P seconds).

* G4 P and a cycle's P are seconds; the repeat count of a native cycle is L.
* No G44: unsupported. No one-shot exact stop (G9): the lowering writes G61 for the block (``exact_stop``). A program number is a comment until the main
  program's end (M2/M30) is written, ``O<n>`` after it (a subprogram start, as rs274 reads it); from a
  LinuxCNC source every ``O<n>`` stays one.
* A subprogram call sharing the caller's locals (``Call(kind="sub")``) is ``M98 P<n> [L<k>]``, alone on
  its line (rs274 refuses M98 with other words: the call is unsupported then), and a plain return
  ``M99``; a return to a block number (``M99 P``) is unsupported.
* Another dialect's subprograms keep their numbers and names (names in lower case), decided once for the
  definition and every call (``SubprogramNames``). rs274 runs an ``O<n>`` .. ``M99`` program only by
  ``M98`` and an ``o<n> sub`` only by ``o<n> call`` (``postproc.interp.rules``): a Fanuc program called
  by ``G65`` (a macro call, ``o<n> call``) is written ``o<n> sub`` .. ``o<n> endsub``, its ``M99`` as
  ``o<n> return``; one program called both ways is unsupported.
* An o-word call from grblHAL gives every argument it does not give as the caller's ``[#k]``: grblHAL hands the
  callee the caller's values there, rs274 0 (``INHERITING_SOURCES``).
* Work offsets 7-9 are G59.1-G59.3; inverse-time feed is G93; M19 takes its angle as R.
* A comment from another dialect never becomes an active one: ``( MSG, x)`` read from Fanuc or ISG is
  written ``(- MSG, x)`` (``active_comments.COMMENTS``, ``FOREIGN_COMMENTS``); from LinuxCNC it is the program's own.
* F in a block that changes units is written in the old units (LinuxCNC sets the feed first).
* Parameters, expressions and o-words (``SPELLING``, ``statement_words``): a computed word is written
  in LinuxCNC's spelling (``X[#1*2.]``), an assignment as ``#1=5.``, a control statement as its o-word
  line (``o100 while [#1 LT 3.]``, ``o<probe> call [1.] [#2]``). What an o-word cannot say (a ``GOTO``,
  Fanuc's ``IF .. THEN``, a call that shares the caller's locals or repeats, a modal call) is an
  ``UnsupportedError`` naming the construct.
* A native cycle is written from its words as programmed. Only cycles resolved under RS274/NGC rules
  arrive here native: the lowering expands every other family's cycle exactly (``CYCLE_SEMANTICS``),
  because LinuxCNC's start-below-R, G98 and G91 R rules would move differently.
"""

from __future__ import annotations

import copy
from typing import Any, ClassVar, Iterable, Mapping, TextIO, cast

from postproc.errors import Location, UnsupportedError
from postproc.ir import Block, Comments, ProgramControl, Section
from postproc.context import Context
from postproc.dialect import Dialect
from postproc.interp.control import (
    Assign, Break, Call, Continue, Do, DoWhile, Else, ElseIf, EndFor, EndIf, EndRepeat, EndWhile, For, If, Repeat,
    Return, SubEnd, SubStart, While,
)
from postproc.ir.expr import Binary, Expr, Num, Var
from postproc.rs274.codes import CodeTable
from postproc.rs274.expressions import LINUXCNC_SPELLING, ExprSpelling
from postproc.rs274.writer import WordWriter
from postproc.output.line_feeds import LineFeeds
from postproc.interp.subprogram_names import NameRule, SubprogramNames
from postproc.syntaxes.comments import CommentSyntax

from .active_comments import COMMENTS, semicolon_comment
from .codes import CODES


_AFTER_ORIENT = frozenset({"SpindleOrientation", "Coolant", "ProgramControl"})
"""What a block does after its spindle orientation (the toolpath's order): coolant off and a stop or end."""
_WITH_ORIENT = frozenset({"Sequence", "BlockDelete", "Comments", "SpindleOrientation", "ProgramControl"})
"""What M19 shares a block with in LinuxCNC without changing the order of events (no split needed)."""

_COMP_LOCKED = frozenset({"ToolLengthOffset", "WorkOffset", "ReturnLevel", "Plane"})
"""What rs274 refuses to change while cutter compensation is on."""
_OPENING = (While, If, Do, Repeat)
_CLOSING = (EndWhile, EndIf, DoWhile, EndRepeat)
_LABELLED = (*_OPENING, *_CLOSING, ElseIf, Else, Break, Continue)
NAMES = NameRule(numbers=range(0, 2**31), spare=range(0), names=True, lower_case=True, one_kind=True)
"""o-word numbers and ``<names>`` (rs274 lower-cases a line outside its comments); the kind of call
fixed by the definition (``postproc.interp.rules``)."""



CALL_ARGUMENTS = 30
"""``#1``-``#30``: what an o-word call may set."""
INHERITING_SOURCES = frozenset(("grblhal",))
"""Sources whose o-word call hands the callee the caller's ``#k`` for an argument it does not give, where rs274
reads 0: grblHAL fills ``#n+1``-``#30`` with ``ngc_param_get`` in the caller's context before it opens the
callee's [V: grblHAL core ``ngc_flowctrl.c`` ``NGCFlowCtrl_Call``, stored commit f80fc34]."""


def inherited_arguments(call: Call) -> Call:
    """``call`` with every argument it does not give written as the caller's parameter (``[#k]``: rs274
    evaluates a call's arguments in the caller's level), so the callee reads what an inheriting source's does."""
    if call.kind != "macro" or len(call.args) >= CALL_ARGUMENTS:
        return call
    given = dict(call.args)
    for k in range(1, CALL_ARGUMENTS + 1):
        given.setdefault(k, Var(Num(float(k))))
    return Call(call.name, given, call.repeat, call.kind)


class LinuxcncWriter(WordWriter):
    DIALECT: ClassVar[str] = "linuxcnc"
    CODES: ClassVar[CodeTable] = CODES
    WORK_OFFSET_SETTING: ClassVar[str] = "G10 L2"
    """G10 L2 P1-P9 sets work system P's offset, absolutely (G91 does not change it)."""
    WORK_OFFSET_COUNT: ClassVar[int] = 9
    TOOL_DATA_SETTINGS: ClassVar[Mapping[str, tuple[str, int, str]]] = {
        "tool_length": ("G10 L1", 2**31 - 1, "Z"), "cutter_offset": ("G10 L1", 2**31 - 1, "R")}
    """Another family's length and radius registers (Fanuc memory C's H and D geometry) as the tool table
    entry of that number, whose Z ``G43 H`` and whose R ``G41 D`` read (``tool_entry``: [V] LinuxCNC
    g-code.adoc "G10 L1"); absolute whatever the distance mode. A wear register has no column here."""
    TOOL_DATA_IN_TABLE: ClassVar[bool] = True
    """[V] rs274: ``G10 L1 P5 Z1`` with no tool 5 in its table is "Requested tool 5 not found in the tool table"
    (``convert_setup_tool`` looks the tool up first): the set-up's ``<Tools>`` stand for that table."""
    """G76 threads, G87/G88 take other words: no row spells Fanuc's fine, back or manual boring."""
    FOREIGN_COMMENTS: ClassVar[CommentSyntax | None] = COMMENTS
    """Another dialect's comment text is written as a comment that does not act (LinuxCNC reads ``(MSG,``,
    ``(LOGOPEN,``, ``(ABORT,`` ... as instructions: ``active_comments.WORDS``)."""
    DWELL_WORD: ClassVar[str] = "P"
    CYCLE_CANCEL_IS_MOTION: ClassVar[bool] = True
    """G80 is a motion code here: ``G80 G0`` is refused, a block's G0-G3 ends the cycle by itself."""
    BARE_FEED_MOTION_NEEDS_FEED: ClassVar[bool] = True
    SPELLING: ClassVar[ExprSpelling | None] = LINUXCNC_SPELLING
    STRUCTURE: ClassVar[frozenset[str]] = frozenset(("TapeMark", "ProgramStart", "ProgramControl"))
    """A tape mark opens or closes the program, or is a lone one; a program start or tape mark ends the
    ``o<n> sub`` body being written; a program end is noted (a program number after it starts a subprogram)."""
    SPLIT: ClassVar[frozenset[str]] = frozenset(("CutterCompensation", "SpindleOrientation"))
    """Compensation turned on beside settings rs274 refuses to change under it, and M19 beside other actions
    (``split_block``)."""
    PER_REV_NEEDS_SPEED: ClassVar[str] = ("a feed move in feed per revolution (G95) with no spindle speed (rs274: \"Cannot "
                                          "feed with zero spindle speed in feed per rev mode\"; program S first)")
    ZERO_RADIUS_ARC: ClassVar[str] = "rs274 refuses it: \"Zero-radius arc\""
    MIN_ARC_RADIUS: ClassVar[tuple[float, float]] = (0.001, 0.00004)
    """rs274 refuses a centre-form arc whose radius to its start or end is below MIN_CENTER_ARC_RADIUS_TOLERANCE
    (0.001 mm, 0.00004 in) [V: interp_internal.hh, interp_arc.cc arc_data_ijk; a fuzz case: I0.001 refused]."""

    def __init__(self, ctx: Context, source_dialect: str, target: type[Dialect] | None = None) -> None:
        super().__init__(ctx, source_dialect, target)
        self.inverse_time = False
        self._open: dict[str, list[str]] = {}
        """Source label -> the o-word labels written for its open constructs, innermost last."""
        self._taken: set[str] = set()
        """O-word labels and subprogram names written so far."""
        self._counter = 0
        self._ended = False
        """The main program's end was written: an ``O<n>`` now starts a subprogram."""
        self._cutter_on = False
        """Cutter compensation is on (rs274 refuses turning it on again, and G28/G30 under it)."""
        self._cutter_before = False
        self._cutter_register: Any = None
        """The register of the last G41/G42 written (another dialect's G41 without D takes it)."""
        """Whether compensation was on before the block whose compensation word was written last."""
        self._whole = False
        """An orientation split's part is being written: it is one line (``split_block``)."""
        self._closed = False
        """A '%' closed the program opened with one (rs274 then needs no M2/M30)."""
        self._opened_late = False
        """The source's opening '%' came after a blank line (the Fanuc reader runs the program from it, issue 26:
        hand-written Haas programs start so) and was written as a comment: rs274 takes a '%' as the opening one
        only on the file's first line, so a later '%' closes nothing."""
        self._feeds: LineFeeds | None = None
        """The output (``write``); once it ``wrote`` a line (a comment) before any '%', a '%' is no opening
        one: rs274 takes a '%' as the opening one only on the file's first line, and refuses it anywhere
        else ("Bad character '%' used") [V: rs274 2.9, found by make fuzz]. Followed on the output, not in
        ``write_block``, which the straight lane of plain blocks needs unchanged (``postproc.fast.lane``)."""
        self.names = SubprogramNames(NAMES)
        """Another dialect's subprograms: their o-word names and how each is called."""
        self._body: str | None = None
        """Another dialect's numbered program being written as ``o<n> sub`` (it ends at the next program
        start or tape mark, or at the end of the output)."""
        self._counted: dict[str, tuple[Var, float]] = {}
        """Source label of an open counted loop -> its counter and step."""

    def comments_words(self, s: Any, block: Block) -> list[str]:
        """The block's comments (``comment``), a LinuxCNC line's ``;`` comment kept one (``semicolon_comment``)."""
        texts: list[str] = s.texts
        tail = None if self.comment_rule is not None else semicolon_comment(s)
        if tail is None:
            return [self.comment(t) for t in texts]
        return [*(self.comment(t) for t in texts[:-1]), tail]

    def cutter_compensation_words(self, s: Any, block: Block) -> list[str]:
        """rs274 turns compensation on only from off ("Cannot turn cutter radius comp on when on"): G41/G42
        while it is on would need a G40 between them, which moves differently."""
        if s.mode != "off" and self._cutter_on:
            self.unsupported(f"cutter compensation {s.mode} while compensation is on (rs274 needs G40 first: "
                             "\"Cannot turn cutter radius comp on when on\")", block)
        plane = block.sections.get("Plane")
        if s.mode != "off" and (plane.plane if plane is not None else self.modal.plane) == "YZ":  # type: ignore[attr-defined]
            self.unsupported(f"cutter compensation {s.mode} in the YZ plane (rs274: \"Cutter radius compensation "
                             "allowed only in XY, XZ planes\")", block)
        self._cutter_before = self._cutter_on
        self._cutter_on = s.mode != "off"
        if s.mode != "off" and s.register is None:
            s = self._cutter_register_in_force(s, block)
        elif s.mode != "off":
            self._cutter_register = s.register
        return super().cutter_compensation_words(s, block)

    def _cutter_register_in_force(self, s: Any, block: Block) -> Any:
        """Another dialect's G41/G42 without D compensates by the register in force (Fanuc: D is modal [K]);
        LinuxCNC's G41 without D takes the spindle tool's radius instead, so the register is written: the
        last one written, or none known (refused). A LinuxCNC source names it already (its reader fills in
        the spindle tool)."""
        if self._cutter_register is None:
            self.unsupported(f"cutter compensation {s.mode} without its register, before any register was "
                             "programmed (LinuxCNC's G41/G42 without D takes the radius of the tool in the "
                             "spindle; program D)", block)
        named = copy.copy(s)
        named.register = self._cutter_register
        return named

    def plane_words(self, s: Any, block: Block) -> list[str]:
        if self._cutter_on and s.plane != self.modal.plane:
            self.unsupported(f"a change to the {s.plane} plane with cutter compensation on (rs274: \"Cannot change "
                             "planes with cutter radius compensation on\")", block)
        return super().plane_words(s, block)

    def check_reference_return(self, s: Any, block: Block) -> None:
        if self._cutter_on:
            self.unsupported("G28/G30 with cutter compensation on (rs274: \"Cannot use g28 or g30 with cutter "
                             "radius comp\")", block)

    WRITES_PATH_TOLERANCE: ClassVar[bool] = True
    """``G64 P.. Q..`` (``path_control_words``)."""

    def path_control_words(self, s: Any, block: Block) -> list[str]:
        """``G64 P.. Q..`` with the blending tolerances the program gave (``block_syntax``)."""
        words = super().path_control_words(s, block)
        if s.tolerance is not None:
            words.append("P" + self.length(s.tolerance, block, "P"))
        if s.naive is not None:
            words.append("Q" + self.length(s.naive, block, "Q"))
        return words

    def rigid_tap_words(self, s: Any, block: Block) -> list[str]:
        """``G33.1 Z.. K..`` (``postproc.lowering.synchronised_tap``): the end point, K the pitch, I the way out's
        speed factor. Inside an expansion the end point is absolute (G90 first, when incremental). G33.1 has
        no dwell at the bottom [V: g-code.adoc, the tap reverses on reaching the end point]."""
        if s.dwell:
            self.unsupported("a rigid tap with a dwell at the bottom (G33.1 reverses at once)", block)
        if self._cutter_on:
            self.unsupported("a rigid tap with cutter compensation on", block)
        words: list[str] = []
        if self.expanding and self.modal.distance != "absolute":
            words.append(self.code("distance", "absolute", "absolute distance mode", block))
            self.modal.distance = "absolute"
        incremental = not self.expanding and self.modal.distance == "incremental"
        words.append(self.code("motion", "rigid_tap", "rigid tapping", block))
        for axis, value in s.axes.items():
            words.append(axis + (self.expression(value, block) if isinstance(value, Expr)
                                 else self.position(axis, value, incremental)))
        words.append("K" + self.length(s.pitch, block, "K"))
        if s.speedup is not None:
            words.append("I" + self.number(s.speedup))
        return words

    def machine_coordinates_words(self, s: Any, block: Block) -> list[str]:
        distance = block.sections.get("DistanceMode")
        mode = distance.mode if distance is not None else self.modal.distance  # type: ignore[attr-defined]
        if mode == "incremental" and "Motion" in block.sections:
            self.unsupported("a move in machine coordinates in incremental mode (rs274: \"Cannot use g53 "
                             "incremental\")", block)
        return super().machine_coordinates_words(s, block)

    def feed_mode_words(self, s: Any, block: Block) -> list[str]:
        """LinuxCNC sets the feed rate to zero at every G93/G94/G95, even one that selects the mode in
        force (rs274: ``F100`` then ``G94 G1 Z-3`` is "Cannot do g1 with zero feed rate"): the feed rate in
        force is written again beside it, as the source goes on using it."""
        self.inverse_time = s.mode == "inverse_time"
        words = super().feed_mode_words(s, block)
        feed = self.modal.feed
        if (not self.inverse_time and isinstance(feed, (int, float)) and feed
                and "Feed" not in block.sections and "Units" not in block.sections):
            words.append("F" + self.feed_number(feed, block))
        return words

    def statement_words(self, section: Section, block: Block) -> list[str]:
        """``#1=5. #<x>=[#1+2.]`` (``spell_assignments``) or one o-word line (``spell_oword``)."""
        from postproc.rs274.oword import spell_assignments, spell_oword  # (at the first statement: a CAM program has none)
        try:
            if isinstance(section, Assign):
                return [spell_assignments(section)]
            if isinstance(section, Call) and section.kind == "sub":
                return self.subprogram_call(section, block)
            if isinstance(section, Return) and section.name is None and section.value is None:
                if section.target is not None:
                    self.unsupported("a return to a block number (M99 P: rs274 refuses it)", block)
                self._alone("M99", block)
                return ["M99"] if self._body is None else [f"o{self._body} return"]
            if isinstance(section, (For, EndFor)):
                return self.counted_loop(section, block)
            if self.source_dialect != self.DIALECT:
                section = self._relabel(section, block)
            if isinstance(section, Call) and self.source_dialect in INHERITING_SOURCES:
                section = inherited_arguments(section)
            return [spell_oword(section)]
        except UnsupportedError as err:
            if err.location is None:
                err.located(self.ctx.at(block))
            raise

    def counted_loop(self, section: For | EndFor, block: Block) -> list[str]:
        """A counted loop (ISG ``$FOR``) as its counter set before ``o<n> while [#i LE end]`` and grown
        before ``o<n> endwhile``: exact when the end and the step are constants (a computed one would be
        evaluated on every pass instead of once), and the step is not 0."""
        from postproc.rs274.oword import spell_assignments, spell_oword
        eol = block.eol or "\n"
        if isinstance(section, For):
            step, end = section.step, section.end
            if not (isinstance(step, Num) and step.value != 0.0 and isinstance(end, Num)):
                self.unsupported("a counted loop whose end or step is computed or whose step is 0 (a while "
                                 "loop would evaluate it on every pass, the counted loop once)", block)
            assert isinstance(section.counter, Var)  # For's constructor holds it
            test = Binary("le" if step.value > 0 else "ge", section.counter, end)
            head = spell_oword(self._relabel(While(section.label, test), block))
            self._counted[section.label] = (section.counter, step.value)
            return [spell_assignments(Assign([(section.counter, section.start)])) + eol + head]
        if section.label not in self._counted:
            self.unsupported(f"the end of loop {section.label!r}, which no written loop opened", block)
        counter, step_value = self._counted.pop(section.label)
        grow = spell_assignments(Assign([(counter, _grown(counter, step_value))]))
        return [grow + eol + spell_oword(self._relabel(EndWhile(section.label), block))]

    def subprogram_name(self, name: str, kind: str, what: str, block: Block) -> str:
        """Another dialect's subprogram ``name`` as written here, for a definition or call of ``kind``
        (``SubprogramNames``: a name in lower case; an ``o<n> sub`` only by ``o<n> call``...)."""
        try:
            target = self.names.use(name, kind, f"{what} on line {block.line}")
        except UnsupportedError as err:
            self.unsupported(err.message, block)
        self._taken.add(target)
        return target

    def _relabel(self, section: Section, block: Block) -> Section:
        """A fresh o-word label for every loop or condition translated from another dialect: LinuxCNC refuses a
        label opened twice ("duplicate O-word label"), where Fanuc reuses ``DO1`` for every loop at one depth. Closing,
        ``elseif``/``else`` and ``break``/``continue`` lines take the label of the construct they belong to."""
        if isinstance(section, (SubStart, SubEnd, Call)):
            if isinstance(section.name, str):
                what = "the call" if isinstance(section, Call) else "the definition"
                target = self.subprogram_name(section.name, "macro", what, block)
                if target != section.name:
                    section = copy.copy(section)
                    section.name = target
            return section
        if not isinstance(section, _LABELLED):
            return section
        label = section.label
        stack = self._open.setdefault(label, [])
        if isinstance(section, _OPENING):
            self._counter += 1
            while str(self._counter) in self._taken:
                self._counter += 1
            fresh = str(self._counter)
            self._taken.add(fresh)
            stack.append(fresh)
        elif not stack:
            self.unsupported(f"an o-word line closing {label!r}, which no written line opened", block)
        else:
            fresh = stack[-1]
            if isinstance(section, _CLOSING):
                stack.pop()
        renamed = copy.copy(section)
        renamed.label = fresh
        return renamed

    def subprogram_call(self, call: Call, block: Block) -> list[str]:
        """``M98 P<n> [L<k>]``: no arguments (they would set locals the caller shares)."""
        if call.args:
            self.unsupported("a subprogram call with arguments (M98 passes none)", block)
        self._alone("M98", block)
        name = call.name
        if isinstance(name, str):
            if not name.isdigit():
                self.unsupported(f"a call of the named subprogram {name} with M98 (it calls program numbers)", block)
            if self.source_dialect != self.DIALECT:
                name = self.subprogram_name(name, "sub", "the subprogram call (M98)", block)
            words = ["M98", "P" + str(int(name))]
        else:
            words = ["M98", "P" + self._count(name, block)]
        if call.repeat is not None:
            words.append("L" + self._count(call.repeat, block))
        return words

    def _count(self, value: Expr, block: Block) -> str:
        """A P or L value: a whole number without a point (rs274 reads ``L2.`` too, but this is what
        it prints), else the expression."""
        if isinstance(value, Num) and value.value.is_integer() and value.value >= 0:
            return str(int(value.value))
        return self.expression(value, block)

    def _alone(self, code: str, block: Block) -> None:
        """rs274 runs M98 and M99 only alone on their line (an N and comments aside)."""
        others = [key for key in block.sections if key not in ("Control", "Sequence", "Comments")]
        if others:
            self.unsupported(f"{code} sharing its line with other words ({', '.join(others)}): rs274 refuses it",
                             block)

    def write(self, blocks: Iterable[Block], out: TextIO) -> None:
        """Through ``LineFeeds``: a source's lone CR line ends (kept as read) are written as LF, as rs274 ends a
        line at LF only, so a CR-only file is one long line it refuses ("Command too long") [V: rs274 2.9, found
        by make fuzz]; CR LF it reads."""
        self._feeds = LineFeeds(out)
        super().write(blocks, cast(TextIO, self._feeds))

    def normalized(self, block: Block) -> str:
        """A line with polar coordinates (``@``, ``^``) is written as read: its words were replaced by the X and
        Y of the point they reach from where the tool stood when the line was read (``polar``), which is that
        point only where the line runs once from there; in a loop each pass turns further (LinuxCNC's own
        ``spiral.ngc``, ``o100 repeat [800]`` of ``G91 G1 @-.0025 ^4.5``, was normalized to one fixed step, a
        straight line, exit 0). Under ``--renumber`` only its block number changes (``polar.renumbered``): rewritten
        from those words, the line in a loop moved by one fixed step on every pass (rs274 run here). An ``@`` or
        ``^`` inside a comment is text, not a polar word (``has_polar_words``): before, such a line was not normalized, and
        under ``--renumber`` a comment-only, o-word or ``%`` line got a block number."""
        text = block.text
        if text is not None and ("@" in text or "^" in text):
            from .polar import has_polar_words, renumbered  # (loaded for such a line only)
            if has_polar_words(text):
                if not self.renumber:
                    return text.strip()
                return renumbered(text.strip(), self.take_number(block))
        comments = cast("Comments | None", block.sections.get("Comments"))
        tail = None if comments is None or self.comment_rule is not None else semicolon_comment(comments)
        if comments is None or tail is None:
            return super().normalized(block)
        texts = comments.texts
        comments.texts = texts[:-1]  # (the base writes the others, last on the line)
        try:
            line = super().normalized(block)
        finally:
            comments.texts = texts
        return line + " " + tail if line else tail

    def structure_block(self, block: Block) -> str | None:
        sections = block.sections
        if self._body is not None and ("TapeMark" in sections or "ProgramStart" in sections):
            ended = self._end_body()
            return ended + (self.write_block(block) or "")
        if "TapeMark" in sections:
            lines_before = self._feeds is not None and self._feeds.wrote
            blank_before = lines_before and self._feeds is not None and not self._feeds.content
            if self.opening is None and blank_before and not self._ended and self.source_dialect != self.DIALECT:
                # Another dialect's opening '%' after blank lines only (a comment before it begins the program,
                # and the '%' then ends it, as the simulation has it): it opens the program
                # there, so it is no end; rs274 would refuse it off the first line, so it becomes a comment.
                self._opened_late = True
                return self.comment("%") + (block.eol or "\n")
            if (self.opening is False or self._opened_late or self.opening is None and lines_before) \
                    and not self._ended:
                return self._lone_tape_mark(block)
            self._closed = self.opening is True  # a '%' after the opening one
        if self.normalize and block.text is not None and not block.words and "ProgramStart" in sections \
                and self.source_dialect == self.DIALECT:
            # A Fanuc-style program number (``O1``, the start of an ``M98`` subprogram) is read into its section
            # with no words, from which a normalized line is written: it was written as a comment ("nothing in
            # this block has a meaning"), so the ``M98 P1`` before it found no subprogram, exit 0. As read, from
            # a LinuxCNC source only: another dialect's start is its own text (an ISG ``% NAME`` header, which
            # rs274 refuses off the first line: "Bad character '%' used", found by make fuzz), so it is written
            # as without --normalize (``program_start``).
            return block.text.strip() + (block.eol or "\n")
        text = super().structure_block(block)
        end = sections.get("ProgramControl")
        if end is not None and end.kind in ("end", "end_rewind"):  # type: ignore[attr-defined]
            self._ended = True
        return text

    def _lone_tape_mark(self, block: Block) -> str:
        """A closing ``%`` with no opening one and no program end before it: rs274 refuses it ("Bad
        character '%' used"), and the opening line is long written. The program ends there, so M2 ends
        it (rs274 refuses a file that runs out without an end too) and the ``%`` becomes a comment."""
        self.ctx.diagnostics.warn("the program ends with '%' and no M2/M30, without an opening '%': LinuxCNC "
                                  "refuses a lone '%': M2 written for it, the '%' as a comment", self.ctx.at(block))
        return self._end(block.line) + self.comment("%") + (block.eol or "\n")

    def finish(self) -> str:
        """A program that runs out with neither M2/M30 nor a closing ``%`` after an opening one: rs274 refuses
        it ("File ended with no percent sign or program end"; LinuxCNC's G-code overview says a file ends
        with a program end or lies between two ``%`` lines [V, rs274 2.9]). The program ends there, so M2
        is written (with a warning), and a ``%`` after it where one opened the program. A LinuxCNC source
        is written back as it is (lossless: it is the user's own file). A subprogram body written as
        ``o<n> sub`` (a macro call's) still open at the end is closed first."""
        closing = self._end_body() if self._body is not None else ""
        if self._ended or self._closed or self._failed() or self.source_dialect == self.DIALECT:
            return closing
        self.ctx.diagnostics.warn("the program has no end (M2/M30): M2 written after its last block, as LinuxCNC "
                                  "refuses a program that runs out", Location(self.ctx.file, max(self.last_line, 1)))
        return closing + self._end(self.last_line) + ("%\n" if self.opening and not self._opened_late else "")

    def _end(self, line: int) -> str:
        """The program end a source without one gets (M2: an end that does not rewind)."""
        end = Block(line, None, "\n")
        end.sections = {"ProgramControl": ProgramControl("end")}
        return self.write_block(end) or ""

    def _settings_first(self, block: Block) -> str:
        """A block that turns compensation on and also changes what rs274 refuses to change under it (tool
        length offset, work system, retract mode, plane): rs274 runs compensation first (order of execution
        15 before 16-18), so those settings go in a block of their own before it, where both orders agree."""
        first = Block(block.line, None, "\n")
        first.sections = {k: v for k, v in block.sections.items() if k in _COMP_LOCKED or k == "BlockDelete"}
        rest = Block(block.line, None, block.eol)
        rest.sections = {k: v for k, v in block.sections.items() if k not in _COMP_LOCKED}
        return self.generate(first) + self.generate(rest)

    def _locked(self, what: str, block: Block) -> None:
        """rs274 refuses to change ``what`` while cutter compensation is on."""
        if self._cutter_on:
            self.unsupported(f"a change of {what} with cutter compensation on (rs274 refuses it: program G40 "
                             "first)", block)

    def tool_length_offset_words(self, s: Any, block: Block) -> list[str]:
        self._locked("tool length offset", block)
        return super().tool_length_offset_words(s, block)

    def tool_change_words(self, s: Any, block: Block) -> list[str]:
        """rs274: "Cannot change tools with cutter radius compensation on". It changes the tool before it
        runs the block's G40/G41/G42 (order of execution 6 before 15): what counts is compensation before
        the block (``G40 M6`` under compensation is refused, ``G41 M6`` from off is not)."""
        on = self._cutter_before if "CutterCompensation" in block.sections else self._cutter_on
        if on:
            self.unsupported("a tool change (M6) with cutter compensation on (rs274 changes the tool before it "
                             "runs the block's G40: \"Cannot change tools with cutter radius compensation on\"; "
                             "program G40 in a block before)", block)
        return super().tool_change_words(s, block)

    def work_offset_words(self, s: Any, block: Block) -> list[str]:
        self._locked("work coordinate system", block)
        return super().work_offset_words(s, block)

    def return_level_words(self, s: Any, block: Block) -> list[str]:
        self._locked("canned-cycle retract mode", block)
        return super().return_level_words(s, block)

    def _end_body(self) -> str:
        text = f"o{self._body} endsub\n"
        self._body = None
        return text

    def program_start(self, s: Any, block: Block) -> str:
        """``O<n>`` after the main program's end (a subprogram start, as rs274 reads it) or from a
        LinuxCNC source; else a comment: in the flow an ``O`` line does nothing, and leaving the
        program number out keeps a later ``M98`` from finding it. Another dialect's program called by a
        macro call (Fanuc ``G65``) starts ``o<n> sub`` instead (rs274 runs an ``O<n>`` only by ``M98``)."""
        if s.number is not None and self._ended and self.source_dialect != self.DIALECT:
            name = str(int(s.number))
            if self.names.kind(name) == "macro":
                self._body = self.subprogram_name(name, "macro", "the definition", block)
                return f"o{self._body} sub"
            return "O" + self.subprogram_name(name, "sub", "the definition", block)
        if s.number is not None and (self._ended or self.source_dialect == self.DIALECT):
            return f"O{int(s.number)}"
        name = f"O{int(s.number):04d}" if s.number is not None else str(s.name)
        return self.comment(name)

    def block_delete_words(self, s: Any, block: Block) -> list[str]:
        if s.level != 1:
            self.unsupported(f"block delete level {s.level} (LinuxCNC has one block delete switch)", block)
        return ["/"]

    def split_block(self, block: Block) -> str | None:
        """M19 in a block of its own after the block's other actions: LinuxCNC orients before it runs the
        block's spindle codes (the same modal group: ``M5 M19`` is refused), dwell and motion, and reads its
        ``R`` as the angle (so an R arc, a cycle's R or I/J/K beside it are refused); the neutral order is
        the other way round. What the block does after the orientation (coolant off, a stop) follows it.
        Compensation turned on beside what it locks: those settings first (``_settings_first``)."""
        if self._whole:
            return None
        sections = block.sections
        comp = sections.get("CutterCompensation")
        if comp is not None and comp.mode != "off" and not _COMP_LOCKED.isdisjoint(sections):  # type: ignore[attr-defined]
            return self._settings_first(block)
        if "SpindleOrientation" not in sections or "CompoundMotion" in sections or sections.keys() <= _WITH_ORIENT:
            return None
        first = Block(block.line, None, block.eol or "\n")
        then = Block(block.line, None, block.eol)
        first.sections = {}
        then.sections = {k: v for k, v in sections.items() if k == "BlockDelete"}
        for key, section in sections.items():
            after = key in _AFTER_ORIENT and (key != "Coolant" or section.mode == "off")  # type: ignore[attr-defined]
            (then if after else first).sections[key] = section
        if not first.sections:
            return self._one_line(block)  # M19 then coolant off or a stop: LinuxCNC's own order
        return self._one_line(first) + self._one_line(then)

    def _one_line(self, block: Block) -> str:
        """``block`` written without a split."""
        self._whole = True
        try:
            return self.generate(block)
        finally:
            self._whole = False

    def spindle_orientation_words(self, s: Any, block: Block) -> list[str]:
        """M19 R<angle>: a bare M19 leaves the angle to the machine's default."""
        return [self.code("orient", None, "an oriented spindle stop", block), "R" + self.length(s.angle, block)]


def _grown(counter: Var, step: float) -> Binary:
    """The counter after one pass: ``#i+step`` or ``#i-|step|``."""
    return Binary("add", counter, Num(step)) if step > 0 else Binary("sub", counter, Num(-step))
