"""``postproc.lowering.move_words``: a plain move's X, Y and Z read once for the steps that follow the point, and
the steps that note them instead of writing their position at once (the frame evaluation, the arc pass).

* ``MoveWords.read`` against the move's dictionary read word by word, on random moves (another axis, an ``int``
  or a computed word: ``OTHER``), and its reads keyed on the ``Motion``, its dictionary and its size;
* the frame evaluation's and the arc pass's position after random plain moves (noted, then brought up to date
  before a read) against the dictionary updated move by move, as both did before.
"""

from __future__ import annotations

from hypothesis import example, given
from hypothesis import strategies as st

from postproc.context import Context
from postproc.errors import Diagnostics, ErrorLevel
from postproc.frames.lowering import FrameEvaluator
from postproc.frames.run_state import FrameRun
from postproc.ir import Block, Motion
from postproc.ir.expr import Expr, Var
from postproc.lowering.arcs import ArcOption, _Arcs
from postproc.lowering.move_words import OTHER, X, Y, Z, MoveWords, move_words
from postproc.setup.machine_setup import MachineSetup

_BITS = {"X": X, "Y": Y, "Z": Z}

words = st.one_of(
    st.floats(-1e4, 1e4, allow_nan=False),
    st.integers(-5, 5),
    st.just(Var(name="depth")),
)
axes = st.dictionaries(st.sampled_from(["X", "Y", "Z", "A", "U"]), words, max_size=4)
plain_axes = st.dictionaries(st.sampled_from(["X", "Y", "Z"]), st.floats(-1e4, 1e4, allow_nan=False), max_size=3)


def _expected(given: dict[str, float | Expr]) -> tuple[int, dict[str, float]]:
    """The bits and numbers of a move, word by word."""
    bits = 0
    for axis, value in given.items():
        if axis not in _BITS or type(value) is not float:
            return OTHER, {}
        bits |= _BITS[axis]
    return bits, dict(given)  # type: ignore[arg-type]


@given(st.lists(axes, min_size=1, max_size=6))
def test_a_read_gives_the_moves_numbers(moves: list[dict[str, float | Expr]]) -> None:
    read = MoveWords()
    for given in moves:
        motion = Motion("linear", dict(given))
        bits, numbers = _expected(given)
        for _ in range(2):  # the second read: the same Motion, read before
            assert read.read(motion) == bits
            if bits != OTHER:
                got = {a: getattr(read, a.lower()) for a, bit in _BITS.items() if bits & bit}
                assert got == numbers


def test_a_read_is_made_again_for_a_changed_move() -> None:
    read = MoveWords()
    motion = Motion("linear", {"X": 1.0})
    assert read.read(motion) == X
    motion.axes = {"X": 2.0}  # a new dictionary (a step that changes a move's words makes one)
    assert read.read(motion) == X and read.x == 2.0
    motion.axes["Z"] = 3.0  # a word added: another size
    assert read.read(motion) == X | Z and read.z == 3.0
    assert read.read(Motion("linear", {"X": 4.0, "A": 1.0})) == OTHER


def _ctx() -> Context:
    return Context("t.nc", MachineSetup(), Diagnostics(ErrorLevel.IMMEDIATE), "fanuc")


def _moves(moves: list[dict[str, float | Expr]]) -> list[Block]:
    blocks = []
    for n, given in enumerate(moves):
        block = Block(n + 1, "", "\n")
        block.sections = {"Motion": Motion("linear", dict(given))}
        blocks.append(block)
    return blocks


@given(st.lists(st.one_of(plain_axes, plain_axes, axes.filter(lambda a: not any(isinstance(v, Expr)
                                                                                for v in a.values()))),
                max_size=12))
def test_the_frame_evaluations_point_follows_every_move(moves: list[dict[str, float | Expr]]) -> None:
    ctx = _ctx()
    evaluator = FrameEvaluator(ctx)
    run = ctx.frame_run
    assert isinstance(run, FrameRun)
    expected = dict(run.p)
    for block, given in zip(_moves(moves), moves):
        assert evaluator.take_move(block) is None
        expected.update(given)
        assert run.point() == expected


@given(st.lists(st.one_of(plain_axes, plain_axes, axes), max_size=12))
def test_the_arc_passs_position_follows_every_move(moves: list[dict[str, float | Expr]]) -> None:
    ctx = _ctx()
    ctx.state.symbolic = any(isinstance(v, Expr) for given in moves for v in given.values())
    step = _Arcs(ctx, ArcOption("settle"), _target())
    rewriter = step.rewriter
    expected = dict(rewriter.position)
    for block, given in zip(_moves(moves), moves):
        assert step.take_move(block) is None
        expected.update({a: None if isinstance(v, Expr) else v for a, v in given.items()})
        rewriter.settle()
        assert rewriter.position == expected


def test_one_reading_for_a_run() -> None:
    ctx = _ctx()
    assert move_words(ctx) is move_words(ctx)


def _target() -> type:
    from postproc.plugins import default_registry
    return default_registry().dialect("grbl")


arc_moves = st.tuples(st.sampled_from(["linear", "rapid", "cw", "ccw"]), plain_axes,
                      st.sampled_from(["ijk", "ijk", "r", "none"]))


@given(st.lists(arc_moves, max_size=12))
@example([("linear", {"X": 0.0, "Y": 0.0}, "none"), ("cw", {"X": 50.0, "Y": 0.0}, "r"), ("ccw", {"X": 0.0}, "ijk")])
def test_the_arc_pass_takes_a_kept_centre_arc_as_a_straight_move(moves: list[tuple[str, dict[str, float], str]]) -> None:
    """From a source whose controller keeps the programmed centre (Fanuc's), the settle pass follows a plain I/J/K
    arc as a straight move (``_Arcs.kept_centres``): the same position, the block as it was, as through ``take``
    (``_Arcs.rewrite``, the general way; the example's half circle by R is written by I/J/K, ``settle_arc_ends``)."""
    fast, slow = _ctx(), _ctx()
    fast_step = _Arcs(fast, ArcOption("settle"), _target())
    slow_step = _Arcs(slow, ArcOption("settle"), _target())
    assert fast_step.kept_centres
    for n, (mode, given, centre) in enumerate(moves):
        blocks = []
        for _ in range(2):
            block = Block(n + 1, "", "\n")
            arc = mode in ("cw", "ccw")
            block.sections = {"Motion": Motion(mode, dict(given), {"X": 1.5, "Y": -0.5} if arc and centre == "ijk" else None,
                                               25.0 if arc and centre == "r" else None)}
            blocks.append(block)
        assert fast_step.take_move(blocks[0]) == slow_step.rewrite(blocks[1]) is None
        fast_step.rewriter.settle()
        slow_step.rewriter.settle()
        assert fast_step.rewriter.position == slow_step.rewriter.position
        assert blocks[0].sections["Motion"] == blocks[1].sections["Motion"]


ends = st.dictionaries(st.sampled_from(["X", "Y", "Z", "A"]),
                       st.one_of(st.floats(-1e4, 1e4, allow_nan=False), st.integers(-5, 5), st.none()), max_size=4)


@given(st.lists(st.one_of(plain_axes.map(lambda a: ("move", a)), ends.map(lambda e: ("end", e))), max_size=10),
       st.dictionaries(st.sampled_from(["X", "Y", "Z", "A"]), st.floats(-1e4, 1e4, allow_nan=False)))
@example([("end", {"X": 1.0, "Y": 2.0, "Z": 3.0})], {"X": 0.0, "Y": 0.0, "Z": 0.0})
def test_an_expansions_end_noted_is_the_position_updated(steps: list[tuple[str, dict[str, float | None]]],
                                                           start: dict[str, float | None]) -> None:
    """``NotedPoint.note_end`` (X, Y and Z numbers only; else False, the dictionary updated at once) among plain moves
    noted: the position after each, brought up to date, is the dictionary updated end by end and move by move."""
    ctx = Context("t.nc", MachineSetup(), Diagnostics(ErrorLevel.IMMEDIATE), "fanuc")
    notes = _Arcs(ctx, ArcOption("settle"), _target()).rewriter.notes
    position: dict[str, float | None] = dict(start)
    expected: dict[str, float | None] = dict(start)
    for kind, given_axes in steps:
        expected.update(given_axes)
        if kind == "move":
            bits = notes.words.read(Motion("linear", dict(given_axes)))  # type: ignore[arg-type]  # numbers
            assert bits >= 0
            notes.note(notes.words, bits)
        elif not notes.note_end(given_axes):
            assert set(given_axes) - {"X", "Y", "Z"} or any(type(v) is not float for v in given_axes.values())
            notes.into(position)
            position.update(given_axes)
        else:
            assert set(given_axes) <= {"X", "Y", "Z"} and all(type(v) is float for v in given_axes.values())
        notes.into(position)
        assert position == expected


machines = st.sampled_from([frozenset("XYZ"), frozenset("XZ"), frozenset("XY"), frozenset("XYZA"), frozenset("YZU")])


@given(machines, st.lists(st.tuples(st.sampled_from(["linear", "rapid", "linear"]), axes), max_size=10))
@example(frozenset("XYZ"), [("linear", {"Z": 1.0, "X": 2.0}), ("rapid", {"A": 1.0, "X": 3.0})])
@example(frozenset("XZ"), [("linear", {"X": 1.0}), ("linear", {"Y": 2.0, "X": 3.0}), ("linear", {"Z": 4.0})])
def test_the_modal_states_plain_move_is_its_general_move(machine: frozenset[str],
                                                         moves: list[tuple[str, dict[str, float | Expr]]]) -> None:
    """``ModalStateSyntax``: a block that is only a move (and its number) is read by the run's ``MoveWords`` where
    its words are X, Y and Z numbers on the machine (``_move``'s first branch); with another section beside it
    (a comment: no modal change) it goes the general way. Both leave the same position, in the same order, the
    same motion mode, and refuse the same blocks (an axis not on the machine) with the same message."""
    from postproc.errors import ProgramError
    from postproc.ir import Comments, Sequence
    from postproc.syntaxes.modal_state import ModalStateSyntax

    runs = []
    for beside in (None, Sequence(7), Comments(["beside"])):
        ctx = _ctx()
        ctx.axis_words = machine
        ctx.state.symbolic = any(isinstance(v, Expr) for _, given in moves for v in given.values())
        syntax = ModalStateSyntax()
        seen = []
        for n, (mode, given) in enumerate(moves):
            block = Block(n + 1, "", "\n")
            block.sections = {"Motion": Motion(mode, dict(given))}
            if beside is not None:
                block.sections[beside.KEY] = beside
            try:
                syntax.build(block, ctx)
                error = ""
            except ProgramError as err:
                error = str(err)
            position = ctx.state.position
            seen.append((list(position.items()), ctx.state.motion, error, "Motion" in block.sections))
        runs.append(seen)
    assert runs[0] == runs[2]
    assert runs[1] == runs[2]


sim_axes = st.dictionaries(st.sampled_from(["X", "Y", "Z", "A"]), st.one_of(
    st.floats(-1e4, 1e4, allow_nan=False), st.integers(-5, 5)), max_size=4)


@given(st.sampled_from(["XYZ", "XZ", "XY", "XYZA", "ZYX", "YZA"]),
       st.lists(st.tuples(sim_axes, st.booleans(), st.sampled_from(["mm", "inch"]), st.booleans(), st.booleans(),
                          st.booleans()), min_size=1, max_size=8))
@example("XYZ", [({"X": 1.5, "Z": -2.25}, True, "mm", False, False, False)])
@example("XZ", [({"X": 1.5, "Y": -2.25}, True, "mm", False, False, False)])
def test_the_simulators_target_of_a_read_move_is_its_general_target(
        machine: str, moves: list[tuple[dict[str, float | int], bool, str, bool, bool, bool]]) -> None:
    """``Position.target`` takes a move the run's ``MoveWords`` read last (the modal state's read, keyed on the
    move's dictionary) from its X, Y and Z words; any other move by its look-ups. On random machines, moves,
    units, distance modes, work shifts and machine moves, both give the same point, each value the same object
    (a word's own float where the general loop stores it), or refuse the move with the same message: the read
    move's target against the same simulator's with a fresh (unread) ``MoveWords``. The test fails with the
    read's machine check (``xyz_bits``) or its mode checks taken out."""
    from postproc.errors import ProgramError
    from postproc.simulate.simulator import Simulator

    setup = MachineSetup()
    setup.machine.axes = machine
    sim = Simulator(Context("t.nc", setup, Diagnostics(ErrorLevel.IMMEDIATE), "fanuc"))
    block = Block(1, "G1", "\n")
    for given, read_it, units, incremental, shifted, machine_move in moves:
        sim.set_scale(25.4 if units == "inch" else 1.0)
        sim.incremental = incremental
        sim.shift = {"X": 2.5} if shifted else {}
        motion = Motion("linear", dict(given))
        got = []
        for fresh in (False, True):
            if fresh:
                sim.ctx.move_words = MoveWords()
            elif read_it:
                sim.ctx.move_words.read(motion)
            try:
                out = sim.target(block, motion.axes, False, machine_move)
                got.append(([(type(v), v) for v in out], [any(v is w for w in given.values()) for v in out]))
            except ProgramError as err:
                got.append((str(err), []))
        assert got[0] == got[1]
        sim.at = [float(v) for v in sim.at]
