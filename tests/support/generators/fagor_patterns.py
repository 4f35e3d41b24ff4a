"""Fagor multiple machining G160-G164 after a drilling cycle, with random and hostile words: counts K and D
from none to a hundred million, angular steps I down to 0.0001 degree, lengths and steps that do not
divide, angles A and B of any size, the moves between points C0-C3 with and without F, skipped points.
These found patterns that built every point before any bound (``G163 ... K99999999``: gigabytes) and a
message that counted the wrong moves ("1 holes make more than 0 moves").

Each case runs the simulator and a translation (to Fagor itself, where the pattern stays native, and to
targets that get it point by point): it must end, within the fuzzer's time per case, with output or
located errors. ``<Limits movesPerBlock>`` is drawn small so that a pattern within it is written and
verified in a fraction of a second; a pattern beyond it must be refused before its points are made.
"""

from __future__ import annotations

from typing import Callable

from hypothesis import strategies as st

from postproc.setup.machine_setup import Limits, MachineSetup
from tests.support.fuzzing import check_toolpath, check_translation

from . import Case

KIND = "fagor patterns"

COUNTS = ["0", "1", "2", "3", "4", "12", "100000", "99999999", "2.5", "-3"]
STEPS = ["0", "0.0001", "1", "7.5", "30", "45", "90", "-45", "360", "400", "1E6"]
LENGTHS = ["0", "10", "25", "-10", "0.001", "99999999"]
ANGLES = ["0", "30", "90", "180", "-45", "360", "1E20"]
CODES = {
    "G160": "AXIK", "G161": "ABXIKYJD", "G162": "ABXIKYJD", "G163": "XYIKCF", "G164": "XYBIKCF",
}
WORDS = {
    "A": ANGLES, "B": ANGLES, "X": LENGTHS, "Y": LENGTHS, "I": STEPS, "J": STEPS, "K": COUNTS, "D": COUNTS,
    "C": ["0", "1", "2", "3", "4"], "F": ["100", "0", "-5"], "P": [c for c in COUNTS if "." not in c],
    "Q": [c for c in COUNTS if "." not in c],
}
"""Skipped points are whole numbers: a fractional one is a range, kept verbatim for Fagor by design and
refused by the simulator (so by ``verify``)."""
PRELUDE = ["%1000", "G71 G90 G17", "G00 X0 Y0 Z50", "M03 S1000", "G81 G98 X20 Y0 Z2 I-5 F100"]


SHAPES = {
    "G160": ["A", "I", "K"], "G161": ["A", "I", "K", "J", "D"], "G162": ["B", "I", "K", "J", "D"],
    "G163": ["X", "I"], "G164": ["X", "B", "K"],
}
"""Words that make each pattern whole (with values drawn from the hostile lists)."""


@st.composite
def patterns(draw: st.DrawFn) -> str:
    code = draw(st.sampled_from(sorted(CODES)))
    if draw(st.booleans()):
        letters = SHAPES[code] + draw(st.lists(st.sampled_from("PQC"), unique=True, max_size=2))
    else:
        letters = draw(st.lists(st.sampled_from(CODES[code] + "PQ"), unique=True, min_size=1, max_size=6))
    words = [f"{letter}{draw(st.sampled_from(WORDS[letter]))}" for letter in letters]
    if "C" in letters and code in ("G163", "G164"):
        words.append(f"F{draw(st.sampled_from(WORDS['F']))}")
    return "\n".join([*PRELUDE, " ".join([code, *words]), "G80", "M30"]) + "\n"


def _run(target: str, setup: MachineSetup) -> Callable[[str], object]:
    def run(program: str) -> object:
        check_toolpath("fagor", program, setup)
        return check_translation("fagor", target, program, setup, warn=False)
    return run


def cases() -> st.SearchStrategy[Case]:
    # at least one hole's moves (4): the cycle's own block is expanded by the simulator
    setups = st.integers(16, 2000).map(lambda n: MachineSetup(limits=Limits(moves_per_block=n)))
    return st.tuples(st.sampled_from(["fagor", "fanuc", "linuxcnc", "grbl"]), patterns(), setups).map(
        lambda c: Case(f"fagor patterns fagor-{c[0]}", c[0], c[1], _run(c[0], c[2]), c[2]))
