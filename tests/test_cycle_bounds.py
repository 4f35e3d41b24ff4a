"""Canned cycles cannot run away: the repeat count is range-checked against the controller (Fanuc K
0-9999), and an expansion is bounded by the set-up's ``<Limits movesPerBlock>``, refused before any
move is made when the count is known in advance (holes x pecks), else counted while expanding. The
tests count the items built, never time."""

from __future__ import annotations

import io
import types

import pytest

from postproc.api import translate
from postproc.cycles import expansion
from postproc.errors import ErrorList
from postproc.setup.machine_setup import Limits, MachineSetup


def _errors(cycle_line: str, *, source: str = "fanuc", target: str = "grbl",
            setup: MachineSetup | None = None) -> list[str]:
    end = "M30" if source == "fanuc" else "M2"
    program = f"G21 G17 G90\nG0 X0. Y0. Z10.\n{cycle_line}\nG80\n{end}\n"
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(program), io.StringIO(), file="p.nc", source=source, target=target,
                  setup=setup or MachineSetup())
    return [str(e) for e in info.value.errors]


@pytest.fixture
def built(monkeypatch: pytest.MonkeyPatch) -> list[int]:
    """Counts the items every expansion appends. Compiled, the expansion calls ``ToolPath.add`` directly
    and a patch cannot see it: these tests then run in the suite's pure-Python pass (``make test`` runs
    both); the errors they check are checked in both passes by the tests without this fixture."""
    if not isinstance(expansion.ToolPath.add, types.FunctionType):
        pytest.skip("ToolPath is compiled: its calls are counted in the pure-Python pass")
    count = [0]
    add = expansion.ToolPath.add

    def counting(self: expansion.ToolPath, item: object) -> None:
        count[0] += 1
        add(self, item)  # type: ignore[arg-type]

    monkeypatch.setattr(expansion.ToolPath, "add", counting)
    return count


def test_fanuc_repeat_count_over_9999_is_refused(built: list[int]) -> None:
    assert _errors("G98 G81 X5. Y5. Z-1. R2. F100. K99999999") == [
        "p.nc:3:32: error: repeat count K99999999 is more than the controller accepts (K0-K9999)"]
    assert built[0] == 0


def test_fanuc_repeat_count_9999_is_accepted() -> None:
    out = io.StringIO()
    program = "G21 G17 G90\nG0 X0. Y0. Z10.\nG91 G98 G81 X1. Z-3. R-8. F100. K9999\nG80\nM30\n"
    translate(io.StringIO(program), out, file="p.nc", source="fanuc", target="grbl")
    assert out.getvalue().count("G1 ") == 9999  # one feed into each hole


def test_tiny_peck_is_refused_before_expanding(built: list[int]) -> None:
    assert _errors("G98 G73 X5. Y5. Z-1. R2. Q0.0000001 F100.") == [
        "p.nc:3:26: error: G73: 30000000 pecks per hole make more than 100000 moves in one block (the set-up's "
        "<Limits movesPerBlock>)"]
    assert built[0] == 0


def test_pecks_times_holes_are_counted_before_expanding(built: list[int]) -> None:
    setup = MachineSetup(limits=Limits(moves_per_block=1000))
    assert _errors("G98 G83 X5. Y5. Z-100. R2. Q1. F100. K10", setup=setup) == [
        "p.nc:3:28: error: G83: 102 pecks per hole at 10 holes make more than 1000 moves in one block (the "
        "set-up's <Limits movesPerBlock>)"]
    assert built[0] == 0


def test_linuxcnc_repeat_is_bounded_by_the_set_up(built: list[int]) -> None:
    """rs274 itself accepts L100000000 (and runs for minutes): only the set-up's bound stops it."""
    assert _errors("G91 G81 X1. Y0. Z-1. R2. F100. L100000000", source="linuxcnc") == [
        "p.nc:3:32: error: G81: 100000000 holes make more than 100000 moves in one block (the set-up's "
        "<Limits movesPerBlock>)"]
    assert built[0] == 0


def test_expansion_is_counted_while_it_grows(built: list[int]) -> None:
    """13 holes pass the advance count (one move each) but take 4 moves each: the 51st item is refused,
    so no more than the bound is ever held."""
    setup = MachineSetup(limits=Limits(moves_per_block=50))
    assert _errors("G91 G98 G81 X1. Z-3. R-8. F100. K13", setup=setup) == [
        "p.nc:3:33: error: G81: the expansion makes more than 50 moves in one block (the set-up's "
        "<Limits movesPerBlock>)"]
    assert built[0] == 51


def test_moves_per_block_default() -> None:
    assert Limits().moves_per_block == 100_000
