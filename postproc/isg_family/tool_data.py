"""Tool data selected with ``D`` (the ISG/Fagor family): read into the neutral tool length and cutter
compensation sections, and written from another family's separate registers (Fanuc ``G43 H<n>`` for the
length, ``G41 D<r>`` for the radius).

The facts:

* ISG [V: Beckhoff TF5200 "Tool offset" (tf5200_coordinate_systems/306370955), "Tool geometry
  compensation" (tccncprogramming/15557086347), tool data ``wz[i]`` (tccnctooldata/15283111563)]:
  ``D<n>`` selects tool data block n, whose length (perpendicular to the main plane) and radius both
  apply; ``D0`` deselects (all zero). There is no length on/off code: the length applies while a D is
  selected. G41/G42 take the radius of the selected data. By default (P-CHAN-00100 = 0) a new length
  applies to Z only at the next block that programs Z absolutely (G90).
* Fagor [V: 8055 programming manual 8.2; 8070 programming manual REF 1709 p.240]: ``D<n>`` selects the
  tool offset (length and radius); ``G43`` turns length compensation on with it, **``G44`` cancels it**
  (Fanuc's G44 is a *negative* offset: the same number, another meaning); G41/G42 take the selected
  offset's radius. With no D selected the 8070 takes ``D1``. [?] The 8070 keeps its offsets per tool
  (T and D); here ``D<n>`` is the set-up's ``<Tool number="n">``, as on the 8055's offset table.

When the new length applies: ISG takes it at the next absolute position of Z (P-CHAN-00100 = 0, its
default; see ``Dialect.LENGTH_AT_PROGRAMMED_AXIS``), Fagor when the axis moves [V: 8055 manual 8.2,
``Fagor.LENGTH_AT_AXIS_MOVE``]. A source with the same rule (LinuxCNC: a change moves nothing, the next
programmed Z applies it) may change the length in a block without Z: towards ISG as it is, towards Fagor
while the next Z move is absolute (an incremental one, where the two may differ, is a located error). A
source without that rule (Fanuc: by its parameters the axis may move at the change) must change the length
beside an absolute Z move; towards Fagor one written alone is given that move first
(``postproc.lowering.length_timing``).

Writing from separate registers: one D carries both values, so the D written is the radius register
while radius compensation is on, else the length register (ISG: D0 without a length). Where that D would
bring another length than the program's (``G43 H1`` then ``G41 D21`` with another length in register
21; a G41 D1 run with no length offset), ISG is given the compensated path instead, as plain moves,
where the source's compensation rules are modelled (``resolve_radius_where_d_cannot``, exact to them);
otherwise the translation is a located error naming both registers; the set-up's ``<Tools>`` decides.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Final

from mypy_extensions import mypyc_attr

from ..compensation.tool_table import ToolTable
from ..context import Context
from ..dialect import Dialect
from ..interp.control import CONTROL
from ..errors import Location, PostprocError, UnsupportedError
from ..ir.expr import Expr
from ..ir import Block, CutterCompensation, DataSetting, Motion, ToolLengthOffset
from ..ir.keys import watches_none
from ..lowering.lower import BlockStep, LoweringStep
from ..lowering.units_and_distance import UnitsAndDistance

SELECTED_KEY: Final = "isg_family.tool_data"
"""``ModalState.extra`` key of the D selected while reading (an int or an expression)."""
_WATCHED: Final = frozenset(("ToolLengthOffset", "CutterCompensation", "DataSetting", "Units", "DistanceMode"))
SAME_MM: Final = 1e-9


# -- reading -----------------------------------------------------------------------------------------

def read_tool_data(block: Block, ctx: Context, values: dict[str, Any], used: set[str], toggles: bool,
                   first: int) -> None:
    """A block's ``D`` and the compensation sections it feeds (call after the G codes were read).

    ``toggles``: the length applies only while ``G43`` is in force (Fagor); otherwise while a D is
    selected (ISG). ``first``: the D in force before any (ISG 0, Fagor 1)."""
    extra = ctx.state.extra
    sections = block.sections
    if "D" in values:
        used.add("D")
        selected = values["D"]
        extra[SELECTED_KEY] = selected
        length_on = ctx.state.length == "positive" if toggles else True
        if "ToolLengthOffset" not in sections and length_on:
            zero = isinstance(selected, (int, float)) and selected == 0
            block.add(ToolLengthOffset("cancel") if zero and not toggles else ToolLengthOffset("positive", selected))
    selected = extra.get(SELECTED_KEY, first)
    offset = sections.get("ToolLengthOffset")
    if isinstance(offset, ToolLengthOffset) and offset.mode == "positive" and offset.register is None:
        offset.register = selected
    cutter = sections.get("CutterCompensation")
    if isinstance(cutter, CutterCompensation) and cutter.mode != "off" and cutter.register is None:
        cutter.register = selected


def expects_register(values: dict[str, Any], ctx: Context, first: int) -> None:
    """Fagor's ``G43`` takes the selected D (the rules read a register H): give it that one."""
    values.setdefault("H", values.get("D", ctx.state.extra.get(SELECTED_KEY, first)))


# -- writing -----------------------------------------------------------------------------------------

@mypyc_attr(allow_interpreted_subclasses=True)
class ResolveRadiusWhereDCannot(LoweringStep):
    """Lowering step for a target whose D brings its length (ISG always; Fagor while ``G43`` is on,
    ``LENGTH_TOGGLES``): a G41/G42 whose register has another length than the one in force becomes the
    compensated path (see the module docstring). It runs after the tool length timing, which decides that length,
    and it is the translation's one resolver: it resolves G41.1/G42.1 too, the generic step handing over to it
    (``postproc.lowering.cutter_compensation.TARGET_RESOLVES``)."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.dialect == target.NAME:
            return None
        from ..lowering.cutter_compensation import resolution_unless
        return resolution_unless(ctx, target, _d_keeps_the_length_on if target.LENGTH_TOGGLES else _d_keeps_the_length)


resolve_radius_where_d_cannot = ResolveRadiusWhereDCannot()


def _d_keeps_the_length_on(resolver: Any, cc: CutterCompensation) -> bool:
    """``_d_keeps_the_length`` on a target that applies a D's length only while its length code is on
    (Fagor ``G43``): with no length offset in force the D brings none, whatever its register holds."""
    return resolver.length_register is None or _d_keeps_the_length(resolver, cc)


def _d_keeps_the_length(resolver: Any, cc: CutterCompensation) -> bool:
    """Whether the D of ``cc``'s register brings the length in force (else the path is resolved); a
    register not known here is left to ``select_tool_data``, which says what is missing."""
    register = cc.register if cc.register is not None else resolver.spindle_tool
    length = resolver.length_register
    if not isinstance(register, int) or not (length is None or isinstance(length, int)):
        return True
    table: ToolTable = resolver.table
    try:
        have = table.length(register) if register else 0.0
        wanted = table.length(length) if length else 0.0
    except PostprocError:
        return True
    return abs(have - wanted) <= SAME_MM


@mypyc_attr(allow_interpreted_subclasses=True)
@dataclass
class _Selection:
    """The source's tool data selection in force (its length and radius registers). (A docstring of its own:
    ``dataclasses`` imports ``inspect`` to write one for a class without.)"""

    length: int | None = None
    """The source's length register in force (None: no length offset)."""
    radius: int | None = None
    """The source's radius register while cutter compensation is on."""
    written: int | None = None
    """The D the output has selected (None: none written yet)."""
    applied: float = 0.0
    """The length (mm) the output applies."""
    pending: bool = False
    """A length changed without a Z move, waiting for the next Z move (which must be absolute: Fagor)."""
    unapplied: Location | None = None
    """Where a length changed without a Z move that the source applies at its next move and the target only at
    an absolute Z: an error at the next block that moves unless it moves Z absolutely, none if nothing moves
    before the program ends (a ``G49`` before ``M30``)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class SelectToolData(LoweringStep):
    """Lowering step for a target that selects tool data with D (see the module docstring): a program
    of another family gets its length and radius registers as the D they need; the target's own
    programs pass. ``target.LENGTH_TOGGLES``: the target turns the length on and off by code (Fagor)."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.dialect == target.NAME:
            return None
        shifts = ctx.length_at_axis  # the reading dialect's LENGTH_AT_PROGRAMMED_AXIS (``Dialect.context``)
        return _Select(ctx, target.LENGTH_TOGGLES, shifts and not target.LENGTH_AT_PROGRAMMED_AXIS if shifts
                       else None)


select_tool_data = SelectToolData()


@mypyc_attr(allow_interpreted_subclasses=True)
class _Select(BlockStep):
    """``later_z``: a length may change without a Z move (the source applies it at the next Z, as the
    target does), True where that next Z move must then be absolute; None: it may not. A move is its
    business only while a changed length waits for one."""

    def __init__(self, ctx: Context, toggles: bool, later_z: bool | None) -> None:
        super().__init__()
        self.moves = False
        self.ctx = ctx
        self.toggles = toggles
        self.later_z = later_z
        self.table = ToolTable(ctx.setup)
        self.state = _Selection()
        self.modes = UnitsAndDistance()
        """The distance mode in force (ISG applies a new length at an absolute Z only), and the units."""

    def take(self, block: Block) -> list[Block] | None:
        made = self._take(block)
        state = self.state
        self.moves = state.unapplied is not None or state.pending
        return made

    def _take(self, block: Block) -> list[Block] | None:
        ctx, state, toggles, later_z, modes = self.ctx, self.state, self.toggles, self.later_z, self.modes
        sections = block.sections
        if state.unapplied is not None and _moves(block):
            motion = sections.get("Motion")
            if not (_moves_z(block, modes.absolute_in(sections) or toggles) and isinstance(motion, Motion)
                    and motion.mode not in ("home", "home2")):
                ctx.diagnostics.error(UnsupportedError(UNAPPLIED).located(state.unapplied))
            state.unapplied = None
        if state.pending and _z_move(block):
            state.pending = False
            if later_z and not modes.absolute_in(sections) and "MachineCoordinates" not in sections:
                ctx.diagnostics.error(UnsupportedError(
                    "the tool length changed before is applied by this incremental Z move on the target (when "
                    "the axis moves [?]), on the source's controller only at the next absolute Z: program Z "
                    "absolutely here", ctx.at(block, ctx.column_of(block, "Z"))))
        if watches_none(sections, _WATCHED):
            return None
        modes.follow(sections)
        setting = sections.get("DataSetting")
        if isinstance(setting, DataSetting):
            self.table.write(setting, modes.scale)
        if "ToolLengthOffset" in sections or "CutterCompensation" in sections:
            at = ctx.at(block, ctx.column_of(block, "H" if "ToolLengthOffset" in sections else "D"))
            try:
                if _rewrite(block, self.table, state, modes.absolute, toggles, later_z is not None):
                    state.unapplied = at
            except PostprocError as err:
                ctx.diagnostics.error(err.located(at))
                return []
        return None


def _register(value: int | Expr | None, what: str) -> int | None:
    if value is None or isinstance(value, int):
        return value
    raise UnsupportedError(f"a {what} register that is computed (the D selecting it is chosen from its value)")


def _rewrite(block: Block, table: ToolTable, state: _Selection, absolute: bool, toggles: bool, later_z: bool) -> bool:
    """The block's length and radius registers as the D (and, with ``toggles``, G43/G44) they need. True: the
    new length is left for a later move, which must move Z absolutely (``_Selection.unapplied``)."""
    sections = block.sections
    offset = sections.get("ToolLengthOffset")
    cutter = sections.get("CutterCompensation")
    length_changed = isinstance(offset, ToolLengthOffset)
    if isinstance(offset, ToolLengthOffset):
        if offset.mode == "negative" and cutter is None:
            return False  # left to the writer, which refuses it (with --on-unsupported warn: that word only)
        if offset.mode == "dynamic":
            raise UnsupportedError("a dynamic tool length offset (a length given in the program, not a register of "
                                   "the tool table: the target selects a tool's data with D)")
        if offset.mode not in ("positive", "cancel"):
            raise UnsupportedError(f"a tool length offset '{offset.mode}'")
        state.length = _register(offset.register, "tool length") if offset.mode == "positive" else None
        if offset.mode == "positive" and state.length is None:
            raise UnsupportedError("a tool length offset without its register")
    if isinstance(cutter, CutterCompensation):
        if cutter.mode == "off":
            state.radius = None
        else:
            radius = _register(cutter.register, "cutter radius")
            state.radius = radius if radius is not None else state.radius if state.radius is not None else state.written
            if state.radius is None:
                raise UnsupportedError("cutter compensation without its register, and no tool data selected")
    want = state.radius if state.radius is not None else state.length if state.length is not None else 0
    wanted_mm = 0.0 if state.length is None else table.length(state.length)
    if want != state.length and (state.length is not None or not toggles):
        have = table.length(want) if want else 0.0
        if abs(have - wanted_mm) > SAME_MM:
            raise UnsupportedError(
                f"D{want} selects the length and the radius together, and its length ({have:g} mm) is not the "
                + (f"length of register {state.length} ({wanted_mm:g} mm) in force" if state.length is not None
                   else "zero the program runs with (no length offset)")
                + f": give register {want} that length in the set-up's <Tools>, or use one register for both")
    unapplied = False
    if abs(wanted_mm - state.applied) > SAME_MM and not _moves_z(block, absolute or toggles):
        if later_z:
            state.pending = True  # both apply it at the next (absolute) Z: checked there
        else:
            unapplied = True  # the source applies it at its next move: checked there
    state.applied = wanted_mm
    sections.pop("ToolLengthOffset", None)
    if toggles:  # Fagor: G43 D<n> / G44, and G41 D<r>
        if length_changed:
            sections["ToolLengthOffset"] = (ToolLengthOffset("positive", want) if state.length is not None
                                            else ToolLengthOffset("cancel"))
        if isinstance(cutter, CutterCompensation):
            sections["CutterCompensation"] = CutterCompensation(cutter.mode, want if cutter.mode != "off" else None)
        if state.length is not None or state.radius is not None:
            state.written = want
    else:  # ISG: D<n> selects both; G41/G42 take the selected one's radius
        if isinstance(cutter, CutterCompensation):
            sections["CutterCompensation"] = CutterCompensation(cutter.mode, None)
        if want != state.written or length_changed:
            sections["ToolLengthOffset"] = ToolLengthOffset("positive", want) if want else ToolLengthOffset("cancel")
            state.written = want
    block.changed()
    return unapplied


UNAPPLIED = ("the new tool length is applied only at a move of Z (ISG: programmed absolutely, P-CHAN-00100 by "
             "default; Fagor: when the axis moves), the source's at its next move: program the length offset beside "
             "a Z move")


def _moves(block: Block) -> bool:
    """Whether a block may move an axis (a call or jump runs moves elsewhere: counted as one)."""
    sections = block.sections
    motion = sections.get("Motion")
    if isinstance(motion, Motion) and motion.axes:
        return True
    return any(key in sections for key in ("CompoundMotion", "CannedCycle", "CycleCall", CONTROL))


def _z_move(block: Block) -> bool:
    motion = block.sections.get("Motion")
    return isinstance(motion, Motion) and "Z" in motion.axes


def _moves_z(block: Block, absolute: bool) -> bool:
    """The block moves Z to a position: under ``absolute``, or in machine coordinates, which are positions under
    G91 too (the IR's ``MachineCoordinates``; the target writes such a move after ``G90``:
    ``postproc.isg_family.machine_moves``)."""
    motion = block.sections.get("Motion")
    return isinstance(motion, Motion) and "Z" in motion.axes and (absolute or "MachineCoordinates" in block.sections)
