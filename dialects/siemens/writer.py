"""SINUMERIK writer: words spelt from the 840D table (G710/G700 units, G4 F seconds, ``CR=`` radii), ``;``
comments (``SemicolonCommentWriter``) and ``%_N_NAME_MPF`` headers.

* A block read from SINUMERIK and unchanged is copied byte for byte (``WordWriter``); normalised, a block
  with an ``=`` form, a statement, a label or a main-block number keeps its own text (only plain words are
  rebuilt).
* Variables and control flow of another dialect are written where each construct has an exact SINUMERIK
  spelling (``control_writing``: R parameters, ``IF``/``WHILE``/``REPEAT``/``FOR``, ``GOTOF``/``GOTOB`` to
  block numbers and labels), else the program is flattened; a computed word is ``X=<expr>``.
* Fanuc G81/G82 (and the others ``cycle_writing`` lists) are ``MCALL CYCLE81``/``CYCLE82`` with the holes as position blocks and a bare ``MCALL`` before
  anything else that moves (``cycle_writing``, which says where; every other cycle arrives expanded). The
  return level is in the call's RTP, so G98/G99 write nothing. A cycle read from SINUMERIK arrives here only
  when a program transform changed it (no lowering step expands a cycle back to its own dialect): a call once
  is written once again, the ``MCALL`` definition as itself where the call can stand there (else nothing until
  its first hole), a ``HOLES1``/``HOLES2`` block its moves (``cycle_block``; a hole of a modal ``CYCLE84``, which
  the reader marks ``expand`` for the other dialects, is a hole, and a pattern of rigid taps is refused: no plain
  move taps). Fanuc's taps are ``CYCLE84`` (rigid) and ``CYCLE840`` (floating, G99), a floating tap in feed per
  revolution its moves.
* A dwell is ``G4 F<seconds>`` alone in its block (only a block number joins it) [K: 840D Fundamentals,
  "G4 must be programmed in a separate block"]; what acts before it goes in a block before.
* Tool data: ``D<n>`` selects cutting edge n (its length and radius), ``D0`` none: a Fanuc ``G43 H``/``G41 D``
  is written as the D it needs (``postproc.isg_family.tool_data``); a negative offset (G44) is refused.
* Another dialect's tape mark ``%`` is the comment ``;%`` (a SINUMERIK ``%`` line is a header).
* Units: ``G710``/``G700`` (lengths and feeds), never G71/G70 (lengths only).
* A reference return (Fanuc ``G28``) is its intermediate point, then ``G75 FP=1`` to the set-up's home
  (``fixed_point``).
"""

from __future__ import annotations

from typing import Any, ClassVar

from postproc.context import Context
from postproc.interp.control import ASSIGN, CONTROL, LABEL
from postproc.cycles.section import CannedCycle
from postproc.lowering.synchronised_tap import RigidTap
from postproc.dialect import Dialect
from postproc.compensation.tool_table import ToolTable
from postproc.errors import PostprocError, UnsupportedError
from postproc.ir.event_order import after_motion
from postproc.ir.expr import Expr
from postproc.ir import Block, CompoundMotion, DistanceMode, Dwell, Motion, Section, SpindleControl, ToolLengthOffset
from postproc.rs274.codes import CodeTable
from postproc.isg_family.taps import stroke_words
from postproc.rs274.semicolon_comments import SemicolonCommentWriter

from .codes import CODES
from .control_writing import JumpTargets, expression, label_name, statement
from .cycle_writing import TAPS, Call, floating_call, floating_tap_moves, in_place_moves, moves_in_plane, parameters_writable
from .fixed_point import g75_line, reference_problem

NAME_LENGTH = 24
"""The longest program name, without ``_N_`` and ``_MPF`` [K: SINUMERIK ONE programming manual 12/2019 2.2.1
"Maximum length: 24 characters"; 840D sl 11/2006 "Program names: 24 characters"]."""
_WITH_DWELL = ("Dwell", "Sequence")
_ALONE_WITH_DWELL = frozenset((*_WITH_DWELL, "Comments", "BlockDelete"))
_OWN_TEXT = frozenset((ASSIGN, CONTROL, LABEL, "NativeCode", "ProgramStart", "FrameChange"))
"""Sections whose block keeps its text when normalised."""
_BESIDE_ASSIGN = frozenset((ASSIGN, "Sequence", "Comments", "BlockDelete", LABEL))
"""What may share a block with an assignment."""
_CYCLE_OWN = frozenset(("CannedCycle", "ReturnLevel", "Comments", "Sequence", "CompoundMotion"))
"""Sections of a cycle block the call and its position block write themselves (a cycle read from SINUMERIK and
changed by a program transform still has its expansion: written only where the block is written as motion)."""
_ENDS_CALL = frozenset(("Motion", "CompoundMotion", "CycleCancel"))
"""Sections after which a modal call must not stay active: they move (the call would run after them) or end
the source's cycle."""


class SiemensWriter(SemicolonCommentWriter):
    DIALECT: ClassVar[str] = "siemens"
    CODES: ClassVar[CodeTable] = CODES
    DWELL_WORD: ClassVar[str] = "F"
    TOOL_TABLE_LACK: ClassVar[str] = (
        "SINUMERIK writes a tool's edge data from a program ($TC_DP3[t,d] its length 1, $TC_DP6 its radius, $TC_DP12 "
        "the length's wear [K: SINUMERIK system variable list]), but which of its tools and edges a register "
        "number is, and when a written edge acts on the active D, are [?]: not written here")

    def __init__(self, ctx: Context, source_dialect: str, target: type[Dialect] | None = None) -> None:
        super().__init__(ctx, source_dialect, target)
        self.targets = JumpTargets()
        """Block numbers and labels written, and the jumps to them (``control_writing``)."""
        self.call: Call | None = None
        """The active ``MCALL`` (``cycle_writing``)."""
        self.flowing = False
        """A control statement or label was written: from there a block may run from another state."""
        self.length_register: int | None = None
        """The D whose length is in force (None: D0; -1: computed)."""
        self.radius_on = False
        """G41/G42 in force."""

    def normalized(self, block: Block) -> str:
        text = block.text or ""
        if block.values or not _OWN_TEXT.isdisjoint(block.sections) or "=" in text or ":" in text \
                or any(letter in "Rr" for letter, _ in block.words):
            return text.rstrip()
        return super().normalized(block)

    WORK_OFFSET_VARIABLE: ClassVar[str] = "$P_UIFR[{index},{axis},TR]={value}"
    """Another dialect's work offset setting (Fanuc ``G10 L2 P1 X0``) is the coarse translation of settable frame
    n, ``$P_UIFR[1,X,TR]=0`` [K: SINUMERIK 840D sl job planning manual, frame components TR/FI/RT/SC/MI of
    ``$P_UIFR[n,axis,component]``; Autodesk's SINUMERIK posts write ``$P_UIFR[1,X,TR]=..`` before the program].
    The control writes the frame into the data management and activates it with the next G54-G57/G505-G599
    [K: same manual, settable frames: a ``$P_UIFR`` written in the program acts from the next selection of its
    G code]: for the active system that selection is written again after it (``work_offset_assignments``). A
    fine offset (FI) the machine holds for that frame stays: the fine offset is a machine datum option
    (MD18600) the set-up does not describe [?]."""
    WORK_OFFSET_COUNT: ClassVar[int] = 99
    """$P_UIFR[1]-[4]: G54-G57; [5]-[99]: G505-G599 (the work systems 5-99 the code table writes so)."""

    def generate(self, block: Block) -> str:
        sections = block.sections
        if "DataSetting" in sections:
            setting = self.work_offset_assignments(block, self._part)
            if setting is not None:
                return setting
        if "TapeMark" in sections:
            return ";%" + (block.eol or "\n")  # another dialect's tape mark: a SINUMERIK % line is a header
        if "Dwell" in sections and any(k not in _ALONE_WITH_DWELL for k in sections) \
                and "CompoundMotion" not in sections:
            return self.around_dwell(block, _WITH_DWELL)
        cycle = sections.get("CannedCycle")
        if isinstance(cycle, CannedCycle):
            return self.cycle_block(block, cycle)
        if self.call is not None and (not _ENDS_CALL.isdisjoint(sections) or _ends_program(sections)):
            return self.end_call(block)
        motion = sections.get("Motion")
        if isinstance(motion, Motion) and motion.mode in ("home", "home2"):
            return self.reference_return(block, motion)
        if "MachineCoordinates" in sections and isinstance(motion, Motion) and motion.axes \
                and self.length_between(sections):
            return self.machine_move(block)
        label = sections.get(LABEL)
        sequence = sections.get("Sequence")
        if sequence is not None:
            self.targets.mark(f"N{getattr(sequence, 'number')}")
        if label is None:
            return super().generate(block)
        name = self._label(getattr(label, "name"), block)
        self.targets.mark(name)
        self.flowing = True
        text = super().generate(block)
        body = text.lstrip()
        head = ""
        if body[:1] == "/":  # a block skip, then the block number, then the label [K]
            head, _, body = body.partition(" ")
            head += " "
        if body[:1] == "N" and body[1:2].isdigit():
            number, _, body = body.partition(" ")
            head += number + " "
        return f"{head}{name}: {body}" if body.strip() else f"{head}{name}:" + (block.eol or "\n")

    def _label(self, name: str, block: Block) -> str:
        try:
            return label_name(name)
        except UnsupportedError as err:
            self.unsupported(err.message, block)

    def statement_words(self, section: Section, block: Block) -> list[str]:
        """Variables and control flow (``control_writing``); an assignment shares its block with nothing
        that acts (in which order SINUMERIK evaluates an assignment and the block's words is not
        confirmed here [?])."""
        if ASSIGN in block.sections and any(key not in _BESIDE_ASSIGN for key in block.sections):
            self.unsupported("an assignment beside other words in one block", block)
        self.flowing = True
        try:
            return statement(section, self.targets, self.ctx.at(block))
        except UnsupportedError as err:
            self.unsupported(err.message, block)

    def expression(self, expr: Expr, block: Block, what: str = "a computed word") -> str:
        """A computed word is ``<address>=<expr>`` [K: 840D Fundamentals, "an address with an expression
        takes '='"]."""
        try:
            return "=" + expression(expr)
        except UnsupportedError as err:
            self.unsupported(err.message, block)

    def finish(self) -> str:
        for problem in self.targets.problems():
            self.ctx.diagnostics.error(problem)
        return super().finish()

    def program_start(self, s: Any, block: Block) -> str:
        """``%_N_NAME_MPF``; a numbered program is ``%_N_PROG<number>_MPF`` [?: a name starts with a
        letter]."""
        name = str(s.name) if s.name is not None else f"PROG{int(s.number)}"
        name = "".join(c if c.isalnum() or c == "_" else "_" for c in name).upper()
        if not (name.endswith("_MPF") or name.endswith("_SPF")):
            name += "_MPF"
        if not name[:1].isalpha():
            name = "P" + name
        if len(name) - 4 > NAME_LENGTH:
            self.unsupported(f"a program name of {len(name) - 4} characters ({name[:-4][:NAME_LENGTH]}...): SINUMERIK "
                             f"takes {NAME_LENGTH}", block)
        return f"%_N_{name}"

    def block_delete_words(self, s: Any, block: Block) -> list[str]:
        """Neutral level k is ``/k-1`` (level 1, Fanuc's ``/``, is SINUMERIK's plain ``/``)."""
        if s.level - 1 > 9:
            self.unsupported(f"block skip level {s.level} (SINUMERIK has /0 to /9)", block)
        return ["/" if s.level == 1 else f"/{s.level - 1}"]

    def motion_words(self, s: Motion, block: Block) -> list[str]:
        """An arc by radius is ``CR=`` (negative for more than 180 degrees, as Fanuc's R) [K]."""
        words = super().motion_words(s, block)
        if s.radius is not None and words and words[-1].startswith("R"):
            value = words[-1][1:]
            words[-1] = "CR" + value if value.startswith("=") else "CR=" + value
        return words

    def spindle_orientation_words(self, s: Any, block: Block) -> list[str]:
        """``SPOS=<angle>``: the spindle stops at the angle under position control (``reader``)."""
        if isinstance(s.angle, Expr):
            return ["SPOS" + self.expression(s.angle, block, "a computed orientation angle")]
        return ["SPOS=" + (f"{float(s.angle):.6f}".rstrip("0").rstrip(".") or "0")]

    def rigid_tap_words(self, s: Any, block: Block) -> list[str]:
        """A rigid tap stroke, ``G331`` in or ``G332`` out, as ISG and SINUMERIK write it
        (``postproc.isg_family.taps.stroke_words``; read by ``tap_strokes``)."""
        return stroke_words(self, s, block, "SINUMERIK")

    def return_level_words(self, s: Any, block: Block) -> list[str]:
        """Fanuc's G98/G99: the level is the RTP of the ``MCALL`` written for a cycle (``cycle_writing``)."""
        return []

    def cycle_cancel_words(self, s: Any, block: Block) -> list[str]:
        """The bare ``MCALL`` is written by ``end_call`` where a call is active; an expanded cycle has nothing
        to cancel."""
        return []

    def words_block(self, block: Block) -> str | None:
        """A bare ``MCALL`` copied as written ends the call this writer made active (a program transform
        rewrites the cycle blocks around it, not it)."""
        if self.call is not None and self.copy_ok and block.text is not None and "CycleCancel" in block.sections:
            self.call = None
        return super().words_block(block)

    # -- drilling cycles (``cycle_writing``) ----------------------------------------------------------------
    def cycle_block(self, block: Block, cycle: CannedCycle) -> str:
        """A cycle block by what it is (a block read from SINUMERIK and changed by a program transform reaches
        here with its record as the reader made it, ``cycles``): a call once (``CYCLE81(..)``: ``call``,
        ``expand``) is written once where its parameters are a call's, a block the reader marked ``expand``
        (a ``HOLES1``/``HOLES2`` call's holes, a call once that is not) as its moves with any active call ended
        first, the block that only defines the modal call (``MCALL CYCLE81(..)``: repeat 0) as that definition
        where ``definable`` (else nothing of it: the ``MCALL`` goes before the first hole, ``hole_block``), a
        hole as ``hole_block`` writes it."""
        compound = block.sections.get("CompoundMotion")
        if cycle.expand and not _modal_tap(cycle, compound):
            if cycle.call and cycle.repeat == 1 and not moves_in_plane(cycle) and parameters_writable(cycle):
                return self.once_block(block, cycle)
            if not isinstance(compound, CompoundMotion):
                self.unsupported(f"a {cycle.kind.replace('_', ' ')} cycle whose moves are not known here", block)
            if any(isinstance(item, RigidTap) for item in compound.items):
                self.unsupported("rigid taps of a hole pattern changed by a program transform: SINUMERIK taps only "
                                 "in CYCLE84, and a call per hole is not written here", block)
            rest = {k: v for k, v in block.sections.items() if k not in ("CannedCycle", "ReturnLevel")}
            text = "MCALL\n" if self.call is not None else ""
            self.call = None
            return text + self.compound(_with(block, rest), compound)
        if cycle.repeat == 0:
            if self.definable(block, cycle):
                return self.definition_block(block, cycle)
            rest = {k: v for k, v in block.sections.items() if k not in _CYCLE_OWN or k in ("Comments", "Sequence")}
            return self.generate(_with(block, rest)) if rest else ""
        if cycle.repeat != 1 or not parameters_writable(cycle):
            self.unsupported(f"a {cycle.kind.replace('_', ' ')} cycle block that no CYCLE8x call writes "
                             "(its levels, dwell or strokes)", block)
        return self.hole_block(block, cycle)

    def definable(self, block: Block, cycle: CannedCycle) -> bool:
        """Whether the block that defines the modal call (``MCALL CYCLE81(..)``, changed by a program transform)
        can be written as that definition where it stands: no call active, G17 G90 in force, nothing else in
        the block but its number and comments, a straight run of the text, parameters a call writes. Otherwise nothing of it is written, and the first hole writes the call
        or says why it cannot (``hole_block``)."""
        speed_known = cycle.kind not in TAPS or cycle.pitch is None or (
            isinstance(self.modal.spindle_rpm, (int, float)) and self.modal.spindle_rpm > 0)
        return (self.call is None and not self.flowing and self.modal.distance == "absolute" and self.modal.plane == "XY"
                and all(k in _CYCLE_OWN for k in block.sections) and parameters_writable(cycle) and speed_known)

    def definition_block(self, block: Block, cycle: CannedCycle) -> str:
        """``N.. G0`` and ``MCALL CYCLE8x(..)``: the call is active from here, so its holes are position blocks
        (``hole_block`` writes the call again only where it changes). G0 is stated as ``hole_block`` states it:
        the source had it in force (the reader asks for it), but a cycle written as its moves before may have
        left the output in G1."""
        sequence = block.sections.get("Sequence")
        if sequence is not None:
            self.targets.mark(f"N{getattr(sequence, 'number')}")
        self.call = self.call_of(cycle, block)  # a rigid tap's SST: the speed in force, as its holes write it
        text = self.call.text(lambda value: self.number(value, "Z"), lambda value: self.number(value, "F"))
        comments = block.sections.get("Comments")
        if comments is not None:
            text = " ".join([text, *(self.comment(t) for t in getattr(comments, "texts"))])
        return self._cycle_text(block, [self.code("motion", "rapid", "rapid motion", block) + "\n", text + "\n"])

    def once_block(self, block: Block, cycle: CannedCycle) -> str:
        """``CYCLE8x(..)`` alone: it drills where the tool stands, retracts to RTP (the record's initial level,
        ``cycles.SiemensCycleEnd``) and leaves no call active; what acts before and after it in blocks of
        their own."""
        sections = block.sections
        if self.call is not None:
            self.unsupported("a drilling cycle called once while a modal call is active (whether the modal call "
                             "runs too is not confirmed)", block)
        head = {k: v for k, v in sections.items() if k not in _CYCLE_OWN and not after_motion(k, v)}
        tail = {k: v for k, v in sections.items() if k not in _CYCLE_OWN and k not in head}
        lines = [self._part(block, head)] if head else []
        call = self.call_of(cycle, block)
        text = call.text(lambda value: self.number(value, "Z"), lambda value: self.number(value, "F"), once=True)
        comments = sections.get("Comments")
        if comments is not None:
            text = " ".join([text, *(self.comment(t) for t in getattr(comments, "texts"))])
        lines.append(text + "\n")
        if tail:
            lines.append(self._part(block, tail))
        return self._cycle_text(block, lines)

    def hole_block(self, block: Block, cycle: CannedCycle) -> str:
        """A native hole: what acts before it, the ``MCALL`` where the call changes (G0 before it), the position
        block, what acts after it."""
        sections = block.sections
        if "BlockDelete" in sections:
            self.unsupported("a block skip on a drilling cycle written as a modal call (the call stays active "
                             "whether the block runs or not)", block)
        if self.modal.distance != "absolute" or self.modal.plane != "XY":
            self.unsupported("a drilling cycle outside G17 G90 written as a modal call", block)
        if self.flowing:
            self.unsupported("a drilling cycle after a control statement or label as a modal call (which call is "
                             "active, and the initial level, depend on the run; the text is written in its order)",
                             block)
        head = {k: v for k, v in sections.items() if k not in _CYCLE_OWN and not after_motion(k, v)}
        tail = {k: v for k, v in sections.items() if k not in _CYCLE_OWN and k not in head}
        sequence = sections.get("Sequence")
        lines: list[str] = []
        if sequence is not None:
            self.targets.mark(f"N{getattr(sequence, 'number')}")
        if head:
            lines.append(self._part(block, head))
        call = self.call_of(cycle, block)
        if cycle.kind in TAPS and cycle.pitch is None and not floating_call(cycle, self.modal.feed_mode):
            return self._cycle_text(block, self.floating_tap(block, cycle, call, lines, tail))
        if not moves_in_plane(cycle):
            if self.call is not None:
                lines.append("MCALL\n")
                self.call = None
            if cycle.kind in TAPS:  # a rigid tap where the tool stands: the call once (no plain move taps)
                lines.append(call.text(lambda value: self.number(value, "Z"), lambda value: self.number(value, "F"),
                                       once=True) + "\n")
                if tail:
                    lines.append(self._part(block, tail))
                return self._cycle_text(block, lines)
            for kind, value in in_place_moves(cycle, call):
                part: dict[str, Section] = ({"Dwell": Dwell(value)} if kind == "dwell"
                                            else {"Motion": Motion(kind, {"Z": value})})
                lines.append(self._part(block, part))
            if tail:
                lines.append(self._part(block, tail))
            return self._cycle_text(block, lines)
        if call != self.call:
            if self.call is not None:
                lines.append("MCALL\n")
            # G0 in force at the call: the holes are reached at rapid (the writer does not track the motion mode
            # written, so it is always stated)
            lines.append(self.code("motion", "rapid", "rapid motion", block) + "\n")
            lines.append(call.text(lambda value: self.number(value, "Z"), lambda value: self.number(value, "F")) + "\n")
            self.call = call
        axes: dict[str, float | Expr] = {a: float(cycle.words[a]) for a in ("X", "Y") if a in cycle.words}
        words = self.motion_words(Motion("rapid", axes), block)[1:]
        comments = sections.get("Comments")
        if comments is not None:
            words.extend(self.comment(t) for t in getattr(comments, "texts"))
        lines.append(" ".join(words) + "\n")
        if tail:
            lines.append(self._part(block, tail))
        return self._cycle_text(block, lines)

    def floating_tap(self, block: Block, cycle: CannedCycle, call: Call, lines: list[str],
                     tail: dict[str, Section]) -> list[str]:
        """A floating tap no ``CYCLE840`` writes (``floating_call``) as its moves, any active call ended first."""
        if self.call is not None:
            lines.append("MCALL\n")
            self.call = None
        lines.append(self.comment_line(f"{cycle.kind} from line {block.line}: {self.source_text(block)}"))
        if moves_in_plane(cycle):
            axes: dict[str, float | Expr] = {a: float(cycle.words[a]) for a in ("X", "Y") if a in cycle.words}
            lines.append(self._part(block, {"Motion": Motion("rapid", axes)}))
        for kind, value in floating_tap_moves(cycle, call):
            part: dict[str, Section]
            if kind == "spindle":
                part = {"SpindleControl": SpindleControl(str(value))}
            elif kind == "dwell":
                part = {"Dwell": Dwell(float(value))}
            else:
                part = {"Motion": Motion(kind, {"Z": float(value)})}
            lines.append(self._part(block, part))
        if tail:
            lines.append(self._part(block, tail))
        return lines

    def call_of(self, cycle: CannedCycle, block: Block) -> Call:
        """``Call.of``, a rigid tap's with the spindle speed in force (the block's own first: Fanuc's
        ``M29 S..`` may share it), which SINUMERIK's ``CYCLE84`` is given as SST."""
        rpm = None
        if cycle.kind in TAPS and cycle.pitch is not None:
            speed = block.sections.get("SpindleSpeed")
            rpm = getattr(speed, "rpm", None) if speed is not None else self.modal.spindle_rpm
            if not isinstance(rpm, (int, float)) or rpm <= 0:
                self.unsupported("a rigid tap without a known spindle speed (CYCLE84 takes it as SST)", block)
        return Call.of(cycle, None if rpm is None else float(rpm))

    def _cycle_text(self, block: Block, lines: list[str]) -> str:
        """The lines of a cycle block, its block number on the first, its end of line on the last."""
        sections = block.sections
        self._track({k: v for k, v in sections.items() if k != "CannedCycle"})
        sequence = sections.get("Sequence")
        if sequence is not None:
            lines[0] = " ".join(self.sequence_words(sequence, block)) + " " + lines[0]
        text = "".join(lines)
        return text[:-1] + (block.eol or "\n") if text.endswith("\n") else text

    def end_call(self, block: Block) -> str:
        """The bare ``MCALL`` before a block that moves otherwise or ends the program."""
        if "BlockDelete" in block.sections:
            self.unsupported("a block skip on the block that ends a modal cycle call", block)
        self.call = None
        rest = self.generate(block)
        return "MCALL\n" + ("" if not rest.strip() or rest.strip() == ";" else rest)

    def _part(self, block: Block, sections: dict[str, Section]) -> str:
        part = Block(block.line, None, "\n")
        part.sections = sections
        return self.generate(part)

    # -- reference returns (``fixed_point``) --------------------------------------------------------------
    def reference_return(self, block: Block, motion: Motion) -> str:
        """What the block sets in a block before, the intermediate point as a ``G0`` move (none for Fanuc's
        ``G91 G28 Z0``), ``G75 FP=1`` alone, what the block ends after."""
        sections = block.sections
        problem = reference_problem(self.ctx.setup, motion, self.modal.units == "inch")
        if problem is not None:
            self.unsupported(problem, block)
        if "BlockDelete" in sections:
            self.unsupported("a block skip on a reference return (G75 is a block of its own)", block)
        moving = ("Motion", "Sequence")
        before = {k: v for k, v in sections.items() if k not in moving and not after_motion(k, v)}
        after = {k: v for k, v in sections.items() if k not in moving and k not in before}
        if "Sequence" in sections:
            before = {"Sequence": sections["Sequence"], **before}
        text = self._part(block, before) if before else ""
        if motion.axes and (self.modal.distance == "absolute" or any(v != 0 for v in motion.axes.values())):
            text += self._part(block, {"Motion": Motion("rapid", dict(motion.axes))})  # the intermediate point
        for axis in motion.axes:
            self.carry.pop(axis, None)  # the axis is at its home: its next word is written whole
        if motion.axes:  # a return naming no axis moves none (Fanuc G28 alone): no G75, which needs its axes
            text += g75_line(list(motion.axes)) + "\n"
        if after:
            text += self._part(block, after)
        eol = block.eol or "\n"
        return text[:-1] + eol if text.endswith("\n") else text

    # -- machine coordinates (``frame_suppression``) -------------------------------------------------------
    MACHINE_MOVES: ClassVar[frozenset[str]] = frozenset(("rapid",))
    """A block without frames moves in the mode in force; the reader reads it back in G0 only."""

    def length_between(self, sections: dict[str, Section]) -> bool:
        """Whether a move in machine coordinates has a tool length to take out first: one in force, or the
        block's own cancel (Haas ``G53 G49 Z0``), which ``machine_move`` writes as ``D0`` in a block before."""
        offset = sections.get("ToolLengthOffset")
        if isinstance(offset, ToolLengthOffset):
            return offset.mode == "cancel"
        return self.length_register is not None and self.length_register >= 0 and not self.no_length()

    def machine_move(self, block: Block) -> str:
        """A move in machine coordinates with a tool length in force, exact whatever ``$MN_G53_TOOLCORR`` says:
        ``D0`` in a block of its own, the ``SUPA`` block with no length to suppress, then the ``D`` in force
        again in a block of its own (none where the block cancels the length itself, Fanuc ``G49``).

        Why that is the neutral move (``Simulator._machine_coordinates``: the controlled point at the machine
        position, the length offset still in force for the blocks after):
        [V: SINUMERIK 840D sl Function Manual Basic logic functions: Tool Offset (W1), 11/2006,
        6FC5397-0BP10-2BA0, 2.1 p.13 "Activating the tool compensations"] a D change (D0 too) is traversed on
        the first G0/G1 motion of the axis it acts on, so a ``D`` block without motion moves nothing and the
        ``SUPA`` block after ``D0`` moves with no length, which the machine datum cannot suppress further;
        [V: 802D sl/840D ISO Milling 04.07, 3.1.1] with ``$MN_G53_TOOLCORR = 0`` the length would have stayed
        in force in the ``SUPA`` block, with 1 it is suppressed: after ``D0`` both are the same.
        [K: Fanuc 0i-MB operator's manual B-63844EN/02 14.1.2] Fanuc's ``G53`` cancels the length for its own
        block only: the ``D`` written again after it gives the next move of the axis its length back, as on
        Fanuc. [?] An incremental move of the axis next (G91) is not checked against SINUMERIK's rule for a
        length change traversed with an incremental dimension; every such program seen moves in G90.
        A block skip goes on all three blocks: skipped, none of them runs. Radius compensation in force stays
        refused (``machine_coordinates_words``): the source cannot run it."""
        sections = block.sections
        if self.radius_on or "CutterCompensation" in sections:
            self.unsupported("a move in machine coordinates with radius compensation in force (whether SUPA "
                             "suppresses it is machine data $MN_G53_TOOLCORR)", block)
        offset = sections.get("ToolLengthOffset")
        register = self.length_register
        skip = {"BlockDelete": sections["BlockDelete"]} if "BlockDelete" in sections else {}  # all three or none
        text = self._part(block, {**skip, "ToolLengthOffset": offset or ToolLengthOffset("cancel")})
        rest = {k: v for k, v in sections.items() if k != "ToolLengthOffset"}
        text += self.generate(_with(block, rest))
        if offset is None and register is not None:
            text += self._part(block, {**skip, "ToolLengthOffset": ToolLengthOffset("positive", register)})
        return text

    def machine_coordinates_words(self, s: Any, block: Block) -> list[str]:
        """``SUPA``: the block without any frame or offset, which is what the neutral machine coordinates are,
        where neither a tool length nor radius compensation is in force (whether SUPA suppresses them is machine
        data ``$MN_G53_TOOLCORR``: ``frame_suppression``); ``machine_move`` takes a tool length out around it."""
        sections = block.sections
        motion = sections.get("Motion")
        if not isinstance(motion, Motion) or not motion.axes:
            return []  # no move to qualify: it does nothing
        if motion.mode not in self.MACHINE_MOVES:
            self.unsupported(f"a {motion.mode} move in machine coordinates (read back in G0 only)", block)
        distance = sections.get("DistanceMode")
        if (distance.mode if isinstance(distance, DistanceMode) else self.modal.distance) == "incremental":
            self.unsupported("a move in machine coordinates under G91 (read back in G90 only: machine positions "
                             "are absolute)", block)
        if self.radius_on or "CutterCompensation" in sections or "ToolLengthOffset" in sections \
                or not self.no_length():
            self.unsupported("a move in machine coordinates with a tool length or radius compensation in force "
                             "(whether SUPA suppresses them is machine data $MN_G53_TOOLCORR)", block)
        return ["SUPA"]

    def no_length(self) -> bool:
        """Whether the D in force brings no length (D0, or the set-up's tool of that number is 0 long)."""
        register = self.length_register
        if register is None:
            return True
        try:
            return ToolTable(self.ctx.setup).length(register) == 0.0
        except PostprocError:
            return False

    # -- tool data (``postproc.isg_family.tool_data`` chose the D) ---------------------------------------
    def tool_length_offset_words(self, s: Any, block: Block) -> list[str]:
        """``D<n>`` selects cutting edge n (its length applies), ``D0`` none."""
        self.length_register = s.register if s.mode == "positive" and isinstance(s.register, int) else None
        if s.mode == "positive" and not isinstance(s.register, int):
            self.length_register = -1  # computed: unknown
        if s.mode == "cancel":
            return ["D0"]
        if s.mode == "negative":
            self.unsupported("a negative tool length offset (Fanuc G44): D adds the tool's length, and no code "
                             "subtracts it", block)
        if s.mode != "positive" or s.register is None:
            self.unsupported(f"tool length offset {s.mode} (SINUMERIK selects a tool's data with D)", block)
        return ["D" + self.register(s.register, block)]

    def cutter_compensation_words(self, s: Any, block: Block) -> list[str]:
        """``G41``/``G42`` take the radius of the selected D: a D is written only where no ``D`` of the
        block's length offset selects it already."""
        self.radius_on = s.mode != "off"
        if "ToolLengthOffset" in block.sections:
            return self._code("cutter", s.mode, f"cutter compensation {s.mode}", block)
        return super().cutter_compensation_words(s, block)


def _with(block: Block, sections: dict[str, Section]) -> Block:
    """A block of ``block``'s line and end with ``sections`` in place of its own (its source text kept for the
    expansion's comment)."""
    part = Block(block.line, block.text, block.eol, block.words)
    part.sections = sections
    return part


def _ends_program(sections: dict[str, Section]) -> bool:
    control = sections.get("ProgramControl")
    return control is not None and getattr(control, "kind", "") in ("end", "end_rewind")


def _modal_tap(cycle: CannedCycle, compound: object) -> bool:
    """Whether ``cycle`` is the definition or one hole of a ``MCALL CYCLE84`` read from SINUMERIK: the reader
    marks every rigid tap ``expand`` for the other dialects (``cycles.rigid_tap_pitch``), a hole pattern's
    taps (several in one block) are its moves."""
    if cycle.kind not in TAPS or cycle.pitch is None:
        return False
    if cycle.repeat == 0:
        return True
    items = getattr(compound, "items", ())
    return not cycle.call and sum(isinstance(item, RigidTap) for item in items) == 1
