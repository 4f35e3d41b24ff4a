"""``--renumber`` and words that name block numbers (#20: wrong code with exit 0).

Before: renumbering a Fanuc lathe program turned ``N10``/``N20`` into other numbers but left ``G71 P10 Q20``
and ``G70 P10 Q20`` as written, so the cycles roughed and finished whatever blocks now carried N10..N20 (the
set-up lines at the program's top). A GOTO, an ``IF [...] GOTO`` and an ``M99 P`` were refused already; a
lathe cycle's profile range now is too, by the writer's renumbering and by ``<Output blockNumbers>`` alike.
Refused rather than rewritten: the cycle names blocks that follow it (their new numbers are not known when it
is written) and a computed target (``GOTO #1``) cannot be mapped at all; a refusal is exact, a partial rewrite
would not be. Also before: ``--renumber`` between two dialects was ignored with exit 0; it now numbers the
written lines (``blockNumbers="all"``), and the renumbered program moves as its source (``verify``)."""

from __future__ import annotations

import io
import re
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.commands.cli import main
from postproc.errors import ErrorList
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


def test_renumbering_a_lathe_cycle_profile_is_refused_at_the_cycle() -> None:
    with pytest.raises(ErrorList) as caught:
        _translate(LATHE_PROGRAM, _lathe(renumber_start=10, renumber_step=10))
    errors = str(caught.value).splitlines()
    assert errors[0].startswith("t.nc:6:1: error: --renumber cannot renumber a program that jumps to block "
                                "numbers or names them")
    assert any(line.startswith("t.nc:11:1: error: --renumber") for line in errors)  # the G70 too


def test_numbering_the_lines_of_a_lathe_cycle_profile_is_refused() -> None:
    with pytest.raises(ErrorList, match=r"t\.nc:6:1: error: block numbers cannot be rewritten in a program that "
                                        r"jumps to block numbers or names them"):
        _translate(LATHE_PROGRAM, _lathe(block_numbers="all", renumber_start=10))


def test_a_lathe_cycle_is_copied_with_its_numbers_when_nothing_renumbers() -> None:
    assert _translate(LATHE_PROGRAM, _lathe()) == LATHE_PROGRAM


@pytest.mark.parametrize("jump", ["GOTO 10", "IF [#1 LT 3] GOTO 10", "GOTO #2", "IF [#1 LT 3] GOTO [#2+10]"],
                         ids=["goto", "if-goto", "computed-goto", "computed-if-goto"])
def test_renumbering_a_jump_is_refused(jump: str) -> None:
    program = MILL_HEAD + f"#1=0\n#2=10\nN10 #1=#1+1\n{jump}\nM30\n"
    with pytest.raises(ErrorList, match=r"t\.nc:7:1: error: --renumber cannot renumber a program that jumps"):
        _translate(program, MachineSetup(output=OutputSettings(renumber_start=100)))


def test_renumbering_a_return_to_a_block_number_is_refused() -> None:
    program = MILL_HEAD + "N10 G1 X1. F100.\nN20 G1 X2.\nM99 P10\n"
    with pytest.raises(ErrorList, match=r"t\.nc:6:1: error: --renumber cannot renumber a program that jumps"):
        _translate(program, MachineSetup(output=OutputSettings(renumber_start=100)))


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
