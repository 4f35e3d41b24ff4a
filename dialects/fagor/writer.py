"""Fagor 8070 writer: DIN words spelt from Fagor's table (G70/G71 units, G54-G59, G98/G99), ``;``
comments (``SemicolonCommentWriter``), ``%name`` headers, and the hole cycles Fagor runs with its own words.

* A block read from Fagor and unchanged is copied byte for byte (``WordWriter``).
* Hole cycles: a drilling (Fanuc ``G81``/``G82``) or feed-out boring (``G85``/``G89``) cycle read in
  another dialect is written as Fagor's ``G81``/``G89`` with each word by its role (``R`` -> ``Z``,
  ``Z`` -> ``I``; ``cycle_role_words``); the dwell ``K`` is written from the cycle's seconds in the set-up's
  unit. Which cycle parameters the 8070 keeps from one cycle definition to the next, and which a cancel,
  a ``G53`` or a rapid resets, is not confirmed [?: DIALECTS.md 4.2, the 8070's cycle pages were not
  reached], so the dwell never depends on it: once a program has written a nonzero ``K``, every block that
  names the cycle code writes its ``K`` (``K0`` for a cycle without a dwell), and a block repeating the
  active cycle writes ``K`` when its dwell differs from the one in force. Before any nonzero ``K`` a cycle
  without a dwell writes none (a controller that has never been given a dwell has none). For the same reason a
  block that names the cycle code writes the reference plane ``Z`` and depth ``I`` in force where its source
  carried them over from the cycle before (a Fanuc ``G82 X5. P1000`` after ``G81 .. Z-6. R2.``: ``G81 X5. Z2.
  I-6. K1.``), as last written [K: Autodesk's post for the Fagor 8037/8055 writes every definition whole, ``G90
  G8x X Y Z I (K)``].
  Every other cycle arrives expanded (``Fagor.NATIVE_CYCLES``). A ``G80`` ends a written cycle before any
  move outside it (``cycle_end``: whether a motion code ends a cycle on the 8070 is not confirmed [?]).
* Another dialect's tape mark ``%`` is written as the comment ``;%`` (a Fagor ``%`` line is a header).
* A dwell is ``G04 K`` in the set-up's unit (as the cycle ``K`` [?]).
* No block skip and no oriented spindle stop are written: their 8070 spelling is not confirmed [?] (a
  located error names them).
* The cutting mode (Fanuc/LinuxCNC ``G64``) is ``G05``, the square corner ``G07``/``G60`` (``codes``).
* A move in machine coordinates (Fanuc ``G53``, always a rapid) is ``G53 G00`` in absolute positions
  (``G90`` before it and ``G91`` after it under incremental distance); a reference return (``G28``) is
  its intermediate move, then ``G53 G00`` to the set-up's ``<Axis home>`` of each axis it names, as ISG
  writes it with ``#SUPPRESS OFFSETS`` (``codes``: [K] for the 8070's G53).
* Multiple machining: a ``HolePattern`` (kept native: ``Fagor.HOLE_PATTERNS``) read from Fagor and
  unchanged is copied byte for byte like any block; regenerated, it is written by
  ``multiple_machining.pattern_words`` (``G160``-``G164``, its points by step and count, skipped points
  ``P``..``V``).
"""

from __future__ import annotations

from typing import Any, ClassVar

from postproc.context import Context
from postproc.cycle_words import CycleWords
from postproc.cycles.section import WORD_ORDER
from postproc.dialect import Dialect
from postproc.errors import UnsupportedError
from postproc.ir.event_order import after_motion
from postproc.ir.expr import Expr
from postproc.ir import Block, Comments, DistanceMode, MachineCoordinates, Motion, Section
from postproc.output.home_position import SECOND_RETURN, reference_problem, reference_target
from postproc.rs274.codes import CodeTable
from postproc.rs274.cycle_words import NEUTRAL_CYCLE_WORDS
from postproc.rs274.semicolon_comments import SemicolonCommentWriter
from postproc.ir.state import PLANE_AXES

from .codes import CODES, CYCLE_ALIASES
from .cycle_words import cycle_words
from .multiple_machining import pattern_words

NATIVE = frozenset(("drill", "drill_dwell", "bore_feed", "bore_dwell_feed"))
"""``Fagor.NATIVE_CYCLES``."""
_CANCELS = frozenset(("rapid", "linear", "cw", "ccw"))
_REFERENCE = frozenset(("home", "home2"))
"""Motion modes of a reference return."""


class FagorWriter(SemicolonCommentWriter):
    DIALECT: ClassVar[str] = "fagor"
    CODES: ClassVar[CodeTable] = CODES
    DWELL_WORD: ClassVar[str] = ""
    MACHINE_MOVES: ClassVar[frozenset[str]] = frozenset(("rapid",))
    """``G53`` is written with ``G00`` only (``codes``: a feed move under G53 is not confirmed [?])."""
    SPLIT: ClassVar[frozenset[str]] = frozenset(("TapeMark", "MachineCoordinates", "DataSetting"))
    """Another dialect's tape mark, a move in machine coordinates, a work offset setting: ``split_block``."""
    WORK_OFFSET_VARIABLE: ClassVar[str] = "V.A.ORGT[{index}].{axis}={value}"
    """Another dialect's work offset setting (Fanuc ``G10 L2 P1 X0``) is ``V.A.ORGT[1].X=0``, the zero offset
    table's entry [K: two independent programs for the 8070 write it so, each then selecting the entry:
    4DIAC FORTE's L0_8070Service ``V.A.ORGT[n].X=.. V.A.ORGT[n].Y=.. V.A.ORGT[n].Z=.. G159=n``, a CAM post's
    machine start ``V.A.ORGT[1].Z=190`` ``#FLUSH`` ``G54``; the 8070 programming manual's variable list was not
    reachable here]. That the table's entry acts only from its next selection is taken from those programs,
    which all select it after writing it [?]: for the active system the selection is written again after
    it (``work_offset_assignments``)."""
    WORK_OFFSET_COUNT: ClassVar[int] = 6
    TOOL_TABLE_LACK: ClassVar[str] = (
        "the 8070's tool table variables (V.G.TOOL.. / V.A.TOOL.., [?]) and when a written entry acts on the "
        "active tool are not confirmed from its manual's variable list, which was not reachable: not written here")
    """ORGT[1]-[6]: G54-G59 (``G159=1``-``G159=6``, DIALECTS.md 1.4)."""
    SPLIT_MOTIONS: ClassVar[frozenset[str]] = _REFERENCE
    """A reference return: ``split_block``."""

    dwell_in_force: float | None = None
    """The dwell (seconds) of the cycle the written program has active: None before any cycle and after a
    cancel, a move or a move in machine coordinates."""
    dwell_written: bool = False
    """Whether a nonzero ``K`` has been written: from then on every cycle call writes its ``K`` (the module
    docstring)."""

    def __init__(self, ctx: Context, source_dialect: str, target: type[Dialect] | None = None) -> None:
        super().__init__(ctx, source_dialect, target)
        self.levels_in_force: dict[str, str] = {}
        """The reference plane and depth words (``Z..``, ``I..``) the active written cycle was given last."""

    def target_cycle_words(self) -> CycleWords:
        return cycle_words(self.ctx.setup)

    def split_block(self, block: Block) -> str | None:
        if "DataSetting" in block.sections:
            setting = self.work_offset_assignments(block, self._part)
            if setting is not None:
                return setting
        if "TapeMark" in block.sections:
            return ";%" + (block.eol or "\n")  # a tape's start or end: no Fagor block, kept as a trace
        motion = block.sections.get("Motion")
        if isinstance(motion, Motion) and motion.mode in _REFERENCE or "MachineCoordinates" in block.sections:
            self.dwell_in_force = None  # a G80 comes before it (``cycle_end``): no cycle stays active after it
            self.levels_in_force = {}
        if isinstance(motion, Motion) and motion.mode in _REFERENCE and not motion.axes:
            rest = {k: v for k, v in block.sections.items() if k != "Motion"}  # a return of no axis: no move
            return self._part(block, rest)[:-1] + (block.eol or "\n") if rest else ""
        if isinstance(motion, Motion) and motion.axes \
                and (motion.mode in _REFERENCE or "MachineCoordinates" in block.sections):
            return self.machine_move(block, motion)
        return None

    def compound(self, block: Block, compound: Any) -> str:
        """A hole of a native cycle expanded after the lowering (a hole pattern that ``--units`` or
        ``--transform`` rewrites), so while the written cycle is active: ``G80`` first, as ``cycle_end``
        writes before the other moves."""
        cycle = block.sections.get("CannedCycle")
        if cycle is None or getattr(cycle, "call", True) or cycle.kind not in NATIVE:  # type: ignore[attr-defined]
            return super().compound(block, compound)
        self.dwell_in_force = None
        self.levels_in_force = {}
        self.after_blocks = False
        self.modal.cycle = None
        return self.code("cycle_cancel", None, "a cycle cancel", block) + "\n" + super().compound(block, compound)

    def after_block(self, block: Block) -> None:
        """A cycle cancel or a move ends the cycle whose dwell is in force (followed from the cycle on:
        ``after_blocks``; not after a move in machine coordinates, written by ``split_block``)."""
        sections = block.sections
        motion = sections.get("Motion")
        if "CycleCancel" in sections or (isinstance(motion, Motion) and motion.mode in _CANCELS):
            self.dwell_in_force = None
            self.levels_in_force = {}
            self.after_blocks = False

    def canned_cycle_words(self, s: Any, block: Block) -> list[str]:
        source, target = self.ctx.cycle_words or NEUTRAL_CYCLE_WORDS, self.target_cycle_words()
        if source.same_letters(target):
            return super().canned_cycle_words(s, block)
        kind = CYCLE_ALIASES.get(s.kind, s.kind)
        words: list[str] = []
        if s.call:
            words.extend(self._code("cycle", kind, f"the {s.kind.replace('_', ' ')} cycle", block))
        roles = self.cycle_role_words(s, block, source, target, dwell=False)
        words.extend(self._whole_definition(s, target, roles))
        seconds = (s.dwell or 0.0) if kind == s.kind else 0.0
        if s.call or self.dwell_in_force is None:
            explicit = bool(seconds) or self.dwell_written
        else:
            explicit = abs(seconds - self.dwell_in_force) > 1e-12
        if explicit:
            words.append(target.dwell + self.cycle_dwell(seconds, target, block))
        self.dwell_written = self.dwell_written or bool(seconds)
        self.dwell_in_force = seconds
        self.after_blocks = True  # until a cancel (``after_block``)
        return words

    def _whole_definition(self, s: Any, target: CycleWords, roles: list[str]) -> list[str]:
        """A cycle block's words, a call's with the reference plane and depth in force where its source carried
        them over (the module docstring); the words written are kept for the next call."""
        letters = (target.level, target.bottom_letter(s.plane, PLANE_AXES[s.plane][2]))
        written = {word[0] for word in roles}
        for word in roles:
            if word[0] in letters:
                self.levels_in_force[word[0]] = word
        missing = [self.levels_in_force[letter] for letter in letters
                   if s.call and letter not in written and letter in self.levels_in_force]
        if not missing:
            return roles
        order = {c: i for i, c in enumerate(WORD_ORDER)}
        return sorted(roles + missing, key=lambda word: order.get(word[0], 99))

    def hole_pattern_words(self, s: Any, block: Block) -> list[str]:
        """A multiple machining block from its ``HolePattern`` (the inverse of the reader's words)."""
        try:
            return pattern_words(s, self.number)
        except UnsupportedError as err:
            raise err.located(self.ctx.at(block)) from None

    def dwell_words(self, s: Any, block: Block) -> list[str]:
        if isinstance(s.seconds, Expr):
            self.unsupported("a computed dwell time", block)
        target = self.target_cycle_words()
        return [self.code("dwell", None, "a dwell", block), target.dwell + self.cycle_dwell(s.seconds, target, block)]

    def spindle_orientation_words(self, s: Any, block: Block) -> list[str]:
        """M19 only where the set-up says the machine has it (``<Cycles orientation="m19"/>``) [?]."""
        if self.ctx.setup.cycles.orientation != "m19":
            self.unsupported("an oriented spindle stop (not confirmed on the 8070; a set-up with "
                             "<Cycles orientation=\"m19\"/> writes M19)", block)
        return super().spindle_orientation_words(s, block)

    def program_start(self, s: Any, block: Block) -> str:
        return "%" + (str(s.number) if s.number is not None else str(s.name))

    def normalized(self, block: Block) -> str:
        """The program header has no words to rebuild it from: written from its ``ProgramStart`` (it was taken
        for a block with no meaning and written as a comment, the header lost, by ``--normalize``)."""
        start = block.sections.get("ProgramStart")
        if start is not None and not block.words:
            comments = block.sections.get("Comments")
            texts = [self.comment(t) for t in comments.texts] if isinstance(comments, Comments) else []
            return " ".join([self.program_start(start, block), *texts])
        return super().normalized(block)

    def block_delete_words(self, s: Any, block: Block) -> list[str]:
        self.unsupported("a block skip (its 8070 spelling is not confirmed)", block)

    def return_level_words(self, s: Any, block: Block) -> list[str]:
        return self._code("return", s.level, "a cycle return level", block)

    # -- machine coordinates ---------------------------------------------------------------------------
    def machine_move(self, block: Block, motion: Motion) -> str:
        """A move in machine coordinates or a reference return (the module docstring): ``G53`` positions
        are absolute, so ``G90`` comes before them (and ``G91`` after) under incremental distance."""
        sections = block.sections
        if "BlockDelete" in sections:
            self.block_delete_words(sections["BlockDelete"], block)
        rest = {k: v for k, v in sections.items() if k not in ("Motion", "MachineCoordinates")}
        after: dict[str, Section] = {}
        if motion.mode in _REFERENCE:  # what the block sets goes before the return, what it ends after it
            after = {k: v for k, v in rest.items() if after_motion(k, v)}
            before = {k: v for k, v in rest.items() if k not in after}
            text = self._part(block, before) if before else ""  # (its distance mode included: the return's own)
            if self.modal.distance == "absolute" or any(v != 0 for v in motion.axes.values()):
                text += self._part(block, {"Motion": Motion("rapid", dict(motion.axes))})  # intermediate point
            moving: dict[str, Section] = {"Motion": Motion("rapid", dict(self._reference(motion, block)))}
        else:
            text = ""
            moving = {**rest, "Motion": motion}
        mode = moving.get("DistanceMode")
        incremental = (self.modal.distance if mode is None else getattr(mode, "mode", None)) != "absolute"
        if any(isinstance(v, Expr) for v in moving["Motion"].axes.values()):  # type: ignore[attr-defined]
            self.unsupported("a computed position in machine coordinates", block)
        if incremental:
            moving["DistanceMode"] = DistanceMode("absolute")
        text += self._part(block, {"MachineCoordinates": MachineCoordinates(), **moving})
        if incremental:
            text += self._part(block, {"DistanceMode": DistanceMode("incremental")})
        if after:
            text += self._part(block, after)
        return text[:-1] + (block.eol or "\n")

    def _part(self, block: Block, sections: dict[str, Section]) -> str:
        part = Block(block.line, None, "\n")
        part.sections = sections
        return self.unsplit(part)

    def _reference(self, motion: Motion, block: Block) -> dict[str, float]:
        """The home position of each axis a reference return names, from the set-up, in program units."""
        inch = self.modal.units == "inch"
        problem = reference_problem(self.ctx.setup, motion, inch, "Fagor writes it as a G53 move to the home position",
                                    SECOND_RETURN + " (G30)")
        if problem is not None:
            self.unsupported(problem, block)
        return reference_target(self.ctx.setup, motion, inch)

    # -- tool data (``postproc.isg_family.tool_data`` chose the D) ---------------------------------------
    def tool_length_offset_words(self, s: Any, block: Block) -> list[str]:
        """``G43 D<n>`` applies offset n's length, ``G44`` cancels it (not Fanuc's negative offset)."""
        if s.mode == "cancel":
            return [self.code("length", "cancel", "tool length offset cancel", block)]
        if s.mode == "negative":
            self.unsupported("a negative tool length offset (Fanuc G44): Fagor's G44 cancels the offset, and no "
                             "code subtracts a length", block)
        if s.mode != "positive" or s.register is None:
            self.unsupported(f"tool length offset {s.mode}", block)
        return [self.code("length", "positive", "a tool length offset", block), "D" + self.register(s.register, block)]

    def cutter_compensation_words(self, s: Any, block: Block) -> list[str]:
        """``G41 D<r>``; the D is left out where the block's ``G43 D`` already selects it."""
        offset = block.sections.get("ToolLengthOffset")
        if offset is not None and getattr(offset, "register", None) == s.register:
            return self._code("cutter", s.mode, f"cutter compensation {s.mode}", block)
        return super().cutter_compensation_words(s, block)
