"""``<Output tapeMarks programNumber>``: the program's ``%`` lines and main program number on output
(``postproc.lowering.program_frame``). Outputs are read back by the target and verified against the source."""

from __future__ import annotations

import io
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import ConfigError
from postproc.setup.machine_setup import MachineSetup, OutputSettings
from postproc.simulate.verify import verify_lines
from tests.support.tools import with_tools

ROOT = Path(__file__).resolve().parents[1]
NGC = "G21 G90\nG0 X0 Y0 Z10\nG1 X5 F100\nM2\n"


def framed(program: str, source: str, target: str, **output: object) -> str:
    setup = MachineSetup(output=OutputSettings(**output))
    out = io.StringIO()
    translate(io.StringIO(program), out, file="p.nc", source=source, target=target, setup=setup)
    text = out.getvalue()
    translate(io.StringIO(text), io.StringIO(), file="back.nc", source=target, target=target)  # reads back
    report = verify_lines(io.StringIO(program), io.StringIO(text), file_in="a", file_out="b", source=source,
                          target=target, tolerance=0.0, setup=with_tools())
    assert report.ok, report.summary()
    return text


def test_a_program_without_either_gets_both_for_fanuc():
    assert framed(NGC, "linuxcnc", "fanuc", tape_marks="always", program_number=1001) == (
        "%\nO1001\nG21 G90\nG00 X0. Y0. Z10.\nG01 X5. F100.\nM02\n%\n")


def test_the_main_program_is_renumbered_and_keeps_its_comment():
    source = (ROOT / "examples/fanuc/o1001_plate_drill_tap.nc").read_text()
    text = framed(source, "fanuc", "fanuc", program_number=2001)
    assert text.splitlines()[:2] == ["%", "O2001 (PLATE 120X80 - SPOT, DRILL, TAP M10)"]
    assert text.splitlines()[2:] == source.splitlines()[2:]  # nothing else changes


def test_a_subprograms_number_is_never_changed():
    program = "%\nO1000\nM98 P2000\nM30\nO2000\nG91 G01 X1. F100.\nM99\n%\n"
    text = framed(program, "fanuc", "fanuc", program_number=1234)
    assert text == "%\nO1234\nM98 P2000\nM30\nO2000\nG91 G01 X1. F100.\nM99\n%\n"


def test_none_and_never_leave_a_grbl_program_without_the_fanuc_frame():
    program = "%\nO1234 (PART)\nG21 G90 G00 X0. Y0. Z10.\nG01 X5. F100.\nM30\n%\n"
    assert framed(program, "fanuc", "grbl", tape_marks="never", program_number="none") == (
        "(PART)\nG21 G90 G0 X0. Y0. Z10.\nG1 X5. F100.\nM30\n")


def test_isg_writes_the_number_its_own_way():
    assert framed(NGC, "linuxcnc", "isg", program_number=5).splitlines()[0] == "%5"


@pytest.mark.parametrize("target, output, message", [
    ("grbl", {"tape_marks": "always"}, '<Output tapeMarks="always">: the grbl dialect has no % lines'),
    ("isg", {"tape_marks": "always"}, '<Output tapeMarks="always">: the isg dialect has no % lines'),
    ("linuxcnc", {"program_number": 12}, '<Output programNumber="12">: the linuxcnc dialect writes no program '
                                         "number"),
])
def test_what_a_dialect_lacks_is_a_set_up_error(target, output, message):
    with pytest.raises(ConfigError) as info:
        translate(io.StringIO(NGC), io.StringIO(), file="p.ngc", source="linuxcnc", target=target,
                  setup=MachineSetup(output=OutputSettings(**output)))
    assert info.value.message == message


@pytest.mark.parametrize("value", [0, 10000, "first"])
def test_a_program_number_out_of_range_is_refused(value):
    with pytest.raises(ValueError):
        OutputSettings(program_number=value)


def test_the_attributes_load_and_dump(tmp_path):
    from postproc.setup.machine_setup import load_setup
    path = tmp_path / "m.xml"
    text = ('<?xml version=\'1.0\' encoding=\'UTF-8\'?>\n<MachineSetup name="m">\n'
            '  <Output tapeMarks="always" programNumber="1001"/>\n</MachineSetup>\n')
    path.write_text(text)
    setup = load_setup(path)
    assert (setup.output.tape_marks, setup.output.program_number) == ("always", 1001)
    none = tmp_path / "n.xml"
    none.write_text(text.replace('programNumber="1001"', 'programNumber="none"'))
    assert load_setup(none).output.program_number == "none"
