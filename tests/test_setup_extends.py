"""Set-ups that describe a machine: ``extends`` chains, every problem reported with its line, hostile
files refused quickly, the machine's axes/offsets/tools, and groups that plugins add through the hook."""

from __future__ import annotations

import time
from pathlib import Path

import pytest

from postproc.errors import ConfigError, ErrorList
from postproc.hookspecs import hookimpl
from postproc.plugins import Registry, make_plugin_manager
from postproc.setup.machine_setup import MachineSetup, SetupGroup, load_setup, setting
from postproc.setup.load import BASES
from postproc.xmlio import XFactory

DECLARATION = "<?xml version='1.0' encoding='UTF-8'?>\n"


def _write(folder: Path, name: str, body: str) -> Path:
    path = folder / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(DECLARATION + body)
    return path


BASE = ('<MachineSetup name="base VMC" dialect="fanuc">\n'
        '  <Input decimalPoint="calculator"/>\n'
        '  <Cycles peckRetract="0.2" peckClearance="0.3"/>\n'
        '  <Machine axes="XYZA" startZ="100.0"/>\n'
        '  <Axes>\n'
        '    <Axis name="X" min="-762.0" max="0.0" home="0.0"/>\n'
        '    <Axis name="Z" min="-508.0" max="0.0" home="0.0"/>\n'
        '  </Axes>\n'
        '  <MachineCodes>\n'
        '    <M number="60" action="stop" name="pallet change"/>\n'
        '  </MachineCodes>\n'
        '</MachineSetup>\n')
CHILD = ('<MachineSetup name="cell 3" extends="base.xml">\n'
         '  <Cycles peckClearance="0.5"/>\n'
         '  <Axes>\n'
         '    <Axis name="X" min="-700.0"/>\n'
         '  </Axes>\n'
         '</MachineSetup>\n')


# -- extends ------------------------------------------------------------------------------------------

def test_the_child_overrides_single_attributes(tmp_path):
    _write(tmp_path, "base.xml", BASE)
    setup = load_setup(_write(tmp_path, "cell3.xml", CHILD))
    assert (setup.name, setup.dialect, setup.input.decimal_point) == ("cell 3", "fanuc", "calculator")
    assert (setup.cycles.peck_retract, setup.cycles.peck_clearance) == (0.2, 0.5)  # one kept, one overridden
    assert (setup.travel["X"].minimum, setup.travel["X"].maximum) == (-700.0, 0.0)
    assert setup.travel["Z"].minimum == -508.0
    assert [c.number for c in setup.machine_codes] == ["60"]
    assert setup.machine.axes == "XYZA"


def test_dump_keeps_extends_and_the_files_own_values(cli, tmp_path):
    _write(tmp_path, "base.xml", BASE)
    child = _write(tmp_path, "cell3.xml", CHILD)
    result = cli("config", "dump", child)
    assert result.status == 0, result.err
    assert result.out == child.read_bytes()


def test_dump_flatten_writes_the_resolved_setup(cli, tmp_path):
    _write(tmp_path, "base.xml", BASE)
    child = _write(tmp_path, "cell3.xml", CHILD)
    result = cli("config", "dump", "--flatten", child)
    assert result.status == 0, result.err
    expected = BASE.replace('name="base VMC"', 'name="cell 3"').replace(
        ' peckClearance="0.3"', '').replace('min="-762.0"', 'min="-700.0"')
    assert result.out.decode() == DECLARATION + expected
    flat = tmp_path / "flat.xml"
    flat.write_bytes(result.out)
    assert load_setup(flat) == load_setup(child)


def test_a_value_set_back_to_its_default_is_an_override(cli, tmp_path):
    _write(tmp_path, "base.xml", BASE)
    child = _write(tmp_path, "c.xml", '<MachineSetup extends="base.xml">\n'
                                      '  <Input decimalPoint="least-increment"/>\n</MachineSetup>\n')
    assert load_setup(child).input.decimal_point == "least-increment"
    assert cli("config", "dump", child).out == child.read_bytes()


def test_a_shipped_base_by_name(tmp_path):
    assert (Path(BASES) / "haas-mill.xml").is_file()
    child = _write(tmp_path, "vf2.xml", '<MachineSetup name="VF-2" extends="haas-mill.xml">\n'
                                        '  <Machine axes="XYZA"/>\n</MachineSetup>\n')
    setup = load_setup(child)
    assert (setup.dialect, setup.controller.variant) == ("fanuc", "haas")
    assert setup.machine.axes == "XYZA"


def test_a_local_base_wins_over_a_shipped_one_of_the_same_name(tmp_path):
    _write(tmp_path, "haas-mill.xml", '<MachineSetup name="ours" dialect="linuxcnc"/>\n')
    setup = load_setup(_write(tmp_path, "m.xml", '<MachineSetup extends="haas-mill.xml"/>\n'))
    assert (setup.name, setup.dialect) == ("ours", "linuxcnc")


def test_a_chain_of_three(tmp_path):
    _write(tmp_path, "a.xml", '<MachineSetup name="a" dialect="fanuc">\n  <Output decimals="4"/>\n</MachineSetup>\n')
    _write(tmp_path, "sub/b.xml", '<MachineSetup name="b" extends="../a.xml">\n  <Output leadingZero="false"/>\n'
                                  '</MachineSetup>\n')
    c = _write(tmp_path, "c.xml", '<MachineSetup extends="sub/b.xml">\n  <Output decimals="2"/>\n</MachineSetup>\n')
    setup = load_setup(c)
    assert (setup.name, setup.output.decimals, setup.output.leading_zero) == ("b", 2, False)


def test_relative_paths_of_a_base_stay_relative_to_the_base(tmp_path):
    _write(tmp_path, "shop/base.xml", '<MachineSetup name="b">\n  <Library path="macros"/>\n</MachineSetup>\n')
    child = _write(tmp_path, "cells/c.xml", '<MachineSetup extends="../shop/base.xml">\n'
                                            '  <Library path="mine"/>\n</MachineSetup>\n')
    setup = load_setup(child)
    assert setup.library == ["mine", "../shop/macros"]  # the child's folders are searched first
    assert setup.library_paths()[1].resolve() == (tmp_path / "shop/macros").resolve()


def test_templates_of_a_base_are_located_in_the_base(cli, tmp_path):
    base = _write(tmp_path, "base.xml", '<MachineSetup name="b">\n  <Templates>\n'
                                        '    <Header>(A)\n{{ nope }}</Header>\n  </Templates>\n</MachineSetup>\n')
    child = _write(tmp_path, "c.xml", '<MachineSetup extends="base.xml"/>\n')
    result = cli("config", "check", child)
    assert result.status == 1
    assert result.err == f"{base}:5:1: error: template header: 'nope' is undefined\n"


CYCLES = [
    ({"a.xml": '<MachineSetup extends="b.xml"/>\n', "b.xml": '<MachineSetup extends="a.xml"/>\n'},
     "b.xml", 2, "inheritance cycle: {a} extends {b} extends {a}"),
    ({"a.xml": '<MachineSetup extends="a.xml"/>\n'}, "a.xml", 2, "inheritance cycle: {a} extends {a}"),
    ({"a.xml": '<MachineSetup name="x" extends="gone.xml"/>\n'}, "a.xml", 2,
     "base 'gone.xml' not found (neither beside a.xml nor among the shipped bases: "),
]


@pytest.mark.parametrize("files, culprit, line, message", CYCLES, ids=["cycle", "self", "missing"])
def test_chain_errors_are_located_at_the_extends(cli, tmp_path, files, culprit, line, message):
    for name, body in files.items():
        _write(tmp_path, name, body)
    a, b = (tmp_path / "a.xml").resolve(), (tmp_path / "b.xml").resolve()
    start = time.monotonic()
    result = cli("config", "check", tmp_path / "a.xml")
    assert time.monotonic() - start < 5
    assert result.status == 1
    prefix = f"{tmp_path / culprit}:{line}:1: error: extends: "
    assert result.err.startswith(prefix + message.format(a=a, b=b)), result.err


# -- every problem, each with its line ------------------------------------------------------------

def test_config_check_reports_every_problem(cli, tmp_path):
    path = _write(tmp_path, "m.xml", '<MachineSetup name="m" colour="red">\n'
                                     '  <Output decimals="9" bogus="1"/>\n'
                                     '  <Spindle maxRpm="12000"/>\n'
                                     '  <Machine axes="XYZ"/>\n'
                                     '  <Axes>\n'
                                     '    <Axis name="X" min="10.0" max="-10.0"/>\n'
                                     '    <Axis name="B" min="-120.0" max="120.0"/>\n'
                                     '    <Axis name="Y" min="many"/>\n'
                                     '  </Axes>\n'
                                     '  <Templates>\n'
                                     '    <Header>{{ "".__class__ }}</Header>\n'
                                     '  </Templates>\n'
                                     '</MachineSetup>\n')
    result = cli("config", "check", path)
    assert result.status == 1
    assert result.err_lines == [
        f"{path}:2:1: error: <MachineSetup> has unknown attribute(s) colour",
        f"{path}:3:1: error: <Output> decimals: Input should be less than or equal to 6",
        f"{path}:3:1: error: <Output> bogus: unknown parameter",
        f"{path}:4:1: error: unknown element <Spindle> in <MachineSetup>",
        f'{path}:7:1: error: <Axis name="X"> axis X: min 10 is not below max -10',
        f'{path}:8:1: error: <Axis name="B">: axis B is not on this machine (axes XYZ)',
        f'{path}:9:1: error: <Axis name="Y"> min: Input should be a valid number, unable to parse string as a number',
        f"{path}:12:1: error: template header: access to attribute '__class__' of 'str' object is unsafe.",
    ]


def test_load_setup_raises_every_problem(tmp_path):
    path = _write(tmp_path, "m.xml", '<MachineSetup name="m">\n  <Output decimals="9"/>\n'
                                     '  <Cycles peckRetract="-1"/>\n</MachineSetup>\n')
    with pytest.raises(ErrorList) as info:
        load_setup(path)
    assert [(e.location.line, e.message[:8]) for e in info.value.errors] == [(3, "<Output>"), (4, "<Cycles>")]


# -- hostile set-ups are refused quickly -----------------------------------------------------------

HOSTILE = [
    ('<!DOCTYPE MachineSetup SYSTEM "http://example.com/evil.dtd">\n<MachineSetup name="m"/>\n',
     2, "a DOCTYPE is not allowed in postproc XML"),
    ('<MachineSetup name="m">\n  <Axes>\n    <Axis name="X" min="-1e308" max="0.0"/>\n  </Axes>\n</MachineSetup>\n',
     4, '<Axis name="X"> min: Input should be greater than or equal to -100000'),
    ('<MachineSetup name="m">\n  <Output decimals="1000000000"/>\n</MachineSetup>\n',
     3, "<Output> decimals: Input should be less than or equal to 6"),
    ('<MachineSetup name="m">\n  <Axes>\n    <Axis name="Z" min="0.0" max="-500.0"/>\n  </Axes>\n</MachineSetup>\n',
     4, '<Axis name="Z"> axis Z: min 0 is not below max -500'),
    ('<MachineSetup name="m">\n  <Machine startZ="1e308"/>\n</MachineSetup>\n',
     3, "<Machine> startZ: Input should be less than or equal to 100000"),
    ('<MachineSetup name="m">\n  <Tools>\n    <Tool number="1" length="inf"/>\n  </Tools>\n</MachineSetup>\n',
     4, '<Tool number="1"> length: Input should be a finite number'),
    ('<MachineSetup name="m">\n  <Templates>\n    <Header>{% for i in range(99999) %}{% for j in range(99999) %}'
     '{% endfor %}{% endfor %}</Header>\n  </Templates>\n</MachineSetup>\n', 4, "template header ran longer than 5 s"),
]


@pytest.mark.parametrize("body, line, message", HOSTILE,
                         ids=["external_dtd", "1e308_travel", "1e9_decimals", "negative_range", "1e308_start",
                              "infinite_tool", "looping_template"])
def test_hostile_setups_are_refused_quickly(cli, tmp_path, body, line, message):
    path = _write(tmp_path, "m.xml", body)
    start = time.monotonic()
    result = cli("config", "check", path)
    assert time.monotonic() - start < 10
    assert (result.status, result.out) == (1, b"")
    assert result.err == f"{path}:{line}:1: error: {message}\n"


def test_a_huge_setup_is_refused_before_it_is_parsed(cli, tmp_path):
    path = tmp_path / "huge.xml"
    path.write_bytes(DECLARATION.encode() + b'<MachineSetup name="m">' + b"<!-- x -->" * 500_000 + b"</MachineSetup>")
    start = time.monotonic()
    result = cli("config", "check", path)
    assert time.monotonic() - start < 2
    assert result.status == 1
    assert result.err == f"{path}:1:1: error: XML file is larger than {4 << 20} bytes\n"


# -- the machine: axes, work offsets, tools ----------------------------------------------------------

def test_machine_description_values(tmp_path):
    path = _write(tmp_path, "m.xml", '<MachineSetup name="m">\n'
                                     '  <Machine axes="XYZB" units="inch"/>\n'
                                     '  <Axes>\n    <Axis name="B" min="-120.0" max="120.0"/>\n  </Axes>\n'
                                     '  <WorkOffsets>\n    <Offset number="1" x="-10.0" z="-20.5"/>\n  </WorkOffsets>\n'
                                     '  <Tools>\n    <Tool number="3" length="6.0"/>\n  </Tools>\n'
                                     '</MachineSetup>\n')
    setup = load_setup(path)
    assert setup.machine.mm() == 25.4
    assert setup.travel["B"].within(120.0) and not setup.travel["B"].within(120.001)
    assert setup.work_offsets["1"].axes() == {"X": -10.0, "Z": -20.5}  # Y unknown, not zero
    assert setup.tools["3"].length == 6.0
    assert setup.travel_limited()


def test_tool_radius_is_checked_and_dumped(cli, tmp_path):
    body = ('<MachineSetup name="m">\n  <Tools>\n    <Tool number="1" length="120.0" radius="5.0"/>\n'
            '    <Tool number="2" radius="-0.5"/>\n  </Tools>\n</MachineSetup>\n')
    path = _write(tmp_path, "m.xml", body)
    setup = load_setup(path)
    assert (setup.tools["1"].radius, setup.tools["2"].radius, setup.tools["2"].length) == (5.0, -0.5, None)
    assert cli("config", "dump", path).out.decode().splitlines()[1:] == body.splitlines()
    bad = _write(tmp_path, "bad.xml", body.replace('radius="5.0"', 'radius="1e6"'))
    assert cli("config", "check", bad).err_lines == [
        f'{bad}:4:1: error: <Tool number="1"> radius: Input should be less than or equal to 100000']


def test_entry_errors(cli, tmp_path):
    path = _write(tmp_path, "m.xml", '<MachineSetup name="m">\n'
                                     '  <WorkOffsets>\n    <Offset number="7" x="1.0"/>\n'
                                     '    <Offset x="1.0"/>\n    <Offset number="1" a="1.0"/>\n  </WorkOffsets>\n'
                                     '  <Tools>\n    <Tool number="1"/>\n    <Tool number="1"/>\n    <Slot/>\n'
                                     '  </Tools>\n  <Axes>\n    <Axis name="X" home="5.0" max="0.0"/>\n  </Axes>\n'
                                     '</MachineSetup>\n')
    result = cli("config", "check", path)
    assert result.err_lines == [
        f'{path}:4:1: error: <Offset number="7"> number: Input should be less than or equal to 6',
        f"{path}:5:1: error: <Offset> needs attribute 'number'",
        f'{path}:6:1: error: <Offset number="1">: axis A is not on this machine (axes XYZ)',
        f'{path}:10:1: error: <Tool number="1"> appears twice',
        f"{path}:11:1: error: unknown element <Slot> in <Tools> (expected <Tool>)",
        f'{path}:14:1: error: <Axis name="X"> axis X: home 5 is outside the travel',
    ]


# -- groups plugins add through the hook -------------------------------------------------------------

class ProbeSettings(SetupGroup):
    """A plugin's own group: a probing cycle's parameters."""

    TAG = "Probe"
    approach_feed: float = setting(100.0, gt=0)
    max_travel: float = 10.0


class ProbePlugin:
    @hookimpl
    def postproc_register_setup_groups(self, register):
        register(ProbeSettings)


def _groups(*plugins: object) -> dict[str, type[SetupGroup]]:
    return Registry(make_plugin_manager(plugins), XFactory()).setup_groups


def test_a_plugin_group_is_read_validated_and_dumped(tmp_path):
    groups = _groups(ProbePlugin())
    path = _write(tmp_path, "m.xml", '<MachineSetup name="m">\n  <Probe approachFeed="50.0"/>\n</MachineSetup>\n')
    setup = load_setup(path, groups=groups)
    probe = setup.group(ProbeSettings)
    assert isinstance(probe, ProbeSettings)
    assert (probe.approach_feed, probe.max_travel) == (50.0, 10.0)
    dumped = setup.make_xml_source()
    assert [(c.tag, dict(c.attrib)) for c in dumped] == [("Probe", {"approachFeed": "50.0"})]
    assert MachineSetup().group(ProbeSettings) == ProbeSettings()  # absent: its defaults


def test_a_plugin_group_bound_is_checked_on_loading_only(tmp_path):
    path = _write(tmp_path, "m.xml", '<MachineSetup name="m">\n  <Probe approachFeed="0" depth="1"/>\n</MachineSetup>\n')
    with pytest.raises(ErrorList) as info:
        load_setup(path, groups=_groups(ProbePlugin()))
    assert [str(e) for e in info.value.errors] == [
        f"{path}:3:1: error: <Probe> approachFeed: Input should be greater than 0",
        f"{path}:3:1: error: <Probe> depth: unknown parameter"]
    assert ProbeSettings(approach_feed=0.0).approach_feed == 0.0  # code is trusted: no validation per run


def test_a_plugin_group_error_is_located(tmp_path):
    path = _write(tmp_path, "m.xml", '<MachineSetup name="m">\n\n  <Probe maxTravel="far"/>\n</MachineSetup>\n')
    with pytest.raises(ConfigError) as info:
        load_setup(path, groups=_groups(ProbePlugin()))
    assert str(info.value) == (f"{path}:4:1: error: <Probe> maxTravel: Input should be a valid number, "
                               "unable to parse string as a number")
    with pytest.raises(ConfigError, match="unknown element <Probe>"):  # without the plugin
        load_setup(path, groups=_groups())


class Clash(SetupGroup):
    TAG = "Cycles"


class ClashPlugin:
    @hookimpl
    def postproc_register_setup_groups(self, register):
        register(Clash)


def test_a_plugin_group_cannot_take_a_core_element():
    with pytest.raises(TypeError, match="<Cycles> registered twice"):
        _groups(ClashPlugin())


# -- the shipped bases and example set-ups -------------------------------------------------------------

ROOT = Path(__file__).resolve().parents[1]


@pytest.mark.parametrize("path", sorted(Path(BASES).glob("*.xml")), ids=lambda p: p.name)
def test_every_shipped_base_checks_clean_and_dumps_identical(cli, path):
    assert cli("config", "check", path).status == 0
    assert cli("config", "dump", path).out == path.read_bytes()


@pytest.mark.parametrize("path", sorted((ROOT / "examples/setups").glob("*.xml")), ids=lambda p: p.name)
def test_example_flattened_dump_reloads_to_the_same_setup(cli, tmp_path, path):
    flat = tmp_path / "flat.xml"
    flat.write_bytes(cli("config", "dump", "--flatten", path).out)
    assert load_setup(flat) == load_setup(path)
    assert cli("config", "dump", flat).out == flat.read_bytes()  # the flattened file is canonical too


def test_some_examples_extend_a_shipped_and_some_a_local_base():
    extends = {p.name: load_setup(p).extends for p in (ROOT / "examples/setups").glob("*.xml")}
    assert extends["fanuc_0i_mf_vmc.xml"] == "fanuc-mill.xml"
    assert extends["haas_vf2_cell3.xml"] == "haas_vf2_shop.xml"
    assert extends["gsk_980tdc_ck6140.xml"] == "gsk_980tdc.xml"


def test_the_vmc_example_values():
    setup = load_setup(ROOT / "examples/setups/fanuc_0i_mf_vmc.xml")
    assert (setup.dialect, setup.input.decimal_point, setup.machine.start_z) == ("fanuc", "calculator", 100.0)
    assert (setup.travel["X"].minimum, setup.travel["X"].maximum, setup.travel["X"].home) == (-800.0, 0.0, 0.0)
    assert setup.work_offsets["1"].axes() == {"X": -400.0, "Y": -250.0, "Z": -350.0}
    assert setup.tools["3"].length == 140.25


SHOP_RUNS = [
    ("fanuc", "fanuc_0i_mf_vmc.xml", "examples/fanuc", ("o1001", "o1002", "o1003", "o1005")),
    ("fanuc", "haas_vf2_cell3.xml", "examples/fanuc", ("o1001", "o1002", "o1003", "o1005")),
    ("linuxcnc", "linuxcnc_mill.xml", "examples/linuxcnc", ("",)),
    ("gsk", "gsk_980tdc_ck6140.xml", "examples/gsk", ("",)),
    ("isg", "isg_twincat_mill.xml", "examples/isg", ("prof_contour_xy", "steps_subroutine")),
    ("fagor", "fagor_8070_mill.xml", "examples/fagor", ("drill_plate",)),
]


@pytest.mark.parametrize("dialect, setup, folder, stems", SHOP_RUNS, ids=[r[1] for r in SHOP_RUNS])
def test_the_example_programs_stay_inside_their_machines_travel(cli, dialect, setup, folder, stems):
    """Every offset and tool the programs use is in the set-up, and every move is inside the travel."""
    programs = [p for p in sorted((ROOT / folder).glob("*.n*c")) if p.stem.startswith(stems)]
    assert programs
    for program in programs:
        result = cli("toolpath", program, "--dialect", dialect, "--machine", ROOT / "examples/setups" / setup)
        assert (result.status, result.err) == (0, ""), program


def test_an_element_alone_cannot_extend(tmp_path):
    from lxml import etree
    el = etree.fromstring(b'<MachineSetup name="m" extends="base.xml"/>')
    with pytest.raises(ConfigError, match="load it with load_setup"):
        MachineSetup.from_xml(el)
    assert MachineSetup.from_xml(etree.fromstring(b'<MachineSetup name="m"/>')).name == "m"
