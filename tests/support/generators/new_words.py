"""Fuzz kind "new words": the pairs fuzz (``fuzzing.FRAGMENTS``, every reader to every writer) with the words
the last session taught the readers mixed in: lathe modes and threading (G7/G8, G32, G33, G50 S, G96/G97,
G96 D, U/W), feed modes (G93/G95), dynamic cutter compensation (G41.1/G42.1 D), path control (G61/G64), on
the default mill set-up and on a lathe set-up. Checks are the pairs' (``fuzzing.check_translation``).
"""

from __future__ import annotations

from hypothesis import strategies as st

from postproc.setup.machine_setup import InputSettings, MachineSettings, MachineSetup

from ..fuzzing import FRAGMENTS, PAIRS, check_translation
from ..tools import with_tools
from . import Case

KIND = "new words"
NEW = ["G7", "G8", "G32", "G33", "G50", "G96", "G97", "G93", "G95", "G41.1", "G42.1", "G61", "G64", "D2500", "D5.",
       "U1.", "W-1.", "K1.5", "F1.5", "S150", "G18", "X30.", "Z-10.", "I2.", "K-2."]
LATHE = with_tools(MachineSetup(input=InputSettings(machine_type="lathe"), machine=MachineSettings(axes="XZ")))
MILL = with_tools()


def programs() -> st.SearchStrategy[str]:
    word = st.one_of(st.sampled_from(FRAGMENTS), st.sampled_from(NEW), st.sampled_from(NEW))
    line = st.lists(word, min_size=0, max_size=6).map(" ".join)
    return st.lists(line, min_size=1, max_size=8).map(
        lambda lines: "G21 G90 G0 X0. Y0. Z10.\n" + "\n".join(lines) + "\n")


def _case(pair: tuple[str, str], lathe: bool, program: str, warn: bool) -> Case:
    source, target = pair
    setup = LATHE if lathe else MILL
    if lathe:
        program = program.replace(" Y0.", "", 1)
    return Case(f"new words {source}-{target}", target, program,
                lambda p: check_translation(source, target, p, setup, warn),
                f"{'lathe' if lathe else 'mill'}, on_unsupported={'warn' if warn else 'error'}")


def cases() -> st.SearchStrategy[Case]:
    return st.builds(_case, st.sampled_from(PAIRS), st.booleans(), programs(), st.booleans())
