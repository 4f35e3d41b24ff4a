"""Cutter compensation started after a hole cycle (issue 26, ``make fuzz`` case 006): the resolver must start
from where the cycle left the tool, whether the target keeps the cycle native (grblHAL's G81/G82, LinuxCNC's
cycles) or expands it (grbl). It did not follow a cycle kept native: the start-up after ``G81 X10. Y2. ...`` was
computed from Y0 and written ``G1 X0. Y0.`` (2 mm off, exit 0). The same for the tool length timing: a ``G43``
alone after a native ``G99`` cycle got the Z from before the cycle.

Independent checks: the start-up point derived by hand from the source's rules (``CutterRules`` ``FANUC_A``,
``entry="perpendicular"`` [K: Fanuc 15.6.2 type A]: the start-up move ends one radius beside the start of the
*next* move, square to it; G42 on its right, G41 on its left), and the source's own simulation (``verify`` at
zero deviation, which runs the Fanuc program with its cycles and compensation); the differential between a
target that keeps the cycle native and one that expands it (their compensated toolpaths, read back, equal).
"""

from __future__ import annotations

import io
import re
from dataclasses import dataclass

import pytest
from hypothesis import assume, given, settings
from hypothesis import strategies as st

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.simulate.verify import verify_lines
from tests.support.tools import with_tools

RADII = {1: 1.0, 2: 2.0}
SETUP = with_tools(lengths={1: 100.0}, radii=RADII)
"""Tool 1 radius 1 (length 100), tool 2 radius 2."""
LOST = "the start point of a compensated move is not known"


def _translate(text: str, target: str) -> str:
    out = io.StringIO()
    translate(io.StringIO(text).readlines(), out, file="t.nc", source="fanuc", target=target, setup=SETUP,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def _verify(text: str, out: str, source: str, target: str) -> None:
    report = verify_lines(io.StringIO(text), io.StringIO(out), file_in="t.nc", file_out="o", source=source,
                          target=target, setup=SETUP)
    assert report.ok and report.max_deviation == 0, (text, out, report.summary())


def _number(value: float) -> str:
    """A number as the RS274 writers spell it (``2.``, ``-2.5``)."""
    text = f"{value:.3f}".rstrip("0")
    return "0." if text in ("-0.", "0.") else text


# -- the fuzz case, by hand ---------------------------------------------------------------------------------
CASE = "G21 G90 G17 G0 X0 Y0 Z10.\nG81 X10. Y2. Z-2.5 R2. F250.\nG80\nG42 D2 G1 X0. F100.\nY20.\nG40 G0 X-10.\nM30\n"


@pytest.mark.parametrize("target", ["grblhal", "grbl", "linuxcnc"])
def test_the_start_up_after_a_cycle_starts_at_its_last_hole(target: str) -> None:
    """Hand-derived: the G81 leaves the tool over its hole, X10 Y2, at the initial level Z10 (G98, the default).
    The start-up ``G42 D2 G1 X0.`` runs from (10, 2) to (0, 2); the next move goes +Y, so under type A the tool
    ends one radius (2) on its right, +X: (2, 2); the next move then runs to (2, 20), and the cancel ``G40 G0
    X-10.`` goes to the programmed (-10, 20). grblHAL keeps the G81 (native), grbl expands it, LinuxCNC keeps
    it and tries the stretch under its own rules (they differ: written as moves)."""
    out = _translate(CASE, target)
    if target == "grblhal":
        assert "G81 X10. Y2." in out, out  # kept native: the case the resolver did not follow
    assert not re.search(r"\bG4[12]\b", out), out
    assert "G1 X2. Y2. F100." in out and "G1 X2. Y20." in out and "G0 X-10. Y20." in out, out
    _verify(CASE, out, "fanuc", target)


def test_a_repeat_of_the_cycle_moves_the_start_too() -> None:
    """Hand-derived: the repeat ``X30. Y5.`` drills a second hole there (G81 modal), so the start-up ``G41 D1
    G1 X50.`` runs from (30, 5) to (50, 5); the next move goes -Y, the tool ends one radius (1) on its left, +X:
    (51, 5), then (51, -10)."""
    text = ("G21 G90 G17 G0 X0 Y0 Z10.\nG81 X10. Y2. Z-2.5 R2. F250.\nX30. Y5.\nG80\nG41 D1 G1 X50. F100.\n"
            "Y-10.\nG40 G0 X70.\nM30\n")
    out = _translate(text, "grblhal")
    assert "G81 X10. Y2." in out and "\nX30. Y5.\n" in out, out
    assert "G1 X51. Y5. F100." in out and "G1 X51. Y-10." in out, out
    _verify(text, out, "fanuc", "grblhal")


def test_a_length_change_after_a_native_g99_cycle_gets_its_r_level() -> None:
    """Hand-derived: ``G99 G81 ... R2.`` leaves Z at R, 2 (not at the initial 50). Fanuc applies ``G43 H1``
    written alone at the next move; grblHAL applies a length where Z is programmed, so the move gets the Z the
    program stands at: ``G1 X20. Z2.`` (was ``Z50.``, 48 mm off, exit 0)."""
    text = "G21 G90 G17 G0 X0 Y0 Z50.\nG99 G81 X10. Y2. Z-2.5 R2. F250.\nG80\nG43 H1\nG1 X20. F100.\nM30\n"
    out = _translate(text, "grblhal")
    assert "G99 G81 X10. Y2." in out and "G1 X20. Z2. F100." in out, out
    _verify(text, out, "fanuc", "grblhal")


def test_a_length_change_waiting_over_a_native_cycle_is_refused() -> None:
    """LinuxCNC applies a length change where Z is next programmed absolutely, Mach3 (as Fanuc) at the next
    move: a ``G43`` alone before a cycle Mach3 keeps native (both RS274/NGC cycles) is a located error, as before
    an expanded one (the positioning runs at the old length on one, at the new on the other). It was written
    ``G43 H01`` beside the next move after the cycle, 100 mm off at the cycle, exit 0."""
    text = "G21 G90 G17 G0 X0 Y0 Z50.\nG43 H1\nG81 X10. Y2. Z-2.5 R2. F250.\nG80\nG1 X20. Z5. F100.\nM30\n"
    out = io.StringIO()
    with pytest.raises(ErrorList) as info:
        translate(io.StringIO(text).readlines(), out, file="t.nc", source="linuxcnc", target="mach3", setup=SETUP,
                  diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    messages = [str(e) for e in info.value.errors]
    assert messages == ["t.nc:3:1: error: a canned cycle while a tool length change waits for the next absolute Z (the "
                        "source applies it there, the target at its next move): program Z beside the length change"], \
        messages


def test_an_arc_after_a_native_cycle_is_settled_from_its_last_hole() -> None:
    """grblHAL refuses an R arc whose chord the writer's and its own rounding may put over 2R, so the settle pass
    writes such an arc by I/J (``Dialect.R_ARC_FLOAT_SLACK``), which needs its start. Hand-derived: the G81
    leaves the tool over (10, 2); ``G2 X10. Y22. R10.`` is a half circle about the chord's midpoint (10, 12):
    I0 J10. The pass did not follow the native cycle and wrote the R arc as it was."""
    text = "G21 G90 G17 G0 X0 Y0 Z10.\nG81 X10. Y2. Z-2.5 R2. F250.\nG80\nG1 Z0. F100.\nG2 X10. Y22. R10.\nM30\n"
    out = _translate(text, "grblhal")
    assert "G81 X10. Y2." in out and "G2 X10. Y22. I0. J10." in out, out
    _verify(text, out, "fanuc", "grblhal")


@pytest.mark.parametrize("target", ["grblhal", "grbl"])
def test_a_length_change_beside_a_cycle_is_refused_whether_kept_or_expanded(target: str) -> None:
    """Fanuc applies ``G43 H1`` beside ``G81`` at the cycle's first move (its positioning at the initial level),
    grbl and grblHAL where Z is next programmed (the R level): the machine's Z differs during the positioning,
    so the change is a located error at its block for both; grblHAL, which keeps the G81, had the change carried
    to the move after the cycle (100 mm off during it, exit 0)."""
    text = "G21 G90 G17 G0 X0 Y0 Z50.\nG43 H1 G81 X10. Y2. Z-2.5 R2. F250.\nG80\nG1 X20. F100.\nM30\n"
    with pytest.raises(ErrorList) as info:
        _translate(text, target)
    messages = [str(e) for e in info.value.errors]
    assert len(messages) == 1 and messages[0].startswith("t.nc:2:") and "tool length change" in messages[0], messages


def test_a_tap_cycle_made_at_the_spot_ends_where_it_started() -> None:
    """A LinuxCNC rigid tap ``G33.1`` becomes a tap cycle at the spot for SINUMERIK (``CYCLE84``: a record with no
    hole position, made by a lowering step); G33.1 leaves the tool where it was [V: LinuxCNC ``interp_convert.cc``,
    ``synchronised_tap``'s docstring], so the point after it is where it stood: the drilling axis at the cycle's
    R level (its start), X and Y unchanged. The translation runs through the steps that follow the point
    without a traceback (``cycle_end`` raised ``KeyError: 'X'`` on the record), and cuts the source's path."""
    text = "G21 G90 G17 G0 X0 Y0 Z1\nS1000 M3\nG33.1 Z-1.2 K0.1\nG41 D1 G1 X10 F100\nY10\nG40 G0 X20\nM2\n"
    out = io.StringIO()
    translate(io.StringIO(text).readlines(), out, file="t.ngc", source="linuxcnc", target="siemens", setup=SETUP,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    assert "CYCLE84(" in out.getvalue(), out.getvalue()
    report = verify_lines(io.StringIO(text), io.StringIO(out.getvalue()), file_in="t.ngc", file_out="o",
                          source="linuxcnc", target="siemens", setup=SETUP, allow_ignored=True)
    assert report.ok and report.max_deviation == 0, report.summary()


# -- the differential --------------------------------------------------------------------------------------
CYCLES = {"G73": "Q1.", "G74": "", "G81": "", "G82": "P300", "G83": "Q1.5", "G84": "", "G85": "", "G86": "",
          "G88": "P300", "G89": "P300"}
"""Fanuc's hole cycles and the words each needs besides the hole and its levels. Not G76/G87: they need an
oriented spindle stop, which grbl has not (an operator's stop, ``<Cycles orientation="stop">``, is another
structure to ``verify``)."""
BETWEEN = {"": "", "G28 Z20.": "Z", "G91 G28 Z0.\nG90": "Z", "G53 Z0.": "Z", "G28 X0. Y0.": "XY", "G53 X0. Y0.": "XY"}
"""A block between the cycle and what follows, and the axes it leaves at a machine position (not known in work
coordinates: a start-up from there, or a length change's Z, is a located error)."""
LENGTH_LOST = "the programmed Z is not known where it applies"
ENTRY_X = 60.0


def _coordinate(low: float, high: float) -> st.SearchStrategy[float]:
    return st.integers(int(low * 2), int(high * 2)).map(lambda n: n / 2)


@dataclass
class Drawn:
    text: str
    start: tuple[float, float]
    """Where the start-up move starts, by hand: the last hole (the cycles end over it)."""
    corner: tuple[float, float]
    """Where it ends, by hand (type A): beside the next move's start, square to it."""
    lost: bool
    """The block between leaves X and Y at a machine position (for a length change: Z)."""
    level: float
    """Where the cycle left Z, by hand: the initial level (G98) or R (G99)."""


@st.composite
def programs(draw: st.DrawFn, tail: str = "compensation") -> Drawn:
    """A cycle, perhaps a block between, then a compensated stretch (or a tool length change alone and a move:
    ``tail="length"``)."""
    code = draw(st.one_of(st.sampled_from(["G81", "G82"]), st.sampled_from(sorted(CYCLES))))  # half: grblHAL's own
    incremental = draw(st.booleans())
    initial = draw(_coordinate(5, 15))
    r = draw(_coordinate(0.5, 4))
    bottom = draw(_coordinate(-8, -1))
    x, y = draw(_coordinate(-20, 30)), draw(_coordinate(-20, 20))
    lines = [f"G21 G90 G17 G0 X0 Y0 Z{_number(initial)}", "S1000 M4" if code == "G74" else "S1000 M3"]
    mode = draw(st.sampled_from(["G98", "G99"]))
    count = draw(st.sampled_from([None, 1, 2, 3]))
    step = (draw(_coordinate(-5, 5)), draw(_coordinate(-5, 5))) if incremental else (0.0, 0.0)
    here = (x, y)
    levels = (f"Z{_number(bottom - r)} R{_number(r - initial)}" if incremental
              else f"Z{_number(bottom)} R{_number(r)}")
    words = f"X{_number(step[0] if incremental else x)} Y{_number(step[1] if incremental else y)}"
    if incremental:
        lines.append(f"G0 X{_number(x - step[0])} Y{_number(y - step[1])}")  # the first hole one step on
    extra = CYCLES[code]
    k = "" if count is None else f" K{count}"
    lines.append(f"{'G91 ' if incremental else ''}{mode} {code} {words} {levels} {extra} F200.{k}".replace("  ", " "))
    if incremental:
        here = (x + step[0] * ((count or 1) - 1), y + step[1] * ((count or 1) - 1))
    for _ in range(draw(st.integers(0, 2))):
        nx, ny = draw(_coordinate(-20, 30)), draw(_coordinate(-20, 20))
        if incremental:
            lines.append(f"X{_number(nx - here[0])} Y{_number(ny - here[1])}")
        else:
            lines.append(f"X{_number(nx)} Y{_number(ny)}")
        here = (nx, ny)
    lines += ["G80", "G90"]
    between = draw(st.sampled_from(sorted(BETWEEN)))
    if between:
        lines.append(between)
    level = initial if mode == "G98" else r
    if tail == "length":
        lines += ["G43 H1", f"G1 X{_number(ENTRY_X)} F100.", "M30"]
        return Drawn("\n".join(lines) + "\n", here, (ENTRY_X, here[1]), BETWEEN[between] == "Z", level)
    side, register = draw(st.sampled_from(["G41", "G42"])), draw(st.sampled_from([1, 2]))
    named_y = draw(st.booleans())
    entry_y = draw(_coordinate(-10, 10)) if named_y else here[1]
    lines.append(f"{side} D{register} G1 X{_number(ENTRY_X)}{f' Y{_number(entry_y)}' if named_y else ''} F100.")
    lines += [f"Y{_number(entry_y + 30)}", "X80.", f"G40 G0 X100. Y{_number(entry_y + 50)}", "M30"]
    radius = RADII[register]
    corner = (ENTRY_X + radius if side == "G42" else ENTRY_X - radius, entry_y)  # beside the +Y move's start
    return Drawn("\n".join(lines) + "\n", here, corner, BETWEEN[between] == "XY", level)


@settings(max_examples=60, deadline=None)
@given(drawn=programs())
def test_native_and_expanded_cycles_leave_the_same_start_up(drawn: Drawn) -> None:
    """Random Fanuc cycles (every hole cycle, G98/G99, K counts, G91 rows, repeat blocks), then perhaps a
    reference return or a machine move, then a compensated stretch: grblHAL (G81/G82 native where they move as
    Fanuc's), grbl (every cycle expanded) and LinuxCNC (native, its rules tried) write the start-up at the point
    derived by hand from the last hole, and cut the source's simulated path; their toolpaths equal each other.
    Where the block between left X and Y at a machine position, every target refuses the start-up at its line."""
    text = drawn.text
    outputs: dict[str, str] = {}
    for target in ("grblhal", "grbl", "linuxcnc"):
        try:
            outputs[target] = _translate(text, target)
        except ErrorList as err:
            messages = [str(e) for e in err.errors]
            assert drawn.lost and any(LOST in m for m in messages), (target, text, messages)
            continue
        assert not drawn.lost, (target, text, outputs[target])
    if drawn.lost:
        assert not outputs, outputs
        return
    assume(abs(drawn.start[0] - ENTRY_X) > 1e-9 or abs(drawn.start[1] - drawn.corner[1]) > 1e-9)
    corner = f"G1 X{_number(drawn.corner[0])} Y{_number(drawn.corner[1])} F100."
    for target in ("grblhal", "grbl"):
        assert corner in outputs[target], (target, text, outputs[target])
        _verify(text, outputs[target], "fanuc", target)
    _verify(text, outputs["linuxcnc"], "fanuc", "linuxcnc")
    _verify(outputs["grbl"], outputs["grblhal"], "grbl", "grblhal")


@settings(max_examples=40, deadline=None)
@given(drawn=programs(tail="length"))
def test_a_length_change_after_a_cycle_gets_its_return_level(drawn: Drawn) -> None:
    """The same random cycles, then ``G43 H1`` alone and a move: Fanuc applies it at that move, grbl and grblHAL
    where Z is programmed, so the move gets the Z the cycle left, derived by hand (the initial level under G98,
    R under G99), whether the cycle was kept (grblHAL) or expanded (grbl); both cut the source's simulated path.
    Where the block between left Z at a machine position, both refuse the change at its line."""
    text = drawn.text
    move = f"G1 X{_number(ENTRY_X)} Z{_number(drawn.level)} F100."
    for target in ("grblhal", "grbl"):
        try:
            out = _translate(text, target)
        except ErrorList as err:
            messages = [str(e) for e in err.errors]
            assert drawn.lost and len(messages) == 1 and LENGTH_LOST in messages[0], (target, text, messages)
            continue
        assert not drawn.lost, (target, text, out)
        assert move in out and "G43.1 Z100." in out, (target, text, out)
        _verify(text, out, "fanuc", target)


def test_an_incremental_row_ends_at_its_last_hole() -> None:
    """Hand-derived: ``G91 G81 X5. Y1. Z-7.5 R-8. K3`` from (0, 0), Z10: Fanuc's G91 R is the distance from the
    initial level (R at 2), Z the distance from R (the bottom at -5.5); three holes one step apart, (5, 1),
    (10, 2), (15, 3), the tool over the last at Z10 (G98). The start-up ``G42 D2 G1 X60.`` runs from (15, 3);
    the next move goes +Y, so the tool ends on its right: (62, 3)."""
    text = ("G21 G90 G17 G0 X0 Y0 Z10.\nG91 G81 X5. Y1. Z-7.5 R-8. K3 F250.\nG80\nG90\nG42 D2 G1 X60. F100.\n"
            "Y30.\nX80.\nG40 G0 X100. Y50.\nM30\n")
    for target in ("grblhal", "grbl"):
        out = _translate(text, target)
        assert "G1 X62. Y3. F100." in out, (target, out)
        _verify(text, out, "fanuc", target)
