"""The IR as XML: every registered node class round-trips, and ``postproc ir`` output loads back.

The four-step round trip (as python-docx tests its oxml): a sample object serialises to the expected
canonical bytes, those bytes parse back through the factory to an equal object, and that object
serialises to the same bytes again. ``SAMPLES`` must name every class the installed plugins register:
a new class without a sample fails ``test_every_registered_class_has_a_round_trip_sample``.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

import pytest

from postproc.compensation.dynamic import DynamicCutterCompensation
from postproc.api import read_program
from postproc.ir.expr import Binary, Func, Num, Unary, Var
from postproc.errors import ConfigError
from postproc.ir import (
    Block, BlockDelete, Comments, CompoundMotion, Coolant, CutterCompensation, CycleCall, CycleCancel,
    DistanceMode, Dwell, Feed, FeedMode, MachineCoordinates, MachineFunction, Motion, NativeCode, DataSetting, PathControl, Plane,
    ProgramControl, ProgramStart, ReturnLevel, Sequence, SpindleControl, SpindleOrientation, SpindleSpeed,
    Section, TapeMark, ToolChange, ToolLengthOffset, ToolSelect, Units, WorkOffset, iter_sections,
    register_sections,
)
from postproc.plugins import default_registry
from postproc.commands.program_xml import load_program
from postproc.setup.machine_setup import (
    load_setup, LatheCycleSettings, InputSettings, MachineSettings, MachineSetup, OutputSettings, CycleSettings,
    Templates,
)
from postproc.xmlio import XFactory, parse_xml_bytes, to_bytes
from tests.support.control_samples import CONTROL_SAMPLES

ROOT = Path(__file__).resolve().parents[1]
DECLARATION = "<?xml version='1.0' encoding='UTF-8'?>\n"
FACTORY = default_registry().factory
CLASSES: dict[str, type] = {cls.XNAME: cls for cls in FACTORY.classes()}

Builder = Callable[[dict[str, type]], Any]
"""Makes a sample from the registered classes (plugin classes are reached through the factory)."""


def _empty(name: str) -> list[tuple[Builder, str]]:
    """The sample of a syntax step without attributes or children."""
    return [(lambda classes: classes[name](), f"<{name}/>")]


SAMPLES: dict[str, list[tuple[Builder, str]]] = {
    "BlockDelete": [(lambda c: BlockDelete(2), '<BlockDelete level="2"/>'),
                    (lambda c: BlockDelete(1), "<BlockDelete/>")],
    "Comments": [(lambda c: Comments(["FIRST", "  spaced  ", "", "a < b & \"c\"", "tab\there"]),
                  "<Comments>\n  <Text>FIRST</Text>\n  <Text>  spaced  </Text>\n  <Text></Text>\n"
                  "  <Text>a &lt; b &amp; \"c\"</Text>\n  <Text>tab\there</Text>\n</Comments>")],
    "CompoundMotion": [(lambda c: CompoundMotion("drill", [Motion("rapid", {"X": 1.0, "Y": 2.0}), Dwell(0.5),
                                                           Motion("linear", {"Z": -3.0})]),
                        '<CompoundMotion term="drill">\n  <Motion mode="rapid">\n    <Axes X="1.0" Y="2.0"/>\n'
                        '  </Motion>\n  <Dwell seconds="0.5"/>\n  <Motion mode="linear">\n    <Axes Z="-3.0"/>\n'
                        "  </Motion>\n</CompoundMotion>")],
    "Coolant": [(lambda c: Coolant("flood"), '<Coolant mode="flood"/>'),
                (lambda c: Coolant("off", before_motion=True), '<Coolant mode="off" before_motion="true"/>')],
    "CutterCompensation": [(lambda c: CutterCompensation("left", 4), '<CutterCompensation mode="left" register="4"/>'),
                           (lambda c: CutterCompensation("off"), '<CutterCompensation mode="off"/>')],
    "CycleCall": [(lambda c: CycleCall("peck_deep"), '<CycleCall kind="peck_deep"/>')],
    "CycleCancel": [(lambda c: CycleCancel(), "<CycleCancel/>")],
    "DistanceMode": [(lambda c: DistanceMode("incremental"), '<DistanceMode mode="incremental"/>')],
    "Dwell": [(lambda c: Dwell(1.5), '<Dwell seconds="1.5"/>')],
    "Feed": [(lambda c: Feed(250.0), '<Feed value="250.0"/>')],
    "FeedMode": [(lambda c: FeedMode("per_rev"), '<FeedMode mode="per_rev"/>')],
    "MachineCoordinates": [(lambda c: MachineCoordinates(), "<MachineCoordinates/>")],
    "Motion": [
        (lambda c: Motion("cw", {"X": 10.0, "Y": 0.0}, center={"X": 5.0, "Y": 0.0}),
         '<Motion mode="cw">\n  <Axes X="10.0" Y="0.0"/>\n  <Center X="5.0" Y="0.0"/>\n</Motion>'),
        (lambda c: Motion("ccw", {"X": 1.0}, radius=-5.0),
         '<Motion mode="ccw" radius="-5.0">\n  <Axes X="1.0"/>\n</Motion>'),
        (lambda c: Motion(None, {"X": 30.0}), '<Motion>\n  <Axes X="30.0"/>\n</Motion>'),
        (lambda c: Motion("home", {}), '<Motion mode="home">\n  <Axes/>\n</Motion>'),
        (lambda c: Motion("linear", {"X": 0.1 + 0.2}),
         '<Motion mode="linear">\n  <Axes X="0.30000000000000004"/>\n</Motion>'),
    ],
    "DataSetting": [
        (lambda c: DataSetting("fanuc", "work_offset", 1, {"X": 100.0, "Z": -200.5}, False, "G10 L2 P1 X100. Z-200.5"),
         '<DataSetting family="fanuc" table="work_offset" index="1" text="G10 L2 P1 X100. Z-200.5">\n'
         '  <Values X="100.0" Z="-200.5"/>\n</DataSetting>'),
        (lambda c: DataSetting("fanuc", "tool_length", 5, {"R": -1.5}, True, "G10 L10 P5 R-1.5"),
         '<DataSetting family="fanuc" table="tool_length" index="5" incremental="true" text="G10 L10 P5 R-1.5">\n'
         '  <Values R="-1.5"/>\n</DataSetting>')],
    "FrameChange": [
        (lambda c: __import__("postproc.frames", fromlist=["FrameChange"]).FrameChange(
            "rotate", {"X": 10.0, "Y": -2.5, "R": 30.0}, "layered", "fanuc", "G68 X10. Y-2.5 R30."),
         '<FrameChange kind="rotate" rules="layered" family="fanuc" text="G68 X10. Y-2.5 R30.">\n'
         '  <Words X="10.0" Y="-2.5" R="30.0"/>\n</FrameChange>'),
        (lambda c: __import__("postproc.frames", fromlist=["FrameChange"]).FrameChange(
            "origin", {"X": Var(Num(1.0))}, "shared_offset", "linuxcnc", "G92 X#1"),
         '<FrameChange kind="origin" rules="shared_offset" family="linuxcnc" text="G92 X#1">\n'
         '  <Words>\n    <Value of="X">\n      <Var>\n        <Num value="1.0"/>\n      </Var>\n    </Value>\n  </Words>\n</FrameChange>'),
        (lambda c: __import__("postproc.frames", fromlist=["FrameChange"]).FrameChange(
            "local", {"X": 10.0}, "chain", "siemens", "TRANS X10", increment_setting="setting data SD42440"),
         '<FrameChange kind="local" rules="chain" family="siemens" text="TRANS X10" '
         'incrementSetting="setting data SD42440">\n  <Words X="10.0"/>\n</FrameChange>')],
    "Generated": [
        (lambda c: __import__("postproc.lowering.sequences", fromlist=["GeneratedText"]).GeneratedText("(LOAD T1)", "tool_change"),
         '<Generated text="(LOAD T1)" template="tool_change"/>')],
    "MachineFunction": [
        (lambda c: MachineFunction("fanuc", "M88", "M88", "coolant-on", "through-spindle coolant on"),
         '<MachineFunction family="fanuc" code="M88" action="coolant-on" name="through-spindle coolant on" '
         'text="M88"/>'),
        (lambda c: MachineFunction("fanuc", "G187", "G187 P1 E0.01", name="smoothness"),
         '<MachineFunction family="fanuc" code="G187" name="smoothness" text="G187 P1 E0.01"/>'),
        (lambda c: MachineFunction("fanuc", "M77", "M77 P2", declared=False),
         '<MachineFunction family="fanuc" code="M77" text="M77 P2" declared="false"/>')],
    "NativeCode": [(lambda c: NativeCode("fanuc", "G68 (coordinate rotation)", 'G68 X0 Y0 R45. (a<b & "c")\t'),
                    '<NativeCode dialect="fanuc" what="G68 (coordinate rotation)" '
                    'text="G68 X0 Y0 R45. (a&lt;b &amp; &quot;c&quot;)&#9;"/>')],
    "PathControl": [(lambda c: PathControl("exact_stop", True), '<PathControl mode="exact_stop" one_shot="true"/>'),
                    (lambda c: PathControl("cutting"), '<PathControl mode="cutting"/>'),
                    (lambda c: PathControl("cutting", tolerance=0.01, naive=0.02),
                     '<PathControl mode="cutting" tolerance="0.01" naive="0.02"/>')],
    "RigidTap": [(lambda c: c["RigidTap"]({"Z": -8.0}, 1.25), '<RigidTap pitch="1.25">\n  <Axes Z="-8.0"/>\n</RigidTap>'),
                 (lambda c: c["RigidTap"]({"X": 1.0, "Z": -2.5}, 0.05, 0.5, 2.0),
                  '<RigidTap pitch="0.05" dwell="0.5" speedup="2.0">\n  <Axes X="1.0" Z="-2.5"/>\n</RigidTap>'),
                 (lambda c: c["RigidTap"]({"Z": -10.0}, -1.5, stroke="out"),
                  '<RigidTap pitch="-1.5" stroke="out">\n  <Axes Z="-10.0"/>\n</RigidTap>')],
    "Plane": [(lambda c: Plane("ZX"), '<Plane plane="ZX"/>')],
    "ProgramControl": [(lambda c: ProgramControl("end_rewind"), '<ProgramControl kind="end_rewind"/>')],
    "ProgramStart": [(lambda c: ProgramStart(1234), '<ProgramStart number="1234"/>'),
                     (lambda c: ProgramStart(None, "MAIN"), '<ProgramStart name="MAIN"/>')],
    "ReturnLevel": [(lambda c: ReturnLevel("r"), '<ReturnLevel level="r"/>')],
    "Sequence": [(lambda c: Sequence(10), '<Sequence number="10"/>')],
    "SpindleControl": [(lambda c: SpindleControl("ccw"), '<SpindleControl direction="ccw"/>'),
                       (lambda c: SpindleControl("stop", True), '<SpindleControl direction="stop" before_motion="true"/>')],
    "SpindleOrientation": [(lambda c: SpindleOrientation(90.0), '<SpindleOrientation angle="90.0"/>'),
                           (lambda c: SpindleOrientation(), "<SpindleOrientation/>")],
    "SpindleSpeed": [(lambda c: SpindleSpeed(1200.0), '<SpindleSpeed rpm="1200.0"/>')],
    "TapeMark": [(lambda c: TapeMark(), "<TapeMark/>")],
    "ToolChange": [(lambda c: ToolChange(), "<ToolChange/>")],
    "ToolLengthOffset": [(lambda c: ToolLengthOffset("positive", 1),
                          '<ToolLengthOffset mode="positive" register="1"/>'),
                         (lambda c: ToolLengthOffset("cancel"), '<ToolLengthOffset mode="cancel"/>'),
                         (lambda c: ToolLengthOffset("dynamic", None, 25.5),
                          '<ToolLengthOffset mode="dynamic" length="25.5"/>')],
    "ToolSelect": [(lambda c: ToolSelect(3), '<ToolSelect number="3"/>')],
    "Units": [(lambda c: Units("inch"), '<Units system="inch"/>')],
    "WorkOffset": [(lambda c: WorkOffset(2), '<WorkOffset index="2"/>')],
    "MachineSetup": [
        (lambda c: MachineSetup(
            name="VMC 850", dialect="fanuc", pipeline="pipelines/mill.xml",
            input=InputSettings(decimal_point="calculator", increment_system="IS-C"),
            output=OutputSettings(normalize=True, decimals=4), cycles=CycleSettings(peck_retract=0.2),
            machine=MachineSettings(axes="XYZA", start_z=100.0),
            templates=Templates(header="(PROGRAM {{ program }})\n(FOR {{ machine }})", footer="")),
         '<MachineSetup name="VMC 850" dialect="fanuc" pipeline="pipelines/mill.xml">\n'
         '  <Input decimalPoint="calculator" incrementSystem="IS-C"/>\n'
         '  <Output normalize="true" decimals="4"/>\n'
         '  <Cycles peckRetract="0.2"/>\n'
         '  <Machine axes="XYZA" startZ="100.0"/>\n'
         "  <Templates>\n    <Header>(PROGRAM {{ program }})\n(FOR {{ machine }})</Header>\n    <Footer></Footer>\n"
         "  </Templates>\n</MachineSetup>"),
        (lambda c: MachineSetup(), '<MachineSetup name="default"/>'),
        (lambda c: MachineSetup(
            name="Lathe", dialect="gsk",
            input=InputSettings(machine_type="lathe", gcode_system="B", x_programming="radius",
                                lathe_cycle_format="one-block"),
            lathe_cycles=LatheCycleSettings(rough_depth=1.5, rough_retract=0.5, pattern_passes=3, thread_angle=55)),
         '<MachineSetup name="Lathe" dialect="gsk">\n'
         '  <Input machineType="lathe" gcodeSystem="B" xProgramming="radius" latheCycleFormat="one-block"/>\n'
         '  <LatheCycles roughDepth="1.5" roughRetract="0.5" patternPasses="3" threadAngle="55"/>\n'
         '</MachineSetup>'),
    ],
    "Pipeline": [(lambda c: c["Pipeline"]("fanuc", [c["FanucBlockSyntax"](), c["ModalStateSyntax"]()]),
                  '<Pipeline dialect="fanuc">\n  <FanucBlockSyntax/>\n  <ModalStateSyntax/>\n</Pipeline>'),
                 (lambda c: c["Pipeline"]("empty", []), '<Pipeline dialect="empty"/>')],
    "CannedCycle": [
        (lambda c: c["CannedCycle"](
            "peck_deep", call=True, semantics="fanuc", return_level="r", initial=50.0, r=3.0, bottom=-18.5, q=3.0, clearance=0.3,
            feed=150.0, spindle="cw", motion="rapid", start={"X": 0.0, "Y": 0.0, "Z": 50.0},
            position={"X": 15.0, "Y": 15.0}, shift={"X": 1.0},
            words={"X": 15.0, "Y": 15.0, "Z": -18.5, "R": 3.0, "Q": 3.0, "K": 2}),
         '<CannedCycle kind="peck_deep" call="true" semantics="fanuc" return_level="r" initial="50.0" r="3.0" bottom="-18.5" '
         'q="3.0" clearance="0.3" feed="150.0" spindle="cw" motion="rapid">\n'
         '  <Start X="0.0" Y="0.0" Z="50.0"/>\n  <Position X="15.0" Y="15.0"/>\n  <Shift X="1.0"/>\n'
         '  <Words X="15.0" Y="15.0" Z="-18.5" R="3.0" Q="3.0" K="2"/>\n</CannedCycle>'),
        (lambda c: c["CannedCycle"]("drill", semantics="rs274", repeat=0, plane="ZX", step={"X": 10.0}),
         '<CannedCycle kind="drill" semantics="rs274" plane="ZX" repeat="0">\n  <Step X="10.0"/>\n</CannedCycle>'),
        (lambda c: c["CannedCycle"]("drill", semantics="fanuc", r=2.0, expand=True),
         '<CannedCycle kind="drill" semantics="fanuc" r="2.0" expand="true"/>'),
    ],
    "HolePattern": [
        (lambda c: c["HolePattern"](
            "circle", 6, -60.0, center={"X": -20.0, "Y": 0.0}, skip=(3, 5), move="cw", feed=400.0,
            start={"X": 20.0, "Y": 0.0, "Z": 50.0}, incremental=True, split=(4, 7, 7),
            cycle=c["CannedCycle"]("drill", semantics="fanuc", initial=50.0, r=2.0, bottom=-5.0, feed=100.0)),
         '<HolePattern kind="circle" count="6" step="-60.0" move="cw" feed="400.0" incremental="true" '
         'skip="3 5" split="4 7 7">\n  <Center X="-20.0" Y="0.0"/>\n  <Start X="20.0" Y="0.0" Z="50.0"/>\n'
         '  <CannedCycle kind="drill" semantics="fanuc" initial="50.0" r="2.0" bottom="-5.0" feed="100.0"/>\n'
         '</HolePattern>'),
        (lambda c: c["HolePattern"]("grid", 3, 10.0, plane="ZX", angle=30.0, count2=2, step2=5.0, angle2=60.0),
         '<HolePattern kind="grid" plane="ZX" count="3" step="10.0" angle="30.0" count2="2" step2="5.0" '
         'angle2="60.0"/>'),
    ],
    "CannedCycleResolveSyntax": [
        (lambda c: c["CannedCycleResolveSyntax"]("fanuc"), '<CannedCycleResolveSyntax semantics="fanuc"/>'),
        (lambda c: c["CannedCycleResolveSyntax"]("rs274", [c["DrillingSyntax"](), c["TappingSyntax"]()]),
         '<CannedCycleResolveSyntax semantics="rs274">\n  <DrillingSyntax/>\n  <TappingSyntax/>\n'
         "</CannedCycleResolveSyntax>"),
    ],
    "SpindleMode": [(lambda c: c["SpindleMode"]("css"), '<SpindleMode mode="css"/>')],
    "SpindleClamp": [(lambda c: c["SpindleClamp"](2500.0), '<SpindleClamp rpm="2500.0"/>')],
    "ThreadLead": [(lambda c: c["ThreadLead"](1.5), '<ThreadLead lead="1.5"/>')],
    "XProgramming": [(lambda c: c["XProgramming"]("radius"), '<XProgramming mode="radius"/>')],
    "CoordinateSet": [(lambda c: c["CoordinateSet"]({"X": 200.0, "Z": 150.0}), '<CoordinateSet X="200.0" Z="150.0"/>')],
    "InProfile": [(lambda c: c["InProfile"](12), '<InProfile cycle="12"/>')],
    "LatheCycle": [
        (lambda c: c["LatheCycle"]("turn_rough", "second", {"ns": 10, "nf": 20, "allow_x": 0.5, "allow_z": 0.1}),
         '<LatheCycle kind="turn_rough" form="second">\n  <Params ns="10" nf="20" allow_x="0.5" allow_z="0.1"/>\n'
         '</LatheCycle>'),
        (lambda c: c["LatheCycle"]("turn_finish", "single"), '<LatheCycle kind="turn_finish" form="single"/>'),
    ],
    "Num": [(lambda c: Num(-2.5), '<Num value="-2.5"/>')],
    "Var": [(lambda c: Var(Num(1.0)), '<Var>\n  <Num value="1.0"/>\n</Var>'),
            (lambda c: Var(name="_global"), '<Var name="_global"/>')],
    "Unary": [(lambda c: Unary("neg", Var(name="a")), '<Unary op="neg">\n  <Var name="a"/>\n</Unary>')],
    "Binary": [(lambda c: Binary("mod_pos", Num(7.0), Num(3.0)),
                '<Binary op="mod_pos">\n  <Num value="7.0"/>\n  <Num value="3.0"/>\n</Binary>')],
    "Func": [(lambda c: Func("atan2", [Num(1.0), Num(2.0)]),
              '<Func name="atan2">\n  <Num value="1.0"/>\n  <Num value="2.0"/>\n</Func>')],
    **{name: _empty(name) for name in (
        "FanucBlockSyntax", "FanucLatheBlockSyntax", "GskBlockSyntax", "LatheCycleSyntax", "FanucProgramSyntax",
        "ModalStateSyntax", "GrblBlockSyntax", "GrblhalBlockSyntax", "GrblhalCycleRules", "GrblhalProgramSyntax",
        "NgcBlockSyntax", "NgcLatheBlockSyntax", "Mach3BlockSyntax",
        "LinuxcncProgramSyntax", "PolarSyntax", "IsgBlockSyntax", "IsgProgramSyntax", "FagorBlockSyntax",
        "FagorProgramSyntax", "SiemensBlockSyntax", "SiemensProgramSyntax", "SiemensCycleEnd", "DrillingSyntax",
        "PeckDrillingSyntax", "GrblhalPeckSyntax", "TappingSyntax", "BoringSyntax", "FineBoringSyntax", "BackBoringSyntax",
        "ManualBoringSyntax",
    )},
    "DynamicCutterCompensation": [
        (lambda c: DynamicCutterCompensation("right", -0.8), '<DynamicCutterCompensation mode="right" diameter="-0.8"/>'),
        (lambda c: DynamicCutterCompensation("left", 0.4, 2),
         '<DynamicCutterCompensation mode="left" diameter="0.4" orientation="2"/>')],
    "SiemensCycleLevels": [(lambda c: c["SiemensCycleLevels"](10.0, 2.5),
                            '<SiemensCycleLevels retract="10.0" r="2.5"/>'),
                           (lambda c: c["SiemensCycleLevels"](10.0, 2.5, True, 150.0, "CYCLE85"),
                            '<SiemensCycleLevels retract="10.0" r="2.5" once="true" feed="150.0" name="CYCLE85"/>')],
    "SiemensHoles": [(lambda c: c["SiemensHoles"]("HOLES2", 60.0, 40.0, 10.0, 90.0, 0.0, 4),
                      '<SiemensHoles name="HOLES2" a="60.0" b="40.0" c="10.0" d="90.0" e="0.0" num="4"/>')],
    "SiemensArc": [(lambda c: c["SiemensArc"](90.0), '<SiemensArc angle="90.0"/>')],
    "SiemensSupa": [(lambda c: c["SiemensSupa"](), '<SiemensSupa/>')],
    "SiemensTurn": [(lambda c: c["SiemensTurn"](3), '<SiemensTurn turns="3"/>')],
    "SiemensCip": [(lambda c: c["SiemensCip"](0.0, 10.0), '<SiemensCip i1="0.0" j1="10.0"/>'),
                   (lambda c: c["SiemensCip"](1.0, 2.0, 3.0), '<SiemensCip i1="1.0" j1="2.0" k1="3.0"/>')],
    "SiemensFixedPoint": [(lambda c: c["SiemensFixedPoint"](1, "ZY"), '<SiemensFixedPoint number="1" axes="ZY"/>')],
    **CONTROL_SAMPLES,
}


def _without_sample(factory: XFactory) -> list[str]:
    return [f"<{cls.XNAME}> ({cls.__module__}.{cls.__qualname__})"
            for cls in factory.classes() if cls.XNAME not in SAMPLES]


def test_every_registered_class_has_a_round_trip_sample():
    missing = _without_sample(FACTORY)
    assert not missing, ("registered XML classes without a round-trip sample; add one to SAMPLES in "
                         "tests/test_ir_xml.py: " + ", ".join(missing))


def test_the_sample_check_catches_a_new_class():
    class Teleport(Section):
        XNAME = KEY = "Teleport"
        __slots__ = ()

    factory = XFactory()
    register_sections(factory)
    assert _without_sample(factory) == []
    Teleport.reg(factory)
    assert _without_sample(factory) == [f"<Teleport> ({__name__}.{Teleport.__qualname__})"]


def test_core_classes_are_registered():
    core = {cls.XNAME for cls in iter_sections()} | {"Pipeline", "MachineSetup", "ModalStateSyntax"}
    assert core <= set(FACTORY.names())


CASES = [pytest.param(name, i, id=f"{name}-{i}") for name in FACTORY.names() if name in SAMPLES
         for i in range(len(SAMPLES[name]))]


@pytest.mark.parametrize("name, index", CASES)
def test_round_trip(name, index):
    build, body = SAMPLES[name][index]
    expected = DECLARATION + body + "\n"
    sample = build(CLASSES)
    assert type(sample).XNAME == name
    # 1. serialise: the canonical bytes are the ones written by hand
    first = to_bytes(sample.make_xml_source())
    assert first.decode() == expected
    # 2. parse the expected bytes through the factory: an equal object
    created = FACTORY.create(parse_xml_bytes(expected.encode(), "sample.xml"))
    assert type(created) is type(sample)
    assert created == sample
    # 3. serialise again: the same bytes
    assert to_bytes(created.make_xml_source()).decode() == expected


def test_equal_means_equal_content():
    assert Motion("rapid", {"X": 1.0}) != Motion("rapid", {"X": 2.0})
    assert Motion("rapid", {"X": 1.0}) != Motion("linear", {"X": 1.0})
    assert Sequence(1) != ToolSelect(1)
    assert Comments(["A"]) != Comments(["A", "B"])


# -- blocks and whole programs ---------------------------------------------------------------------

def _sample_block() -> Block:
    block = Block(7, "n10 G01 x1. (C)", "\r\n", [("n", "10"), ("G", "01"), ("x", "1.")])
    block.values.update({"N": 10, "X": 1.0})
    block.add(Sequence(10))
    block.add(Comments(["C"]))
    block.add(Motion("linear", {"X": 1.0}))
    return block


BLOCK_XML = (
    '<Block line="7" text="n10 G01 x1. (C)" eol="CRLF">\n'
    '  <Word letter="n" text="10" kind="int" value="10"/>\n'
    '  <Word letter="G" text="01"/>\n'
    '  <Word letter="x" text="1." kind="float" value="1.0"/>\n'
    '  <Sequence number="10"/>\n'
    "  <Comments>\n    <Text>C</Text>\n  </Comments>\n"
    '  <Motion mode="linear">\n    <Axes X="1.0"/>\n  </Motion>\n'
    "</Block>\n"
)


def test_block_round_trip():
    block = _sample_block()
    assert to_bytes(block.make_xml_source()).decode() == DECLARATION + BLOCK_XML
    loaded = Block.from_xml(parse_xml_bytes((DECLARATION + BLOCK_XML).encode(), "b.xml"), FACTORY)
    assert loaded == block
    assert isinstance(loaded.values["N"], int) and isinstance(loaded.values["X"], float)


@pytest.mark.parametrize("eol, name", [("\n", None), ("\r\n", "CRLF"), ("\r", "CR"), ("", "none")])
def test_block_end_of_line(eol, name):
    block = Block(1, "G90", eol, [("G", "90")])
    el = block.make_xml_source()
    assert el.get("eol") == name
    assert Block.from_xml(el, FACTORY).eol == eol


def test_changed_block_has_no_text():
    block = Block(3, None, "\n")
    block.add(Coolant("off"))
    el = block.make_xml_source()
    assert "text" not in el.attrib
    assert Block.from_xml(el, FACTORY) == block


EXAMPLES = sorted(ROOT.glob("examples/**/*.nc")) + [
    p for p in sorted((ROOT / "tests/golden/fanuc/roundtrip").glob("*.nc"))
    if p.stem not in ("non_utf8_comment", "colon_program_number")  # tested on their own
]


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: str(p.relative_to(ROOT)))
def test_ir_command_output_loads_back_to_the_read_blocks(cli, tmp_path, path):
    out = tmp_path / "ir.xml"
    name, setup_file = {"gsk": ("gsk", "gsk_980tdc.xml"), "fanuc-lathe": ("fanuc", "fanuc_0i_tf.xml"),
                        "isg": ("isg", "isg_twincat_cylinder.xml"), "fagor": ("fagor", None),
                        }.get(path.parent.name, ("fanuc", None))  # examples/<dialect>/
    machine = ["--machine", ROOT / "examples/setups" / setup_file] if setup_file else []
    result = cli("ir", path, "--dialect", name, "-o", out, *machine)
    assert result.status == 0, result.err
    dialect, loaded = load_program(out)
    setup = load_setup(ROOT / "examples/setups" / setup_file) if setup_file else None
    with open(path, encoding="utf-8", errors="surrogateescape", newline="") as src:
        expected = read_program(src, file=str(path), dialect=name, setup=setup)
    assert dialect == name
    assert len(loaded) == len(expected)
    for got, want in zip(loaded, expected):
        assert got == want, f"line {want.line}"


def test_ir_command_writes_to_stdout(cli, root):
    path = root / "examples/fanuc/o1003_pocket_and_edge.nc"
    result = cli("ir", path, "--dialect", "fanuc")
    assert result.status == 0, result.err
    assert result.out.startswith(DECLARATION.encode() + f'<Program dialect="fanuc" file="{path}">\n'.encode())
    assert result.out.endswith(b"</Program>")
    assert result.out.count(b"<Block ") == len(path.read_bytes().splitlines())


@pytest.mark.parametrize("text, col, what", [
    (b"G00 X0. (BELL \x07)\n", 15, "character '\\x07' (U+0007)"),
    (b"G00 X0. (DURCHMESSER \xd8)\n", 22, "byte 0xD8 (not UTF-8)"),
])
def test_ir_of_text_xml_cannot_hold_is_a_located_error(cli, tmp_path, text, col, what):
    path = tmp_path / "odd.nc"
    path.write_bytes(text)
    result = cli("ir", path, "--dialect", "fanuc", "-o", tmp_path / "ir.xml")
    assert result.status == 1
    assert result.err == f"{path}:1:{col}: error: {what} cannot be written to the IR XML\n"
    assert not (tmp_path / "ir.xml").exists()


BAD_PROGRAMS = [
    # (XML after the declaration, message, line counted from the declaration's line 1)
    ('<Program dialect="fanuc">\n  <Block line="1">\n    <Teleport/>\n  </Block>\n</Program>',
     "unknown element <Teleport>", 4),
    ('<Program dialect="fanuc">\n  <Blok line="1"/>\n</Program>', "unknown element <Blok> in <Program>", 3),
    ('<Pipeline dialect="fanuc"/>', "expected <Program>, found <Pipeline>", 2),
    ('<Program>\n  <Block line="1">\n    <Sequence number="ten"/>\n  </Block>\n</Program>',
     "<Sequence> attribute number='ten' is not a valid int", 4),
    ('<Program>\n  <Block line="1">\n    <Units/>\n  </Block>\n</Program>', "<Units> needs attribute 'system'", 4),
    ('<Program>\n  <Block line="1">\n    <Motion mode="rapid">\n      <Speed/>\n    </Motion>\n  </Block>\n</Program>',
     "invalid <Motion>: unexpected <Speed>", 4),
    ('<Program>\n  <Block line="1" eol="LFCR"/>\n</Program>', "invalid <Block>: unknown end of line 'LFCR'", 3),
    ('<Program>\n  <Block line="1">\n    <Pipeline dialect="x"/>\n  </Block>\n</Program>',
     "<Pipeline> is not a block section", 4),
]


@pytest.mark.parametrize("xml, message, line", BAD_PROGRAMS, ids=[m for _, m, _ in BAD_PROGRAMS])
def test_load_program_errors_are_located(tmp_path, xml, message, line):
    path = tmp_path / "bad.xml"
    path.write_text(DECLARATION + xml + "\n")
    with pytest.raises(ConfigError) as info:
        load_program(path)
    assert info.value.message == message
    assert (info.value.location.file, info.value.location.line) == (str(path), line)
