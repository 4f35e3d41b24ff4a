"""ModalStateSyntax: carries the modal state from block to block (neutral, every dialect uses it).

Runs after a dialect's block syntax and the cycle resolution: it applies each block's modal sections
to ``ctx.state`` (``ModalState.apply``, the one place that says how a section changes the modal state,
shared with the writer and the simulator) and tracks the position, so later steps (cycle expansion, lowering) know where the
tool is. A position becomes unknown (None) after moves the IR cannot place, such as a reference return
or a computed coordinate (a program kept symbolically).
It also refuses a negative F or S (``postproc.block_rules``): every reading passes here, so
``translate``, ``toolpath`` and ``verify`` refuse them alike.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from math import hypot
from typing import Final, NoReturn, cast

from postproc.block_rules import ZERO_FEED, ArcError, arc_centre, check_values, needs_feed, per_rev_problem
from postproc.interp.control import ASSIGN, CONTROL
from postproc.geometry.arc_end import NEAREST_CENTRE, SPIRAL, TARGET_ARC_END, UNKNOWN_START_TARGET, ArcEndRule
from postproc.geometry.arc_end_math import circle_spiral_gap, rule_allows
from postproc.errors import ProgramError, UnsupportedError
from postproc.ir.event_order import MOVING, after_motion
from postproc.geometry.arcs import ARC_TOLERANCE_MM, PLACES
from postproc.ir.expr import Expr
from postproc.ir import Block, Motion
from postproc.ir.move_words import X, Y, Z
from postproc.ir.state import (LEFT_START, MM_PER_INCH, MODAL_KEYS, PLACED_AXES, PLACED_LENGTH_AXIS, PLANE_AXES,
                                ModalState, SetUpPlaces)
from postproc.context import Context
from postproc.syntaxes.syntax import Syntax
from postproc.syntaxes.power_on_units import KEY as _POWER_ON_UNITS, take_power_on_units

_CONTROL: Final = CONTROL
_ASSIGN: Final = ASSIGN
"""The construct keys, as constants of this module (compiled: no global look-up on every block)."""
_MODAL_MOTION: Final = frozenset(("rapid", "linear", "cw", "ccw", "thread"))
_WATCHED: Final = MODAL_KEYS | {CONTROL, ASSIGN}
"""A block with none of these keys changes no modal state and no construct: one pass over its keys."""


@mypyc_attr(allow_interpreted_subclasses=True)
class ModalStateSyntax(Syntax):
    XNAME = "ModalStateSyntax"
    __slots__ = ()

    def build(self, block: Block, ctx: Context) -> None:
        sections = block.sections
        if not sections:
            return
        state = ctx.state
        if state.extra and _POWER_ON_UNITS in state.extra:
            take_power_on_units(block, ctx)
        spindle = state.spindle
        # no modal section and no construct (most blocks: a move and its block number, ``only_move``'s test
        # made with the look-up of the move; any other block one pass over its keys)
        motion = cast("dict[str, object]", sections).get("Motion")  # (an object: typed ``Section``, compiled, the
        size = len(sections)  # look-up's answer was checked against the base class, PyType_IsSubtype a block)
        only = motion is not None and (size == 1 or size == 2 and "Sequence" in sections)
        quiet = only
        if not quiet:
            quiet = True
            for key in sections:
                if key in _WATCHED:
                    quiet = False
                    break
        if not quiet:
            state.apply(sections)  # (which passes a block of constructs only at once)
            if not state.computes and (_CONTROL in sections or _ASSIGN in sections):
                state.computes = True
        if motion is not None:
            self._move(block, ctx, motion, only)  # type: ignore[arg-type]
            feed = state.feed
            if feed is not None and feed == 0.0 and not state.computes and needs_feed(motion):
                raise ProgramError(ZERO_FEED, ctx.at(block))
            if state.feed_mode == "per_rev":
                _check_turning(block, ctx, motion, spindle)  # type: ignore[arg-type]
        if not quiet and ("Feed" in sections or "SpindleSpeed" in sections):
            check_values(block, ctx)  # after the state is carried: an error keeps the block's settings

    def _move(self, block: Block, ctx: Context, motion: Motion, only: bool = False) -> None:
        """Carry ``motion`` into the state; ``only``: it is the block's only section but its number."""
        words = ctx.axis_words
        # As objects: compiled, a float narrowed from the union would be unboxed and boxed again (a new float
        # an axis word) to be stored.
        words_read = cast("dict[str, object]", motion.axes)
        state = ctx.state
        mode = motion.mode
        if only and (mode == "linear" or mode == "rapid") and not ctx.increments and state.distance != "incremental":
            # The commonest move (no machine-coordinate section beside it: ``only``; no lathe increments) of X, Y
            # and Z numbers on the machine's axes: its words are the position. Read by the run's ``MoveWords``,
            # which the lowering steps that follow the point read it with after this (they find it read): a pass
            # over the items here, and a test of each letter against the machine's, cost ~630 instructions a block
            # compiled. Stored axis by axis (``dict.update`` cost ~870 instructions a block, three stores ~620): the
            # position holds X, Y and Z from the start (``ModalState``) and never loses them, so its order is the
            # same whatever the order of the stores. Any other move goes the general way below.
            reader = ctx.move_words
            bits = reader.read(motion)
            if bits >= 0 and bits & reader.on(words) == bits:
                store = cast("dict[str, object]", state.position)
                if bits & X:
                    store["X"] = reader.x_word
                if bits & Y:
                    store["Y"] = reader.y_word
                if bits & Z:
                    store["Z"] = reader.z_word
                state.motion = mode
                return
        numbers = True  # every word a number (none computed): an absolute move's words are the position
        for letter, value in words_read.items():  # (one pass: the machine's axes, and the words' kinds)
            if letter not in words:
                _check_axes(block, ctx, motion)
                numbers = False  # (an increment of an axis of the machine: the general loop below)
                break
            if type(value) is not float:
                numbers = False
        machine = not only and "MachineCoordinates" in block.sections
        if mode in _MODAL_MOTION and not machine:
            state.motion = mode
        elif mode is None:
            return
        if mode == "cw" or mode == "ccw":
            if not state.extra.get("polar"):  # (polar words are no end point: the simulation checks those)
                _check_arc(block, ctx, motion)  # whatever else the block says: the simulator checks every arc
        pos = state.position
        increments = ctx.increments  # a lathe's U/W (``Dialect.INCREMENTAL_AXES``); empty on a mill
        if increments and not increments.keys().isdisjoint(motion.axes):
            _lathe_move(ctx, motion)
            return
        if machine or mode == "home" or mode == "home2":
            for axis in motion.axes:
                pos[axis] = None
            places = state.places
            if places is not None:  # the set-up may place the tool there (``ModalState.places``)
                state.place(_machine_ends(state, places, motion, machine))
            state.extra[LEFT_START] = True
            return
        incremental = state.distance == "incremental"
        store = cast("dict[str, object]", pos)
        if numbers and not incremental:
            store.update(words_read)  # (one C call: the words, in their order, as the loop below stores them)
            return
        for axis, value in words_read.items():
            if type(value) is not float and isinstance(value, Expr):  # (a float first: it is cheaper)
                store[axis] = None  # computed: known only when the program runs
            elif incremental:
                old = pos.get(axis)
                pos[axis] = None if old is None else old + cast(float, value)
            else:
                store[axis] = value


def _machine_ends(state: ModalState, places: SetUpPlaces, motion: Motion, machine: bool) -> dict[str, float]:
    """Where a reference return or a move in machine coordinates (``machine``) leaves the tool on each axis the
    set-up places (machine coordinates, mm): the block's machine word under absolute distance, or the declared
    home after a first reference return. Not an axis a tool length offset acts on while one is in force (the
    programmed point is the controlled point less a length only the run may know)."""
    ends: dict[str, float] = {}
    scale = MM_PER_INCH if state.units == "inch" else 1.0
    for axis, value in motion.axes.items():
        if axis not in PLACED_AXES or axis == PLACED_LENGTH_AXIS and state.length != "cancel":
            continue
        if machine:
            if state.distance != "incremental" and type(value) is float:
                ends[axis] = value * scale
        elif motion.mode == "home":
            home = places.homes.get(axis)
            if home is not None:
                ends[axis] = home
    return ends


_FEED_MOTION: Final = frozenset(("linear", "cw", "ccw", "thread"))


def _check_axes(block: Block, ctx: Context, motion: Motion) -> None:
    """Refuse a move with a word for an axis the set-up's machine lacks (``Context.axis_words``, or an
    increment of one: ``Context.increments``), as the simulator does: written out, the target would move
    an axis that is not there or alarm. The move goes from the block (reported once, here) and the tool's
    place on its axes is unknown after it."""
    axes = ctx.axis_words
    increments = ctx.increments
    letter = next((a for a in motion.axes if increments.get(a, a) not in axes), None)
    if letter is None:
        return
    del block.sections["Motion"]
    for axis in motion.axes:
        ctx.state.position[increments.get(axis, axis)] = None
    raise ProgramError(f"axis {increments.get(letter, letter)} is not on this machine "
                       f"(axes {ctx.setup.machine.axes})", ctx.at(block, ctx.column_of(block, letter)))


def _check_turning(block: Block, ctx: Context, motion: Motion, before: str) -> None:
    """Refuse a feed-per-revolution move while the spindle stands or turns at S0 (``per_rev_problem``).
    ``before`` is the spindle's state before the block: a stop in the block acts after its motion, a
    start before it; the block's S is in force for its motion."""
    sections = block.sections
    control = sections.get("SpindleControl")
    turning = before if control is None or after_motion("SpindleControl", control) \
        else control.direction  # type: ignore[attr-defined]
    if not motion.axes:
        return
    problem = per_rev_problem(turning, ctx.state.spindle_rpm)
    if problem is None:
        return
    if motion.mode not in _FEED_MOTION and MOVING.isdisjoint(sections.keys()):
        return  # a rapid move needs no revolutions
    letter = next(iter(motion.axes))
    raise ProgramError(problem, ctx.at(block, ctx.column_of(block, letter)))


def _lathe_move(ctx: Context, motion: Motion) -> None:
    """A lathe move with incremental words (``ctx.increments``: U/W): each is an increment of its axis,
    beside absolute words."""
    pos = ctx.state.position
    increments = ctx.increments
    homing = motion.mode in ("home", "home2")
    for axis, value in motion.axes.items():
        target = increments.get(axis)
        if homing:
            pos[target or axis] = None
        elif target is None:
            if ctx.state.distance == "incremental":
                old = pos.get(axis)
                pos[axis] = None if old is None or isinstance(value, Expr) else old + value
            else:
                pos[axis] = None if isinstance(value, Expr) else value
        else:
            old = pos.get(target)
            pos[target] = None if old is None or isinstance(value, Expr) else old + value


def _numbers(values: dict[str, float | Expr]) -> dict[str, float] | None:
    """The words' values as numbers (the dictionary itself: no copy an arc), or None when one is computed (known
    only when the program runs)."""
    for value in values.values():
        if type(value) is not float and isinstance(value, Expr):  # (a float first: it is cheaper)
            return None
    return cast("dict[str, float]", values)


def _check_arc(block: Block, ctx: Context, motion: Motion) -> None:
    """Refuse an arc no controller runs (``postproc.block_rules.arc_centre``) when its start is known or
    does not matter (incremental words), so ``translate`` refuses what ``toolpath`` refuses; an arc with a
    computed word waits for the run. An arc in a plane the machine lacks an axis of (an XY arc on a lathe's
    XZ set-up) is refused whatever its words: it would sweep that axis (``postproc.simulate.moves``)."""
    state = ctx.state
    a1, a2, _ = PLANE_AXES[state.plane]
    machine = ctx.axis_words
    if a1 not in machine or a2 not in machine:  # (an XY arc on a lathe's XZ: the simulator refuses it alike)
        missing = a1 if a1 not in machine else a2
        _refuse(block, ctx, motion, ArcError(f"an arc in the {state.plane} plane needs axis {missing}, not on this "
                                             f"machine (axes {ctx.setup.machine.axes})", "G"))
    if motion.center:
        for axis in motion.center:
            if axis != a1 and axis != a2:
                _refuse(block, ctx, motion, ArcError(f"arc centre offset along {axis} is outside the "
                                                     f"{state.plane} plane", _CENTRE_LETTERS.get(axis, "G")))
    axes = _numbers(motion.axes)
    center = _numbers(motion.center) if motion.center else {}
    radius = motion.radius
    if axes is None or center is None or (
            radius is not None and type(radius) is not float and isinstance(radius, Expr)):
        return  # a computed word (a symbolic program): the arc is checked when the program runs
    incremental = state.distance == "incremental"
    increments = ctx.increments  # a lathe's U/W: increments of X/Z beside the absolute words
    if radius is not None and not any(
            a in axes and (not incremental or axes[a] != 0.0) for a in (a1, a2)) \
            and not any(axes.get(a, 0.0) != 0.0 for a in increments):
        # no end point in the plane: an R arc that ends where it starts, wherever that is
        _refuse(block, ctx, motion, ArcError("a full circle cannot be programmed with R (use I/J/K)", "R"))
    position = state.position
    s1, s2 = position.get(a1), position.get(a2)
    if s1 is None or s2 is None:
        # An axis the block does not move, or moves by an increment, ends where it starts plus its word:
        # the arc's shape does not depend on where that is. An absolute word from an unknown start does.
        if not incremental and (s1 is None and a1 in axes or s2 is None and a2 in axes):
            target = ctx.run_data.get(UNKNOWN_START_TARGET)
            if target is None or state.symbolic or state.computes:
                return  # read for itself (the simulator starts at the set-up's start) or copied as written; or
                # the text is not the order of execution or its positions compute (a loop, a call, a computed
                # word): where the tool stands is the run's to know, which checks the arc as it flattens or keeps
            _refuse_unknown_start(block, ctx, motion, a1 if s1 is None and a1 in axes else a2, str(target))
        s1 = 0.0 if s1 is None else s1
        s2 = 0.0 if s2 is None else s2
    e1, e2 = axes.get(a1), axes.get(a2)
    e1 = s1 if e1 is None else s1 + e1 if incremental else e1
    e2 = s2 if e2 is None else s2 + e2 if incremental else e2
    if increments:  # (a mill's are none: no method call an arc)
        for letter, axis in increments.items():
            step = axes.get(letter)
            if step is not None:
                if axis == a1:
                    e1 += step
                elif axis == a2:
                    e2 += step
    if ctx.diameter:  # a lathe's X words are diameters, the centre offset I a radius
        if a1 == "X":
            s1, e1 = s1 / 2.0, e1 / 2.0
        elif a2 == "X":
            s2, e2 = s2 / 2.0, e2 / 2.0
    if state.units == "inch":
        s1, s2, e1, e2 = s1 * MM_PER_INCH, s2 * MM_PER_INCH, e1 * MM_PER_INCH, e2 * MM_PER_INCH
        scale = MM_PER_INCH
    else:
        scale = 1.0
    if radius is None:
        offsets = {a: v * scale for a, v in center.items() if a == a1 or a == a2} if center else {}
        c1, c2 = s1 + offsets.get(a1, 0.0), s2 + offsets.get(a2, 0.0)
        r0 = hypot(s1 - c1, s2 - c2)
        rule = ctx.arc_end
        always = rule.inch * MM_PER_INCH if scale != 1.0 else rule.metric  # accepted whatever the radius
        r1 = hypot(e1 - c1, e2 - c2)
        if rule.of_centre_shift:  # the move onto the chord's bisector, (r0^2 - r1^2) / (2 chord), within the limit
            common = abs(r0 * r0 - r1 * r1) <= 2.0 * always * hypot(e1 - s1, e2 - s2)
        else:
            common = abs(r0 - r1) <= always
        if common and r0 >= _SMALLEST:
            target = ctx.run_data.get(TARGET_ARC_END)
            if target is None:
                return  # the common arc: its end on its circle, its centre away from its start
            _target_accepts(block, ctx, motion, target, (s1, s2), (e1, e2), (c1, c2), scale, r0, r1)
            return
    else:
        radius *= scale
        offsets = {}
        half = hypot(e1 - s1, e2 - s2) / 2.0
        if half >= _SMALLEST and abs(radius) - half >= -ARC_TOLERANCE_MM:
            return  # the common R arc: a chord its radius reaches
    try:  # the rare arc: arc_centre says what is wrong with it (or that it is a zero-length no-op)
        centre = arc_centre((s1, s2), (e1, e2), (a1, a2), radius, offsets, motion.mode == "cw", ctx.arc_end,
                            scale != 1.0, scale)
    except ArcError as err:
        _refuse(block, ctx, motion, err)
    target = ctx.run_data.get(TARGET_ARC_END)
    if target is not None and radius is None and centre is not None:
        c1, c2 = s1 + offsets.get(a1, 0.0), s2 + offsets.get(a2, 0.0)
        _target_accepts(block, ctx, motion, target, (s1, s2), (e1, e2), (c1, c2), scale)


def _refuse_unknown_start(block: Block, ctx: Context, motion: Motion, axis: str, target: str) -> NoReturn:
    """Refuse a translated arc that ends at an absolute ``axis`` from a start unknown on it: the target checks
    its radius (or an R arc's chord) from wherever the machine stands, and accepts it about one such place only
    [V: rs274 refuses ``G1 X10 Z-1`` then ``G2 X20 Y5 I5 J0`` from Y0, "Radius to end of arc differs from radius
    to start"]; the source's controller is no different, so no output is sure to run."""
    for moved in motion.axes:
        ctx.state.position[moved] = None
    del block.sections["Motion"]
    letter = axis if axis in motion.axes else "G"
    state = ctx.state
    placeable = " (or, after a reference return, a move in machine coordinates or a change of work system, declare " \
        "the machine's home and work offsets in the set-up: <Axes><Axis home>, <WorkOffsets>)" \
        if state.extra.get(LEFT_START) or state.work_offset != 1 else ""
    raise UnsupportedError(f"the arc ends at an absolute {axis} from a start whose {axis} is unknown (not programmed "
                           f"since the program start or since a move or offset change the reading cannot follow): "
                           f"the {target} controller checks the arc from wherever the machine stands and refuses "
                           f"it almost everywhere; program {axis} before the arc{placeable}",
                           ctx.at(block, ctx.column_of(block, letter)), needs=axis)
    # (needs: after a refused line that programmed the axis, the unknown start is that refusal's consequence)


def _target_accepts(block: Block, ctx: Context, motion: Motion, target: tuple[str, ArcEndRule],
                    s: tuple[float, float], e: tuple[float, float], c: tuple[float, float], scale: float,
                    r0_mm: float = -1.0, r1_mm: float = -1.0) -> None:
    """Refuse an arc (start, end, programmed centre in mm; ``scale`` mm per program unit; its start and end radii in
    mm where the caller has them) the source's controller runs as a spiral where the translation's target would
    refuse it, or would run it as a circle about a centre it moves that leaves that spiral by more than
    ``SPIRAL_AS_CIRCLE_MM`` (``postproc.geometry.arc_end.TARGET_ARC_END``). A spiral target's rule of radii accepts
    any difference within its absolute limit, the least of its limits (``rule_limit``): most arcs, told without
    the chord and the rule's arithmetic (~3k instructions an arc compiled, every I/J arc a grbl translation reads)."""
    name, rule = target
    inch = scale != 1.0
    r0 = (hypot(s[0] - c[0], s[1] - c[1]) if r0_mm < 0.0 else r0_mm) / scale
    r1 = (hypot(e[0] - c[0], e[1] - c[1]) if r1_mm < 0.0 else r1_mm) / scale
    if rule.runs == SPIRAL and not rule.of_centre_shift and abs(r0 - r1) <= (rule.inch if inch else rule.metric):
        return
    unit = "in" if inch else "mm"
    chord = hypot(e[0] - s[0], e[1] - s[1]) / scale
    if rule_allows(rule, r0, r1, inch, chord):  # (``rule.allows`` and ``rule.spiral_gap``, called compiled)
        runs = rule.runs
        if runs == SPIRAL:
            return
        gap = circle_spiral_gap(runs == NEAREST_CENTRE, s, e, c, motion.mode == "cw", SPIRAL_AS_CIRCLE_MM)
        if gap <= SPIRAL_AS_CIRCLE_MM:
            return
        moved = rule.centre_move(r0, r1, chord)
        problem = (f"the {name} controller runs this arc as a circle about a centre it moves by {moved:.6g} {unit}: "
                   f"its end radius differs from its start radius by {abs(r0 - r1):.6g} {unit}, and the source's "
                   f"controller runs it as a spiral about the programmed centre, which that circle leaves by "
                   f"{gap:.6g} mm (more than {SPIRAL_AS_CIRCLE_MM:g} mm is past what verify vouches for)")
    else:
        problem = (f"the {name} controller refuses this arc: its end radius differs from its start radius by "
                   f"{abs(r0 - r1):.6g} {unit}, and it accepts {rule.limit(r0, r1, inch, chord):.6g} {unit} here; "
                   f"the source's controller runs it as a spiral, which no arc of the target reproduces")
    for axis in motion.axes:  # the block is refused: after it the tool's place is unknown to later checks
        ctx.state.position[axis] = None
    letter = next((_CENTRE_LETTERS[a] for a in motion.center if a in _CENTRE_LETTERS), "G") if motion.center else "G"
    raise UnsupportedError(f"{problem} (translate with --arcs lines:TOL)", ctx.at(block, ctx.column_of(block, letter)))


SPIRAL_AS_CIRCLE_MM: Final = 0.0005
"""How far the circle a target runs about the centre it moves may leave the source's spiral
(``ArcEndRule.spiral_gap``, the distance ``verify`` measures between the two paths): half verify's default
tolerance (as ``postproc.lowering.arcs.R_FORM_TOLERANCE_MM``). How far the centre moves does not matter:
verify compares the paths, not the centres (a 4-decimal CAM arc's centre moves 0.0007 mm where its circle
stays within 0.000001 mm of the spiral)."""


_SMALLEST: Final = 10.0 ** -PLACES
"""Below this a radius or a half chord is zero (``postproc.block_rules.arc_centre`` uses the same)."""
_CENTRE_LETTERS: Final = {"X": "I", "Y": "J", "Z": "K"}


def _refuse(block: Block, ctx: Context, motion: Motion, err: ArcError) -> NoReturn:
    """The arc goes from the block (reported once, here), and the tool's place is unknown after it."""
    del block.sections["Motion"]
    for axis in motion.axes:
        ctx.state.position[axis] = None
    raise err.located(ctx.at(block, ctx.column_of(block, err.letter))) from None
