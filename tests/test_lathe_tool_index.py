"""A LinuxCNC lathe program's tool changes (``T2 M6`` with ``G43``/``G43 H``/``G49``) written for a turret lathe
(Fanuc T, GSK) as turret indexes (``T0202``): ``postproc.rs274.lathe_tool_index``.

Expected texts are derived by hand from the rule (station = the changed tool, offset = the register G43 puts in
force, 00 for G49 or none); the set-up gives registers 2 and 5 X and Z offsets, so ``verify`` (which applies
them on both sides: LinuxCNC's G43 from the next absolute axis word, the turret's T from the next move) checks
the translation moves the controlled point as the source does.
"""

from __future__ import annotations

import io
import re

import pytest

from postproc.api import translate
from postproc.errors import ErrorList
from postproc.setup.machine_setup import load_setup
from postproc.simulate.verify import verify_lines

SETUP_XML = """<?xml version='1.0' encoding='UTF-8'?>
<MachineSetup name="LinuxCNC lathe with offsets" dialect="linuxcnc">
  <Input machineType="lathe" xProgramming="radius"/>
  <Machine axes="XZ"/>
  <Tools>
    <Tool number="2" x="1.5" z="-2.25"/>
    <Tool number="5" x="-0.75" z="3.5"/>
  </Tools>
</MachineSetup>
"""


@pytest.fixture(scope="module")
def setup(tmp_path_factory: pytest.TempPathFactory):  # type: ignore[no-untyped-def]
    path = tmp_path_factory.mktemp("setup") / "lathe.xml"
    path.write_text(SETUP_XML)
    return load_setup(str(path))


PROGRAM = """G18 G8 G21 F100
T2 M6 G43
G0 X10 Z5
G1 X8 Z-10
T5
G0 X12 Z6
M6 G43 H2
G0 X10 Z5
T2 M6 G49
G0 X12 Z6
T5 M6
G0 X10 Z5
M2
"""


def _t_words(text: str) -> list[str]:
    return re.findall(r"\bT\d+", text)


@pytest.mark.parametrize("target", ["fanuc", "gsk"])
def test_changes_become_turret_indexes_and_verify(setup, target: str) -> None:  # type: ignore[no-untyped-def]
    out = io.StringIO()
    translate(io.StringIO(PROGRAM), out, file="t.ngc", source="linuxcnc", target=target, setup=setup)
    text = out.getvalue()
    # T2 M6 G43 -> T0202; T5 (prepared) -> a comment; M6 G43 H2 -> T0502 (station 5, offset 2); T2 M6 G49 ->
    # T0200; T5 M6 (no length code: the offset in force, none) -> T0500
    assert _t_words(text) == ["T0202", "T0502", "T0200", "T0500"]
    assert "M6" not in text and "G43" not in text and "G49" not in text
    assert "TOOL 5 PREPARED" in text
    report = verify_lines(io.StringIO(PROGRAM), io.StringIO(text), file_in="t.ngc", file_out="t.nc",
                          source="linuxcnc", target=target, setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()


@pytest.mark.parametrize("program, message", [
    ("G18 G8 F100\nT2 M6\nM3 S500\nT5 M6\nM2\n", "spindle turning"),
    # a move between the change and the length code: the code re-selects the offset mid-path (was refused even
    # next to the change, before the fold)
    ("G18 G8 F100\nT2 M6\nG0 X1 Z1\nG43 H2\nG0 X2 Z2\nM2\n", "without a tool change"),
    ("G18 G8 F100\nT123 M6\nG0 X1 Z1\nM2\n", "two digits"),
])
def test_refusals(setup, program: str, message: str) -> None:  # type: ignore[no-untyped-def]
    with pytest.raises(ErrorList, match=message):
        translate(io.StringIO(program), io.StringIO(), file="t.ngc", source="linuxcnc", target="fanuc", setup=setup)


FOLDED = """G18 G8 G21 F100
G49
T0 M6
G0 X12 Z6
T2 M6
(the tool is in)
G43 H5
G0 X10 Z5
G1 X8 Z-10
G0 X12 Z6
G49
T5 M6
G43
G0 X10 Z5
G49
T0 M6
M2
"""
"""LinuxCNC's usual lathe pattern (``lathecomp.ngc``): the length code in a block of its own next to the change."""


@pytest.mark.parametrize("target", ["fanuc", "gsk"])
def test_a_length_code_next_to_the_change_is_folded_into_its_index(setup, target: str) -> None:  # type: ignore[no-untyped-def]
    out = io.StringIO()
    translate(io.StringIO(FOLDED), out, file="t.ngc", source="linuxcnc", target=target, setup=setup)
    text = out.getvalue()
    # G49 then T0 M6 -> T0000 (the code before the change); T2 M6, a comment, G43 H5 -> T0205 (after it);
    # G49, T5 M6, G43 -> T0505 (the cancel before: the change's own G43 after takes tool 5's offset)
    assert _t_words(text) == ["T0000", "T0205", "T0505", "T0000"]
    assert "G43" not in text and "G49" not in text and "(the tool is in)" in text
    # the simulation of the source, independent of the fold, is the oracle
    report = verify_lines(io.StringIO(FOLDED), io.StringIO(text), file_in="t.ngc", file_out="t.nc",
                          source="linuxcnc", target=target, setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary()


def test_two_length_codes_before_a_change_refuse_the_first(setup) -> None:  # type: ignore[no-untyped-def]
    program = "G18 G8 F100\nT2 M6\nG0 X1 Z1\nG43 H2\nG49\nT5 M6\nG0 X2 Z2\nM2\n"
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(program), io.StringIO(), file="t.ngc", source="linuxcnc", target="fanuc", setup=setup)
    assert [e.location.line for e in info.value.errors if e.location is not None] == [4]


def test_the_first_move_after_an_index_must_name_each_axis_whose_offset_changed(setup) -> None:  # type: ignore[no-untyped-def]
    """Tool 2's offsets (X 1.5, Z -2.25) after none: LinuxCNC's G43 H2 applies X's only where X is next
    programmed, the turret's T0202 on both at the next move, so ``G0 Z1`` alone would end 1.5 mm off in X on
    the target (was translated so, exit 0: only verify saw it). A located error at that move."""
    program = "G18 G8 G21 F100\nT2 M6\nG43 H2\nG0 Z1\nG0 X1\nM2\n"
    with pytest.raises(ErrorList, match="leaves X unprogrammed") as info:
        translate(io.StringIO(program), io.StringIO(), file="t.ngc", source="linuxcnc", target="fanuc", setup=setup)
    assert [e.location.line for e in info.value.errors if e.location is not None] == [4]
    both = "G18 G8 G21 F100\nT2 M6\nG43 H2\nG0 X1 Z1\nG0 X2\nM2\n"
    out = io.StringIO()
    translate(io.StringIO(both), out, file="t.ngc", source="linuxcnc", target="fanuc", setup=setup)
    report = verify_lines(io.StringIO(both), io.StringIO(out.getvalue()), file_in="t.ngc", file_out="t.nc",
                          source="linuxcnc", target="fanuc", setup=setup, tolerance=0.0)
    assert report.ok, report.summary()
