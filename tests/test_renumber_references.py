"""``--renumber`` and words that name block numbers (#20: wrong code with exit 0).

Before leftovers8: renumbering a Fanuc lathe program turned ``N10``/``N20`` into other numbers but left
``G71 P10 Q20`` and ``G70 P10 Q20`` as written, so the cycles roughed and finished whatever blocks now carried
N10..N20. leftovers8 refused such a program (and a GOTO, an ``IF [...] GOTO``, an ``M99 P``). Now, in the
program's own dialect, the renumbering is an exact old -> new mapping (``postproc.output.block_renumbering``):
every literal reference is written with its target's new number, checked by golden files (checked by hand,
``tests/golden/renumber/README.md``), by ``verify`` (the renumbered program moves as its source, move for move,
loops and returns included) and by random programs; what cannot be rewritten exactly (a computed target, a
missing or repeated number, a line the writer keeps as written, a GSK ``G65 H80`` macro jump) is refused,
located; past ``numberMax`` ``--renumber`` wraps to its start, refused where the wrap would give a referenced
block's new number to a second block.
``<Output blockNumbers>`` (numbering the written lines) still refuses a program that names block numbers.
Also: ``--renumber`` between two dialects numbers the written lines (``blockNumbers="all"``), and so does a
set-up's ``renumberStart`` alone between two dialects (before: ignored, exit 0)."""

from __future__ import annotations

import io
import re
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from postproc.api import translate
from postproc.commands.cli import main
from postproc.errors import Diagnostics, ErrorList
from postproc.setup.machine_setup import InputSettings, MachineSettings, MachineSetup, OutputSettings
from postproc.simulate.verify import verify_lines

LATHE_PROGRAM = ("O1000\nG21 G18 G40 G97 G99\nT0101\nG0 X52. Z2. S1500 M3\nG71 U2. R0.5\n"
                 "G71 P10 Q20 U0.4 W0.1 F0.25\nN10 G0 X20.\nG1 Z-20.\nX40. Z-30.\nN20 X52.\nG70 P10 Q20\n"
                 "G0 X100. Z100.\nM30\n")
"""A roughing cycle (line 6) and a finishing cycle (line 11) on the profile N10..N20."""

MILL_HEAD = "O1000\nG21 G17 G90 G40 G49 G80\nG0 X0. Y0. Z5.\n"


def _lathe(**output: int | str) -> MachineSetup:
    return MachineSetup(input=InputSettings(machine_type="lathe"), machine=MachineSettings(axes="XZ"),
                        output=OutputSettings(**output))  # type: ignore[arg-type]


def _translate(program: str, setup: MachineSetup, source: str = "fanuc", target: str = "fanuc") -> str:
    out = io.StringIO()
    translate(program.splitlines(keepends=True), out, file="t.nc", source=source, target=target, setup=setup)
    return out.getvalue()


GOLDEN = Path(__file__).parent / "golden" / "renumber"
CASES = sorted(p for p in GOLDEN.glob("*.nc") if ".expected." not in p.name)


def _setup_for(case: Path, **output: int | str) -> MachineSetup:
    return _lathe(**output) if case.name.startswith("lathe_") else MachineSetup(
        output=OutputSettings(**output))  # type: ignore[arg-type]


def _verified(source: str, written: str, setup: MachineSetup) -> None:
    """``written`` moves the tool as ``source``, move for move (a flattened run of each: loops and returns)."""
    report = verify_lines(source.splitlines(keepends=True), written.splitlines(keepends=True), file_in="in.nc",
                          file_out="out.nc", source="fanuc", target="fanuc", setup=setup)
    assert report.ok, report.summary()
    assert report.max_deviation == 0.0


@pytest.mark.parametrize("case", CASES, ids=[p.stem for p in CASES])
def test_renumbering_rewrites_every_reference_as_checked_by_hand(case: Path) -> None:
    source = case.read_text()
    written = _translate(source, _setup_for(case, renumber_start=100, renumber_step=5))
    assert written == case.with_name(case.stem + ".expected.nc").read_text()
    _verified(source, written, _setup_for(case))


def test_the_goldens_cover_a_profile_a_loop_a_jump_and_a_return() -> None:
    texts = "".join(case.read_text() for case in CASES)
    for reference in ("G71 P", "G70 P", "IF [", "GOTO 30", "M99 P"):
        assert reference in texts


def test_verify_tells_a_reference_to_the_wrong_block() -> None:
    """The check above can fail: the same output with the return one block off moves the tool elsewhere."""
    case = GOLDEN / "return_to_block.nc"
    written = case.with_name("return_to_block.expected.nc").read_text().replace("M99 P115", "M99 P120")
    report = verify_lines(case.read_text().splitlines(keepends=True), written.splitlines(keepends=True),
                          file_in="in.nc", file_out="out.nc", source="fanuc", target="fanuc", setup=MachineSetup())
    assert not report.ok


def test_the_lathe_cycles_follow_their_profile() -> None:
    written = _translate(LATHE_PROGRAM, _lathe(renumber_start=10, renumber_step=10))
    lines = written.splitlines()
    assert lines[5] == "N50 G71 P60 Q90 U0.4 W0.1 F0.25" and lines[10] == "N100 G70 P60 Q90"
    assert lines[6].startswith("N60 G0 X20.") and lines[9].startswith("N90 X52.")
    _verified(LATHE_PROGRAM, written, _lathe())


def test_numbering_the_lines_of_a_lathe_cycle_profile_is_refused() -> None:
    with pytest.raises(ErrorList, match=r"t\.nc:6:1: error: block numbers cannot be rewritten in a program that "
                                        r"jumps to block numbers or names them"):
        _translate(LATHE_PROGRAM, _lathe(block_numbers="all", renumber_start=10))


def test_a_lathe_cycle_is_copied_with_its_numbers_when_nothing_renumbers() -> None:
    assert _translate(LATHE_PROGRAM, _lathe()) == LATHE_PROGRAM


def test_a_profile_to_a_missing_block_is_refused_at_its_word() -> None:
    program = LATHE_PROGRAM.replace("G70 P10 Q20", "G70 P10 Q25")
    with pytest.raises(ErrorList, match=r"t\.nc:11:9: error: --renumber cannot rewrite the profile's last block "
                                        r"N25: no block of the file carries that number"):
        _translate(program, _lathe(renumber_start=10, renumber_step=10))


@pytest.mark.parametrize("jump", ["GOTO #2", "IF [#1 LT 3] GOTO [#2+10]", "M99 P#2"],
                         ids=["computed-goto", "computed-if-goto", "computed-return"])
def test_renumbering_a_computed_target_is_refused(jump: str) -> None:
    program = MILL_HEAD + f"#1=0\n#2=10\nN10 #1=#1+1\n{jump}\nM30\n"
    with pytest.raises(ErrorList, match=r"t\.nc:7:1: error: --renumber cannot rewrite a computed block number"):
        _translate(program, MachineSetup(output=OutputSettings(renumber_start=100)))


def test_a_jump_to_a_missing_block_is_refused() -> None:
    program = MILL_HEAD + "N10 G1 X1. F100.\nGOTO 40\nM30\n"
    with pytest.raises(ErrorList, match=r"t\.nc:5:1: error: --renumber cannot rewrite the jump's target N40: no "
                                        r"block of the file carries that number"):
        _translate(program, MachineSetup(output=OutputSettings(renumber_start=100)))


def test_a_jump_to_a_repeated_number_is_refused() -> None:
    """Fanuc searches forward from the jump, then from the start: which N10 it reaches depends on where the
    jump stands; the renumbering gives the two blocks two numbers, so the reference is refused, not guessed."""
    program = MILL_HEAD + "#1=0\nN10 #1=#1+1\nN10 G1 X#1 F100.\nIF [#1 LT 3] GOTO 10\nM30\n"
    with pytest.raises(ErrorList, match=r"t\.nc:7:1: error: --renumber cannot rewrite the jump's target N10: the "
                                        r"number is on several blocks \(lines 5, 6\)"):
        _translate(program, MachineSetup(output=OutputSettings(renumber_start=100)))


def test_a_jump_to_a_number_a_subprogram_and_its_caller_both_carry_is_refused() -> None:
    """Which of the two a controller reaches depends on whether it holds the subprogram as a program of its own
    (this tool's simulator searches the whole file): refused, not guessed."""
    program = (GOLDEN / "return_to_block.nc").read_text().replace("N70 #5", "N10 #5").replace("GOTO 70", "GOTO 10")
    with pytest.raises(ErrorList, match=r":14:1: error: --renumber cannot rewrite the jump's target N10: the number "
                                        r"is on several blocks \(lines 4, 12\)"):
        _translate(program, MachineSetup(output=OutputSettings(renumber_start=100)))


def test_a_return_to_a_repeated_number_is_refused() -> None:
    program = (GOLDEN / "return_to_block.nc").read_text().replace("N70 #5", "N50 #5").replace("GOTO 70", "GOTO 50")
    with pytest.raises(ErrorList, match=r":17:1: error: --renumber cannot rewrite the return's block number N50: "
                                        r"the number is on several blocks \(lines 7, 12\)"):
        _translate(program, MachineSetup(output=OutputSettings(renumber_start=100)))


JUMP_BACK = "O1000\nN1 G0 X0. Y0. Z5.\nN2 G1 X1. F100.\nN3 G1 X2.\nN4 G1 X3.\nGOTO 1\nM30\n"
"""A jump to the first block (line 6 names N1)."""


def test_a_wrap_that_would_repeat_a_referenced_number_is_refused_at_the_block_past_number_max() -> None:
    """``numberMax`` 20 from 10 by 5: N10 N15 N20, then line 5 would be N25 and wraps to N10, which the first
    block, the jump's target, already has (was: N25 and N30 written past ``numberMax``, exit 0)."""
    setup = MachineSetup(output=OutputSettings(renumber_start=10, renumber_step=5, number_max=20))
    with pytest.raises(ErrorList) as info:
        _translate(JUMP_BACK, setup)
    assert [str(e) for e in info.value.errors] == [
        "t.nc:5:1: error: --renumber would number this block N25, past numberMax 20 (the largest block number the "
        "set-up's controller takes), and wrapped back to N10 the numbering gives N10 to several blocks: the jump's "
        "target on line 6, N1, would name more than one block. Renumber with a smaller START or STEP (or raise "
        "numberMax, if the controller takes more digits)"]


def test_a_wrap_that_leaves_every_referenced_number_single_is_written_and_moves_the_same() -> None:
    """``numberMax`` 30 from 10 by 10: N10 N20 N30, then N10 N20 again; the jump's target N5 became N30, on one
    block only, so the wrap is exact (worked out by hand; the jump skips the X9. move)."""
    program = "O1000\nG0 X0. Y0. Z5.\nGOTO 5\nG1 X9. F100.\nN5 G1 X2. F100.\nG1 X3.\nM30\n"
    written = _translate(program, MachineSetup(output=OutputSettings(renumber_start=10, renumber_step=10,
                                                                     number_max=30)))
    assert written.splitlines()[1:7] == ["N10 G0 X0. Y0. Z5.", "GOTO 30", "N20 G1 X9. F100.", "N30 G1 X2. F100.",
                                         "N10 G1 X3.", "N20 M30"]
    _verified(program, written, MachineSetup())


def test_renumbering_past_five_digits_wraps_where_nothing_names_a_block(tmp_path: Path) -> None:
    """A Fanuc's N address takes five digits (``numberMax`` 99999 by default): from 99980 by 10 the third block
    wraps to N99980, and so on (was: N100000, an alarm on the controller, exit 0)."""
    source = tmp_path / "in.nc"
    source.write_text(PLAIN)
    written = tmp_path / "out.nc"
    assert main(["translate", str(source), "--from", "fanuc", "--to", "fanuc", "--renumber", "99980,10",
                 "-o", str(written)]) == 0
    numbers = re.findall(r"^N(\d+) ", written.read_text(), re.M)
    assert numbers == ["99980", "99990"] * 3
    report = verify_lines(PLAIN.splitlines(keepends=True), written.read_text().splitlines(keepends=True),
                          file_in="in.nc", file_out="out.nc", source="fanuc", target="fanuc", setup=MachineSetup())
    assert report.ok and report.max_deviation == 0.0, report.summary()


def test_a_start_above_number_max_is_refused_at_the_first_block() -> None:
    """Nothing to wrap into: N100000 is already past what the controller takes."""
    with pytest.raises(ErrorList) as info:
        _translate(PLAIN, MachineSetup(output=OutputSettings(renumber_start=100000)))
    assert [str(e) for e in info.value.errors] == [
        "t.nc:2:1: error: --renumber numbers this block N100000, above numberMax 99999, the largest block number "
        "the set-up's controller takes (<Output numberMax>): start at 99999 or lower"]


def test_a_program_number_is_not_a_block_number() -> None:
    """``M98 P2000`` names a program: it stays as written while every block number changes."""
    written = (GOLDEN / "return_to_block.expected.nc").read_text()
    assert "M98 P2000" in written and "O2000" in written


PLAIN = MILL_HEAD + "N5 G1 X10. Y5. F300.\nG2 X20. Y5. R5.\n(a comment)\nN99 G0 Z50.\nM30\n"
"""A program that names no block number: renumbered freely."""


def _cli(tmp_path: Path, target: str) -> str:
    source = tmp_path / "in.nc"
    source.write_text(PLAIN)
    written = tmp_path / f"out-{target}.nc"
    assert main(["translate", str(source), "--from", "fanuc", "--to", target, "--renumber", "100,5",
                 "-o", str(written)]) == 0
    return written.read_text()


@pytest.mark.parametrize("target", ["fanuc", "linuxcnc", "grbl"])
def test_renumber_applies_in_every_dialect_and_keeps_the_motion(tmp_path: Path, target: str) -> None:
    """Before: to linuxcnc or grbl the written lines kept no numbers (N5, N99 dropped, none given)."""
    written = _cli(tmp_path, target)
    numbers = [int(m.group(1)) for line in written.splitlines() if (m := re.match(r"N(\d+) ", line))]
    assert numbers[:3] == [100, 105, 110] and numbers == list(range(100, 100 + 5 * len(numbers), 5))
    assert not re.search(r"\bN(5|99)\b", written)
    report = verify_lines(PLAIN.splitlines(keepends=True), written.splitlines(keepends=True), file_in="in.nc",
                          file_out="out.nc", source="fanuc", target=target, setup=MachineSetup())
    assert report.ok, report.summary()
    assert report.max_deviation == 0.0


def test_renumber_applies_between_dialects_in_a_batch(tmp_path: Path) -> None:
    """The batch sets the option up on its own path (``commands.batch.work``): the same numbering."""
    sources = [tmp_path / "a.nc", tmp_path / "b.nc"]
    for source in sources:
        source.write_text(PLAIN)
    (tmp_path / "out").mkdir()
    assert main(["translate", *map(str, sources), "--from", "fanuc", "--to", "grbl", "--renumber", "100,5",
                 "-o", str(tmp_path / "out") + "/"]) == 0
    for source in sources:
        written = (tmp_path / "out" / source.name).read_text()
        assert [line.split()[0] for line in written.splitlines()[1:4]] == ["N100", "N105", "N110"]


@st.composite
def _programs(draw: st.DrawFn) -> tuple[str, int, int]:
    """A mill program of numbered and unnumbered moves, counted loops (``IF [..] GOTO`` back to the loop's
    head), forward ``GOTO``s over a part of it and, maybe, a subprogram returning with ``M99 P`` to a block of
    the main program after its call; and a START, STEP that number it below ``numberMax``."""
    units = draw(st.lists(st.sampled_from(["move", "numbered", "loop", "goto"]), min_size=2, max_size=8))
    numbers = iter(draw(st.permutations(range(1, 200)))[:40])
    lines: list[str] = []
    later: list[int] = []  # the forward jumps waiting for a block to name: indexes into ``lines``
    x = 0
    for pos, unit in enumerate(units):
        x += 1
        if unit == "move":
            lines.append(f"G1 X{x}. Y{draw(st.integers(0, 9))}. F100.")
        elif unit == "numbered":
            number = next(numbers)
            lines.append(f"N{number} G1 X{x}. F100.")
            for at in later:
                lines[at] = lines[at].format(number)
            later.clear()
        elif unit == "loop":
            head, var, count = next(numbers), 100 + pos, draw(st.integers(1, 3))
            lines += [f"#{var}=0", f"N{head} #{var}=#{var}+1", f"G91 G1 X1. Y{draw(st.integers(-2, 2))}. F100.",
                      "G90", f"IF [#{var} LT {count}] GOTO {head}"]
        else:
            later.append(len(lines))
            lines += ["GOTO {}", f"G1 X{x}. Y7. F100."]  # (skipped by the jump)
    if later:  # a block for the jumps still waiting
        number = next(numbers)
        lines.append(f"N{number} G0 Z6.")
        for at in later:
            lines[at] = lines[at].format(number)
    body = "\n".join(lines)
    program = MILL_HEAD + body + "\n"
    if draw(st.booleans()):
        back = next(numbers)
        program = (MILL_HEAD + "M98 P2000\nG1 X-1. F100.\n" + f"N{back} G1 Y-1. F100.\n" + body
                   + f"\nM30\nO2000\nG1 X-5. Y-5. F100.\nM99 P{back}\n")
    else:
        program += "M30\n"
    start = draw(st.integers(1, 5000))
    step = draw(st.integers(1, 50))
    return program, start, step


@given(_programs())
@settings(max_examples=30)
def test_random_programs_renumber_and_move_as_their_source(case: tuple[str, int, int]) -> None:
    """Every reference of a random program follows its block: the renumbered program, run flattened (its loops
    and return included), makes the source's moves; its numbers run from START by STEP."""
    program, start, step = case
    written = _translate(program, MachineSetup(output=OutputSettings(renumber_start=start, renumber_step=step)))
    numbers = [int(m.group(1)) for line in written.splitlines() if (m := re.match(r"N(\d+) ", line))]
    assert numbers == list(range(start, start + step * len(numbers), step))
    _verified(program, written, MachineSetup())


@pytest.mark.parametrize("target", ["linuxcnc", "grbl"])
def test_a_set_up_renumber_start_alone_numbers_the_lines_between_two_dialects(target: str) -> None:
    """Before: ``<Output renumberStart="100">`` without ``blockNumbers`` was ignored between two dialects (the
    writer numbers only the blocks it normalises: none there), exit 0. Now it numbers as ``--renumber`` does."""
    setup = MachineSetup(output=OutputSettings(renumber_start=100, renumber_step=5))
    written = _translate(PLAIN, setup, target=target)
    assert written == _translate(PLAIN, MachineSetup(output=OutputSettings(
        renumber_start=100, renumber_step=5, block_numbers="all")), target=target)
    numbers = [int(m.group(1)) for line in written.splitlines() if (m := re.match(r"N(\d+) ", line))]
    assert numbers[:3] == [100, 105, 110] and not re.search(r"\bN(5|99)\b", written)


def test_a_set_up_renumber_start_alone_flattens_a_jump_between_two_dialects() -> None:
    """The numbered lines cannot keep a jump to a number (``LineFormat`` refuses it), so a program the target
    could keep symbolic (SINUMERIK ``GOTOF N30``) is flattened instead, with the usual warning, and moves as read."""
    program = MILL_HEAD + "N10 G1 X1. F100.\nGOTO 30\nN20 G1 X2.\nN30 G1 X3.\nM30\n"
    assert "GOTOF N30" in _translate(program, MachineSetup(), target="siemens")
    setup = MachineSetup(output=OutputSettings(renumber_start=100, renumber_step=10))
    out = io.StringIO()
    warnings = io.StringIO()
    translate(program.splitlines(keepends=True), out, file="t.nc", source="fanuc", target="siemens", setup=setup,
              diagnostics=Diagnostics(warn_stream=warnings))
    written = out.getvalue()
    assert "GOTO" not in written.replace(";LINE 5: GOTO 30", "") and "N130 G1 X3." in written
    assert "t.nc:5:1: warning: the program is flattened" in warnings.getvalue()
    report = verify_lines(program.splitlines(keepends=True), written.splitlines(keepends=True), file_in="in.nc",
                          file_out="out.nc", source="fanuc", target="siemens", setup=MachineSetup())
    assert report.ok, report.summary()


def test_a_gsk_macro_jump_is_refused() -> None:
    """``G65 H80 P30`` (kept verbatim: postproc runs no GSK macro) jumps to N30: renumbered, it would jump
    elsewhere with exit 0 (before). Refused, located; another G65 operation (``H2``: addition) is renumbered."""
    program = "O1000\nG0 X50. Z5.\nN10 G1 X40. F0.2\nG65 H80 P30\nN20 G1 X30.\nN30 G0 X60.\nM30\n"
    with pytest.raises(ErrorList, match=r"t\.nc:4:1: error: --renumber cannot rewrite the block number G65 H80 names"):
        _translate(program, _lathe(renumber_start=100), source="gsk", target="gsk")
    written = _translate(program.replace("G65 H80 P30", "G65 H2 P#1 Q1"), _lathe(renumber_start=100),
                         source="gsk", target="gsk")
    assert "N120 G65 H2 P#1 Q1" in written


@st.composite
def _lathe_programs(draw: st.DrawFn) -> tuple[str, int, int]:
    """A G71 roughing and a G70 finishing cycle on a random profile (X rising, Z falling: a type I profile)
    whose first and last blocks carry random numbers, among blocks numbered or not at random."""
    numbers = iter(draw(st.permutations(range(1, 100)))[:30])

    def numbered(text: str) -> str:
        return f"N{next(numbers)} {text}" if draw(st.booleans()) else text

    ns, nf = next(numbers), next(numbers)
    steps = draw(st.integers(1, 4))
    xs = sorted(draw(st.lists(st.integers(21, 50), min_size=steps, max_size=steps, unique=True)))
    zs = sorted(draw(st.lists(st.integers(-40, -2), min_size=steps, max_size=steps, unique=True)), reverse=True)
    profile = [f"N{ns} G0 X20."] + [numbered(f"G1 X{x}. Z{z}.") for x, z in zip(xs, zs)] + [f"N{nf} G1 X52."]
    lines = ["O1000", numbered("G21 G18 G40 G97 G99"), numbered("T0101"), numbered("G0 X52. Z2. S1500 M3"),
             numbered("G71 U2. R0.5"), numbered(f"G71 P{ns} Q{nf} U0.4 W0.1 F0.25"), *profile,
             numbered(f"G70 P{ns} Q{nf}"), numbered("G0 X100. Z100."), "M30"]
    return "\n".join(lines) + "\n", draw(st.integers(1, 5000)), draw(st.integers(1, 50))


@given(_lathe_programs())
@settings(max_examples=20)
def test_random_lathe_profiles_renumber_and_move_as_their_source(case: tuple[str, int, int]) -> None:
    program, start, step = case
    written = _translate(program, _lathe(renumber_start=start, renumber_step=step))
    numbers = [int(m.group(1)) for line in written.splitlines() if (m := re.match(r"N(\d+) ", line))]
    assert numbers == list(range(start, start + step * len(numbers), step))
    _verified(program, written, _lathe())


def test_an_isg_jump_follows_its_block() -> None:
    program = "%1\nN10 G01 X1. F100.\n$GOTO N30\nN20 G01 X2.\nN30 G01 X3.\nM30\n"
    written = _translate(program, MachineSetup(output=OutputSettings(renumber_start=100)), source="isg",
                         target="isg")
    assert written == "%1\nN100 G01 X1. F100.\n$GOTO N120\nN110 G01 X2.\nN120 G01 X3.\nN130 M30\n"
    report = verify_lines(program.splitlines(keepends=True), written.splitlines(keepends=True), file_in="in.nc",
                          file_out="out.nc", source="isg", target="isg", setup=MachineSetup())
    assert report.ok and report.max_deviation == 0.0, report.summary()


def test_a_sinumerik_jump_kept_as_written_is_refused() -> None:
    """The SINUMERIK writer keeps a ``GOTOF`` line as written (its own text): the jump would keep N30 while that
    block becomes N120, so the run is refused at the jump (``Renumbering.check``)."""
    program = "N10 G1 X1. F100.\nGOTOF N30\nN20 G1 X2.\nN30 G1 X3.\nM30\n"
    with pytest.raises(ErrorList, match=r"t\.nc:2:1: error: --renumber cannot rewrite the block numbers this line "
                                        r"names: the writer keeps it as written"):
        _translate(program, MachineSetup(output=OutputSettings(renumber_start=100)), source="siemens",
                   target="siemens")


def test_linuxcnc_o_word_labels_are_no_block_numbers() -> None:
    """LinuxCNC jumps to o-word labels, never to N numbers (which it ignores): the labels stay as written."""
    program = "G21 G90\n#1=0\no100 while [#1 LT 3]\nN10 G1 X#1 F100\n#1=[#1+1]\no100 endwhile\nN20 M2\n"
    written = _translate(program, MachineSetup(output=OutputSettings(renumber_start=100)), source="linuxcnc",
                         target="linuxcnc")
    assert written == ("N100 G21 G90\n#1=0.\no100 while [#1 LT 3.]\nN110 G1 X#1 F100.\n#1=[#1+1.]\no100 endwhile\n"
                       "N120 M2\n")


@pytest.mark.parametrize("numbers", ["all", "tool-changes", "none"])
def test_a_gsk_macro_jump_is_refused_when_the_lines_are_numbered(numbers: str) -> None:
    """Before: ``<Output blockNumbers>`` renumbered (or dropped) N30 and left ``G65 H80 P30`` as written, exit 0."""
    program = "O1000\nG0 X50. Z5.\nN10 G1 X40. F0.2\nG65 H80 P30\nN20 G1 X30.\nN30 G0 X60.\nM30\n"
    with pytest.raises(ErrorList, match=r"t\.nc:4:1: error: block numbers cannot be rewritten in a program that jumps "
                                        r"to block numbers: G65 H80 names one"):
        _translate(program, _lathe(block_numbers=numbers, renumber_start=100), source="gsk", target="gsk")
    assert _translate(program, _lathe(), source="gsk", target="gsk") == program
