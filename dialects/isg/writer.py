"""ISG writer: DIN words spelt from ISG's table (G70/G71 units, G04 X seconds), expressions and ``$``
statements in ISG's spelling, ``P`` parameters for the neutral ``#501``-``#999``.

* A block read from ISG and unchanged is copied byte for byte (``WordWriter``).
* Canned cycles arrive expanded (ISG's ``G80``-``G89`` are the machine builder's subroutine files, not
  cycles): the return level and the cycle cancel of the source say nothing here and are not written,
  so Fanuc's ``G98``/``G99`` (ISG's software limit switches) and ``G80`` never reach ISG text.
* Calls: ``LL name`` for a local subroutine (``<name>``), ``L file`` for a global one; a call with
  arguments or a repeat count has no ISG spelling here. A numbered subprogram of another dialect
  (LinuxCNC ``o100 sub``, Fanuc ``O2000``) is refused, its definition and its calls alike
  (``SubprogramNames``): ISG names its subroutines (``%L <name>`` [V]), and whether a name of digits
  only is one is not confirmed [?].
* A subroutine's end and a return are ``M17``; the definition's start is ``%L name``.
* A move in machine coordinates (Fanuc ``G53``) is ``#SUPPRESS OFFSETS X..`` [V: TF5200 programming manual
  207072907: the positions without any active offset, tool offsets included, in that block only], alone in
  its block after ``G00`` (Fanuc moves there at rapid) and ``G90``; a reference return (``G28``) is its
  intermediate move, then such a move to the set-up's ``<Axis home>`` (ISG's ``G74`` homes the axis, a
  reference search, not a return). ISG's own ``G53`` (zero offset deselection) is never written.
"""

from __future__ import annotations

from typing import Any, ClassVar

from postproc.context import Context
from postproc.interp.control import Assign, Call, Return, SubEnd, SubStart
from postproc.dialect import Dialect
from postproc.errors import UnsupportedError
from postproc.ir.expr import Expr
from postproc.ir.event_order import after_motion
from postproc.ir import Block, DistanceMode, Motion, Section
from postproc.output.home_position import SECOND_RETURN, reference_problem, reference_target
from postproc.rs274.codes import CodeTable
from postproc.isg_family.taps import stroke_words
from postproc.rs274.writer import WordWriter
from postproc.interp.subprogram_names import NameRule, SubprogramNames

from .codes import CODES
from .commands import OPENING, command_line
from postproc.isg_family.expressions import spell_expr, spell_var, spell_word_value
from postproc.isg_family.statements import spell_statement


REFERENCE = frozenset(("home", "home2"))
"""Motion modes of a reference return."""
_WITH_DWELL = ("Dwell", "Sequence")
"""What shares an ISG dwell's block."""
_ALONE_WITH_DWELL = frozenset((*_WITH_DWELL, "Comments", "BlockDelete"))
"""What a dwell's block may hold without being split."""

class IsgWriter(WordWriter):
    DIALECT: ClassVar[str] = "isg"
    CODES: ClassVar[CodeTable] = CODES
    DWELL_WORD: ClassVar[str] = "X"
    SUBPROGRAM_NAMES: ClassVar[NameRule] = NameRule(numbers=range(0), spare=range(0), names=True)
    """Local subroutines by name only (DIALECTS.md 1.3 [V])."""
    SPLIT: ClassVar[frozenset[str]] = frozenset(("MachineCoordinates", "Dwell", "Label", "DataSetting"))
    """A move in machine coordinates, a dwell beside other words, a label, a work offset setting:
    ``split_block``."""
    TOOL_TABLE_LACK: ClassVar[str] = (
        "ISG writes a tool's length and radius from a program (V.G.WZ[j].L, V.G.WZ[j].R) only with an internal tool "
        "table, an external tool management's entries being read-only [V: TF5200 external tool management, "
        "\"Access to tool data in the NC program (V.G.WZ..)\"]; which the machine has, and when a written entry acts "
        "on the selected D, a set-up does not say [?]: not written here")
    WORK_OFFSET_VARIABLE: ClassVar[str] = "V.G.NP[{index}].V.{axis}={value}"
    """Another dialect's work offset setting (Fanuc ``G10 L2 P2 X0``) is ``V.G.NP[2].V.X=0`` [V: Beckhoff TF5200
    programming manual, "Zero offsets (G53/G54/...G59)", example ``V.G.NP[1].V.X=10`` then ``G54`` ("corresponds
    to group [1]")]: it writes the zero offset list, and the decoder takes a list entry when its G54-G59 is
    selected [K: same manual, "Enhanced zero offset variables": a write via ``V.G.NP_AKT`` acts on the offset in
    the decoder only, and the list's values come back when that offset is selected again], so for the active
    system the selection is written again after it (``work_offset_assignments``)."""
    WORK_OFFSET_COUNT: ClassVar[int] = 6
    """V.G.NP[1]-[6]: G54-G59."""
    SPLIT_MOTIONS: ClassVar[frozenset[str]] = REFERENCE
    """A reference return: ``split_block`` (``machine_move``)."""

    def __init__(self, ctx: Context, source_dialect: str, target: type[Dialect] | None = None) -> None:
        super().__init__(ctx, source_dialect, target)
        self.names = SubprogramNames(self.SUBPROGRAM_NAMES)
        """Another dialect's subprograms: the names written for their definitions and calls."""
        self._verbatim: str | None = None
        """The ``#`` command that opened the lines being normalised as they are (``#VAR``, ``#COMMENT``)."""

    def normalized(self, block: Block) -> str:
        """An ISG block rebuilt from its words; what has none keeps its own text: the program header
        (``%1``), a ``#`` command line, and the lines of ``#VAR`` (a declaration's type is in its text only)
        and ``#COMMENT`` blocks (read as comments, they are no parenthesised ones)."""
        text = block.text or ""
        command = command_line(text)
        if self._verbatim is not None:
            if command == OPENING[self._verbatim]:
                self._verbatim = None
            return text
        if command is not None:
            if command in OPENING:
                self._verbatim = command
            return text
        start = block.sections.get("ProgramStart")
        if start is not None and not block.words:
            return text.strip()
        return super().normalized(block)

    def local_name(self, name: str, block: Block) -> str:
        """The subroutine name of a definition or ``LL`` call (``SubprogramNames``, then ISG's characters)."""
        if self.source_dialect != self.DIALECT:
            try:
                name = self.names.of(name)
            except UnsupportedError as err:
                self.unsupported(err.message, block)
        return _local(name, block, self)

    def expression(self, expr: Expr, block: Block, what: str = "a computed word") -> str:
        try:
            return spell_word_value(expr)
        except UnsupportedError as err:
            if err.location is None:
                err.located(self.ctx.at(block))
            raise

    def split_block(self, block: Block) -> str | None:
        if "DataSetting" in block.sections:
            setting = self.work_offset_assignments(block, self._part)
            if setting is not None:
                return setting
        motion = block.sections.get("Motion")
        if isinstance(motion, Motion) and ("MachineCoordinates" in block.sections or motion.mode in REFERENCE):
            return self.machine_move(block, motion)
        return self.generate_words(block)

    def generate_words(self, block: Block) -> str:
        """A dwell is alone in its ISG block (only a block number may join it), in the block's order of
        events (``postproc.ir.event_order``): what acts before the dwell (settings, tool, spindle start, coolant
        on) in a block before it, the motion and what ends the block after it."""
        sections = block.sections
        if "Dwell" in sections and any(k not in _ALONE_WITH_DWELL for k in sections) \
                and "CompoundMotion" not in sections:
            return self.around_dwell(block, _WITH_DWELL)
        label = sections.get("Label")
        if label is not None:
            return f"[{getattr(label, 'name')}] " + self.unsplit(block)
        return self.unsplit(block)

    def program_start(self, s: Any, block: Block) -> str:
        return "%" + (str(s.number) if s.number is not None else str(s.name))

    # -- machine coordinates ---------------------------------------------------------------------------
    def machine_move(self, block: Block, motion: Motion) -> str:
        """A move in machine coordinates (Fanuc ``G53``) or a reference return (``G28``: through its
        intermediate point to the set-up's home position) as ``#SUPPRESS OFFSETS``, alone in its block, at
        rapid and in absolute positions; what the block sets goes before it, what it ends after it."""
        sections = block.sections
        if "BlockDelete" in sections:
            self.unsupported("a block skip on a move in machine coordinates (#SUPPRESS OFFSETS is a block "
                             "of its own)", block)
        moving = ("Motion", "MachineCoordinates", "Sequence")
        before = {k: v for k, v in sections.items() if k not in moving and not after_motion(k, v)}
        after = {k: v for k, v in sections.items() if k not in moving and k not in before}
        if "Sequence" in sections:
            before = {"Sequence": sections["Sequence"], **before}
        own = before.get("DistanceMode")
        say_absolute = isinstance(own, DistanceMode) and own.mode == "absolute" and motion.mode not in REFERENCE
        if say_absolute:  # (``absolute_machine_moves``' G90 for a run of them): on the line of the modes
            del before["DistanceMode"]
        text = self._part(block, before)
        if motion.mode in REFERENCE:
            if motion.axes and (self.modal.distance == "absolute" or any(v != 0 for v in motion.axes.values())):
                text += self._part(block, {"Motion": Motion("rapid", dict(motion.axes))})  # the intermediate point
            target: dict[str, float | Expr] = dict(self._reference(motion, block))
        else:
            target = dict(motion.axes)
        incremental = self.modal.distance != "absolute"
        if say_absolute:
            self.modal.distance = "absolute"
        rapid = [] if self.modal.motion == "rapid" else [self.code("motion", "rapid", "rapid motion", block)]
        modes = ([self.code("distance", "absolute", "absolute distance mode", block)]
                 if incremental or say_absolute else []) + rapid
        words = []
        for axis, value in target.items():
            if not isinstance(value, (int, float)):
                self.unsupported("a computed position in machine coordinates", block)
            words.append(axis + self.number(float(value), axis))
            self.carry.pop(axis, None)
        if words:  # a return naming no axis moves none (Fanuc G28 alone): nothing to write for it
            text += (" ".join(modes) + "\n" if modes else "") + "#SUPPRESS OFFSETS " + " ".join(words) + "\n"
            if incremental and not say_absolute:  # (a G90 of the block's own stays in force, as in the source)
                text += self.code("distance", "incremental", "incremental distance mode", block) + "\n"
        text += self._part(block, after)
        if not text.endswith(block.eol or "\n"):
            text = text[:-1] + (block.eol or "\n")
        return text

    def _part(self, block: Block, sections: dict[str, Section]) -> str:
        if not sections:
            return ""
        part = Block(block.line, None, "\n")
        part.sections = sections
        return self.generate_words(part)

    def _reference(self, motion: Motion, block: Block) -> dict[str, float]:
        """The home position of each axis a reference return names, from the set-up, in program units."""
        inch = self.modal.units == "inch"
        problem = reference_problem(self.ctx.setup, motion, inch,
                                    "ISG writes it as a move to the home position in machine coordinates",
                                    SECOND_RETURN + " (G30)")
        if problem is not None:
            self.unsupported(problem, block)
        return reference_target(self.ctx.setup, motion, inch)

    def statement_words(self, section: Section, block: Block) -> list[str]:
        try:
            if isinstance(section, Assign):
                return [f"{spell_var(var)}={spell_expr(value)}" for var, value in section.items]
            if isinstance(section, Call):
                return self.call_words(section, block)
            if isinstance(section, SubStart):
                return ["%L " + self.local_name(section.name, block)]
            if isinstance(section, SubEnd):
                if section.value is not None:
                    self.unsupported("a subprogram end returning a value", block)
                return ["M17"]
            if isinstance(section, Return):
                if section.value is not None or section.target is not None:
                    self.unsupported("a return with a value or to a block number", block)
                return ["M17"]
            return [spell_statement(section)]
        except UnsupportedError as err:
            if err.location is None:
                err.located(self.ctx.at(block))
            raise

    def call_words(self, call: Call, block: Block) -> list[str]:
        if call.args or call.repeat is not None:
            self.unsupported("a subroutine call with arguments or a repeat count", block)
        if not isinstance(call.name, str):
            self.unsupported("a call of a computed program number", block)
        if call.name.startswith("<") or call.name.isdigit():
            return ["LL " + self.local_name(call.name, block)]
        return ["L " + call.name]

    def rigid_tap_words(self, s: Any, block: Block) -> list[str]:
        """A rigid tap stroke, ``G331`` in or ``G332`` out, as ISG and SINUMERIK write it
        (``postproc.isg_family.taps.stroke_words``; read by ``taps``)."""
        return stroke_words(self, s, block, "ISG")

    def return_level_words(self, s: Any, block: Block) -> list[str]:
        """Fanuc's G98/G99 steer canned cycles, which reach ISG expanded: nothing to write."""
        return []

    def cycle_cancel_words(self, s: Any, block: Block) -> list[str]:
        """Cycles reach ISG expanded, so there is nothing to cancel (ISG's G80 is a subroutine call)."""
        return []

    # -- tool data (``postproc.isg_family.tool_data`` chose the D) ---------------------------------------
    def tool_length_offset_words(self, s: Any, block: Block) -> list[str]:
        """``D<n>`` selects tool data n (its length applies), ``D0`` none: ISG has no other length code."""
        if s.mode == "cancel":
            return ["D0"]
        if s.mode == "negative":
            self.unsupported("a negative tool length offset (Fanuc G44): D adds the tool's length, and no code "
                             "subtracts it", block)
        if s.mode != "positive" or s.register is None:
            self.unsupported(f"tool length offset {s.mode} (ISG selects a tool's data with D)", block)
        return ["D" + self.register(s.register, block)]

    def cutter_compensation_words(self, s: Any, block: Block) -> list[str]:
        """``G41``/``G42`` take the radius of the selected D: a D is written only where no ``D`` of the
        block's length offset selects it already."""
        if "ToolLengthOffset" in block.sections:
            return self._code("cutter", s.mode, f"cutter compensation {s.mode}", block)
        return super().cutter_compensation_words(s, block)


def _local(name: str, block: Block, writer: IsgWriter) -> str:
    bare = name[1:-1] if name.startswith("<") and name.endswith(">") else name
    if not bare or any(not (c.isalnum() or c in "_.") for c in bare):
        writer.unsupported(f"the subroutine name {name!r}", block)
    return bare
