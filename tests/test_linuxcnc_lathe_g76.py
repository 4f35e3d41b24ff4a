"""LinuxCNC's own ``G76`` threading cycle read on a lathe set-up (``postproc_linuxcnc.threading``).

The oracle is rs274 2.9 in lathe mode: a seeded random differential of G76 blocks (outside and inside threads,
towards -Z and +Z, degression, compound angle, spring passes, entry and exit tapers, an end X, G91) read by our LinuxCNC dialect and
run by rs274, move by move (``tests/test_lathe_rs274``: end points as radii, the lead of each synchronised
move). One case is derived by hand from ``interp_convert.cc`` ``threading_pass``. A translation to Fanuc T and
to grblHAL writes the passes as thread moves and verifies at zero deviation; a LinuxCNC program keeps its G76.
"""

from __future__ import annotations

import io
import random
from pathlib import Path

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.setup.groups import ControllerSettings
from postproc.setup.machine_setup import load_setup
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available
from tests.test_lathe_rs274 import difference, ours, theirs

ROOT = Path(__file__).resolve().parents[1]
LATHE = load_setup(str(ROOT / "examples" / "setups" / "linuxcnc_lathe.xml"))
SEEDS = 40
HEAD = "G18 G7 G21 G90 G95\nS500 M3\nF0.2\n"


def moves_of(text: str) -> list[tuple[str, float, float]]:
    """Our moves as (kind, x radius, z)."""
    return [(m["move"], round(m["x"], 6), round(m["z"], 6)) for m in ours(text, "linuxcnc", LATHE)]


def errors(text: str) -> list[str]:
    with pytest.raises(ErrorList) as info:
        moves_of(text)
    return [str(e) for e in info.value.errors]


def test_the_passes_of_a_g76_as_threading_pass_makes_them() -> None:
    """From X30 (radius 15) Z2: I-2 (diameter: crest 1 below the drive line, radius 14), J0.4 (0.2), K1.6 (0.8),
    R1, Q0: passes at depth 1 + 0.2 n while short of the full depth 1.8: 1.2, 1.4, 1.6 (n = 1, 2, 3), then
    1.8 once. Each: rapid to X = 15 - (depth - 1.8) at Z2, in to 15 - depth, thread to Z-10, out; the end
    point (X30, Z-10) is where the last pass left the tool: no move."""
    found = moves_of(HEAD + "G0 X30. Z2.\nG76 P1.5 Z-10. I-2. J0.4 K1.6\nM2\n")
    expected: list[tuple[str, float, float]] = [("rapid", 15.0, 2.0)]
    for depth in (1.2, 1.4, 1.6, 1.8):
        back, cut = round(15 - (depth - 1.8), 6), round(15 - depth, 6)
        expected += [("rapid", back, 2.0), ("rapid", cut, 2.0), ("feed", cut, -10.0), ("rapid", back, -10.0)]
    assert found == expected


def _g76(rng: random.Random) -> str:
    """A G76 program of random words (the module docstring)."""
    inside = rng.random() < 0.3
    toward_plus = rng.random() < 0.25
    x = rng.choice((20.0, 24.0, 30.0)) if inside else rng.choice((30.0, 40.0, 52.0))
    z = -30.0 if toward_plus else rng.choice((2.0, 3.0, 5.0))
    end = rng.choice((0.0, 5.0)) if toward_plus else rng.choice((-10.0, -20.0, -40.0))
    j = rng.choice((0.1, 0.2, 0.3, 0.5))
    words = [f"P{rng.choice((1., 1.5, 2.))}", f"I{'' if inside else '-'}{rng.choice((0.5, 1., 2.))}", f"J{j}",
             f"K{round(j + rng.choice((0.3, 0.8, 1.3)), 3)}"]
    if rng.random() < 0.6:
        words.append(f"R{rng.choice((1., 1.5, 2., 3.))}")
    if rng.random() < 0.6:
        words.append(f"Q{rng.choice((0., 29.5, 30.))}")
    if rng.random() < 0.5:
        words.append(f"H{rng.choice((0, 1, 2))}")
    if rng.random() < 0.5:
        words.append(f"E{rng.choice((0.5, 1., 2.))} L{rng.choice((0, 1, 2, 3))}")
    incremental = rng.random() < 0.2
    if rng.random() < 0.4:
        words.append(f"X{x + (4 if not inside else -4):g}." if not incremental else "X2.")
    program = HEAD + f"G0 X{x:g}. Z{z:g}.\n"
    zword = f"Z{end - z:g}." if incremental else f"Z{end:g}."
    program += ("G91 " if incremental else "") + f"G76 {zword} " + " ".join(words) + "\n"
    return program + "G90 G1 X60. Z10.\nM2\n"


@pytest.mark.skipif(not available(), reason="the LinuxCNC interpreter rs274 is not installed")
@pytest.mark.parametrize("seed", range(SEEDS))
def test_g76_moves_as_rs274_runs_it(seed: int) -> None:
    program = _g76(random.Random(seed))
    problem = difference(ours(program, "linuxcnc", LATHE), theirs(program))
    assert problem is None, f"{problem}\n\n{program}"


@pytest.mark.parametrize("target,controller", [("fanuc", None), ("grblhal", ControllerSettings(spindle_sync=True))])
def test_g76_reaches_another_lathe_as_thread_moves_with_the_same_toolpath(target: str,
                                                                        controller: ControllerSettings | None) -> None:
    program = "G18 G7 G21 G90 G95\nS500 M3\nF0.2\nG0 X30. Z2.\nG76 P1.5 Z-10. I-2. J0.4 K1.6 Q29.5 H1 R2.\nG1 X40.\nM2\n"
    setup = load_setup(str(ROOT / "examples" / "setups" / "linuxcnc_lathe.xml"))
    if controller is not None:
        setup.controller = controller
    out = io.StringIO()
    translate(io.StringIO(program), out, file="in.ngc", source="linuxcnc", target=target, setup=setup,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    text = out.getvalue()
    assert not any("G76" in line for line in text.splitlines() if not line.startswith("("))
    assert ("G32 " if target == "fanuc" else "G33 ") in text
    assert text.splitlines()[-3:] == ["F0.2", "G01 X40." if target == "fanuc" else "G1 X40.",
                                      "M02" if target == "fanuc" else "M2"]  # the feed rate in force put back
    report = verify_lines(io.StringIO(program), io.StringIO(text), file_in="in.ngc", file_out="out.nc",
                          source="linuxcnc", target=target, setup=setup, tolerance=0.0)
    assert report.ok and report.max_deviation == 0.0, report.summary() + "\n" + text


def test_a_linuxcnc_program_keeps_its_g76() -> None:
    program = HEAD + "G0 X30. Z2.\nG76 P1.5 Z-10. I-2. J0.4 K1.6 Q29.5 H1 R2.\nM2\n"
    out = io.StringIO()
    translate(io.StringIO(program), out, file="in.ngc", source="linuxcnc", target="linuxcnc", setup=LATHE)
    assert out.getvalue() == program


@pytest.mark.parametrize("block,message", [
    ("G76 Z-10. I-2. J0.4 K1.6", "5:1: error: G76 needs P, the thread pitch"),
    ("G76 P1.5 Z-10. I-2. J0.4 K0.4", "5:26: error: In G76, K must be greater than J"),
    ("G76 P1.5 Z-10. I0 J0.4 K1.6", "5:16: error: In G76, I must not be 0"),
    ("G76 P1.5 Z-10. I-2. J0.4 K1.6 E2. L4", "5:35: error: G76 L says which ends are tapered: 0 to 3"),
    ("G76 P1.5 Z-10. I-2. J0.4 K1.6 H1.5", "5:31: error: address H takes a whole number"),
])
def test_what_g76_needs_or_this_reader_does_not_model_is_refused(block: str, message: str) -> None:
    found = errors(HEAD + "G0 X30. Z2.\n" + block + "\nM2\n")
    assert len(found) == 1 and found[0].startswith("prog:" + message), found


def test_a_g76_repeated_by_axis_words_alone_is_refused() -> None:
    """rs274 runs G76 again for a later block of axis words (G76 stays the motion mode): not modelled."""
    found = errors(HEAD + "G0 X30. Z2.\nG76 P1.5 Z-10. I-2. J0.4 K1.6\nZ-5.\nM2\n")
    assert found and found[0].startswith("prog:6:"), found


@pytest.mark.parametrize("head,block", [("", ""), ("S500 M3\n", " M5")])
def test_g76_needs_a_turning_spindle(head: str, block: str) -> None:
    """rs274: "Chosen spindle (0) not turning in G76"; an M5 in the block stops the spindle before the motion."""
    found = errors("G18 G7 G21 G90 G95\n" + head + "F0.2\nG0 X30. Z2.\nG76 P1.5 Z-10. I-2. J0.4 K1.6" + block + "\nM2\n")
    assert found and "spindle stopped" in found[0], found


@pytest.mark.parametrize("words", ["J0.0001 K1.6 R30.", "J0.4 K1.6 H1000000000"])
def test_passes_are_bounded(words: str) -> None:
    found = errors(HEAD + "G0 X30. Z2.\nG76 P1.5 Z-10. I-2. " + words + "\nM2\n")
    assert found and "more" in found[0], found
