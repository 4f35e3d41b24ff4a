"""grblHAL writer: the grbl family's writer (``postproc.grbl_family.writer``: ``%`` and O-numbers as comments,
M19 per the set-up, a pause that stops the spindle, G43 H from the tool table where the build has one) with
grblHAL's table.

* A native G81/G82 arrives only where it moves as its source's cycle (``cycles``): it is written with the
  words grblHAL needs. A block that programs the cycle code gets R, Z and (G82) P from the resolved cycle
  when its source carried them over: grblHAL carries nothing over from another cycle [V: ``gcode.c``,
  ``canned_cycle_change`` needs R, the drilling axis word, and P for G82]. Another dialect's words are
  written by their roles (a Fanuc dwell in milliseconds as seconds, its K as L).
* G80 is a motion code (grblHAL's ``MotionMode_None``): ``G80 G0`` is refused, and after it axis words need
  a motion code, even those of ``G43.1 Z`` [V: ``gcode.c``, "[G80 Errors]"; ``G28 Z`` is exempt, a non-modal
  axis command]. So a cancel is written only where a native cycle is in force, as the group-01 code the
  source returns to after it (``G0`` alone: grblHAL ends the cycle and moves nothing [V: ``gcode.c``, G0
  without axis words]; a cancel beside an axis command of its own stands alone before it, ``cancels``); a
  cancel with no native cycle in force writes nothing (the cycles before it arrived expanded).
* G64 writes nothing (path blending is off in every build: grblHAL runs the exact path, its one mode),
  with the tolerance it drops noted; G95 only for a spindle with an encoder (``<Controller spindleSync>``).
* ``/`` block delete is written: grblHAL skips the block when its switch is on.
* Parameters, expressions and o-word flow control, for a build with them (``<Controller expressions="true">``,
  ``program``): a computed word in LinuxCNC's spelling (``X[#1*2.]``), an assignment as ``#1=5.``, a condition
  or loop as its o-word line, from a grblHAL or LinuxCNC program (the same o-words: their labels are kept).
  Numbered subs too (``o100 sub``/``endsub``/``call``/``return``), where grblHAL runs them as the source does
  (``ngc_flowctrl.c`` [V]): a call after its sub's definition (grblHAL finds no sub it has not passed; rs274
  looks ahead), and from LinuxCNC with all 30 arguments written (``[0]`` for those not given: grblHAL hands
  the callee the caller's ``#k`` for an argument not given, rs274 reads 0: ``variables``). ``M98`` subprograms
  of a program that computes nothing arrive as subs from the lowering step ``subprograms``. The statements
  written go through the family's ``Structure`` under grblHAL's rules: a construct that would open entry 21 of
  grblHAL's flow control stack (``program.FLOW_STACK``), with what the subs it calls open, is refused there. A
  sub of another dialect's program that calls itself opens the stack again at each level, deeper only as it
  runs: its body counts as nested to the source's bound of nested calls (``recursion``), so a recursion that
  could reach entry 21 is refused (the program is flattened) and one that cannot is kept.
  Everything else that computes is an ``UnsupportedError`` (so the program reaches grblHAL flattened): any
  statement on a build without expressions, a named sub, and another family's control flow (Fanuc's
  ``WHILE .. DO1`` reuses its labels, ISG's ``$FOR``...).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar

from postproc.context import Context
from postproc.interp.control import Assign, Break, Call, Continue, Do, DoWhile, Else, ElseIf, EndIf, EndRepeat, EndWhile, \
    If, Repeat, Return, SubEnd, SubStart, While
from postproc.cycles.section import WORD_ORDER
from postproc.dialect import Dialect
from postproc.ir.expr import Expr, Num
from postproc.grbl_family.writer import GrblFamilyWriter
from postproc.ir import Block, Motion
from postproc.rs274.codes import CodeTable
from postproc.rs274.expressions import ExprSpelling
from postproc.syntaxes.program import SUBPROGRAM_RULES_KEY

from .cancels import GROUP_01
from .codes import CODES
from .program import FLOW_STACK, GRBLHAL_SPELLING, GrblhalProgramSyntax
from .subprograms import CONVERTED

if TYPE_CHECKING:
    from postproc.interp.rules import SubprogramRules
    from postproc.interp.structure import Structure

_FLOW = (If, ElseIf, Else, EndIf, While, EndWhile, Do, DoWhile, Repeat, EndRepeat, Break, Continue, SubStart, SubEnd,
         Return)
"""The o-word statements written as they are (a call: ``call_words``)."""
CALL_ARGUMENTS = 30
"""``#1``-``#30``: what an o-word call may set, all of them written for a LinuxCNC call."""
_SAME_OWORDS = frozenset(("grblhal", "linuxcnc"))
"""Sources whose o-word labels and meanings are grblHAL's (ngc_flowctrl.c is rs274's)."""

GRBLHAL_AXES = frozenset("XYZABC")
"""Axes a grblHAL build may drive (``N_AXIS`` up to 6 with A, B, C; a set-up may say fewer)."""


class GrblhalWriter(GrblFamilyWriter):
    DIALECT: ClassVar[str] = "grblhal"
    CODES: ClassVar[CodeTable] = CODES
    WORK_OFFSET_SETTING: ClassVar[str] = "G10 L2"
    """G10 L2 P1-P9 sets work system P's offset, absolutely (G91 does not change it)."""
    WORK_OFFSET_COUNT: ClassVar[int] = 9
    SETTING_AXES: ClassVar[frozenset[str]] = GRBLHAL_AXES
    DWELL_WORD: ClassVar[str] = "P"
    CYCLE_CANCEL_IS_MOTION: ClassVar[bool] = True
    """G80 is a motion code here: ``G80 G0`` is refused, a block's G0-G3 ends the cycle by itself."""
    BARE_FEED_MOTION_NEEDS_FEED: ClassVar[bool] = True
    DRIVEN_AXES: ClassVar[frozenset[str]] = GRBLHAL_AXES
    FULL_CIRCLE_HELIX: ClassVar[bool] = False
    """grblHAL's arcs need an end point in the plane, as grbl's (its ``gcode.c`` is grbl's)."""
    STRUCTURE: ClassVar[frozenset[str]] = frozenset(("TapeMark",))
    BLANK_AS_TRACE: ClassVar[bool] = True
    """G64 and the like are not grblHAL's: a block of nothing else is a trace of its source."""
    SPELLING: ClassVar[ExprSpelling | None] = GRBLHAL_SPELLING

    def __init__(self, ctx: Context, source_dialect: str, target: type[Dialect] | None = None) -> None:
        super().__init__(ctx, source_dialect, target)
        self.cycle_motion: str | None = None
        """The group-01 mode around the native cycle in force on the controller; None: none in force."""
        self.cycle_block: Block | None = None
        """The block whose cycle words set ``cycle_motion``, until ``after_block`` has seen it."""
        self.return_in_force: str | None = None
        """The return level (G98/G99) this program has written; None: none yet. A native cycle whose source set
        its level by the source's own power-on default (LinuxCNC's, no G98/G99 in the program) has it written
        (``canned_cycle_words``): grblHAL's default is not relied on (found by make fuzz: a LinuxCNC G82 without
        G98/G99 retracted to R in the source and to the initial level on grblHAL, exit 0)."""
        self.subs: set[str] = set()
        """The numbered subs whose definition is written (a call finds only those on grblHAL)."""
        self.body: str | None = None
        """The sub whose body is being written: registered on grblHAL before it runs, so it may call itself."""
        self.flow: Structure | None = None
        self.recursive: dict[str, int] = {}
        """A sub of another dialect's program that calls itself -> the entries its body holds at that call."""
        """The o-word statements written, nested as grblHAL nests them (its flow control stack); made at the
        first (the structure check imports the evaluator, which a program without statements never needs)."""

    def after_block(self, block: Block) -> None:
        """A motion code of group 01 ends the native cycle on grblHAL (``cycle_motion``): followed after each block
        written while a cycle is in force (``after_blocks``), but for the block that wrote the cycle itself (a
        block's cycle words leave their cycle in force whatever its motion). Following it here, not in an
        override of ``write_block``, leaves the writer the word writer's own ``write_block``, so a straight block
        takes the fast lane (``postproc.fast.lane``: grblHAL's every block went through the section dispatch)."""
        if self.cycle_block is block:
            self.cycle_block = None
        else:
            self.end_cycle(block)
        self.after_blocks = self.cycle_motion is not None

    def end_cycle(self, block: Block) -> None:
        """The block's group-01 motion code ends the native cycle in force."""
        motion = block.sections.get("Motion")
        if isinstance(motion, Motion) and motion.mode in GROUP_01:
            self.cycle_motion = None

    def cycle_cancel_words(self, s: Any, block: Block) -> list[str]:
        """Nothing where no native cycle is in force; else the motion code the source returns to (module
        docstring), or nothing where the block's own motion code ends the cycle."""
        mode, self.cycle_motion = self.cycle_motion, None
        motion = block.sections.get("Motion")
        if mode is None or (isinstance(motion, Motion) and motion.mode in GROUP_01):
            return []
        # A bare G2/G3 is refused (no axis words, error 26 [V: grblHAL core gcode.c, as grbl's]): an arc mode
        # is ended by a bare G0, which moves nothing; every later move is written with its own motion code.
        back = mode if mode in GROUP_01 and mode not in ("cw", "ccw") else "rapid"
        return [self.code("motion", back, "the motion mode after a cycle", block)]

    def expressions(self) -> bool:
        """The build runs parameters, expressions and o-words (``<Controller expressions="true">``)."""
        return bool(self.ctx.setup.controller.expressions)

    def expression(self, expr: Expr, block: Block, what: str = "a computed word") -> str:
        if not self.expressions():
            self.unsupported(f"{what} on a grblHAL build without expressions (NGC_EXPRESSIONS_ENABLE): a set-up "
                             "with <Controller expressions=\"true\"/> has them", block)
        return super().expression(expr, block, what)

    def statement_words(self, section: Any, block: Block) -> list[str]:
        """An assignment or an o-word line (module docstring); anything else is refused."""
        from postproc.rs274.oword import spell_assignments, spell_oword  # (at the first statement: a CAM program has none)
        if not self.expressions():
            self.unsupported("parameters and o-word flow control on a grblHAL build without expressions "
                             "(NGC_EXPRESSIONS_ENABLE): a set-up with <Controller expressions=\"true\"/> has them",
                             block)
        if isinstance(section, Assign):
            return [spell_assignments(section)]
        if isinstance(section, (SubStart, Call)) and not (isinstance(section.name, str) and section.name.isdigit()):
            self.unsupported("a named sub (grblHAL looks o<name> up as the file <name>.macro: not modelled)", block)
        if isinstance(section, SubStart):
            self.body = section.name
        if isinstance(section, SubEnd):
            self.subs.add(section.name)
            self.body = None
        own = self.source_dialect in _SAME_OWORDS or CONVERTED in self.ctx.run_data
        if isinstance(section, _FLOW) and own:
            self.nest(section, block)
            if isinstance(section, SubEnd) and section.name in self.recursive:
                self.recursion(section.name, block)
            return [spell_oword(section)]
        if isinstance(section, Call) and own:
            words = self.call_words(section, block)
            name = section.name
            if isinstance(name, str) and name == self.body and self.source_dialect != self.DIALECT:
                self.recursive[name] = max(self.recursive.get(name, 0), self.structure().held() + 1)
            self.nest(section, block)
            return [words]
        return super().statement_words(section, block)

    def nest(self, section: Any, block: Block) -> None:
        """An o-word statement written: nested as grblHAL nests it (``program.FLOW_STACK``, module docstring)."""
        self.structure().statement(section, 0, block)

    def structure(self) -> Structure:
        if self.flow is None:
            from postproc.interp.structure import Structure
            self.flow = Structure(self.ctx.file, GrblhalProgramSyntax.SUBPROGRAM_RULES)
        return self.flow

    def recursion(self, name: str, block: Block) -> None:
        """A sub that calls itself, its body just written: at its deepest, a run nests it to the source's bound
        of nested calls (rs274: 9), each level holding the entries around its own call again, so its body
        counts that many times over for every call of it (``Structure.uses``); without a bound, past the stack."""
        levels = self.source_call_levels()
        flow = self.structure()
        extra = FLOW_STACK if levels is None else (levels - 1) * self.recursive[name]
        flow.uses[name] = flow.uses.get(name, 0) + extra

    def source_call_levels(self) -> int | None:
        """The source controller's bound of nested calls (``SubprogramRules.call_levels``), as the run's interpreter
        step gave it (``SUBPROGRAM_RULES_KEY``); None where the run has none (a source that runs no program)."""
        rules: SubprogramRules | None = self.ctx.run_data.get(SUBPROGRAM_RULES_KEY)
        return None if rules is None else rules.call_levels

    def call_words(self, call: Call, block: Block) -> str:
        """``o<n> call [..]`` after its sub's definition; from LinuxCNC with its 30 arguments (module docstring), but
        for the calls of ``M98`` subprograms (``subprograms``: a program that computes nothing)."""
        assert isinstance(call.name, str)
        if call.name not in self.subs and call.name != self.body:
            self.unsupported(f"a call of o{call.name} before its sub's definition (grblHAL finds a sub only once "
                             "the program has passed it)", block)
        if self.source_dialect == "linuxcnc" and CONVERTED not in self.ctx.run_data and len(call.args) < CALL_ARGUMENTS:
            given = dict(call.args)
            for k in range(1, CALL_ARGUMENTS + 1):
                given.setdefault(k, Num(0.0))
            call = Call(call.name, given, call.repeat, call.kind)
        from postproc.rs274.oword import spell_oword
        return spell_oword(call)

    def table_refusal(self, register: int | None) -> str:
        number = "" if register is None else f" H{register}"
        return (f"a tool length offset from a table (G43{number}) on a grblHAL build without a tool table: a set-up "
                "with <Controller toolTable=\"true\"/> has one")


    def feed_mode_words(self, s: Any, block: Block) -> list[str]:
        if s.mode == "per_rev" and not self.ctx.setup.controller.spindle_sync:
            self.unsupported("feed per revolution (G95) on a grblHAL spindle without an encoder: a set-up with "
                             "<Controller spindleSync=\"true\"/> has one", block)
        return super().feed_mode_words(s, block)

    def canned_cycle_words(self, s: Any, block: Block) -> list[str]:
        """The cycle as programmed (from grblHAL itself), or by its words' roles with what grblHAL needs
        added (module docstring)."""
        self.cycle_motion = s.motion or "rapid"
        self.cycle_block = block
        self.after_blocks = True  # (``after_block``: until a motion code ends the cycle)
        if self.source_dialect == self.DIALECT:
            return super().canned_cycle_words(s, block)
        words: list[str] = []
        kind = "drill" if s.kind == "drill_dwell" and not s.dwell else s.kind  # a dwell of 0: G82 P0 would dwell
        if s.call:
            words.append(self.code("cycle", kind, f"the {kind.replace('_', ' ')} cycle", block))
        source, target = self.ctx.cycle_words, self.target_cycle_words()
        if source is not None and target is not None:
            words.extend(self.cycle_role_words(s, block, source, target, dwell=kind == "drill_dwell"))
        if s.call:
            have = {word[0] for word in words[1:]}
            extra = [("Z", s.bottom), ("R", s.r)]
            if kind == "drill_dwell":
                extra.append(("P", None))
            for letter, value in extra:
                if letter in have:
                    continue
                if letter == "P":
                    words.append("P" + self.number(round(s.dwell or 0.0, 9)))
                else:
                    words.append(letter + self.length(value, block, letter))
        order = {letter: at for at, letter in enumerate(WORD_ORDER)}
        head = words[:1] if s.call else []
        rest = sorted(words[len(head):], key=lambda word: order.get(word[0], len(order)))
        if s.call and "ReturnLevel" not in block.sections and s.return_level != self.return_in_force:
            self.return_in_force = s.return_level
            head = [self.code("return", s.return_level, f"return to the {s.return_level} level", block), *head]
        return head + rest

    def return_level_words(self, s: Any, block: Block) -> list[str]:
        self.return_in_force = s.level
        return super().return_level_words(s, block)


class GrblhalOwnWriter(GrblhalWriter):
    """The writer of a grblHAL program written back to grblHAL: its blocks are copied or normalised from their
    words, not generated (``words_block``), so ``after_block`` does not see them, and a copied motion code that
    ends a cycle a generated block wrote is followed as the block is taken (``Grblhal.writer_class``)."""

    def write_block(self, block: Block) -> str | None:
        self.end_cycle(block)
        return super().write_block(block)
