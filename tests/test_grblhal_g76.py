"""grblHAL's own ``G76`` threading cycle, read in lathe mode (``plugins/grblhal/postproc_grblhal/threading.py``).

Expected moves are derived by hand from grblHAL core's ``motion_control.c`` ``mc_thread`` and ``gcode.c`` (stored
commit f80fc34), as the module docstring states them; no other interpreter runs grblHAL's cycle (LinuxCNC's G76
retracts differently, so rs274 is the oracle only of the translation: the G33 passes written for LinuxCNC run in
rs274 with the moves simulated from the grblHAL source). A grblHAL program keeps its G76 line.
"""

from __future__ import annotations

import io
import math
import random

import pytest

from postproc.api import translate
from postproc.errors import Diagnostics, ErrorLevel, ErrorList
from postproc.setup.groups import ControllerSettings
from postproc.setup.machine_setup import InputSettings, MachineSetup
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines
from tests.support.rs274 import available
from tests.test_lathe_rs274 import difference, ours, theirs

BUILD = ControllerSettings(tool_table=True, spindle_sync=True)
LATHE = MachineSetup(input=InputSettings(machine_type="lathe"), controller=BUILD)
HEAD = "G18 G7 G21 G90 G95\nS500 M3\nF0.2\n"


def moves(text: str, setup: MachineSetup = LATHE) -> list[tuple[str, float, float, float | None]]:
    """The simulated moves as (kind, X diameter, Z, the feed: a synchronised move's lead along its major axis)."""
    found = []
    for ev in toolpath_events(io.StringIO(text), file="in.nc", dialect="grblhal", setup=setup):
        if "move" in ev:
            feed = None if ev["move"] == "rapid" else round(ev["f"], 6)
            found.append((ev["move"], round(ev["x"], 6), round(ev["z"], 6), feed))
    return found


def write(text: str, target: str, setup: MachineSetup = LATHE) -> str:
    out = io.StringIO()
    translate(io.StringIO(text), out, file="in.nc", source="grblhal", target=target, setup=setup,
              diagnostics=Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO()))
    return out.getvalue()


def errors(text: str, setup: MachineSetup = LATHE) -> list[str]:
    with pytest.raises(ErrorList) as info:
        moves(text, setup)
    return [str(e) for e in info.value.errors]


def test_the_passes_by_hand() -> None:
    """From X20 (radius 10) Z2, ``G76 P1.5 Z-10. I-1. J0.4 K1.2 H1``: crest 0.5 below the drive line (radius), J
    0.2, K 0.6, R 1: pass n cuts 0.2 n beyond the crest, so 0.2, 0.4, 0.6 (the third reaches K), then one spring
    pass at 0.6. A pass: rapid in to 10 - (0.5 + depth), thread to Z-10 at 1.5 per revolution; then, before the
    next pass, rapid out to 10 + (0.6 - the next depth) and back to Z2; after the last, rapid to the drive line
    at Z-10, where the tool stays (the G0 X30. after it starts there)."""
    found = moves(HEAD + "G0 X20. Z2.\nG76 P1.5 Z-10. I-1. J0.4 K1.2 H1\nG0 X30.\nM2\n")
    cut, back = (18.6, 18.2, 17.8, 17.8), (20.4, 20.0, 20.0)
    expected: list[tuple[str, float, float, float | None]] = [("rapid", 20.0, 2.0, None)]
    for n in range(4):
        expected += [("rapid", cut[n], 2.0, None), ("feed", cut[n], -10.0, 1.5)]
        if n < 3:
            expected += [("rapid", back[n], -10.0, None), ("rapid", back[n], 2.0, None)]
    expected += [("rapid", 20.0, -10.0, None), ("rapid", 30.0, -10.0, None)]
    assert found == expected


def test_compound_angle_and_entry_taper_by_hand() -> None:
    """``G76 P1. Z-10. I-1. J0.4 K0.8 Q45. E1. L1`` from X20 Z2: radius crest 0.5, J 0.2, K 0.4: passes at 0.2 and
    0.4. Q45 (tan 1): the passes start at Z 2 + (0.4 - depth): a first rapid to Z2.2. The entry taper (L1, E1):
    each pass comes in K short of its depth, then synchronised 0.4 deeper over 1 along -Z (path sqrt(1.16) per 1
    of Z: a lead along Z of 1 / sqrt(1.16)), then along Z to the end minus the start's offset (the thread is
    12 long less the taper: 11). Pass 1: in to 10 - 0.3 = 9.7 (X19.4) at Z2.2, to 9.3 (X18.6) at Z1.2, to Z-9.8;
    out to 10 + (0.4 - 0.4) (X20), back to Z 2.4 - 0.4 = 2. Pass 2 (the last): in to 9.5 (X19) at Z2, to 9.1
    (X18.2) at Z1, to Z-10; out to X20."""
    taper = round(1.0 / math.sqrt(1.16), 6)
    found = moves(HEAD + "G0 X20. Z2.\nG76 P1. Z-10. I-1. J0.4 K0.8 Q45. E1. L1\nM2\n")
    assert found == [
        ("rapid", 20.0, 2.0, None), ("rapid", 20.0, 2.2, None),
        ("rapid", 19.4, 2.2, None), ("feed", 18.6, 1.2, taper), ("feed", 18.6, -9.8, 1.0),
        ("rapid", 20.0, -9.8, None), ("rapid", 20.0, 2.0, None),
        ("rapid", 19.0, 2.0, None), ("feed", 18.2, 1.0, taper), ("feed", 18.2, -10.0, 1.0),
        ("rapid", 20.0, -10.0, None)]


def test_a_bore_toward_plus_z_with_an_exit_taper() -> None:
    """An inside thread (I positive: cut towards +X) running towards +Z, ``G76 P2. Z10. I1. J0.5 K1. E2. L2`` from
    X20 Z-10 (radius 10): crest 0.5 above, J 0.25, K 0.5: passes at 0.25 and 0.5. The thread runs +Z, so the
    exit taper's length is negated and the thread is 20 - 2 = 18 along Z before it: pass 1 in to 10.75 (X21.5),
    to Z8, out over 2 along +Z and 0.5 in X to 10.25 (X20.5) at Z10; then out to 10 - (0.5 - 0.5) (X20) and back
    to Z-10. Pass 2: in to 11 (X22), to Z8, to 10.5 (X21) at Z10, out to X20."""
    taper = round(2.0 * 2.0 / math.hypot(2.0, 0.5), 6)  # 2 along the path per revolution: along Z
    found = moves(HEAD + "G0 X20. Z-10.\nG76 P2. Z10. I1. J0.5 K1. E2. L2\nM2\n")
    assert found == [
        ("rapid", 20.0, -10.0, None),
        ("rapid", 21.5, -10.0, None), ("feed", 21.5, 8.0, 2.0), ("feed", 20.5, 10.0, taper),
        ("rapid", 20.0, 10.0, None), ("rapid", 20.0, -10.0, None),
        ("rapid", 22.0, -10.0, None), ("feed", 22.0, 8.0, 2.0), ("feed", 21.0, 10.0, taper),
        ("rapid", 20.0, 10.0, None)]


def test_degression_counts_the_passes() -> None:
    """R2: pass n cuts J sqrt(n): J0.4 K1.2 (radius 0.2, 0.6) needs n = 9 (0.2 * 3 = 0.6): nine passes, each
    one thread move."""
    found = moves(HEAD + "G0 X20. Z2.\nG76 P1.5 Z-10. I-1. J0.4 K1.2 R2.\nM2\n")
    cuts = [x for kind, x, _, _ in found if kind == "feed"]
    assert cuts == [round(2 * (10 - 0.5 - 0.2 * math.sqrt(n)), 6) for n in range(1, 10)]


PROGRAM = HEAD + "G0 X20. Z2.\nG76 P1.5 Z-10. I-1. J0.4 K1.2 Q29.5 R1.5 H1 E1. L3\nG0 X30.\nG0 Z5.\nM2\n"


def test_a_grblhal_program_keeps_its_g76() -> None:
    assert write(PROGRAM, "grblhal").splitlines()[-5:] == [
        "G0 X20. Z2.", "G76 P1.5 Z-10. I-1. J0.4 K1.2 Q29.5 R1.5 H1 E1. L3", "G0 X30.", "G0 Z5.", "M2"]


@pytest.mark.parametrize("target", ["linuxcnc", "fanuc"])
def test_the_cycle_reaches_another_controller_as_its_passes(target: str) -> None:
    written = write(PROGRAM, target)
    assert not any(line.startswith("G76") for line in written.splitlines())
    # (towards a Fanuc lathe, which has no path control code [?], grblHAL's power-on exact path [V: grblHAL core
    # gcode.h] is not written but warned about, and verify lists it: compared with --allow-ignored)
    report = verify_lines(io.StringIO(PROGRAM), io.StringIO(written), file_in="in.nc", file_out="out.nc",
                          source="grblhal", target=target, setup=LATHE, tolerance=0.0,
                          allow_ignored=target == "fanuc")
    assert report.ok and report.max_deviation == 0.0, report.summary()


def _random_g76(rng: random.Random) -> str:
    inside = rng.random() < 0.3
    toward_plus = rng.random() < 0.25
    x = rng.choice((20.0, 24.0)) if inside else rng.choice((30.0, 40.0))
    z = -30.0 if toward_plus else rng.choice((2.0, 3.0))
    end = rng.choice((0.0, 5.0)) if toward_plus else rng.choice((-10.0, -20.0))
    j = rng.choice((0.2, 0.3, 0.5))
    words = [f"P{rng.choice((1., 1.5, 2.))}", f"I{'' if inside else '-'}{rng.choice((0.5, 1.))}", f"J{j}",
             f"K{round(j + rng.choice((0.3, 0.8)), 3)}"]
    if rng.random() < 0.5:
        words.append(f"R{rng.choice((1., 1.5, 2.))}")
    if rng.random() < 0.5:
        words.append(f"Q{rng.choice((29.5, 30.))}")
    if rng.random() < 0.5:
        words.append(f"H{rng.choice((0, 1, 2))}")
    if rng.random() < 0.5:
        words.append(f"E{rng.choice((1., 1.5))} L{rng.choice((0, 1, 2, 3))}")  # a taper longer than deep
    return HEAD + f"G0 X{x:g}. Z{z:g}.\nG76 Z{end:g}. " + " ".join(words) + "\nG1 X60. Z10.\nM2\n"


@pytest.mark.skipif(not available(), reason="rs274 (LinuxCNC) is not installed")
@pytest.mark.parametrize("seed", range(12))
def test_random_cycles_run_in_rs274_as_simulated(seed: int) -> None:
    """The G33 passes written for LinuxCNC, run by rs274 in lathe mode, make the moves simulated from the
    grblHAL source (end points and each synchronised move's lead)."""
    program = _random_g76(random.Random(seed))
    assert difference(ours(program, "grblhal", LATHE), theirs(write(program, "linuxcnc"))) is None, program


@pytest.mark.parametrize("text,message", [
    ("G0 X20. Z2.\nG76 P1. X18. Z-10. I-1. J0.4 K0.8\nM2\n", "5:9: error: an X word in grblHAL's G76"),
    ("G0 X20. Z2.\nG76 P1. Z-10. I-1. J0.4\nM2\n", "5:1: error: grblHAL's G76 needs I and J not 0 and K above J"),
    ("G0 X20. Z2.\nG76 P1. Z-10. I-1. J0.4 K0.8 R0.5\nM2\n", "5:30: error: G76 R0.5: grblHAL's degression is 1"),
    ("G0 X20. Z2.\nG76 P1. Z-10. I-1. J0.4 K0.8 E7. L1\nM2\n", "5:30: error: G76 E7: an end taper longer than half"),
    ("G0 X20. Z2.\nG76 P1. Z-10. I-1. J0.4 K0.8\nG76 P1. Z-10. I-1. J0.4 K0.8\nM2\n",
     "6:1: error: G76 right after a G76"),
    ("G0 X20. Z2.\nG76 P1. Z-10. I-1. J0.4 K0.8\nZ-12.\nM2\n", "6:1: error: axis words with no motion mode in force"),
    ("G20\nG0 X2. Z0.1\nG76 P0.1 Z-1. I-0.1 J0.04 K0.08\nM2\n", "6:1: error: grblHAL's G76 under G20"),
    ("M5\nG0 X20. Z2.\nG76 P1. Z-10. I-1. J0.4 K0.8\nM2\n", "6:1: error: grblHAL's G76 with the spindle stopped"),
    ("G96 S100 D2000\nG0 X20. Z2.\nG76 P1. Z-10. I-1. J0.4 K0.8\nM2\n",
     "6:1: error: grblHAL's G76 under constant surface speed"),
])
def test_what_is_refused_where_it_stands(text: str, message: str) -> None:
    found = errors(HEAD + text)
    assert len(found) == 1 and found[0].startswith("in.nc:" + message), found


def test_a_g76_after_another_motion_mode_is_read_again() -> None:
    text = HEAD + "G0 X20. Z2.\nG76 P1. Z-10. I-1. J0.4 K0.8\nG0 X20. Z2.\nG76 P1. Z-10. I-1. J0.4 K0.8\nM2\n"
    assert sum(1 for kind, *_ in moves(text) if kind == "feed") == 4


def test_g76_is_refused_on_a_mill_set_up() -> None:
    assert errors("G76 P1. Z-10. I-1. J0.4 K0.8\nM2\n", MachineSetup(controller=BUILD)) == [
        "in.nc:1:1: error: grblHAL's G76 threading cycle (mc_thread) is read in lathe mode only: a set-up with "
        "<Input machineType=\"lathe\"/> reads it"]


def test_linuxcncs_g76_of_the_same_words_moves_otherwise() -> None:
    """Why a LinuxCNC G76 reaches grblHAL as G33 passes and not as G76: with the same words LinuxCNC's first move
    backs away from the drive line by K - J (radius 0.4: X20.8) before going in, grblHAL's goes straight in
    (``test_the_passes_by_hand``), and LinuxCNC leaves each pass at its own depth's retract."""
    from tests.test_linuxcnc_lathe_g76 import moves_of
    text = HEAD + "G0 X20. Z2.\nG76 P1.5 Z-10. I-1. J0.4 K1.2 H1\nM2\n"
    linuxcnc = [(kind, round(2 * x, 6), z) for kind, x, z in moves_of(text)]
    assert linuxcnc[1] == ("rapid", 20.8, 2.0)
    assert moves(text)[1] == ("rapid", 18.6, 2.0, None)
