"""Lowering: pure IR-to-IR transforms chosen from the target dialect's capabilities.

Each step is named with a verb (``expand_canned_cycles``, ...) and runs only where the target lacks a
feature, as sqlglot's ``preprocess`` does for SQL dialects. Two sources of steps, applied in this order:

* generic steps, contributed by plugins through the ``postproc_register_lowerings`` hook (the core
  contributes ``expand_canned_cycles``); each decides from the target's capabilities what to do;
* the target dialect's own steps (``Dialect.LOWERING``): rewrites only that target needs, such as
  grbl's manual tool change, owned by the dialect that needs them.

A step is a block-stream transform ``step(blocks, ctx, target) -> blocks`` (a function, often a
generator), or a ``LoweringStep``: an object whose ``start`` gives the run's ``BlockStep``, which takes the
blocks one at a time. ``lower_for`` runs consecutive ``BlockStep``s as one loop over the stream
(``run_blocks``) instead of a generator per step, and a block that is only a plain move (``plain_move``: a move
that is no reference return, and at most its block number; most blocks of a CAM program) skips every step whose
``moves`` says such a block is not its business there: a step costs a few instructions on it instead of a
generator's resumption (~150-250 compiled, issue 30). A step that only follows where such a move takes the
program while it has nothing else to do (the frame evaluation, the tool length timing, the arc pass) says so
with its ``point``: the loop reads a straight move of X, Y and Z numbers once for every such step and notes it in
each one's point (``move_words.NotedPoint``), without calling the step. Both forms compute the same: a
``LoweringStep`` called as a function runs its ``BlockStep`` alone through the same loop.
"""

from __future__ import annotations

from typing import Callable, Final, Iterator, Sequence, cast

from mypy_extensions import mypyc_attr

from ..context import Context
from ..dialect import Dialect
from ..ir import Block, Motion, Section
from ..ir.expr import Expr
from .move_words import OTHER, NotedPoint

Lowering = Callable[[Iterator[Block], Context, type[Dialect]], Iterator[Block]]
"""A lowering step: ``step(blocks, ctx, target)`` -> blocks, a pure block-stream transform."""
Transform = Lowering

TRANSFORMS: list[Lowering] = []
"""The generic steps of the default registry (``postproc.plugins.default_registry``), in order."""


@mypyc_attr(allow_interpreted_subclasses=True)
class BlockStep:
    """One run of a ``LoweringStep``: its state, and what it makes of each block.

    ``take`` gets every block the step before it gives, in order (a block that is only a plain move through
    ``take_move``), except blocks that are only a plain move (``plain_move``) while ``moves`` is False: the step
    says so when such a block can neither change its state nor be changed by it (it may set ``moves`` again at
    any block, in its own ``take``, ``take_move`` or ``finish``: the loop looks at it after each). ``take``
    returns None for the block as it is (perhaps changed in place), or the blocks that replace it (none:
    dropped or held; several: an expansion, or held blocks given back). ``finish`` gives what is still held
    at the end."""

    def __init__(self) -> None:
        self.moves = True
        """A block that is only a move is this step's business (False: it goes past unseen)."""
        self.point: NotedPoint | None = None
        """Set (while ``moves``): a block that is only a straight move (rapid or linear) of X, Y and Z numbers
        (``MoveWords.read``) would only be noted here by ``take_move``, so the loop notes it (``NotedPoint.note``)
        instead of calling the step. The step sets it, and clears it where such a move would do more, in its own
        ``take``, ``take_move`` or ``finish`` (the loop looks at it at each move)."""
        self.passes = False
        """The step's work is over: no block is its business any more (it gives none of them back changed, holds
        none, follows nothing), so every block goes past it unseen, plain move or not; ``finish`` is still
        called. Set in its own ``take``, ``take_move`` or ``finish``, for good (a step of a program's start:
        ``units_at_start``, the feed check, the title of the opening ``%`` line)."""

    def take(self, block: Block) -> list[Block] | None:
        raise NotImplementedError

    def take_move(self, block: Block) -> list[Block] | None:
        """``take`` for a block that is only a plain move (``plain_move``, asked by the loop: a step that follows
        every move overrides this to skip asking its own block again: its ``Motion`` is no reference return); the
        same result as ``take``, except that None means the block is still only the move it was given (the same
        ``Motion``, with the same words: the loop notes what it read of it in the later steps' ``point``): one
        ``take`` changed in place into more (a length change put on it), or into another move (a frame's), comes
        back as ``[block]``, so the steps after it see what it is (``still_moving``)."""
        motion = block.sections.get("Motion")
        return still_moving(block, self.take(block), motion, motion.axes if isinstance(motion, Motion) else None)

    def finish(self) -> list[Block]:
        return []


def still_moving(block: Block, out: list[Block] | None, motion: Section | None = None,
                 axes: dict[str, float | Expr] | None = None) -> list[Block] | None:
    """``out``, what a step's ``take`` gave for ``block``, a block that was only a plain move, as ``take_move`` gives
    it: ``[block]`` where ``take`` changed the block in place so that it is no longer only a plain move, or (given
    the ``motion`` it had and that motion's ``axes``) no longer that move with those words."""
    if out is None:
        now = plain_motion(block.sections)
        if now is None or motion is not None and (now is not motion or now.axes is not axes):
            return [block]
    return out


def plain_move(sections: dict[str, Section]) -> bool:
    """The block holds a move (``Motion``) that is no reference return and at most a ``Sequence`` (block number)
    besides: a step that watches neither key has nothing to look for in it but the move. A reference return
    (G28/G30, ``Motion('home')``) goes the general way (``take``): a step that follows only where the tool is taken
    home (``measured_entries``) skips the rest. Most blocks of a CAM program."""
    return plain_motion(sections) is not None


def plain_motion(sections: dict[str, Section]) -> Motion | None:
    """The move of a block that is only a plain move (``plain_move``), else None: the loop asks it once a block
    (``Walk.through``), and notes the move it gives (``BlockStep.point``). (A key test and a look-up: a pass over
    the one or two items cost ~590 instructions compiled, against ~355.)"""
    size = len(sections)
    if size == 2:
        if "Sequence" not in sections:
            return None
    elif size != 1:
        return None
    motion = cast("dict[str, object]", sections).get("Motion")  # (an object: typed ``Section``, compiled, the
    if not isinstance(motion, Motion):  # look-up's answer was checked against the base class, PyType_IsSubtype)
        return None
    mode = motion.mode
    return motion if mode != "home" and mode != "home2" else None


@mypyc_attr(allow_interpreted_subclasses=True)
class LoweringStep:
    """A lowering step as an object: ``start`` decides from the run (``ctx``) and the target whether it has
    anything to do, and gives the ``BlockStep`` that does it (None: the stream passes unchanged). Called
    like a function step, it runs alone over the blocks."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        raise NotImplementedError

    def __call__(self, blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
        run = self.start(ctx, target)
        return blocks if run is None else run_blocks(blocks, [run])


@mypyc_attr(allow_interpreted_subclasses=True)
class Steps(BlockStep):
    """Several ``BlockStep``s as one, in order (a ``LoweringStep`` whose work is two rewrites, one after the
    other): a block that is only a move is its business while it is one of theirs."""

    def __init__(self, steps: list[BlockStep]) -> None:
        super().__init__()
        self.steps = steps
        self.walk = Walk(steps)
        self.moves = any(step.moves for step in steps)

    def take(self, block: Block) -> list[Block] | None:
        walk = self.walk
        one = walk.through(block, 0)
        made = [one] if one is not None else list(walk.given())
        self.moves = any(step.moves for step in self.steps)
        self.passes = all(step.passes for step in self.steps)
        return None if len(made) == 1 and made[0] is block else made

    def finish(self) -> list[Block]:
        return list(self.walk.finish())


@mypyc_attr(allow_interpreted_subclasses=True)
class Walk:
    """The one walk of blocks through a group of ``BlockStep``s, in order, as the chain of their generators
    would pass them: a block a step expands goes on, block by block, to the next step before the step's next
    block; at the end each step's held blocks (``finish``) go through the steps after it, the first step's
    first. ``through`` walks one block as far as it goes alone (every block of most programs: no generator
    and no list); ``given`` and ``onward`` go on from where a step gave several blocks or none."""

    def __init__(self, steps: list[BlockStep]) -> None:
        self.steps = steps
        self.made: list[Block] = []
        """What the step before ``at`` gave, where ``through`` stopped (None returned)."""
        self.at = 0
        self.next_move: list[int] = []
        """``next_move[i]``: the first step from ``i`` on whose ``moves`` is True (``len(steps)``: none). A block
        that is only a move goes from one such step to the next: most steps of a translation pass such blocks,
        and looking at each of them cost ~50 instructions a step a block compiled (17 of 21 to LinuxCNC)."""
        self.next_take: list[int] = []
        """``next_take[i]``: the first step from ``i`` on whose work is not over (``passes`` False): the other
        blocks go from one such step to the next."""
        self.route: list[Hop] = []
        """The steps a plain move goes to from the first step on (``moves``, not ``passes``), in order: a block that
        comes in as one and stays one goes down this list (one pass over a list, where stepping through
        ``next_move`` cost two indexed look-ups a step). Each in a ``Hop``: an item of a ``list[BlockStep]`` was
        checked against ``BlockStep`` as it was read, a call of ``PyType_IsSubtype`` for every step a block (the
        steps' classes extend it)."""
        self.route_at: list[int] = []
        """``route_at[k]``: the index in ``steps`` of ``route[k]``."""
        self.marked()

    def marked(self) -> None:
        """``next_move`` and ``next_take`` anew: a step's ``moves`` or ``passes`` changed (which a step does in its
        own calls only)."""
        steps = self.steps  # (one pass over the steps, lists appended: a hole cycle's start and its cancel each
        n = len(steps)  # mark anew, ~9k instructions compiled with a list and a comprehension per answer)
        route: list[Hop] = []
        route_at: list[int] = []
        open_at: list[int] = []
        for k in range(n):
            step = steps[k]
            if not step.passes:
                open_at.append(k)
                if step.moves:
                    route.append(Hop(step))
                    route_at.append(k)
        self.next_move = _firsts(route_at, n)
        self.next_take = _firsts(open_at, n)
        self.route = route
        self.route_at = route_at

    def moved(self, k: int) -> None:
        """``marked`` where only step ``k``'s ``moves`` changed, its work not over (``passes`` False, as it was): the
        route gains or loses it, and ``next_move`` changes from the route's step before it to it. A hole cycle's
        start and its cancel each turn two steps' ``moves`` (the cycles' and the hole patterns'): marked anew, that
        cost ~1.5k instructions a hole compiled (a cycle of 25 holes, callgrind)."""
        steps = self.steps
        route_at = self.route_at
        p = 0
        while p < len(route_at) and route_at[p] < k:
            p += 1
        first = route_at[p - 1] + 1 if p > 0 else 0
        route = list(self.route)  # (new lists: a walk down the old route may be under way)
        at = list(route_at)
        next_move = self.next_move
        if steps[k].moves:
            route.insert(p, Hop(steps[k]))
            at.insert(p, k)
            to = k
        else:
            del route[p]
            del at[p]
            to = next_move[k + 1]
        for j in range(first, k + 1):
            next_move[j] = to
        self.route = route
        self.route_at = at

    def through(self, block: Block, start: int) -> Block | None:
        """``block`` through the steps from ``start`` on: the block that comes out of the last, or None where a
        step gave several blocks or none (``made``, to go on from step ``at``: ``given``). A block that is only
        a plain move (``plain_motion``, asked once, and again for a block a step gave) skips a step whose ``moves``
        is False; a straight move of X, Y and Z numbers is noted in the ``point`` of a step that has one (read once,
        ``MoveWords.read``); the other steps get it through ``take_move``, which gives it back as ``[block]`` where
        it changed it in place into more (``still_moving``: a later step must not skip it, nor take it as only a
        move, nor note it: a ``take_move`` that gives None leaves the move it was given, ``BlockStep.take_move``)."""
        steps = self.steps
        n = len(steps)
        motion = plain_motion(block.sections)
        bits = UNREAD
        i = start
        if motion is not None and start == 0:  # down the route while the block stays that move
            at = self.route_at
            k = 0
            down = True  # (no step changed it)
            for hop in self.route:
                step = hop.step
                k += 1
                point = step.point
                if point is not None:
                    if bits == UNREAD:
                        bits = _straight(motion, point)
                    if bits >= 0:
                        if point.follows:  # (a ``PassedPoint`` notes nothing: no call)
                            point.note(point.words, bits)
                        continue
                out = step.take_move(block)  # (None: still this move, with these words)
                if not step.moves or step.passes:
                    self.marked()  # (a new route: this pass goes on down the one it started, the same after here)
                if out is None:
                    continue
                i = at[k - 1] + 1
                if len(out) != 1:
                    self.made = out
                    self.at = i
                    return None
                block = out[0]
                motion = plain_motion(block.sections)
                bits = UNREAD
                down = False
                break
            if down:
                return block
        while i < n:
            if motion is not None:
                i = self.next_move[i]
                if i == n:
                    break
                step = steps[i]
                i += 1
                point = step.point
                if point is not None:
                    if bits == UNREAD:
                        bits = _straight(motion, point)
                    if bits >= 0:
                        if point.follows:  # (a ``PassedPoint`` notes nothing: no call)
                            point.note(point.words, bits)
                        continue
                out = step.take_move(block)  # (None: still this move, with these words)
                if not step.moves or step.passes:
                    self.marked()
            else:
                i = self.next_take[i]
                if i == n:
                    break
                step = steps[i]
                i += 1
                moves = step.moves
                out = step.take(block)
                if step.passes:
                    self.marked()
                elif step.moves != moves:
                    self.moved(i - 1)
            if out is None:
                continue
            if len(out) == 1:
                block = out[0]
                motion = plain_motion(block.sections)
                bits = UNREAD
                continue
            self.made = out
            self.at = i
            return None
        return block

    def given(self) -> Iterator[Block]:
        """The blocks where ``through`` stopped, each through the steps after the one that gave them."""
        made = self.made
        at = self.at
        for block in made:
            yield from self.onward(block, at)

    def onward(self, block: Block, start: int) -> Iterator[Block]:
        """What comes out of the last step for ``block`` walked from step ``start`` on."""
        one = self.through(block, start)
        if one is not None:
            yield one
        else:
            yield from self.given()

    def finish(self) -> Iterator[Block]:
        """At the end: each step's held blocks through the steps after it, the first step's first."""
        steps = self.steps
        for k in range(len(steps)):
            held_blocks = steps[k].finish()
            self.marked()
            for held in held_blocks:
                yield from self.onward(held, k + 1)


@mypyc_attr(allow_interpreted_subclasses=True)
class Hop:
    """A step of ``Walk.route``: compiled, an item of a ``list[Hop]`` is checked by a compare of types (a ``Hop``
    is of this class itself, where a step is of a class that extends ``BlockStep``: ``PyType_IsSubtype``), and its
    ``step`` field is read unchecked."""

    __slots__ = ("step",)

    def __init__(self, step: BlockStep) -> None:
        self.step = step


def _firsts(indices: list[int], n: int) -> list[int]:
    """For each k of 0..n, the first of ``indices`` (ascending, each below n) from k on, else n."""
    firsts: list[int] = []
    k = 0
    for index in indices:
        while k <= index:
            firsts.append(index)
            k += 1
    while k <= n:
        firsts.append(n)
        k += 1
    return firsts


UNREAD: Final = -2
"""``Walk.through``: the block's move is not read yet."""


def _straight(motion: Motion, point: NotedPoint) -> int:
    """What the loop notes of a plain move: the bits of its X, Y and Z numbers read by ``point``'s reader where it is
    a straight move (``OTHER``: an arc, or other words, go to the step's ``take_move``)."""
    mode = motion.mode
    if mode == "linear" or mode == "rapid":
        return point.words.read(motion)
    return OTHER


def register_transform(transform: Lowering) -> Lowering:
    """Add a generic step to ``TRANSFORMS`` (idempotent)."""
    if transform not in TRANSFORMS:
        TRANSFORMS.append(transform)
    return transform


def lower_for(blocks: Iterator[Block], ctx: Context, target: type[Dialect], on_unsupported: str,
              steps: Sequence[Lowering] | None = None, then: Sequence[Lowering] = ()) -> Iterator[Block]:
    """Apply the generic steps (``steps``, by default the default registry's), then the target's own, then
    ``then`` (a run's own last steps: ``translate``'s arc pass); consecutive ``LoweringStep``s run as one
    loop (``run_blocks``). A function step that gives back the stream it was given has nothing to do in this
    program (``convert_inverse_time`` where nothing is in inverse time...): it does not split the loop, whose
    every level would cost each block a generator's resumption and another ``plain_move`` (~700 instructions
    compiled, four such levels in a translation to LinuxCNC)."""
    ctx.on_unsupported = on_unsupported
    stream = blocks
    group: list[BlockStep] = []
    for transform in [*(TRANSFORMS if steps is None else steps), *target.LOWERING, *then]:
        if isinstance(transform, LoweringStep):
            run = transform.start(ctx, target)
            if run is not None:
                group.append(run)
            continue
        if not group:
            stream = transform(stream, ctx, target)
            continue
        grouped = run_blocks(stream, group)  # (a generator: nothing runs until the first block is asked)
        made = transform(grouped, ctx, target)
        if made is grouped:
            continue  # nothing to do in this program (asked once, here): the loop goes on past it
        stream = made
        group = []
    if group:
        stream = run_blocks(stream, group)
    return stream


def run_blocks(blocks: Iterator[Block], steps: list[BlockStep]) -> Iterator[Block]:
    """Every block through ``steps`` in order (``Walk``), then what they still hold."""
    walk = Walk(steps)
    for block in blocks:
        one = walk.through(block, 0)
        if one is not None:
            yield one
        else:
            yield from walk.given()
    yield from walk.finish()
