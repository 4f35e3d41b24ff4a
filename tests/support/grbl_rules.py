"""grbl 1.1's own acceptance rules, as a checker for every grbl program the suite writes.

``grbl_problems(text)`` returns one message per line grbl would answer with ``error:N`` (or act on in a
way the program did not mean), empty when grbl 1.1 runs the whole program. It is written from grbl's
source (github.com/gnea/grbl, ``grbl/protocol.c``, ``grbl/serial.c``, ``grbl/gcode.c``), independently of
the writer it checks:

* the serial layer (``serial.c``) acts on the real-time characters ``?``, ``!``, ``~`` and Ctrl-X wherever
  they stand, inside comments too (status report, feed hold, cycle start, reset); bytes above 0x7F are
  real-time commands or dropped: a program holds none of them;
* the protocol layer (``protocol.c``) drops spaces, control characters and ``/``, ``( )`` and ``;``
  comments, upper-cases letters, and refuses a line of more than 79 remaining characters (error 11);
* the parser (``gcode.c``, ``gc_execute_line``) reads letter + number words: G0-G3, G4, G10, G17-G19,
  G20/G21, G28/G30 (.1), G38.2-G38.5, G40, G43.1, G49, G53, G54-G59, G61, G80, G90/G91, G91.1, G92 (.1),
  G93/G94; M0, M1, M2, M30, M3-M5, M8, M9 (M7 only in a build with ``ENABLE_M7``, off by default); value
  words F I J K L N P R S T X Y Z. One command per modal group (error 21), one axis command per block
  (24), no repeated word (25), no negative F N P S T (4), and then the checks of its step 3: dwell
  needs P (28), G10 its L/P/axes, G53 needs G0/G1 in force (30), axis words with G80 in force (31), a
  feed move needs a feed rate (22), an arc its plane words (26, 32, 35), its radius (34) and a centre
  within 0.005 mm / 0.1 % of both ends (33), and no word may be left unused (36).

The position is followed in work coordinates (offsets taken as zero) wherever it is known; after a
move to a stored position (G28/G30), G53, G92, G10 L20, a new work offset or G43.1 it is unknown, and
the arc checks that need it are skipped until the axes are programmed again.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

__all__ = ["grbl_problems"]

LINE_BUFFER_SIZE = 80
"""``protocol.h``: a line keeps at most 79 characters after spaces and comments are dropped."""
MAX_LINE_NUMBER = 10_000_000
MAX_TOOL_NUMBER = 255
MM_PER_INCH = 25.4
REALTIME = {"?": "status report", "!": "feed hold", "~": "cycle start", "\x18": "soft reset"}
"""``serial.c``: characters executed the moment they arrive, even inside a comment."""

ERRORS = {
    1: "expected command letter", 2: "bad number format", 4: "negative value", 11: "line overflow",
    20: "unsupported command", 21: "modal group violation", 22: "undefined feed rate",
    23: "command value not integer", 24: "axis command conflict", 25: "word repeated", 26: "no axis words",
    27: "invalid line number", 28: "value word missing", 29: "unsupported coordinate system",
    30: "G53 without G0/G1", 31: "axis words with G80", 32: "no axis words in plane", 33: "invalid target",
    34: "arc radius error", 35: "no offsets in plane", 36: "unused words", 37: "G43.1 axis error",
    38: "max value exceeded",
}
"""grbl 1.1's error codes (``report.h``), as its documentation names them."""

_NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)")
"""``nuts_bolts.c`` ``read_float``: a sign, digits and at most one point, at least one digit."""
_VALUE_LETTERS = frozenset("FIJKLNPRSTXYZ")
_PLANES = {17: ("X", "Y", "Z"), 18: ("Z", "X", "Y"), 19: ("Y", "Z", "X")}


class GrblError(Exception):
    def __init__(self, code: int, detail: str = "") -> None:
        super().__init__(f"error:{code} ({ERRORS[code]}){': ' + detail if detail else ''}")


@dataclass
class _State:
    motion: str = "G0"
    """G0 G1 G2 G3 G38.x or G80 (grbl starts in G0)."""
    plane: int = 17
    inches: bool = False
    incremental: bool = False
    inverse_time: bool = False
    feed: float = 0.0
    """mm/min; 0 is undefined."""
    coordinates: str = "G54"
    position: dict[str, float | None] = field(default_factory=lambda: {"X": 0.0, "Y": 0.0, "Z": 0.0})
    """Work coordinates in mm, None where unknown."""


def grbl_problems(text: str, *, m7: bool = False, m19: bool = False) -> list[str]:
    """Every line of ``text`` grbl 1.1 refuses or acts on unexpectedly, as ``LINE: message``.
    ``m7``: the build has ``ENABLE_M7`` (mist coolant); ``m19``: a build with an oriented spindle stop
    ``M19 [R<angle>]`` (a machine whose set-up says ``<Cycles orientation="m19"/>``)."""
    problems: list[str] = []
    state = _State()
    for number, raw in enumerate(re.split(r"\r\n|\r|\n", text.removesuffix("\n").removesuffix("\r")), 1):
        try:
            line = _protocol(raw)
            if line:
                _execute(line, state, m7, m19)
        except GrblError as err:
            problems.append(f"{number}: {err}: {raw}")
    return problems


def _protocol(raw: str) -> str:
    """What ``serial.c`` and ``protocol.c`` hand to the parser (the real-time characters are errors here)."""
    for ch in raw:
        if ch in REALTIME:
            raise GrblError(1, f"{ch!r} is grbl's real-time {REALTIME[ch]} command, even inside a comment")
        if ord(ch) > 0x7F:
            raise GrblError(1, f"non-ASCII {ch!r}: bytes above 0x7F are grbl real-time commands or dropped")
    out: list[str] = []
    in_paren = False
    for ch in raw:
        if in_paren:
            in_paren = ch != ")"
        elif ch <= " " or ch == "/":
            continue
        elif ch == "(":
            in_paren = True
        elif ch == ";":
            break
        else:
            out.append(ch.upper())
    if len(out) >= LINE_BUFFER_SIZE:
        raise GrblError(11, f"{len(out)} characters without spaces and comments, grbl keeps {LINE_BUFFER_SIZE - 1}")
    return "".join(out)


def _words(line: str) -> list[tuple[str, str, float]]:
    words = []
    pos = 0
    while pos < len(line):
        letter = line[pos]
        if not "A" <= letter <= "Z":
            raise GrblError(1, f"{letter!r}")
        m = _NUMBER.match(line, pos + 1)
        if m is None:
            raise GrblError(2, f"after {letter}")
        words.append((letter, m.group(0), float(m.group(0))))
        pos = m.end()
    return words


def _g_group(value: float, text: str) -> tuple[str, str]:
    """(modal group, canonical code) of a G word; raises on what grbl does not support."""
    whole = math.trunc(value)
    tenths = round(100 * (value - whole))
    code = f"G{whole}" if tenths == 0 else f"G{whole}.{tenths // 10}"
    groups = {
        "G4": "0", "G10": "0", "G28": "0", "G28.1": "0", "G30": "0", "G30.1": "0", "G53": "0", "G92": "0",
        "G92.1": "0", "G0": "1", "G1": "1", "G2": "1", "G3": "1", "G38.2": "1", "G38.3": "1", "G38.4": "1",
        "G38.5": "1", "G80": "1", "G17": "2", "G18": "2", "G19": "2", "G90": "3", "G91": "3", "G91.1": "4",
        "G93": "5", "G94": "5", "G20": "6", "G21": "6", "G40": "7", "G43.1": "8", "G49": "8", "G54": "12",
        "G55": "12", "G56": "12", "G57": "12", "G58": "12", "G59": "12", "G61": "13",
    }
    if code not in groups or tenths % 10:
        raise GrblError(20, f"G{text}")
    return groups[code], code


def _m_group(value: float, text: str, m7: bool, m19: bool) -> tuple[str, str]:
    if value != math.trunc(value):
        raise GrblError(23, f"M{text}")
    code = int(value)
    groups = {0: "4", 1: "4", 2: "4", 30: "4", 3: "7", 4: "7", 5: "7", 8: "8", 9: "8"}
    if m7:
        groups[7] = "8"
    if m19:
        groups[19] = "7"
    if code not in groups:
        raise GrblError(20, f"M{text}")
    return "M" + groups[code], f"M{code}"


def _execute(line: str, state: _State, m7: bool, m19: bool) -> None:
    """``gc_execute_line``'s step 2 (words) and step 3 (error checks), then the state update."""
    groups: dict[str, str] = {}
    values: dict[str, float] = {}
    axis_command = ""  # "", "non_modal", "motion", "length"
    non_modal = ""
    motion = state.motion
    for letter, text, value in _words(line):
        if letter in "GM":
            group, code = _g_group(value, text) if letter == "G" else _m_group(value, text, m7, m19)
            if group in groups:
                raise GrblError(21, f"{groups[group]} and {code}")
            groups[group] = code
            if code in ("G10", "G28", "G30", "G92", "G0", "G1", "G2", "G3", "G49", "G43.1") or code.startswith("G38"):
                kind = "non_modal" if code in ("G10", "G28", "G30", "G92") else "length" if code in (
                    "G49", "G43.1") else "motion"
                if axis_command:
                    raise GrblError(24, code)
                axis_command = kind
            if group == "0":
                non_modal = code
            elif group == "1":
                motion = code
            continue
        if letter not in _VALUE_LETTERS:
            raise GrblError(20, f"word {letter}")
        if letter in values:
            raise GrblError(25, letter)
        if letter in "FNPTS" and value < 0:
            raise GrblError(4, f"{letter}{text}")
        if letter == "T" and value > MAX_TOOL_NUMBER:
            raise GrblError(38, f"T{text}")
        values[letter] = value
    axes = {a: values[a] for a in "XYZ" if a in values}
    if axes and not axis_command:
        axis_command = "motion"
    if values.get("N", 0) > MAX_LINE_NUMBER:
        raise GrblError(27)
    unit = MM_PER_INCH if groups.get("6", "G21" if not state.inches else "G20") == "G20" else 1.0
    inverse_time = groups.get("5", "G93" if state.inverse_time else "G94") == "G93"
    feed = values["F"] * unit if "F" in values else (0.0 if inverse_time or state.inverse_time else state.feed)
    if inverse_time and axis_command == "motion" and motion not in ("G80", "G0") and "F" not in values:
        raise GrblError(22, "G93 needs F in every feed block")
    used = set("NFST")
    if groups.get("M7") == "M19":
        used.add("R")
    if non_modal == "G4":
        if "P" not in values:
            raise GrblError(28, "G4 needs P")
        used.add("P")
    plane = int(groups.get("2", f"G{state.plane}")[1:])
    incremental = groups.get("3", "G91" if state.incremental else "G90") == "G91"
    start = dict(state.position)
    if groups.get("12", state.coordinates) != state.coordinates:
        start = {a: None for a in start}
    target = dict(start)
    if non_modal == "G10":
        if not axes:
            raise GrblError(26, "G10")
        if "P" not in values or "L" not in values:
            raise GrblError(28, "G10 needs L and P")
        if math.trunc(values["P"]) > 6:
            raise GrblError(29, f"P{values['P']:g}")
        if values["L"] not in (2, 20) or (values["L"] == 2 and "R" in values):
            raise GrblError(20, "G10 takes L2 (without R) or L20")
        used.update("LP")
    elif non_modal == "G92" and not axes:
        raise GrblError(26, "G92")
    elif axis_command != "length" and axes and non_modal not in ("G10", "G92"):
        for a, v in axes.items():
            v *= unit
            if non_modal == "G53":
                target[a] = None
            elif incremental:
                was = start[a]
                target[a] = None if was is None else was + v
            else:
                target[a] = v
    if non_modal == "G53" and motion not in ("G0", "G1"):
        raise GrblError(30)
    if "8" in groups and groups["8"] == "G43.1" and set(axes) != {"Z"}:
        raise GrblError(37)
    if motion == "G80":
        if axes:
            raise GrblError(31, "G80 is in force: program G0 or G1")
    elif axis_command == "motion":
        if motion != "G0":
            if feed == 0:
                raise GrblError(22, motion)
            if motion in ("G2", "G3"):
                _arc(values, axes, plane, unit, start, target, used)
            elif motion.startswith("G38") and not axes:
                raise GrblError(26, motion)
    if axis_command:
        used.update("XYZ")
    unused = sorted(set(values) - used)
    if unused:
        raise GrblError(36, " ".join(unused))
    # the block runs: update the state
    state.motion = motion
    state.plane = plane
    state.inches = unit != 1.0
    state.incremental = incremental
    state.inverse_time = inverse_time
    state.feed = 0.0 if inverse_time else feed
    state.coordinates = groups.get("12", state.coordinates)
    if non_modal in ("G28", "G30", "G92", "G92.1") or groups.get("8") == "G43.1" or (
            non_modal == "G10" and values.get("L") == 20):
        state.position = {a: None for a in start}
    elif axis_command == "motion" and motion != "G80":
        state.position = target
    else:
        state.position = start


def _arc(values: dict[str, float], axes: dict[str, float], plane: int, unit: float,
         start: dict[str, float | None], end: dict[str, float | None], used: set[str]) -> None:
    a0, a1, _ = _PLANES[plane]
    if not axes:
        raise GrblError(26, "arc")
    if a0 not in axes and a1 not in axes:
        raise GrblError(32, f"arc needs {a0} or {a1}")
    known = all(p is not None for p in (start[a0], start[a1], end[a0], end[a1]))
    if "R" in values:
        used.add("R")
        if not known:
            return
        x = end[a0] - start[a0]  # type: ignore[operator]
        y = end[a1] - start[a1]  # type: ignore[operator]
        if all(start[a] is not None and start[a] == end[a] for a in "XYZ"):
            raise GrblError(33, "R arc ending where it starts")
        r = values["R"] * unit
        if 4 * r * r - x * x - y * y < 0:
            raise GrblError(34, f"R{values['R']:g} is shorter than half the chord {math.hypot(x, y) / 2:.6f}")
        return
    offsets = {"X": "I", "Y": "J", "Z": "K"}
    if offsets[a0] not in values and offsets[a1] not in values:
        raise GrblError(35, f"arc needs {offsets[a0]} or {offsets[a1]}")
    used.update("IJK")
    if not known:
        return
    i = values.get(offsets[a0], 0.0) * unit
    j = values.get(offsets[a1], 0.0) * unit
    x = end[a0] - start[a0] - i  # type: ignore[operator]
    y = end[a1] - start[a1] - j  # type: ignore[operator]
    r = math.hypot(i, j)
    delta = abs(math.hypot(x, y) - r)
    if delta > 0.005 and (delta > 0.5 or delta > 0.001 * r):
        raise GrblError(33, f"end point {delta:.6f} mm off the circle")
