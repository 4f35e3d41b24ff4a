"""The base of the cycle expansions: a tool path builder and the per-hole loop they share.

Each family (drilling, pecking, tapping, ...) is a syntax object that turns a resolved ``CannedCycle``
into a ``CompoundMotion``: absolute rapids and feeds in program units, dwells, spindle actions. The
builder works in plane coordinates (first and second plane axis, drilling-axis level) so one
sequence serves G17, G18 and G19, and it drops zero-length moves, as a controller's path does.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

import abc
from typing import TYPE_CHECKING, Any, ClassVar, Final

from postproc.errors import ConfigError, ProgramError
from postproc.ir.expr import Expr
from postproc.ir import Block, CompoundMotion, Dwell, Feed, Motion, ProgramControl, Section, SpindleControl
from postproc.ir import SpindleOrientation
from postproc.ir.state import PLANE_AXES
from postproc.context import Context
from postproc.syntaxes.syntax import Syntax

from .section import CannedCycle
from .semantics import Semantics, semantics_named, semantics_names

if TYPE_CHECKING:  # annotations only: lxml is imported where XML is read or written (postproc.xmlio)
    from lxml import etree

EPS: Final = 1e-9
"""Two levels closer than this are the same level (float noise of repeated increments)."""
UNBOUNDED: Final = 1 << 62
"""No bound on the items of one expansion (the callers that read a set-up pass its
``<Limits movesPerBlock>``)."""


def rules_of(cycle: CannedCycle) -> Semantics:
    """The family rules the cycle was resolved under (``CannedCycle.semantics``). A name no family has (an IR
    file's, a plugin's) is an error: the core has no default family whose rules it could move by instead."""
    rules = semantics_named(cycle.semantics)
    if rules is None:
        raise ConfigError(f"a hole cycle resolved under the rules {cycle.semantics!r}, which are not modelled "
                          f"(known: {', '.join(semantics_names())}): its motion cannot be made")
    return rules


@mypyc_attr(allow_interpreted_subclasses=True)
class TooManyMoves(ProgramError):
    """An expansion would exceed the set-up's bound on moves per block. ``role`` names the cycle word to
    point at: "repeat" (the repeat count) or "peck" (the peck depth)."""

    def __init__(self, message: str, role: str) -> None:
        super().__init__(message)
        self.role = role


@mypyc_attr(allow_interpreted_subclasses=True)
class ToolPath:
    """Collects the items of one expansion, tracking where the tool is. The items are a list (the
    writer, the simulator and the lowering steps walk them more than once), bounded by ``limit``: at
    most ``limit`` items are ever held, then ``TooManyMoves``."""

    __slots__ = ("axes", "start", "a", "b", "n", "items", "feed", "limit", "last")

    def __init__(self, cycle: CannedCycle, limit: int = UNBOUNDED) -> None:
        self.axes = first, second, normal = PLANE_AXES[cycle.plane]
        start = cycle.start
        self.start = start
        """Where the tool is when the cycle starts (``end`` keeps the axes outside the plane as they are)."""
        self.a: float | None = start.get(first)
        self.b: float | None = start.get(second)
        self.n: float | None = start.get(normal)
        """Where the tool is on the plane's two axes and its normal (None: not known yet). Three fields,
        not a position dict: they are read and written at every move of every hole."""
        self.items: list[Section] = []
        self.feed = cycle.feed
        """Feed in force: the block's own F is already applied, so a Feed item appears only on a change."""
        self.limit = limit
        self.last: dict[str, float | Expr] | None = None
        """The axes of the last move made, while they name the plane's two axes and the normal at ``a``, ``b``
        and ``n`` (None: not so): the next move's are a copy of them (``_axes``)."""

    def add(self, item: Section) -> None:
        """Append an item, counting it against the bound on moves per block."""
        if len(self.items) >= self.limit:
            raise TooManyMoves(f"the expansion makes more than {self.limit} moves in one block (the set-up's "
                               "<Limits movesPerBlock>)", "repeat")
        self.items.append(item)

    def level(self) -> float:
        """Where the tool is on the normal axis."""
        n = self.n
        if n is None:
            raise ProgramError(f"the tool's {self.axes[2]} position is unknown before the cycle")
        return n

    def set_level(self, level: float) -> None:
        """The tool is at ``level`` on the normal axis without a move of its own (LinuxCNC's G88 ends its
        manual retract there)."""
        self.n = level

    def rapid(self, a: float | None = None, b: float | None = None, level: float | None = None) -> None:
        self._move("rapid", a, b, level)

    def cut(self, level: float, feed: float | None) -> None:
        """Feed along the drilling axis (down into the hole, or up in back boring). (The feed of every cut of a
        cycle is the one object ``cycle.feed``: the same object is the same feed, without a compare of numbers.)"""
        given: Any = feed
        if given is not None and given is not self.feed and given != self.feed:
            self.add(Feed(feed))  # type: ignore[arg-type]
            self.feed = feed
        self._move("linear", None, None, level)

    def _move(self, mode: str, a: float | None, b: float | None, level: float | None) -> None:
        """A rapid or feed to the given plane position and level (None: where the tool is on that axis);
        a move shorter than ``EPS`` on every axis is no move. (The positions are held as the objects they
        are, ``Any``, never narrowed from ``float | None``: compiled, a narrowed float is unboxed, and each
        use of it as an object, a word of the move or a field, boxes it anew: six new floats a move.)"""
        was_a: Any = self.a
        was_b: Any = self.b
        was_n: Any = self.n
        given_a: Any = a
        given_b: Any = b
        given_n: Any = level
        if given_a is None and given_b is None and given_n is not None:
            # to a level, over the spot where the tool stands: every move of a hole after its positioning
            if was_a is None or was_b is None:
                _unknown(self.axes, was_a, was_b, given_n)
                return
            if was_n is not None and _near(given_n, was_n):
                return
            last = self.last
            if last is None:
                axes = self._axes(was_a, was_b, given_n, True)
            else:  # (``_axes`` of a level: the last move's, the normal's number set)
                axes = last.copy()
                axes[self.axes[2]] = given_n
            self.add(self._made(mode, axes, was_a, was_b, given_n))
            self.last = axes
            self.n = given_n
            return
        to_a: Any = was_a if given_a is None else given_a
        to_b: Any = was_b if given_b is None else given_b
        to_n: Any = was_n if given_n is None else given_n
        if to_n is None and given_n is None and to_a is not None and to_b is not None:
            # Fanuc's positioning at the level where the tool stands, not known here (after a reference
            # return in cycle mode): a move in the plane alone, the normal axis left where it is
            self.add(Motion(mode, _plane_move(self.axes, to_a, to_b)))
            self.last = None
            self.a = to_a
            self.b = to_b
            return
        if to_a is None or to_b is None or to_n is None:
            _unknown(self.axes, to_a, to_b, to_n)
            return
        if was_a is not None and was_b is not None and was_n is not None and _near(to_a, was_a) \
                and _near(to_b, was_b) and _near(to_n, was_n):
            return
        axes = self._axes(to_a, to_b, to_n, given_a is None and given_b is None)
        self.add(self._made(mode, axes, to_a, to_b, to_n))
        self.last = axes
        self.a = to_a
        self.b = to_b
        self.n = to_n

    def _axes(self, a: Any, b: Any, n: Any, level_only: bool) -> dict[str, float | Expr]:
        """The axes of a move to (a, b, n), in X, Y, Z order: a copy of the last move's with the numbers that
        change set, ``level_only`` the normal's alone (a copy of a small dict clones its table; a new one
        is built key by key, at twice the cost, and a hole's moves after its first change the level only)."""
        first, second, normal = self.axes
        last = self.last
        axes = (_XYZ if last is None else last).copy()
        if last is None or not level_only:
            axes[first] = a
            axes[second] = b
        axes[normal] = n
        return axes

    def _made(self, mode: str, axes: dict[str, float | Expr], a: Any, b: Any, n: Any) -> Motion:
        """The move with ``axes``: a ``PathMove`` where its three numbers are floats (a plain ``Motion``
        otherwise, as a move to a computed position)."""
        if type(a) is not float or type(b) is not float or type(n) is not float:
            return Motion(mode, axes)
        first = self.axes[0]
        if first == "X":
            return PathMove(mode, axes, a, b, n)  # G17 (XY)
        if first == "Z":
            return PathMove(mode, axes, b, n, a)  # G18 (ZX)
        return PathMove(mode, axes, n, a, b)  # G19 (YZ)

    def dwell(self, seconds: float | None, always: bool = False) -> None:
        """A dwell; none without P unless ``always`` (``Semantics.dwell_always``)."""
        if seconds or always:
            self.add(Dwell(float(seconds or 0.0)))

    def spindle(self, direction: str) -> None:
        self.add(SpindleControl(direction))

    def orient(self, angle: float | None) -> None:
        self.add(SpindleOrientation(angle or 0.0))

    def program_stop(self) -> None:
        self.add(ProgramControl("stop"))

    def end(self) -> dict[str, float]:
        """Where the tool is: the start's axes, with the plane's and the normal's where they are known."""
        end = dict(self.start)
        first, second, normal = self.axes
        if self.a is not None:
            end[first] = self.a
        if self.b is not None:
            end[second] = self.b
        if self.n is not None:
            end[normal] = self.n
        return end


@mypyc_attr(allow_interpreted_subclasses=True)
class PathMove(Motion):
    """A move of an expansion to a spot known in X, Y and Z: a ``Motion`` (``axes`` names the three, in that
    order) that also holds its three numbers as floats, so that the expansion-move lane
    (``postproc.fast.expansion_moves``) reads them without walking the dict. ``made``: the dict they are the
    numbers of (a step that gives the move other axes, ``cycles.lathe_offsets``, leaves them behind: ``axes``
    is then another dict). Equal to a ``Motion`` of the same mode and axes: it is one."""

    __slots__ = ("x", "y", "z", "made")

    def __init__(self, mode: str, axes: dict[str, float | Expr], x: float, y: float, z: float) -> None:
        self.mode = mode  # (``Motion.__init__``'s fields, set here: a move of every hole, one call fewer)
        self.axes = axes
        self.center = None
        self.radius = None
        self.x = x
        self.y = y
        self.z = z
        self.made = axes

    def __eq__(self, other: object) -> bool:
        if not isinstance(other, Motion):
            return NotImplemented
        return self._key() == other._key()

    def __hash__(self) -> int:
        return hash((Motion, repr(self._key())))


def _near(x: float, y: float) -> bool:
    """Two positions closer than ``EPS`` (one level, one spot)."""
    return abs(x - y) < EPS


def _unknown(axes: tuple[str, str, str], a: float | None, b: float | None, n: float | None) -> None:
    """The error of a move from a position not known on some axis (the first unknown in X, Y, Z order)."""
    target = dict(zip(axes, (a, b, n)))
    missing = [k for k in "XYZ" if target[k] is None]
    raise ProgramError(f"the tool's {missing[0]} position is unknown before the cycle")


def _plane_move(axes: tuple[str, str, str], a: float, b: float) -> dict[str, float | Expr]:
    """The axes of a move in the plane alone, in X, Y, Z order."""
    first, second, _ = axes
    return {first: a, second: b} if first < second else {second: b, first: a}


_XYZ: Final[dict[str, float | Expr]] = {"X": 0.0, "Y": 0.0, "Z": 0.0}
"""The axes of a move, in X, Y, Z order, whatever the plane (``ToolPath._axes`` copies it and sets each)."""


@mypyc_attr(allow_interpreted_subclasses=True)
class _Whereabouts(ToolPath):
    """A tool path that follows the tool without keeping its moves (``CycleExpansion.end``)."""

    __slots__ = ()

    def add(self, item: Section) -> None:
        pass

    def _move(self, mode: str, a: float | None, b: float | None, level: float | None) -> None:
        if a is not None:
            self.a = a
        if b is not None:
            self.b = b
        if level is not None:
            self.n = level
        if self.a is None or self.b is None or (self.n is None and level is not None):
            _unknown(self.axes, self.a, self.b, self.n)


def level(cycle: CannedCycle, name: str) -> float:
    """A resolved level of the cycle; a record read from XML may lack one, which is a located error."""
    if name == "r":  # the named fields (a compiled field read; ``getattr`` by name is a generic look-up)
        value = cycle.r
    elif name == "initial":
        value = cycle.initial
    elif name == "bottom":
        value = cycle.bottom
    else:
        value = getattr(cycle, name)
    if value is None:
        raise ProgramError(f"the {cycle.kind} cycle has no {name} level")
    return float(value)


@mypyc_attr(allow_interpreted_subclasses=True)
class CycleExpansion(Syntax):
    """Base of the per-family expansion syntaxes. Subclasses set ``KINDS`` and implement ``hole``.

    As a pipeline step it gives a block that has a resolved ``CannedCycle`` of its kinds the
    ``CompoundMotion`` it stands for; ``CannedCycleResolveSyntax`` calls ``expand`` directly.
    """

    __slots__ = ()
    KINDS: ClassVar[frozenset[str]] = frozenset()
    ENDS_OVER_THE_SPOT: ClassVar[bool] = False
    """Every hole of the family ends over its spot at the return level (``return_level``), whatever it
    does in the hole: where a block of holes ends is known from its last spot (``over_the_spot``)."""

    def build(self, block: Block, ctx: Context | None) -> None:
        """(``ctx`` None: built outside a run, as a seed's section is expanded on its own.)"""
        cycle = block.sections.get("CannedCycle")
        if not isinstance(cycle, CannedCycle) or cycle.kind not in self.KINDS:
            return
        if "CompoundMotion" not in block.sections:
            limit = UNBOUNDED if ctx is None else ctx.setup.limits.moves_per_block  # None: built outside a run
            items = self.items(cycle, limit)
            if ctx is not None:
                ctx.moves_made += len(items)
            block.add(CompoundMotion(cycle.kind, items))

    def expand(self, cycle: CannedCycle, limit: int = UNBOUNDED) -> tuple[list[Section], dict[str, float]]:
        """The items of the cycle and where the tool is when it ends; ``TooManyMoves`` when they would be
        more than ``limit`` (refused before expanding when the count is known in advance)."""
        path = self._path(cycle, limit)
        return path.items, path.end()

    def items(self, cycle: CannedCycle, limit: int = UNBOUNDED) -> list[Section]:
        """``expand``'s items alone (a block's motion: where it ends is the resolver's already)."""
        return self._path(cycle, limit).items

    def _path(self, cycle: CannedCycle, limit: int) -> ToolPath:
        path = ToolPath(cycle, limit)
        if cycle.repeat <= 0:
            return path
        self._enter(path, cycle, limit)
        first, second, _ = path.axes
        a, b = cycle.position[first], cycle.position[second]
        da, db = cycle.step.get(first, 0.0), cycle.step.get(second, 0.0)
        for i in range(cycle.repeat):  # the holes: a G91 row, or the same spot K times (no list of them to build)
            self.hole(path, cycle, a + i * da, b + i * db)
        return path

    def end(self, cycle: CannedCycle, limit: int = UNBOUNDED) -> dict[str, float]:
        """Where the tool is when the block's holes are done, found without expanding them all: every
        hole starts by positioning on its own spot and ends at a level the cycle alone sets, so the last
        hole expanded from where the tool stands before the block ends where the whole block ends. It
        refuses what ``expand`` refuses before the first hole (a count over ``limit``, a missing level,
        an unknown position), so a translation that keeps the cycle native fails as one that expands it."""
        path = _Whereabouts(cycle, limit)
        if cycle.repeat <= 0:
            return path.end()
        self._enter(path, cycle, limit)
        first, second, _ = PLANE_AXES[cycle.plane]
        last = cycle.repeat - 1
        self.hole_end(path, cycle, cycle.position[first] + last * cycle.step.get(first, 0.0),
                      cycle.position[second] + last * cycle.step.get(second, 0.0))
        return path.end()

    def hole_end(self, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        """Where one hole leaves the tool, for ``end`` (``path`` keeps no moves): the hole itself, or for a
        family that ``ENDS_OVER_THE_SPOT`` its positioning and return (``over_the_spot``)."""
        if self.ENDS_OVER_THE_SPOT:
            self.over_the_spot(path, cycle, a, b)
        else:
            self.hole(path, cycle, a, b)

    def over_the_spot(self, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        """``hole_end`` of a family whose hole ends over its spot at the return level, whatever it does in
        the hole: positioning (which refuses an unknown level), then that level."""
        self.position(path, cycle, a, b)
        path.rapid(level=self.return_level(cycle))

    def _enter(self, path: ToolPath, cycle: CannedCycle, limit: int) -> None:
        """The checks before the first hole, and RS274's rise to R when the tool starts below it."""
        initial = level(cycle, "initial")
        r = level(cycle, "r")
        level(cycle, "bottom")
        per_hole = self.least_moves_per_hole(cycle)
        if cycle.repeat * per_hole > limit:
            if per_hole > 1:
                where = f" at {cycle.repeat} holes" if cycle.repeat > 1 else ""
                raise TooManyMoves(f"{per_hole} pecks per hole{where} make more than {limit} moves in one block "
                                   "(the set-up's <Limits movesPerBlock>)", "peck")
            raise TooManyMoves(f"{cycle.repeat} holes make more than {limit} moves in one block (the set-up's "
                               "<Limits movesPerBlock>)", "repeat")
        rules = rules_of(cycle)
        if rules.rise_to_r and initial < r - EPS:
            path.rapid(level=cycle.r)

    def least_moves_per_hole(self, cycle: CannedCycle) -> int:
        """A lower bound on the moves one hole takes, known before expanding (a cut to the bottom)."""
        return 1

    @abc.abstractmethod
    def hole(self, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        """Operations 1-6 of one hole at plane position (a, b)."""

    @classmethod
    def position(cls, path: ToolPath, cycle: CannedCycle, a: float, b: float) -> None:
        """Operations 1 and 2: rapid in the plane at the current level, then rapid to R. RS274 keeps
        the current level only while the tool stands above R (a G98 hole after a G99 one with a
        lower R); otherwise it rapids to the hole at the return level in one straight traverse."""
        if rules_of(cycle).position_at_clear and path.level() <= level(cycle, "r") + EPS:
            path.rapid(a, b, max(path.level(), cls.return_level(cycle)))
        else:
            path.rapid(a, b)
        path.rapid(level=cycle.r)

    @staticmethod
    def return_level(cycle: CannedCycle) -> float:
        """Operation 6: the level a rapid-out goes to (initial in G98, R in G99; RS274's G98 goes to
        R instead when R is above the initial level)."""
        r = level(cycle, "r")
        if cycle.return_level != "initial":
            return r
        initial = level(cycle, "initial")
        return max(initial, r) if rules_of(cycle).clear_above_r else initial

    @classmethod
    def from_xml(cls, el: etree._Element) -> "CycleExpansion":
        if len(el):
            raise ValueError(f"<{cls.XNAME}> takes no children")
        return cls()
