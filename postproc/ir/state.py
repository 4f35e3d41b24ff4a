"""Modal state of a controller while a program streams through a pipeline.

Neutral: it knows 'rapid' and 'initial level', never 'G00' or 'G98'. Positions are in program units
(converted when the units change) and None while unknown, so a step that needs an absolute position it
does not have can fail loudly instead of guessing.

One model for every stage: the reading pipeline (``ctx.state``), the writer (what it has written so
far) and the toolpath simulator each keep a ``ModalState`` and change it only through ``apply``.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Callable, Mapping, Final

from mypy_extensions import mypyc_attr

from .expr import Expr

MM_PER_INCH: Final = 25.4
LEFT_START: Final = "state.left_start"
"""``ModalState.extra`` key: a move the reading cannot place (a reference return, a machine-coordinate move)
has taken the machine from its start (``postproc.frames.parameters``' reads at the start)."""

PLACED_AXES: Final = ("X", "Y", "Z")
"""The linear axes ``SetUpPlaces`` follows (an arc's plane is two of them)."""
PLACED_LENGTH_AXIS: Final = "Z"
"""The axis a tool length offset acts on (a mill's): not placed while one is in force."""

PLANE_AXES: Final = {"XY": ("X", "Y", "Z"), "ZX": ("Z", "X", "Y"), "YZ": ("Y", "Z", "X")}
"""Per plane: first and second plane axis, then the axis normal to the plane (the drilling axis). ``Final``:
compiled, a read is a C static's, not a look-up in the module's globals (the cycle expansion reads it every block)."""


@mypyc_attr(allow_interpreted_subclasses=True)
@dataclass(slots=True)
class CycleState:
    """The active canned cycle and its modal data (Fanuc: Z, R, Q, P, F stay in force)."""

    kind: str
    words: dict[str, float | int] = field(default_factory=dict)
    initial: float | None = None
    """Initial level on the drilling axis when the cycle was first commanded."""


@mypyc_attr(allow_interpreted_subclasses=True)
@dataclass(slots=True)
class SetUpPlaces:
    """Where the set-up puts the tool after a move the program text does not place, for a translation's reading.

    A reference return (``G28``), a move in machine coordinates (``G53``) and a change of work system (``G55``)
    leave the reading's position unknown: the work position then depends on the machine's reference positions and
    work offsets. A translation to another dialect refuses an arc whose shape depends on such an unknown start
    (``postproc.syntaxes.modal_state._refuse_unknown_start``): its controller checks the radius from wherever the
    machine stands. Where the set-up declares those values (``<Axes><Axis home>``, ``<WorkOffsets>``), the
    simulator takes the tool there (``postproc.simulate.simulator``: ``machine_to_frame``), and so does the
    reading's state (``ModalState.places``):

        work position = machine position - (offset of the active work system + external offset)

    with the machine position the declared home (a first reference return), the block's machine word (a move in
    machine coordinates under absolute distance), or the work position before a change of work system plus the old
    offsets. Only declared values count, as in ``postproc.lowering.machine_positions`` (issue 26: a guess cannot be
    seen by ``verify``, whose two sides would share it). What the set-up does not give, a tool length offset in
    force on the axis (the programmed point is the controlled point less the length), a second reference return,
    and any offset or frame the program sets (``G10``, ``G92``, a frame command: values the run holds) leave the
    axis unknown. A lathe (diameters, U/W increments, tool offsets) is not followed.

    Data the state reads where it follows those blocks (``_work_offset_change``, ``ModalState.place``, and
    ``ModalStateSyntax`` at a reference return or machine move), made from the set-up by
    ``postproc.setup.work_offsets.set_up_places``: no call of a hook at the blocks that change a mode."""

    homes: dict[str, float]
    """Each followed axis's reference position (machine coordinates, mm), where the set-up gives one."""
    offsets: dict[int, dict[str, float]]
    """Machine minus work position (mm) by work system and axis, where the set-up gives the system's offset: its
    own plus the external one (``postproc.setup.work_offsets.offset_beyond_frame``)."""


@mypyc_attr(allow_interpreted_subclasses=True)
@dataclass(slots=True)
class ModalState:
    """The modal values in force where a program stands (motion, plane, units, feed, spindle, tool...), as its
    blocks left them. (A docstring of its own: ``dataclasses`` writes one for a class without, importing
    ``inspect`` at every start to do it: ``postproc.commands.launch``.)"""

    motion: str | None = None
    plane: str = "XY"
    units: str = "mm"
    distance: str = "absolute"
    feed_mode: str = "per_min"
    feed: float | None = None
    spindle_rpm: float | None = None
    spindle: str = "stop"
    return_level: str = "initial"
    work_offset: int = 1
    tool: int | None = None
    length: str = "cancel"
    """The tool length offset mode in force ("positive", "negative", "cancel"): an offset register word
    alone changes the offset only while one is (``ToolLengthOffset``)."""
    cycle: CycleState | None = None
    position: dict[str, float | None] = field(default_factory=lambda: {"X": None, "Y": None, "Z": None})
    extra: dict[str, Any] = field(default_factory=dict)
    """Room for dialect- or syntax-specific modal data (keyed by the syntax's XML name)."""
    computes: bool = False
    """A construct (an assignment, a jump, a loop, a call) was met in the text: from there on the order of
    the text is not the order of execution, so a check that follows the text (a feed move at a zero
    feed rate) is left to the run."""
    symbolic: bool = False
    """A computed word (an ``Expr`` kept symbolically) was met: positions may be computed, so the steps
    that track them check for one (a straight program never pays for the check)."""
    places: SetUpPlaces | None = None
    """The set-up's declared homes and work offsets, where this state follows them (a translation's reading to
    another dialect on a mill whose set-up declares work offsets: ``postproc.api``); None: the positions those
    blocks leave stay unknown (every other state). A section the program sets its frame with ends the following."""

    def apply(self, sections: Mapping[str, Any]) -> None:
        """Apply a block's modal sections (those that change nothing here are ignored)."""
        if changes_nothing(sections):
            return  # the common block: a move, maybe a block number
        machine = None if self.places is None else _work_offset_change(self, sections)
        for key, section in sections.items():
            change = _APPLY.get(key)
            if change is not None:
                change(self, section)
        if machine is not None:
            self.place(machine)  # after the whole block: in the new work system, in the block's units

    def place(self, machine: dict[str, float]) -> None:
        """Put each machine position (mm) in the work frame of the active work system, in program units, on the
        axes still unknown whose offset the set-up gives (``places``; nothing without it)."""
        places = self.places
        if places is None:
            return
        offsets = places.offsets.get(self.work_offset)
        if offsets is None:
            return
        scale = MM_PER_INCH if self.units == "inch" else 1.0
        position = self.position
        for axis, value in machine.items():
            offset = offsets.get(axis)
            if offset is not None and position.get(axis, 0.0) is None:
                position[axis] = round((value - offset) / scale, 12) + 0.0

    def set_units(self, system: str) -> None:
        """Switch units, converting the tracked position (a controller keeps the physical position)."""
        if system == self.units:
            return
        factor = MM_PER_INCH if system == "mm" else 1.0 / MM_PER_INCH
        for axis, value in self.position.items():
            if value is not None and axis in "XYZUVW":
                self.position[axis] = value * factor
        self.units = system


def _known(value: Any) -> Any:
    """A number, or None for a computed value (an expression kept symbolically: known only at run time)."""
    return None if isinstance(value, Expr) else value


def _work_offset_change(state: ModalState, sections: Mapping[str, Any]) -> dict[str, float] | None:
    """Before a block, while the state follows the set-up's places: the machine position (mm) of each axis whose
    work position and old offset are known, where the block changes the work system (``place`` puts them in the
    new one after it); None where it does not. A block that sets the frame itself (a frame command, a coordinate
    setting, a ``DataSetting`` of a work offset, ``G10 L2``/``L20``; a tool table's entry changes no work position)
    ends the following: the frame then holds values only the run knows."""
    setting = sections.get("DataSetting")
    if "FrameChange" in sections or "CoordinateSet" in sections or (
            setting is not None and str(getattr(setting, "table", "")).startswith("work_offset")):
        state.places = None
        return None
    work = sections.get("WorkOffset")
    if work is None:  # (most blocks: no ``getattr`` of None, whose error compiled code makes and drops)
        return None
    index = work.index
    places = state.places
    if not isinstance(index, int) or index == state.work_offset or places is None:
        return None
    offsets = places.offsets.get(state.work_offset, {})
    scale = MM_PER_INCH if state.units == "inch" else 1.0
    machine: dict[str, float] = {}
    for axis in PLACED_AXES:
        here = state.position.get(axis)
        offset = offsets.get(axis)
        if here is not None and offset is not None:
            machine[axis] = here * scale + offset
    return machine


def _offset_set(state: ModalState, s: Any) -> None:
    """G10 work offset data: the work position is unknown on the axes it sets (the origin moved under it)."""
    if str(getattr(s, "table", "")).startswith("work_offset"):
        for axis in getattr(s, "values", {}):
            if axis in state.position:
                state.position[axis] = None


def _work_offset(state: ModalState, s: Any) -> None:
    """A new work offset moves the origin: the work position is unknown until programmed again. The
    active one selected again moves nothing (a CAM program's ``G54`` beside its first arc keeps the arc
    checkable)."""
    if s.index == state.work_offset:
        return
    state.work_offset = s.index
    position = state.position
    for axis in position:
        position[axis] = None


def _frame_change(state: ModalState, s: Any) -> None:
    """A frame command (``postproc.frames``): G92 gives the present point its words; any other command
    moves the program position by what only the frame knows, so it is unknown on the axes it names (a
    rotation, scaling or mirror: on every axis of the plane) until programmed again."""
    position = state.position
    kind, words = s.kind, s.words
    if s.rules == "chain":  # a replacing command clears every component: any axis may move
        for axis in "XYZ":
            if axis in position:
                position[axis] = None
        return
    if kind in ("polar", "polar_off"):
        state.extra["polar"] = kind == "polar"  # words are a radius and an angle: the arc check waits for the run
        for axis in PLANE_AXES[state.plane][:2]:
            position[axis] = None
        return
    if kind == "origin":
        for axis, value in words.items():
            if axis in position:
                position[axis] = _known(value)
        return
    if kind in ("local", "mirror", "mirror_off"):
        axes = [a for a in words if a in position]
    elif kind in ("rotate", "rotate_off"):
        axes = [a for a in PLANE_AXES[state.plane][:2]]
    elif kind == "scale" and "P" not in words:
        axes = [a for letter, a in (("I", "X"), ("J", "Y"), ("K", "Z")) if letter in words]
    else:
        axes = list(position)
    for axis in axes:
        position[axis] = None


_APPLY: Final[dict[str, Callable[[ModalState, Any], None]]] = {
    "Units": lambda st, s: st.set_units(s.system),
    "Plane": lambda st, s: setattr(st, "plane", s.plane),
    "DistanceMode": lambda st, s: setattr(st, "distance", s.mode),
    "FeedMode": lambda st, s: setattr(st, "feed_mode", s.mode),
    "Feed": lambda st, s: setattr(st, "feed", _known(s.value)),
    "SpindleSpeed": lambda st, s: setattr(st, "spindle_rpm", _known(s.rpm)),
    "SpindleControl": lambda st, s: setattr(st, "spindle", s.direction),
    "ReturnLevel": lambda st, s: setattr(st, "return_level", s.level),
    "WorkOffset": _work_offset,
    "DataSetting": lambda st, s: _offset_set(st, s),
    "ToolSelect": lambda st, s: setattr(st, "tool", _known(s.number)),
    "ToolLengthOffset": lambda st, s: setattr(st, "length", s.mode),
    "FrameChange": _frame_change,
}
"""How each modal section changes the state; sections not listed change nothing here."""

MODAL_KEYS: Final = frozenset(_APPLY)
"""Section keys that change the modal state."""


def changes_nothing(sections: Mapping[str, Any]) -> bool:
    """True when a block's sections hold no modal section (most blocks: a move and a block number). The
    hot paths test it before calling ``ModalState.apply``. A loop over the block's two or three keys:
    compiled, it costs a fifth of ``MODAL_KEYS.isdisjoint(sections)`` (a bound method call that builds a
    key iterator; ~630 instructions, twice per block)."""
    if isinstance(sections, dict):  # narrowed, compiled code iterates the dict directly
        for key in sections:
            if key in MODAL_KEYS:
                return False
        return True
    return MODAL_KEYS.isdisjoint(sections)
