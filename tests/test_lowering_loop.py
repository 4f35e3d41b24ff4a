"""``lower_for`` runs consecutive ``LoweringStep``s as one loop over the block stream (``run_blocks``), and a
block that is only a move skips a step whose ``moves`` is False. That must compute what the steps compute
chained as generators, each given every block, as they ran before the loop:

* ``run_blocks`` on hand-made steps: the order of an expansion, of held blocks and of what each step gives
  back at the end, and the skipping of plain moves, against sequences derived by hand;
* translations of random programs (``tests.support.fuzzing``) and of the corpus's programs, through the loop
  and through the steps chained one by one: the same text, the same errors, the same warnings.
"""

from __future__ import annotations

import io
import tomllib
from pathlib import Path
from typing import Iterator, Sequence

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import postproc.api as api
from postproc.context import Context
from postproc.dialect import Dialect
from postproc.errors import Diagnostics, ErrorList, PostprocError
from postproc.ir import Block, Comments, Motion, Sequence as SequenceSection
from postproc.lowering import lower
from postproc.lowering.lower import BlockStep, Lowering, LoweringStep, Steps, run_blocks
from postproc.lowering.move_words import MoveWords, NotedPoint

from postproc.setup.machine_setup import MachineSetup
from tests.support.fuzzing import programs, setups
from tests.support.tools import with_tools

ROOT = Path(__file__).resolve().parent


def _block(name: str, plain: bool) -> Block:
    """A block named by its line's text: only a move (``plain``), or a move with a comment section too."""
    block = Block(len(name), name, "\n")
    block.sections = {"Motion": Motion("linear", {"X": 1.0})}
    if not plain:
        block.sections["Sequence"] = SequenceSection(1)
        block.sections["Comments"] = Comments([name])  # a third section: not only a move
    return block


class _Log(BlockStep):
    """Records what it sees; expands a block named in ``twice`` into two, holds one named in ``hold`` until
    the next it sees (or the end)."""

    def __init__(self, name: str, seen: list[str], moves: bool = True, twice: str = "", hold: str = "") -> None:
        super().__init__()
        self.name, self.seen, self.twice, self.hold = name, seen, twice, hold
        self.moves = moves
        self.held: list[Block] = []

    def take(self, block: Block) -> list[Block] | None:
        self.seen.append(f"{self.name}:{block.text}")
        if block.text == self.hold:
            self.held.append(block)
            return []
        if block.text == self.twice:
            copy = Block(block.line, f"{block.text}'", "\n")
            copy.sections = dict(block.sections)
            return [*self._release(), block, copy]
        if self.held:
            return [*self._release(), block]
        return None

    def _release(self) -> list[Block]:
        out, self.held = self.held, []
        return out

    def finish(self) -> list[Block]:
        self.seen.append(f"{self.name}:end")
        return self._release()


def _texts(blocks: Iterator[Block]) -> list[str]:
    return [str(b.text) for b in blocks]


def test_an_expansion_goes_through_the_next_steps_before_the_next_block() -> None:
    seen: list[str] = []
    a = _Log("a", seen, twice="b")
    b = _Log("b", seen)
    out = _texts(run_blocks(iter([_block("a", False), _block("b", False), _block("c", False)]), [a, b]))
    assert out == ["a", "b", "b'", "c"]
    assert seen == ["a:a", "b:a", "a:b", "b:b", "b:b'", "a:c", "b:c", "a:end", "b:end"]


def test_a_held_block_comes_out_before_the_one_that_releases_it_and_at_the_end() -> None:
    seen: list[str] = []
    a = _Log("a", seen, hold="a")
    b = _Log("b", seen, hold="c")
    out = _texts(run_blocks(iter([_block("a", False), _block("b", False), _block("c", False)]), [a, b]))
    # a holds "a" until "b"; b gets both then, and holds "c" to the end (after a's end, which gives nothing)
    assert out == ["a", "b", "c"]
    assert seen == ["a:a", "a:b", "b:a", "b:b", "a:c", "b:c", "a:end", "b:end"]


def test_a_held_block_given_back_at_the_end_goes_through_the_later_steps() -> None:
    seen: list[str] = []
    a = _Log("a", seen, hold="b")
    b = _Log("b", seen)
    out = _texts(run_blocks(iter([_block("a", False), _block("b", False)]), [a, b]))
    assert out == ["a", "b"]
    assert seen == ["a:a", "b:a", "a:b", "a:end", "b:b", "b:end"]


def test_a_plain_move_skips_a_step_that_says_moves_are_not_its_business() -> None:
    seen: list[str] = []
    a = _Log("a", seen, moves=False)
    b = _Log("b", seen)
    out = _texts(run_blocks(iter([_block("p", True), _block("q", False)]), [a, b]))
    assert out == ["p", "q"]
    assert seen == ["b:p", "a:q", "b:q", "a:end", "b:end"]


class _MoveLog(_Log):
    """A ``_Log`` that says which of its methods the loop called: ``take_move`` for a block only a move."""

    def take_move(self, block: Block) -> list[Block] | None:
        self.seen.append(f"{self.name}-move:{block.text}")
        return self.take(block)


def test_a_block_only_a_move_goes_to_take_move_once_it_is_one() -> None:
    """The loop asks ``only_move`` once and hands such a block to ``take_move``, any other to ``take``; the blocks
    a step makes are asked again on their way through the later steps (``Walk.onward``)."""
    seen: list[str] = []
    a = _Log("a", seen, twice="p")
    b = _MoveLog("b", seen)
    out = _texts(run_blocks(iter([_block("p", True), _block("q", False)]), [a, b]))
    assert out == ["p", "p'", "q"]
    assert seen == ["a:p", "b-move:p", "b:p", "b-move:p'", "b:p'", "a:q", "b:q", "a:end", "b:end"]


class _Tags(_Log):
    """A ``_Log`` that puts a comment section on the block named ``tag``, in place (returning None), as
    ``length_timing`` puts a waiting length change on the next move."""

    def __init__(self, name: str, seen: list[str], tag: str) -> None:
        super().__init__(name, seen)
        self.tag = tag

    def take(self, block: Block) -> list[Block] | None:
        self.seen.append(f"{self.name}:{block.text}")
        if block.text == self.tag:
            block.sections["Comments"] = Comments(["tagged"])
        return None


def test_a_move_changed_in_place_is_no_longer_taken_as_only_a_move() -> None:
    """A step that skips plain moves (``moves`` False) still sees a move an earlier step changed in place into
    something more, and a later step gets it through ``take``, not ``take_move``: by hand, ``p`` tagged by ``a``
    goes to ``b`` and ``c`` as a block with a comment; ``q`` stays a plain move (``b`` skips it)."""
    seen: list[str] = []
    a = _Tags("a", seen, tag="p")
    b = _Log("b", seen, moves=False)
    c = _MoveLog("c", seen)
    out = _texts(run_blocks(iter([_block("p", True), _block("q", True)]), [a, b, c]))
    assert out == ["p", "q"]
    assert seen == ["a:p", "b:p", "c:p", "a:q", "c-move:q", "c:q", "a:end", "b:end", "c:end"]


class _Toggles(_Log):
    """A ``_Log`` that stops following plain moves at the block named ``off`` and follows them again from the
    one named ``on`` (``moves`` set in its own ``take``, as the steps do)."""

    def __init__(self, name: str, seen: list[str], off: str, on: str) -> None:
        super().__init__(name, seen)
        self.off, self.on = off, on

    def take(self, block: Block) -> list[Block] | None:
        if block.text == self.off:
            self.moves = False
        elif block.text == self.on:
            self.moves = True
        return super().take(block)


def test_a_step_that_stops_and_starts_following_moves_is_skipped_only_between() -> None:
    """By hand: ``a`` sees p1, x (then stops), not p2, y (then starts again), p3; ``b`` and ``c`` follow every
    block; a step between them that never follows moves (``n``) sees x and y only."""
    seen: list[str] = []
    a = _Toggles("a", seen, off="x", on="y")
    n = _Log("n", seen, moves=False)
    c = _Log("c", seen)
    names = [("p1", True), ("x", False), ("p2", True), ("y", False), ("p3", True)]
    out = _texts(run_blocks(iter([_block(name, plain) for name, plain in names]), [a, n, c]))
    assert out == ["p1", "x", "p2", "y", "p3"]
    assert seen == ["a:p1", "c:p1", "a:x", "n:x", "c:x", "c:p2", "a:y", "n:y", "c:y", "a:p3", "c:p3",
                    "a:end", "n:end", "c:end"]


class _Done(_Log):
    """A ``_Log`` whose work is over at the block named ``last`` (``passes``, as the feed check's at the first feed)."""

    def __init__(self, name: str, seen: list[str], last: str) -> None:
        super().__init__(name, seen)
        self.last = last

    def take(self, block: Block) -> list[Block] | None:
        if block.text == self.last:
            self.moves = False
            self.passes = True
        return super().take(block)


def test_a_step_whose_work_is_over_sees_no_block_but_still_finishes() -> None:
    """By hand: ``a`` sees p1 and x (its last), then neither the plain move p2 nor the block y; ``c`` sees all;
    both finish."""
    seen: list[str] = []
    a = _Done("a", seen, last="x")
    c = _Log("c", seen)
    names = [("p1", True), ("x", False), ("p2", True), ("y", False)]
    out = _texts(run_blocks(iter([_block(name, plain) for name, plain in names]), [a, c]))
    assert out == ["p1", "x", "p2", "y"]
    assert seen == ["a:p1", "c:p1", "a:x", "c:x", "c:p2", "c:y", "a:end", "c:end"]


class _Flags(BlockStep):
    """A step that only carries ``moves`` and ``passes`` (the walk's marks are what is looked at)."""

    def take(self, block: Block) -> list[Block] | None:
        return None


def _marks(walk: lower.Walk) -> tuple[list[int], list[int], list[int], list[int]]:
    return walk.next_move, walk.next_take, [id(hop.step) for hop in walk.route], walk.route_at


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(st.booleans(), st.booleans()), min_size=1, max_size=12), st.data())
def test_a_step_turning_moves_marks_the_walk_as_marking_it_anew(flags: list[tuple[bool, bool]],
                                                                 data: st.DataObject) -> None:
    """``Walk.moved`` (one step's ``moves`` turned, its work not over) leaves the walk's marks as ``marked``
    makes them from all the steps, over random steps and turns (a turned step's ``moves`` read before and after)."""
    steps: list[BlockStep] = []
    for moves, passes in flags:
        step = _Flags()
        step.moves, step.passes = moves, passes
        steps.append(step)
    walk = lower.Walk(steps)
    open_steps = [k for k, step in enumerate(steps) if not step.passes]
    for _ in range(data.draw(st.integers(0, 6))):
        if not open_steps:
            break
        k = data.draw(st.sampled_from(open_steps))
        steps[k].moves = not steps[k].moves
        old_route = walk.route
        walk.moved(k)
        assert old_route is not walk.route or not old_route  # (a walk down the old route goes on down it)
        fresh = lower.Walk(steps)
        assert _marks(walk) == _marks(fresh)


def test_steps_run_as_one_step_as_they_run_in_the_loop() -> None:
    blocks = [("a", False), ("b", True), ("c", False), ("d", True)]
    alone: list[str] = []
    out_alone = _texts(run_blocks(iter([_block(n, p) for n, p in blocks]),
                                  [_Log("a", alone, twice="c", hold="a"), _Log("b", alone, moves=False)]))
    inside: list[str] = []
    out_inside = _texts(run_blocks(iter([_block(n, p) for n, p in blocks]),
                                   [Steps([_Log("a", inside, twice="c", hold="a"), _Log("b", inside, moves=False)])]))
    assert out_inside == out_alone == ["a", "b", "c", "c'", "d"]
    assert inside == alone == ["a:a", "a:b", "b:a", "a:c", "b:c", "b:c'", "a:d", "a:end", "b:end"]


class _Notes(_MoveLog):
    """A ``_MoveLog`` that follows the point of straight moves as the frame evaluation does: its ``take_move`` notes a
    straight move of X, Y and Z numbers in its ``point`` (and logs the call), which the loop does itself while the
    point is set (``following``)."""

    def __init__(self, name: str, seen: list[str], following: bool = True) -> None:
        super().__init__(name, seen)
        self.notes = NotedPoint(MoveWords())
        self.point = self.notes if following else None
        self.position: dict[str, float | None] = {}

    def take_move(self, block: Block) -> list[Block] | None:
        self.seen.append(f"{self.name}-move:{block.text}")
        return self._follow(block)

    def take(self, block: Block) -> list[Block] | None:
        self.seen.append(f"{self.name}:{block.text}")
        return self._follow(block)

    def _follow(self, block: Block) -> list[Block] | None:
        motion = block.sections["Motion"]
        assert isinstance(motion, Motion)
        words = self.notes.words
        bits = words.read(motion) if motion.mode in ("linear", "rapid") else -1
        if bits >= 0:
            self.notes.note(words, bits)
        else:
            self.notes.into(self.position)
            self.position.update(motion.axes)  # type: ignore[arg-type]
        return None

    def settled(self) -> dict[str, float | None]:
        self.notes.into(self.position)
        return self.position


class _Moves(_Log):
    """A ``_Log`` that puts another straight move in the block named ``moved`` (``X`` + 100), in place, and gives
    None (still only a move), as a frame under a rotation carries a move."""

    def __init__(self, name: str, seen: list[str], moved: str) -> None:
        super().__init__(name, seen)
        self.moved = moved

    def take(self, block: Block) -> list[Block] | None:
        self.seen.append(f"{self.name}:{block.text}")
        if block.text == self.moved:
            motion = block.sections["Motion"]
            assert isinstance(motion, Motion)
            block.sections["Motion"] = Motion(motion.mode, {a: float(v) + 100.0 for a, v in motion.axes.items()})  # type: ignore[arg-type]
        return None


def _move(name: str, mode: str, **axes: float) -> Block:
    block = Block(len(name), name, "\n")
    block.sections = {"Motion": Motion(mode, dict(axes))}
    return block


def test_a_straight_move_is_noted_in_a_steps_point_without_calling_it() -> None:
    """By hand: ``a`` (a point) and ``b`` (none) follow the same moves; the loop notes p1 and p2 (straight, X, Y and Z
    numbers) in ``a``'s point and calls ``a`` for the arc and for the move with another axis; both end where the
    last move put them."""
    seen: list[str] = []
    a = _Notes("a", seen)
    b = _Notes("b", seen, following=False)
    blocks = [_move("p1", "rapid", X=1.0, Y=2.0), _move("arc", "cw", X=3.0, Y=4.0), _move("p2", "linear", Z=-1.0),
              _move("other", "linear", A=90.0), _move("p3", "linear", X=5.0)]
    out = _texts(run_blocks(iter(blocks), [a, b]))
    assert out == ["p1", "arc", "p2", "other", "p3"]
    assert seen == ["b-move:p1", "a-move:arc", "b-move:arc", "b-move:p2", "a-move:other", "b-move:other", "b-move:p3",
                    "a:end", "b:end"]
    assert a.settled() == b.settled() == {"X": 5.0, "Y": 4.0, "Z": -1.0, "A": 90.0}


def test_a_move_another_step_put_in_the_block_is_the_one_the_later_steps_see() -> None:
    """A step between two points puts another move in the block (``X`` + 100), its ``take`` giving None: its
    ``take_move`` (``BlockStep``'s) gives the block back as ``[block]`` (``still_moving``), so the point before it
    has the move as it came, the point after it the new one (the loop reads the block again)."""
    seen: list[str] = []
    a = _Notes("a", seen)
    m = _Moves("m", seen, moved="p2")
    c = _Notes("c", seen)
    out = _texts(run_blocks(iter([_move("p1", "linear", X=1.0), _move("p2", "linear", X=2.0, Y=3.0)]), [a, m, c]))
    assert out == ["p1", "p2"]
    assert seen == ["m:p1", "m:p2", "a:end", "m:end", "c:end"]
    assert a.settled() == {"X": 2.0, "Y": 3.0}
    assert c.settled() == {"X": 102.0, "Y": 103.0}


# -- translations: the loop against the steps chained one by one -------------------------------------------

def _every_block(blocks: Iterator[Block], run: BlockStep) -> Iterator[Block]:
    """One step's run as a generator that hands it every block, plain moves too (``moves`` ignored)."""
    for block in blocks:
        out = run.take(block)
        if out is None:
            yield block
        else:
            yield from out
    yield from run.finish()


def _chained(blocks: Iterator[Block], ctx: Context, target: type[Dialect], on_unsupported: str,
             steps: Sequence[Lowering] | None = None, then: Sequence[Lowering] = ()) -> Iterator[Block]:
    """``lower_for`` as the steps ran before the loop: every step a generator over the one before, and every
    block handed to every step (what a step's ``moves`` says it may skip, it is given here)."""
    ctx.on_unsupported = on_unsupported
    stream = blocks
    for step in [*(lower.TRANSFORMS if steps is None else steps), *target.LOWERING, *then]:
        if isinstance(step, LoweringStep):
            run = step.start(ctx, target)
            if run is not None:
                stream = _every_block(stream, run)
        else:
            stream = step(stream, ctx, target)
    return stream


def _translation(program: str, source: str, target: str, setup: object, warn: bool) -> tuple[str, list[str], list[str]]:
    out = io.StringIO()
    diagnostics = Diagnostics(warn_stream=io.StringIO())
    try:
        api.translate(io.StringIO(program, newline=""), out, file="t.nc", source=source, target=target,
                      setup=setup, on_unsupported="warn" if warn else "error",  # type: ignore[arg-type]
                      diagnostics=diagnostics)
    except ErrorList as errs:
        return "", [str(e) for e in errs.errors], [str(w) for w in diagnostics.warnings]
    except PostprocError as err:
        return "", [str(err)], [str(w) for w in diagnostics.warnings]
    return out.getvalue(), [], [str(w) for w in diagnostics.warnings]


def _both(program: str, source: str, target: str, setup: object, warn: bool) -> None:
    looped = _translation(program, source, target, setup, warn)
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(api, "lower_for", _chained)
        chained = _translation(program, source, target, setup, warn)
    assert looped == chained


TARGETS = ["linuxcnc", "grbl", "grblhal", "isg", "fagor", "fanuc", "mach3"]


@settings(max_examples=40)
@given(program=programs(), setup=setups(), source=st.sampled_from(["fanuc", "linuxcnc", "isg", "fagor"]),
       target=st.sampled_from(TARGETS), warn=st.booleans())
def test_random_programs_translate_as_through_the_chained_steps(program: str, setup: object, source: str,
                                                                 target: str, warn: bool) -> None:
    _both(program, source, target, setup, warn)


_NUMBER = st.integers(-400, 400).map(lambda n: f"{n / 4:.2f}")
_STRAIGHT = st.builds(lambda g, axes: f"{g} " + " ".join(axes), st.sampled_from(["", "", "G01", "G00"]),
                      st.lists(st.tuples(st.sampled_from("XYZ"), _NUMBER).map("".join), min_size=1, max_size=3,
                               unique_by=lambda w: w[0]))
_OTHER = st.sampled_from(["G91", "G90", "G20", "G21", "G43 H1", "G49", "G52 X5. Y-2.", "G52 X0 Y0", "G68 X0 Y0 R30.",
                          "G69", "G02 I5. J0.", "G03 I-1. J0.", "G01 A15.", "G01 X1 Y2", "F900.",
                          "G41 D1 G01 X10. Y0.", "G40 G01 X0. Y0.", "M03 S1000", "G28 Z0.", "G53 G00 Z0.", "G91 G28 Z0."])
_READERS = st.sampled_from(["G43 H1\nX3. Y4.", "G49\nG43 H2\nG00 X1.", "G68 X0 Y0 R30.\nX2. Y3.\nX7.\nG69",
                            "G52 X5.\nY4.\nG52 X0", "G02 I2. J2.", "G03 I0. J-3."])
"""Blocks that read the point the moves before them noted: a length change put on the next move (its Z), an
omitted axis under a rotation or a local offset, an arc's start (full circles: an R arc between random points
could be no arc, which the controller checks of the suite refuse)."""


def plain_moves() -> st.SearchStrategy[str]:
    """CAM-like programs: runs of straight moves of X, Y and Z numbers (what the loop notes in a step's point), each
    followed by a block that changes what such a move is to a step (incremental or inch words, a length offset, a
    frame, an arc, another axis, compensation, a reference return) or that reads the point they noted."""
    chunk = st.tuples(st.lists(_STRAIGHT, min_size=1, max_size=4), st.one_of(_READERS, _OTHER)).map(
        lambda c: "\n".join([*c[0], c[1]]))
    return st.lists(chunk, min_size=1, max_size=6).map(
        lambda chunks: "G21 G90 G17 G00 X0. Y0. Z10.\nG01 F600.\n" + "\n".join(chunks) + "\nM30\n")


@settings(max_examples=60)
@given(program=plain_moves(), source=st.sampled_from(["fanuc", "linuxcnc"]),
       target=st.sampled_from(["linuxcnc", "grbl", "isg", "fagor", "fanuc"]), warn=st.booleans())
def test_plain_moves_noted_by_the_loop_translate_as_through_the_chained_steps(program: str, source: str, target: str,
                                                                              warn: bool) -> None:
    """The moves the loop notes in the steps' points (``BlockStep.point``) against the same steps given every block
    through ``take``: the same text, errors and warnings (a loop that noted no move fails it: a length change put
    on the next move gets another Z)."""
    _both(program, source, target, with_tools(MachineSetup(), {1: 10.0, 2: 20.0}), warn)


def _corpus() -> list[tuple[str, str]]:
    manifest = tomllib.loads((ROOT / "corpus" / "corpus.toml").read_text(encoding="utf-8"))
    return [(p["path"], p["dialect"]) for p in manifest["program"]
            if p.get("machine", "mill") == "mill" and "setup" not in p]


@pytest.mark.parametrize("path,source", _corpus(), ids=lambda v: str(v))
def test_corpus_programs_translate_as_through_the_chained_steps(path: str, source: str) -> None:
    program = (ROOT / "corpus" / path).read_text(encoding="utf-8", errors="replace")
    for target in ("linuxcnc", "grbl", "isg", "fagor"):
        _both(program, source, target, None, False)


def test_the_core_steps_are_lowering_steps() -> None:
    """The steps every translation runs take the blocks one at a time (else each splits the loop)."""
    from postproc.plugins import default_registry
    registry = default_registry()
    generators = [getattr(s, "__name__", s) for s in registry.lowerings if not isinstance(s, LoweringStep)]
    assert set(generators) <= {"expand_lathe_cycles", "index_turret", "convert_inverse_time",
                                "carry_path_at_start", "hold_stored_offsets", "warn_active_comments"}, generators


@pytest.mark.parametrize("target", ["linuxcnc", "grbl", "grblhal", "isg", "fagor", "siemens"])
def test_the_targets_own_steps_are_lowering_steps(target: str) -> None:
    """A target's own steps that every translation to it runs take the blocks one at a time too (the
    built-ins' and the bundled plugins', grblHAL's included)."""
    from postproc.plugins import default_registry
    dialect = default_registry().dialect(target)
    generators = [getattr(s, "__name__", s) for s in dialect.LOWERING if not isinstance(s, LoweringStep)]
    assert generators == []


def test_a_reference_return_alone_goes_the_general_way() -> None:
    """A block that is only a reference return (``G28 Z0.``: ``Motion('home')``) is no plain move (``plain_move``):
    a step that skips plain moves still sees it, and a step that follows them gets it through ``take`` (where
    ``measured_entries`` notes the axes it takes home). By hand: ``n`` sees only ``r``, ``c`` takes ``r`` the
    general way and ``p`` as a move."""
    seen: list[str] = []
    n = _Log("n", seen, moves=False)
    c = _MoveLog("c", seen)
    home = _block("r", True)
    home.sections["Motion"] = Motion("home", {"Z": 0.0})
    out = _texts(run_blocks(iter([_block("p", True), home]), [n, c]))
    assert out == ["p", "r"]
    assert seen == ["c-move:p", "c:p", "n:r", "c:r", "n:end", "c:end"]
