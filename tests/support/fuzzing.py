"""What a fuzz case is and what it must satisfy; shared by the suite (``test_fuzz_all_dialects.py``) and
the long-running target (``make fuzz``, ``tests/support/fuzz_main.py``).

Programs are built from fragments of real G-code, so they reach deep into the pipelines (cycles, arcs,
modal state) rather than failing at the first character; set-ups vary the output format.
"""

from __future__ import annotations

import contextlib
import io
import re

from hypothesis import strategies as st

from postproc.api import read_program, translate
from postproc.errors import Diagnostics, ErrorList, PostprocError
from postproc.plugins import default_registry
from postproc.setup.machine_setup import InputSettings, MachineSetup, OutputSettings
from postproc.simulate.toolpath import toolpath_events
from postproc.simulate.verify import verify_lines

from .output_rules import problems
from .tools import with_tools

REGISTRY = default_registry()
READERS = sorted(n for n, c in REGISTRY.dialects.items() if c.READER is not None)
WRITERS = sorted(n for n, c in REGISTRY.dialects.items() if c.WRITER is not None)
PAIRS = [(r, w) for r in READERS for w in WRITERS]

FRAGMENTS = [
    "G00", "G01", "G02", "G03", "G04", "G17", "G18", "G19", "G20", "G21", "G28", "G40", "G41", "G43", "G49",
    "G53", "G54", "G80", "G81", "G82", "G83", "G73", "G84", "G74", "G85", "G86", "G87", "G88", "G89", "G76",
    "G90", "G91", "G94", "G95", "G98", "G99", "M03", "M04", "M05", "M06", "M08", "M09", "M19", "M30",
    "X10.", "X-5", "Y2.5", "Y0", "Z-3.", "Z5", "R2.", "R-1", "Q1.", "Q0", "P500", "P0.5", "K2", "K0", "L2",
    "I5.", "J-5.", "K1.", "F100.", "S1000", "T1", "H01", "D02", "N10", "(C)", "/", "%", "X", "1.2.3",
    "X0.0005", "Y-0.0000004", "Z1234.56789", "F0.3", "X1" + "0" * 400 + ".", "R0.", "I0.", "P-1", "S0",
]
"""Words and pieces of real programs, a few at the edges (sub-micrometre, beyond the float range)."""

NON_FINITE = re.compile(r"(?i)\b[A-Z][-+]?\.?(?:inf|nan)")
"""A word whose number is written as inf or nan (Xinf, Y-nan)."""


def programs() -> st.SearchStrategy[str]:
    line = st.lists(st.sampled_from(FRAGMENTS), min_size=0, max_size=6).map(" ".join)
    return st.lists(line, min_size=1, max_size=8).map(
        lambda lines: "G21 G90 G0 X0. Y0. Z10.\n" + "\n".join(lines) + "\n")


def setups() -> st.SearchStrategy[MachineSetup]:
    """The default set-up most of the time; otherwise another output format or input convention. Every
    tool register has a value (zero: the simulation refuses a register it does not know)."""
    output = st.builds(OutputSettings, normalize=st.booleans(), decimals=st.integers(0, 6),
                       inch_decimals=st.integers(0, 7), leading_zero=st.booleans())
    input_ = st.builds(InputSettings, decimal_point=st.sampled_from(["least-increment", "calculator"]))
    other = st.builds(MachineSetup, input=input_, output=output)
    return st.one_of(st.just(None), st.just(None), other).map(lambda s: with_tools(s or MachineSetup()))


KNOWN_DEFECTS: list[tuple[str, str | None, re.Pattern[str]]] = [
    ("cutter compensation outside the XY plane (G18/G19) is not simulated (LinuxCNC's rules are implemented for "
     "XY only)", None,
     re.compile(r"^translated, but verify fails: in\.nc:\d+:\d+: error: cutter compensation in the (ZX|YZ) plane "
                r"cannot be simulated")),
    ("LinuxCNC codes kept verbatim (G76 threading, G87/G88 with their own words) are not simulated", None,
     re.compile(r"^translated, but verify fails: in\.nc:\d+:\d+: error: G\d+ \((RS274/NGC|threading).*cannot be simulated")),
    ("ISG P parameter arrays (P100[2]=5) are kept verbatim between ISG programs and not simulated (not "
     "modelled), so an ISG to ISG copy cannot be verified (found by the derandomized ISG fuzz in CI)", "isg",
     re.compile(r"^translated, but verify fails: in\.nc:\d+:\d+: error: P parameter arrays \(not modelled\) "
                r"cannot be simulated")),
    ("ISG codes kept verbatim (mirroring G20-G23, software limits G98/G99, homing G74, preset G92, G80-G89 calls, "
     "blending) copy to ISG unchanged and are not simulated", "isg",
     re.compile(r"^translated, but verify fails: in\.nc:\d+:\d+: error: G\d+ \([^)]*\) cannot be simulated")),
    ("LinuxCNC codes the mill simulation does not model (G33, G96/G97; G41.1/G42.1 in a block with a move, "
     "which rs274 runs) are copied verbatim from LinuxCNC to LinuxCNC and not simulated (found by the new words "
     "fuzz; G7 is refused on a mill and G8 read since)", "linuxcnc",
     re.compile(r"^translated, but verify fails: in\.nc:\d+:\d+: error: G[\d.]+ \((spindle-synchronised motion|"
                r"constant surface speed|spindle speed in rpm|"
                r"dynamic cutter compensation (left|right))\) cannot be simulated")),
]
"""Defects outside this suite's reach (writers, block syntaxes, lowering), listed so the suite stays green
and they stay visible: ``make fuzz`` counts them. Each entry: description, target (None: any), message."""


def known_defect(target: str, message: str) -> str | None:
    """The description of a listed defect the failure ``message`` matches, or None (a new failure)."""
    for description, where, pattern in KNOWN_DEFECTS:
        if (where is None or where == target) and pattern.search(message):
            return description
    return None


def located(err: PostprocError) -> None:
    assert err.location is not None and err.location.line >= 1 and err.location.col >= 1, str(err)


def check_translation(source: str, target: str, program: str, setup: MachineSetup, warn: bool,
                      tolerance: float = 0.0) -> str:
    """One case: translate, then the output's own checks. Returns what happened ('ok', 'refused').
    ``tolerance`` (mm) is verify's: 0 unless the output rounds computed points (8 decimals of an inch)."""
    out = io.StringIO()
    try:
        diagnostics = translate(io.StringIO(program), out, file="fuzz.nc", source=source, target=target,
                                setup=setup, on_unsupported="warn" if warn else "error",
                                diagnostics=Diagnostics(warn_stream=io.StringIO()))
    except ErrorList as errs:
        for err in errs.errors:
            located(err)
        return "refused"
    text = out.getvalue()
    bad = NON_FINITE.search(text)
    assert bad is None, f"non-finite number {bad.group(0)!r} in the output:\n{text}"
    if REGISTRY.dialects[target].READER is None:
        return "ok"
    with contextlib.redirect_stderr(io.StringIO()):  # the readers' warnings (e.g. grbl ignoring '/')
        try:
            return _check_output(source, target, program, text, setup, warn and bool(diagnostics.warnings),
                                 tolerance)
        except AssertionError as exc:
            warned = warned_difference(str(exc), [str(w) for w in diagnostics.warnings])
            if warned is not None:
                return f"warned: {warned}"
            raise


WARNED_DIFFERENCES: list[tuple[str, str, re.Pattern[str]]] = [
    ("lathe tool offset", "",
     re.compile(r"  lathe tool offset differs: IN offset \d+ \(line \d+\); OUT never set")),
    ("lathe path control", "lathe has no path control code here",
     re.compile(r"  path control differs: IN exact (path|stop) \(line \d+\); OUT never set")),
]
"""Differences verify lists that the translation warned of by design, each: its name, the warning's words
(empty: any warning), the line verify writes. A lathe tool offset a mill control (grbl, Fagor, ISG...) cannot
apply: the translation warns at the turret index that names it (commit 91f98e5). The exact path a grbl or
grblHAL program runs in from power-on, for a Fanuc T or GSK lathe, which has no path control code
(``postproc.lowering.path_at_start``: not written, with a warning; found by make fuzz, new words
grblhal-gsk on a lathe set-up)."""
_NOT_COMPARED = re.compile(r"^translated, but verify says: max deviation 0\.0000 mm .*: settings that move the tool "
                           r"differ .*\nnot compared:\n")


def warned_difference(message: str, warnings: list[str]) -> str | None:
    """The names of the differences in verify's ``message`` when the toolpaths agree and every difference
    it lists is one the translation warned of (``WARNED_DIFFERENCES``), else None (a defect)."""
    head = _NOT_COMPARED.match(message)
    if head is None or not warnings:
        return None
    found: set[str] = set()
    for line in message[head.end():].splitlines():
        if not line.startswith("  "):
            break  # the output program follows the list
        name = next((name for name, warning, pattern in WARNED_DIFFERENCES
                     if pattern.fullmatch(line) and any(warning in w for w in warnings)), None)
        if name is None:
            return None
        found.add(name)
    return ", ".join(sorted(found)) or None


def _check_output(source: str, target: str, program: str, text: str, setup: MachineSetup, warned: bool,
                  tolerance: float = 0.0) -> str:
    refused = problems(target, text, setup, source=source) if source != target else []
    assert not refused, f"the {target} controller refuses the {target} output: {'; '.join(refused)}\n{text}"
    try:
        read_program(io.StringIO(text), file="out.nc", dialect=target, setup=setup)
    except ErrorList as errs:
        raise AssertionError(f"the {target} reader refuses the {target} output: {errs}\n{text}") from None
    if warned:
        return "ok"  # commented-out blocks: the toolpaths differ by design
    try:
        report = verify_lines(io.StringIO(program), io.StringIO(text), file_in="in.nc", file_out="out.nc",
                              source=source, target=target, setup=setup, tolerance=tolerance)
    except ErrorList as errs:
        if source == target and _unknown_meaning(errs):
            return UNKNOWN_MEANING_OUTCOME
        raise AssertionError(f"translated, but verify fails: {errs}\n{text}") from None
    assert report.ok, f"translated, but verify says: {report.summary()}\n{text}"
    return "ok"


UNKNOWN_MEANING_OUTCOME = "verify cannot compare: a construct whose meaning is not known [?]"
"""A copy to its own dialect keeps, byte for byte, a construct whose meaning on the controller no source gives
(Mach3's ``G53`` under ``G91``: machine positions, increments or ignored [?], ``MACHINE_MOVE_INCREMENTAL``), and
verify refuses both sides, located at it: no simulation can compare what is not known, so this is verify's right
answer, not a defect (until the last session it was listed in ``KNOWN_DEFECTS``; found by make fuzz, mach3-mach3).
A construct the simulation does not model but whose meaning is known stays a listed defect."""
_UNKNOWN_MEANING = re.compile(r"^(in|out)\.nc:\d+:\d+: error: .*: not known for this controller \[\?\]\) cannot be "
                              r"simulated$")


def _unknown_meaning(errs: ErrorList) -> bool:
    """Every error of verify is the located refusal of a construct of unknown meaning, on both sides alike."""
    texts = [str(e) for e in errs.errors]
    if not texts or any(e.location is None or _UNKNOWN_MEANING.match(t) is None for e, t in zip(errs.errors, texts)):
        return False
    source = sorted(t[len("in.nc"):] for t in texts if t.startswith("in.nc:"))
    return source == sorted(t[len("out.nc"):] for t in texts if t.startswith("out.nc:"))


def check_toolpath(dialect: str, program: str, setup: MachineSetup) -> None:
    try:
        list(toolpath_events(io.StringIO(program), file="fuzz.nc", dialect=dialect, setup=setup,
                             diagnostics=Diagnostics(warn_stream=io.StringIO())))
    except ErrorList as errs:
        for err in errs.errors:
            located(err)
    except PostprocError as err:
        located(err)
