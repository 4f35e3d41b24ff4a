"""Fuzz kind "program options": ``translate --units``, ``--transform`` and ``--arcs`` on random mill programs
of every reading dialect, to every writer, each output verified with the same options
(``verify_lines(transform=..., chord_tolerance=...)``: a units conversion needs none, both paths are mm).

Programs mix absolute and incremental moves, arcs in every plane (I/J/K and R, full circles, helices),
inch and mm, drilling cycles, tool length and cutter compensation, work offsets and machine
coordinates; transforms rotate in any plane, mirror any axis, scale unevenly. A case passes when it is
refused with located errors (or a usage error naming the option), or when the output reads back in the
target, meets the controller's rules (grbl, grblHAL, LinuxCNC by ``rs274``), and verifies.
"""

from __future__ import annotations

import contextlib
import io

from hypothesis import strategies as st

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorList, UsageError
from postproc.lowering.arcs import parse_arc_option
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.verify import verify_lines
from postproc.transforms.spec import parse_transform

from ..fuzzing import NON_FINITE, located
from ..output_rules import problems
from ..tools import with_tools
from . import Case

KIND = "program options"
SOURCES = ("fanuc", "linuxcnc", "grbl", "mach3", "isg")
TARGETS = ("fanuc", "linuxcnc", "grbl", "grblhal", "mach3", "isg", "fagor")
"""Every mill writer (GSK writes lathes only)."""
TOLERANCE = 2e-3
"""mm: a rotated point is written to the output's decimals (4 of an inch: 1.27e-3 mm each way)."""
SETUP = with_tools()


def _num(lo: int, hi: int) -> st.SearchStrategy[str]:
    return st.integers(lo * 4, hi * 4).map(lambda v: f"{v / 4:.2f}")


@st.composite
def programs(draw: st.DrawFn) -> str:
    inch = draw(st.sampled_from([False, False, False, True]))
    lines = [("G20" if inch else "G21") + " G17 G90 G94", "G0 X0. Y0. Z10."]
    plane = "G17"
    for _ in range(draw(st.integers(2, 8))):
        kind = draw(st.sampled_from(["move", "move", "inc", "circle", "arc", "rarc", "plane", "cycle", "length",
                                     "comp", "offset", "machine", "dwell", "home"]))
        if kind == "move":
            lines.append(f"G90 G1 X{draw(_num(-40, 40))} Y{draw(_num(-40, 40))} Z{draw(_num(-5, 10))} F200.")
        elif kind == "inc":
            lines += [f"G91 G1 X{draw(_num(-10, 10))} Y{draw(_num(-10, 10))} F150.", "G90"]
        elif kind == "circle":
            i, j = draw(_num(-15, 15)), draw(_num(-15, 15))
            if float(i) == 0 and float(j) == 0:
                i = "5.00"
            a, b = {"G17": ("I", "J"), "G18": ("K", "I"), "G19": ("J", "K")}[plane]
            first = {"G17": "X", "G18": "Z", "G19": "Y"}[plane]  # an end point where it starts: grbl needs one
            lines += [f"G91 G{draw(st.sampled_from([2, 3]))} {first}0. {a}{i} {b}{j} F100.", "G90"]
        elif kind == "arc":
            r = draw(_num(2, 12))
            axes = {"G17": ("X", "Y", "I", "J", "Z"), "G18": ("Z", "X", "K", "I", "Y"),
                    "G19": ("Y", "Z", "J", "K", "X")}[plane]
            helix = draw(st.sampled_from(["", "", f" {axes[4]}{draw(_num(-2, 2))}"]))
            # a quarter circle in the plane, incremental, centre beside the start
            lines += [f"G91 G{draw(st.sampled_from([2, 3]))} {axes[0]}{r} {axes[1]}{r} {axes[2]}{r} {axes[3]}0.{helix} "
                      "F90.", "G90"]
        elif kind == "rarc":
            r = draw(_num(3, 20))
            sign = draw(st.sampled_from(["", "-"]))
            axes = {"G17": "XY", "G18": "ZX", "G19": "YZ"}[plane]
            lines += [f"G91 G{draw(st.sampled_from([2, 3]))} {axes[0]}{r} {axes[1]}{r} R{sign}{r} F90.", "G90"]
        elif kind == "plane":
            plane = draw(st.sampled_from(["G17", "G18", "G19"]))
            lines.append(plane)
        elif kind == "cycle":
            cycle = draw(st.sampled_from(["G81", "G83", "G82", "G73"]))
            extra = {"G81": "", "G83": " Q2.", "G82": " P500", "G73": " Q1."}[cycle]
            lines += ["G17 G90 G0 Z12.", f"{draw(st.sampled_from(['G98', 'G99']))} {cycle} X{draw(_num(-30, 30))} "
                      f"Y{draw(_num(-30, 30))} Z-3. R2.{extra} F100.", f"X{draw(_num(-30, 30))}", "G80", "G0 Z10."]
            plane = "G17"
        elif kind == "length":
            lines.append(draw(st.sampled_from(["G43 H01 Z10.", "G49", "G43 H02 Z15."])))
        elif kind == "comp":
            lines += ["G17 G0 Z5.", f"G41 D01 G1 X{draw(_num(-20, 20))} Y{draw(_num(-20, 20))} F100.",
                      f"X{draw(_num(-20, 20))}", "G40 G0 X0. Y0.", "G0 Z10."]
            plane = "G17"
        elif kind == "offset":
            lines.append(draw(st.sampled_from(["G54", "G55", "G54"])))
        elif kind == "machine":
            lines.append(f"G53 G0 Z{draw(_num(-5, 0))}")
        elif kind == "dwell":
            lines.append("G4 P1")
        else:
            lines.append("G28 Z20.")
    lines += ["G17 G90 G0 Z10.", "M30"]
    return "\n".join(lines) + "\n"


def spelled(source: str, program: str) -> str:
    """The program in ``source``'s words: ISG selects inch and mm with G70/G71 (its G20-G23 mirror), and dwells
    with ``G04 X`` (its ``P1`` is a parameter: ``G4 P1`` read an unset one, refused by every evaluation while an
    ISG copy passed it verbatim; make fuzz 'options isg-isg')."""
    if source == "isg":
        return program.replace("G20 ", "G70 ").replace("G21 ", "G71 ").replace("G4 P1\n", "G04 X1\n")
    return program


@st.composite
def transforms(draw: st.DrawFn) -> str | None:
    if draw(st.integers(0, 3)) == 0:
        return None
    ops = []
    for _ in range(draw(st.integers(1, 3))):
        kind = draw(st.sampled_from(["translate", "rotate", "mirror", "scale"]))
        if kind == "translate":
            ops.append(f"translate {draw(_num(-20, 20))},{draw(_num(-20, 20))}"
                       + draw(st.sampled_from(["", f",{draw(_num(-5, 5))}"])))
        elif kind == "rotate":
            plane = draw(st.sampled_from(["", "", " in xy", " in zx", " in yz"]))
            ops.append(f"rotate {draw(st.sampled_from(['90', '30', '-45', '180', '12.5']))}"
                       f"{draw(st.sampled_from(['', ' about 10,5']))}{plane}")
        elif kind == "mirror":
            axes = draw(st.sampled_from(["x", "y", "z", "xy"]))
            about = ",".join(["5"] * len(axes))
            ops.append(f"mirror {axes}{draw(st.sampled_from(['', ' about ' + about]))}")
        else:
            ops.append(f"scale {draw(st.sampled_from(['2', '0.5', '1.5,1.5,1', '2,1,1', '-1', '1,1,2']))}")
    return "; ".join(ops)


def check(source: str, target: str, program: str, units: str | None, how: str | None, arcs: str | None,
          setup: MachineSetup = SETUP) -> str:
    transform = parse_transform(how) if how else None
    arc_option = parse_arc_option(arcs) if arcs else None
    out = io.StringIO()
    try:
        translate(io.StringIO(program), out, file="in.nc", source=source, target=target, setup=setup,
                  units=units, transform=transform, arcs=arc_option, diagnostics=Diagnostics(warn_stream=io.StringIO()))
    except ErrorList as errs:
        for err in errs.errors:
            located(err)
        return "refused"
    except UsageError as err:
        return f"refused (usage): {err}"[:80]
    text = out.getvalue()
    bad = NON_FINITE.search(text)
    assert bad is None, f"non-finite number {bad.group(0)!r} in the output:\n{text}"
    refused = problems(target, text, setup, source=source)
    assert not refused, f"the {target} controller refuses the {target} output: {'; '.join(refused)}\n{text}"
    with contextlib.redirect_stderr(io.StringIO()):
        try:
            read_program(io.StringIO(text), file="out.nc", dialect=target, setup=setup)
        except ErrorList as errs:
            raise AssertionError(f"the {target} reader refuses the {target} output: {errs}\n{text}") from None
        try:
            report = verify_lines(io.StringIO(program), io.StringIO(text), file_in="in.nc", file_out="out.nc",
                                  source=source, target=target, setup=setup, tolerance=TOLERANCE,
                                  transform=transform,
                                  chord_tolerance=arc_option.tolerance if arc_option and arc_option.form == "lines"
                                  else None)
        except ErrorList as errs:
            raise AssertionError(f"translated, but verify fails: {errs}\n{text}") from None
    assert report.ok, f"translated, but verify says: {report.summary()}\n{text}"
    return "ok"


def _case(source: str, target: str, program: str, units: str | None, how: str | None, arcs: str | None,
          setup: MachineSetup = SETUP) -> Case:
    lathe = "lathe " if setup is not SETUP else ""
    return Case(f"options {lathe}{source}-{target}", target, program,
                lambda p: check(source, target, p, units, how, arcs, setup),
                f"--units {units} --transform {how!r} --arcs {arcs}")


def lathe_cases() -> st.SearchStrategy[Case]:
    """Fanuc T and GSK lathe programs (``lathe_threading``) with the options, to the lathe writers and
    LinuxCNC; transforms that keep the turning axis (along and across Z, scaled, mirrored in Z)."""
    from .lathe_threading import lathe_setup, programs as lathe_programs
    lathe_transforms = st.sampled_from([None, None, "translate 0,0,-5", "translate 2,0,3", "mirror z", "scale 2",
                                        "scale 1,1,0.5", "rotate 180 in zx", "mirror x"])
    return st.builds(lambda source, target, program, units, how, arcs:
                     _case(source, target, program, units, how, arcs, lathe_setup(source)),
                     st.sampled_from(["fanuc", "gsk"]), st.sampled_from(["linuxcnc", "fanuc", "gsk"]),
                     lathe_programs(), st.sampled_from([None, "mm", "inch"]), lathe_transforms,
                     st.sampled_from([None, None, "lines:0.01", "ijk", "r"]))


def cases() -> st.SearchStrategy[Case]:
    return st.one_of(mill_cases(), mill_cases(), lathe_cases())


def mill_cases() -> st.SearchStrategy[Case]:
    return st.builds(lambda source, target, program, *options: _case(source, target, spelled(source, program), *options),
                     st.sampled_from(SOURCES), st.sampled_from(TARGETS), programs(),
                     st.sampled_from([None, None, "mm", "inch"]), transforms(),
                     st.sampled_from([None, None, "lines:0.01", "lines:0.001", "ijk", "r"]))
