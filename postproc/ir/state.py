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
class ModalState:
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

    def apply(self, sections: Mapping[str, Any]) -> None:
        """Apply a block's modal sections (those that change nothing here are ignored)."""
        if changes_nothing(sections):
            return  # the common block: a move, maybe a block number
        for key, section in sections.items():
            change = _APPLY.get(key)
            if change is not None:
                change(self, section)

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
