"""ISG declarations and arithmetic: the inputs that found issue #31's items 5 and 14.

* ISG programs with a ``#VAR`` block declaring variables of every data type (with and without initial
  values, some a type cannot hold), ``EXIST[..]`` and ``TRUE``/``FALSE`` in ``$IF``, P parameters computed
  with trigonometry at exact angles, and no-break spaces (U+00A0) where blanks were: translated to ISG
  (byte for byte), Fanuc and LinuxCNC with the usual checks, and simulated; a program with no-break spaces
  must move as the same program with blanks.
* LinuxCNC programs whose words are SIN/COS/TAN/ASIN/ACOS/ATAN at exact angles, FIX/FUP/ROUND of them and
  comparisons with 0: simulated, and compared move by move with ``rs274`` when it is installed.
"""

from __future__ import annotations

import io
import math

from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorList, PostprocError
from postproc.setup.machine_setup import MachineSetup
from postproc.simulate.toolpath import toolpath_events
from tests.support.fuzzing import check_toolpath, check_translation, located
from tests.support.generators import Case
from tests.support.rs274 import RS274Error, available, canonical_moves, run_rs274
from tests.support.tools import with_tools

KIND = "isg declarations and arithmetic"

NBSP = "\u00a0"
SETUP = with_tools()
ANGLES = [0, 30, 45, 60, 90, 120, 135, 180, 225, 270, 300, 360, 450, 540, 720, -30, -90, -180, -270, -360]
TYPES = ["", " : REAL64", " : REAL", " : BOOLEAN", " : SGN08", " : UNS08", " : SGN16", " : UNS16", " : SGN32",
         " : UNS32", " : STRING[20]"]
INITIAL = ["", " = 0", " = 1", " = 10", " = 2.5", " = -1", " = 127", " = 128", " = 255", " = 256", " = TRUE",
           " = FALSE", ' = "PLATE"', " = 4294967295"]


@st.composite
def _isg_program(draw: st.DrawFn) -> str:
    names = [f"V.{draw(st.sampled_from('PLS'))}.V{i}" for i in range(draw(st.integers(1, 4)))]
    lines = ["%fuzz", "G71 G90 G00 X0 Y0 Z10 F100", "#VAR"]
    lines += [f"  {n}{draw(st.sampled_from(TYPES))}{draw(st.sampled_from(INITIAL))}" for n in names]
    lines += ["#ENDVAR", "P1 = 0", "P2 = 0"]
    for _ in range(draw(st.integers(1, 6))):
        kind = draw(st.sampled_from(["trig", "move", "exist", "assign", "round"]))
        name = draw(st.sampled_from(names))
        angle = draw(st.sampled_from(ANGLES))
        function = draw(st.sampled_from(["SIN", "COS", "TAN"]))
        if kind == "trig":
            lines.append(f"P{draw(st.integers(1, 3))} = {function}[{angle}] * {draw(st.sampled_from([1, 10, 1000]))}")
        elif kind == "move":
            lines.append(f"G01 X[{name}] Y[P1 + 0 * P2] Z[{function}[{angle}]]")
        elif kind == "exist":
            lines += [f"$IF EXIST[{name}] == {draw(st.sampled_from(['TRUE', 'FALSE']))}", "G01 X1 Y2",
                      "$ENDIF"]
        elif kind == "assign":
            lines.append(f"{name} = {name} + {draw(st.sampled_from(['1', '0.5', '-200', 'INT[SIN[' + str(angle) + ']]']))}")
        else:
            lines.append(f"G01 X[ROUND[{function}[{angle}] * 1000] + INT[COS[{angle}]]]")
    lines.append("M30")
    text = "\n".join(lines) + "\n"
    if draw(st.booleans()):
        spaces = [i for i, c in enumerate(text) if c == " "]
        chosen = draw(st.sets(st.sampled_from(spaces), max_size=6)) if spaces else set()
        text = "".join(NBSP if i in chosen else c for i, c in enumerate(text))
    return text


def _isg_run(target: str) -> object:
    def run(program: str) -> str:
        if target == "isg":
            out = io.StringIO(newline="")
            try:
                translate(io.StringIO(program, newline=""), out, file="fuzz.nc", source="isg", target="isg",
                          setup=SETUP, diagnostics=Diagnostics(warn_stream=io.StringIO()))
            except ErrorList as errs:
                for err in errs.errors:
                    located(err)
                return "refused"
            assert out.getvalue() == program, f"isg -> isg is not byte for byte:\n{out.getvalue()}"
            _same_moves_with_blanks(program)
            check_toolpath("isg", program, SETUP)
            return "ok"
        return check_translation("isg", target, program, SETUP, False)
    return run


def _moves(program: str, dialect: str) -> list[dict[str, object]] | None:
    try:
        return [e for e in toolpath_events(io.StringIO(program, newline=""), file="fuzz.nc", dialect=dialect,
                                           setup=SETUP, diagnostics=Diagnostics(warn_stream=io.StringIO()))
                if "move" in e]
    except ErrorList as errs:
        for err in errs.errors:
            located(err)
        return None
    except PostprocError as err:
        located(err)
        return None


def _same_moves_with_blanks(program: str) -> None:
    if NBSP not in program:
        return
    with_nbsp = _moves(program, "isg")
    blanks = _moves(program.replace(NBSP, " "), "isg")
    assert with_nbsp == blanks, f"no-break spaces move the tool otherwise than blanks:\n{with_nbsp}\n{blanks}"


@st.composite
def _ngc_program(draw: st.DrawFn) -> str:
    lines = ["G21 G90 G17"]
    for _ in range(draw(st.integers(1, 6))):
        words = []
        for axis in "XYZ":
            angle = draw(st.sampled_from(ANGLES))
            unit = draw(st.sampled_from(["1", "0.5", "-1", "0", "0.7071067811865476"]))
            words.append(axis + draw(st.sampled_from([
                f"[FIX[SIN[{angle}]]]", f"[FUP[COS[{angle}]]]", f"[FIX[TAN[{angle}]]]", f"[[COS[{angle}] LT 0]*5]",
                f"[[SIN[{angle}] GT 0]*5]", f"[ROUND[SIN[{angle}]*1000]/100]", f"[SIN[{angle}]*10]",
                f"[FIX[ASIN[{unit}]]]", f"[FUP[ACOS[{unit}]]/10]", f"[FIX[ATAN[{unit}]/[1]]]",
                f"[[SIN[{angle}] EQ 0]*3]", f"[FIX[SIN[{angle}]*SIN[{angle}]*2]]"])))
        lines.append(draw(st.sampled_from(["G0", "G1 F100"])) + " " + " ".join(words))
    lines.append("M2")
    return "\n".join(lines) + "\n"


def _ngc_run(program: str) -> str:
    ours = _moves(program, "linuxcnc")
    if not available():
        return "refused" if ours is None else "ok"
    try:
        theirs = [e for e in canonical_moves(run_rs274(program), start=(0.0, 0.0, 0.0)) if "move" in e]
    except RS274Error:
        return "refused"
    if ours is None:
        return "refused"
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in rs274:\n{ours}\n{theirs}"
    for a, b in zip(ours, theirs):
        deviation = max(abs(float(a[k]) - float(b[k])) for k in "xyz")  # type: ignore[arg-type]
        assert a["move"] == b["move"] and deviation <= 2e-4 and not math.isnan(deviation), \
            f"postproc {a} but rs274 {b}"
    return "ok"


def cases() -> st.SearchStrategy[Case]:
    isg = st.builds(lambda program, target: Case(f"isg declarations isg-{target}", target, program,
                                                 _isg_run(target)),  # type: ignore[arg-type]
                    _isg_program(), st.sampled_from(["isg", "isg", "fanuc", "linuxcnc"]))
    ngc = _ngc_program().map(lambda program: Case("linuxcnc trig against rs274", "linuxcnc", program, _ngc_run))
    return st.one_of(isg, ngc)
