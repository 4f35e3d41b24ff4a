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

from tests.support.fuzzing import programs, setups

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
