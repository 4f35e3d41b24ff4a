"""Machine set-ups: loading, validation with located errors, canonical dumps, relative pipeline paths."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from postproc.errors import ConfigError
from postproc.setup.machine_setup import InputSettings, MachineSetup, load_setup

ROOT = Path(__file__).resolve().parents[1]
SETUPS = sorted((ROOT / "examples/setups").glob("*.xml"))
DECLARATION = "<?xml version='1.0' encoding='UTF-8'?>\n"


def _write(tmp_path: Path, body: str, name: str = "m.xml") -> Path:
    path = tmp_path / name
    path.write_text(DECLARATION + body)
    return path


# -- the example set-ups ------------------------------------------------------------------------------

def test_there_are_example_setups():
    assert len(SETUPS) >= 2


@pytest.mark.parametrize("path", SETUPS, ids=lambda p: p.name)
def test_config_dump_is_byte_identical(cli, path):
    result = cli("config", "dump", path)
    assert result.status == 0, result.err
    assert result.out == path.read_bytes()


@pytest.mark.parametrize("path", SETUPS, ids=lambda p: p.name)
def test_config_check_accepts_the_examples(cli, path):
    result = cli("config", "check", path)
    assert (result.status, result.out.decode(), result.err) == (0, f"{path}: ok\n", "")


def test_calculator_example_values():
    setup = load_setup(ROOT / "examples/setups/fanuc_0i_mf_calculator.xml")
    assert setup.dialect == "fanuc"
    assert setup.input.decimal_point == "calculator"
    assert setup.input.increment_system == "IS-B"  # the default, not written
    assert (setup.output.normalize, setup.output.renumber_start, setup.output.renumber_step) == (True, 10, 10)
    assert (setup.cycles.peck_retract, setup.cycles.peck_clearance) == (0.2, 0.3)
    assert setup.machine.start_z == 100.0


def test_templates_example_values():
    setup = load_setup(ROOT / "examples/setups/fanuc_0i_mf_templates.xml")
    assert setup.templates.header == ("(MACHINE: VMC 850 - FANUC 0I-MF)\n"
                                      "(PROGRAM {{ program }} POSTED FOR {{ machine | upper }})")
    assert setup.templates.footer == "(END OF {{ program }})"
    assert setup.output.leading_zero is False


def test_four_axis_example_values():
    setup = load_setup(ROOT / "examples/setups/fanuc_30i_is_c_4axis.xml")
    assert setup.input.increment_system == "IS-C"
    assert setup.input.repeat_address == "K+L"
    assert setup.machine.axes == "XYZB"
    assert setup.cycles.expanded() == frozenset({"peck_deep"})


def test_load_dump_load_is_stable(tmp_path, cli):
    """Every dump is written first: a set-up that extends a local base finds the base's dump beside it."""
    for path in SETUPS:
        (tmp_path / path.name).write_bytes(cli("config", "dump", path).out)
    for path in SETUPS:
        assert load_setup(tmp_path / path.name) == load_setup(path)


# -- defaults and helpers -------------------------------------------------------------------------

def test_defaults():
    setup = MachineSetup()
    assert (setup.input.decimal_point, setup.input.increment_system) == ("least-increment", "IS-B")
    assert (setup.output.decimals, setup.output.inch_decimals, setup.output.renumber_start) == (3, 4, 0)
    assert setup.pipeline_path() is None


@pytest.mark.parametrize("system, units, increment", [
    ("IS-A", "mm", 0.01), ("IS-B", "mm", 0.001), ("IS-C", "mm", 0.0001),
    ("IS-B", "inch", 0.0001), ("IS-C", "inch", 0.00001),
])
def test_least_increment(system, units, increment):
    assert InputSettings(increment_system=system).increment(units) == pytest.approx(increment)


def test_expand_list():
    setup = MachineSetup()
    setup.cycles.expand = " drill, peck_deep ,,"
    assert setup.cycles.expanded() == frozenset({"drill", "peck_deep"})


def test_an_empty_setup_dumps_to_one_element(cli, tmp_path):
    path = _write(tmp_path, '<MachineSetup name="bare"/>\n')
    result = cli("config", "dump", path)
    assert result.out == path.read_bytes()


def test_dump_writes_the_canonical_form(cli, tmp_path):
    """Comments, defaults written out and attribute spelling are not kept; values are."""
    path = _write(tmp_path, '<!-- a note -->\n<MachineSetup dialect="fanuc"   name="m">\n'
                            '  <Input decimalPoint="least-increment"/>\n'
                            '  <Output decimals="4" normalize="true"/>\n</MachineSetup>\n')
    result = cli("config", "dump", path)
    assert result.status == 0, result.err
    assert result.out.decode() == (DECLARATION + '<MachineSetup name="m" dialect="fanuc">\n'
                                   '  <Output normalize="true" decimals="4"/>\n</MachineSetup>\n')


# -- errors carry the line -------------------------------------------------------------------------

BAD = [
    # (body after the declaration, message, line, column)
    ('<MachineSetup name="m">\n  <Output decimals="3" bogus="1"/>\n</MachineSetup>\n',
     "<Output> bogus: unknown parameter", 3, 1),
    ('<MachineSetup name="m">\n\n  <Cycles peckRetract="-1"/>\n</MachineSetup>\n',
     "<Cycles> peckRetract: Input should be greater than 0", 4, 1),
    ('<MachineSetup name="m">\n  <Input decimalPoint="dpi"/>\n</MachineSetup>\n',
     "<Input> decimalPoint: Input should be 'least-increment' or 'calculator'", 3, 1),
    ('<MachineSetup name="m">\n  <Output decimals="many"/>\n</MachineSetup>\n',
     "<Output> decimals: Input should be a valid integer, unable to parse string as an integer", 3, 1),
    ('<MachineSetup name="m">\n  <Output decimals="9"/>\n</MachineSetup>\n',
     "<Output> decimals: Input should be less than or equal to 6", 3, 1),
    ('<MachineSetup name="m">\n  <Machine axes="XYX"/>\n</MachineSetup>\n',
     "<Machine> axes must be distinct letters from XYZABCUVW, got 'XYX'", 3, 1),
    ('<MachineSetup name="m">\n  <Input/>\n  <Spindle maxRpm="12000"/>\n</MachineSetup>\n',
     "unknown element <Spindle> in <MachineSetup>", 4, 1),
    ('<MachineSetup name="m">\n  <Input/>\n  <Input/>\n</MachineSetup>\n', "<Input> appears twice", 4, 1),
    ('<MachineSetup name="m">\n  <Input>\n    <Extra/>\n  </Input>\n</MachineSetup>\n',
     "<Input> takes attributes only", 3, 1),
    ('<MachineSetup name="m" colour="red"/>\n', "<MachineSetup> has unknown attribute(s) colour", 2, 1),
    ('<MachineSetup name="m">\n  <Templates>\n    <Preamble>x</Preamble>\n  </Templates>\n</MachineSetup>\n',
     "unknown element <Preamble> in <Templates>", 4, 1),
    ('<Pipeline dialect="fanuc"/>\n', "expected <MachineSetup>, found <Pipeline>", 2, 1),
    ('<MachineSetup name="m" dialect="heidenhain"/>\n', "unknown dialect 'heidenhain' (installed: ", 2, 1),
    ('<MachineSetup name="m">\n  <Input decimalPoint="calculator">\n</MachineSetup>\n',
     "malformed XML: Opening and ending tag mismatch: Input line 3 and MachineSetup", 4, 16),
    ('<MachineSetup name="m">\n  <Input decimalPoint="calculator" decimalPoint="x"/>\n</MachineSetup>\n',
     "malformed XML: Attribute decimalPoint redefined", 3, 52),
    ('<MachineSetup name="m">\n  <Templates>\n    <Header>(A)\n{{ oops }</Header>\n  </Templates>\n</MachineSetup>\n',
     "template header: unexpected '}'", 5, 1),
]


@pytest.mark.parametrize("body, message, line, col", BAD, ids=[b[1][:50] for b in BAD])
def test_config_check_errors_are_located(cli, tmp_path, body, message, line, col):
    path = _write(tmp_path, body)
    result = cli("config", "check", path)
    assert result.status == 1
    assert result.out == b""
    [error] = result.err_lines
    prefix = f"{path}:{line}:{col}: error: "
    assert error.startswith(prefix)
    if message.endswith(": "):  # the list of installed dialects varies
        assert error[len(prefix):].startswith(message)
    else:
        assert error[len(prefix):] == message


def test_config_dump_of_a_bad_setup_writes_nothing(cli, tmp_path):
    path = _write(tmp_path, '<MachineSetup name="m">\n  <Output bogus="1"/>\n</MachineSetup>\n')
    result = cli("config", "dump", path)
    assert (result.status, result.out) == (1, b"")


BILLION_LAUGHS = """<!DOCTYPE lolz [
 <!ENTITY lol "lol">
 <!ENTITY lol1 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
 <!ENTITY lol2 "&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;&lol1;">
]>
<MachineSetup name="&lol2;"/>
"""

PASSWD = """<!DOCTYPE MachineSetup [ <!ENTITY passwd SYSTEM "file:///etc/passwd"> ]>
<MachineSetup name="m">
  <Templates>
    <Header>&passwd;</Header>
  </Templates>
</MachineSetup>
"""


@pytest.mark.parametrize("body", [BILLION_LAUGHS, PASSWD], ids=["billion_laughs", "external_entity"])
def test_doctype_and_entities_are_rejected(cli, tmp_path, body):
    path = _write(tmp_path, body)
    for action in ("check", "dump"):
        result = cli("config", action, path)
        assert result.status == 1
        assert result.out == b""
        assert result.err == f"{path}:2:1: error: a DOCTYPE is not allowed in postproc XML\n"
    with pytest.raises(ConfigError):
        load_setup(path)


def test_missing_setup_file(cli, tmp_path):
    """A set-up named on the command line that cannot be read is wrong usage (docs/cli.md: exit 2)."""
    result = cli("config", "check", tmp_path / "none.xml")
    assert result.status == 2
    assert result.err == f"postproc: cannot read {tmp_path / 'none.xml'}: No such file or directory\n"


def test_missing_base_of_a_setup_is_an_error_of_the_setup(cli, tmp_path):
    machine = _write(tmp_path, '<MachineSetup name="m" extends="none.xml"/>\n')
    result = cli("config", "check", machine)
    assert result.status == 1
    assert result.err.startswith(f"{machine}:2:1: error: extends: base 'none.xml' not found")


def test_translate_with_a_bad_setup_is_a_configuration_error(cli, tmp_path):
    machine = _write(tmp_path, '<MachineSetup name="m">\n  <Input decimalPoint="dpi"/>\n</MachineSetup>\n')
    result = cli("translate", ROOT / "examples/fanuc/o1003_pocket_and_edge.nc", "--from", "fanuc", "--to", "fanuc",
                 "--machine", machine)
    assert result.status == 1
    assert result.err.startswith(f"{machine}:3:1: error: <Input> decimalPoint: ")


# -- the pipeline override is relative to the set-up file -------------------------------------------

PIPELINE = """<Pipeline dialect="fanuc">
  <FanucBlockSyntax/>
  <CannedCycleResolveSyntax semantics="fanuc"/>
  <ModalStateSyntax/>
</Pipeline>
"""


def _setup_folder(where: Path) -> Path:
    """A set-up folder: m.xml (calculator input) naming pipelines/mill.xml relatively."""
    (where / "pipelines").mkdir(parents=True)
    (where / "pipelines/mill.xml").write_text(DECLARATION + PIPELINE)
    return _write(where, '<MachineSetup name="m" dialect="fanuc" pipeline="pipelines/mill.xml">\n'
                         '  <Input decimalPoint="calculator"/>\n</MachineSetup>\n')


def test_pipeline_path_is_relative_to_the_setup_file(tmp_path):
    setup = load_setup(_setup_folder(tmp_path / "cfg"))
    assert setup.pipeline_path() == tmp_path / "cfg/pipelines/mill.xml"


def test_moving_the_setup_folder_keeps_it_working(cli, tmp_path, monkeypatch):
    _setup_folder(tmp_path / "cfg")
    program = tmp_path / "p.nc"
    program.write_text("G21 G90 G00 X10 Y20\n")
    moved = tmp_path / "elsewhere/deeper"
    moved.parent.mkdir()
    shutil.move(str(tmp_path / "cfg"), moved)
    monkeypatch.chdir(tmp_path / "elsewhere")  # a working directory unrelated to the set-up
    for machine_arg in (moved / "m.xml", Path("deeper/m.xml")):
        assert cli("config", "check", machine_arg).status == 0
        assert cli("config", "dump", machine_arg).out == (moved / "m.xml").read_bytes()
        result = cli("translate", program, "--from", "fanuc", "--to", "fanuc", "--machine", machine_arg,
                     "--normalize")
        assert result.status == 0, result.err
        assert result.out == b"G21 G90 G00 X10. Y20.\n"  # calculator input: X10 = 10 mm


def test_the_override_pipeline_is_the_one_used(cli, tmp_path):
    """A pipeline without the Fanuc block syntax gives blocks no meaning: nothing to normalise."""
    machine = _setup_folder(tmp_path / "cfg")
    (tmp_path / "cfg/pipelines/mill.xml").write_text(DECLARATION + '<Pipeline dialect="fanuc"/>\n')
    program = tmp_path / "p.nc"
    program.write_text("G21 G90 G00 X10 Y20\n")
    result = cli("ir", program, "--dialect", "fanuc", "--machine", machine)
    assert result.status == 0, result.err
    assert b"<Motion" not in result.out


PIPELINE_ERRORS = [
    ('<Pipeline dialect="fanuc">\n  <FanucBlockSyntax/>\n  <NoSuchStep/>\n</Pipeline>\n',
     "unknown element <NoSuchStep>", 4),
    ('<Pipeline dialect="fanuc">\n  <FanucBlockSyntax/>\n  <Feed value="1.0"/>\n</Pipeline>\n',
     "<Feed> is not a syntax step", 4),
    ('<MachineSetup name="x"/>\n', "expected <Pipeline>, found <MachineSetup>", 2),
]


@pytest.mark.parametrize("pipeline, message, line", PIPELINE_ERRORS, ids=[e[1] for e in PIPELINE_ERRORS])
def test_pipeline_errors_point_into_the_pipeline_file(cli, tmp_path, pipeline, message, line):
    machine = _setup_folder(tmp_path / "cfg")
    pipe = tmp_path / "cfg/pipelines/mill.xml"
    pipe.write_text(DECLARATION + pipeline)
    result = cli("config", "check", machine)
    assert result.status == 1
    assert result.err == f"{pipe}:{line}:1: error: {message}\n"


def test_a_missing_pipeline_file_is_an_error(cli, tmp_path):
    machine = _setup_folder(tmp_path / "cfg")
    (tmp_path / "cfg/pipelines/mill.xml").unlink()
    result = cli("config", "check", machine)
    assert result.status == 1
    assert f"{tmp_path / 'cfg/pipelines/mill.xml'}" in result.err
    assert "cannot read" in result.err


@pytest.mark.parametrize("kind", ["fifo", "directory"])
def test_a_pipeline_that_is_no_regular_file_is_refused_without_opening_it(tmp_path, kind):
    # open() on a FIFO waits for a writer: the run would block before any message
    import os
    from postproc.output.bounded import run_bounded
    machine = tmp_path / "m.xml"
    machine.write_text(DECLARATION + '<MachineSetup name="x"\n  pipeline="in/pipe.xml"/>\n')
    (tmp_path / "in").mkdir()
    if kind == "fifo":
        os.mkfifo(tmp_path / "in/pipe.xml")
    else:
        (tmp_path / "in/pipe.xml").mkdir()
    described = "a FIFO (named pipe)" if kind == "fifo" else "a directory"

    def refused() -> list[str]:
        from postproc.plugins import default_registry
        try:
            default_registry().dialect("fanuc").pipeline(load_setup(machine))  # what a run does first
        except ConfigError as err:
            return [str(e) for e in getattr(err, "errors", [err])]
        return []

    found = run_bounded(refused, seconds=10)
    assert found.failure is None, found.failure
    assert found.value == [f"{machine}:3:1: error: pipeline: in/pipe.xml is {described}: a pipeline is read from a file"]
