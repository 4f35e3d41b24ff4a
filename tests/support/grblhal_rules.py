"""grblHAL's acceptance rules, as a checker for every grblHAL program the suite writes.

``grblhal_problems(text, ...)`` returns one message per line grblHAL would refuse (``error:N``), act on
unexpectedly, or accept without doing what it says; empty when it runs the whole program. Written from
grblHAL's source (github.com/grblHAL/core, stored commit f80fc34), independently of the writer it checks:

* ``protocol.c``/``protocol.h``: a line keeps at most 256 characters (``LINE_BUFFER_SIZE`` 257), comments and
  spaces included, leading blanks and control characters not; ``?``, ``!``, ``~``, Ctrl-X and bytes above 0x7F
  are real-time commands wherever they stand;
* ``gcode.c`` ``gc_execute_block``: the G and M codes it accepts (the lathe mode's G7/G8, G33, G96/G97
  only in lathe mode, ``lathe``: G33 with a spindle encoder and a K, in its block or from an earlier G33, G96
  with S; a feed move under G96 while the spindle is stopped, or at S0, is error 41; G76 is not checked here; G43/G43.2 only with a tool table; G95 only with a spindle encoder; M7 only with mist
  coolant; M19 is no code of its); one command per modal group; a motion code beside another axis command
  (G10, G28, G30, G92, G43.1) is an axis command conflict; axis words while G80 is in force are refused
  unless a non-modal command (G10, G28, G30, G92) takes them; a feed move needs a feed rate; a block that
  changes the canned cycle needs R and the drilling axis word, G82/G84/G86/G89 a P, G73/G83 a Q; L must be
  positive; G85, G86 and G89 are parsed but never run (``motion_control.c``: the block would not move).

Lines that compute (parameters, expressions, o-words: ``#``, ``[``, a leading ``o``) are checked for their
characters and length, and a numbered ``o<n> call`` for a definition ``o<n> sub`` on an earlier line
(``ngc_flowctrl.c``: the flow registers a sub when it passes it, a call finds only a registered one); after one, the motion mode and the feed rate are unknown (not checked) until
programmed again.
"""

from __future__ import annotations

import re

__all__ = ["grblhal_problems"]

LINE_BUFFER_SIZE = 257
REALTIME = {"?": "status report", "!": "feed hold", "~": "cycle start", "\x18": "soft reset"}
_WORD = re.compile(r"([A-Z])([-+]?(?:\d+\.?\d*|\.\d+))")
_COMMENT = re.compile(r"\([^)]*\)|;.*")
_SUB = re.compile(r"O(\d+)(SUB|CALL)")
AXES = frozenset("XYZABC")

G_ACCEPTED = {
    "0", "1", "2", "3", "4", "5", "5.1", "10", "17", "18", "19", "20", "21", "28", "28.1", "30", "30.1", "38.2",
    "38.3", "38.4", "38.5", "40", "43.1", "49", "53", "54", "55", "56", "57", "58", "59", "59.1", "59.2", "59.3",
    "61", "73", "80", "81", "82", "83", "84", "90", "91", "91.1", "92", "92.1", "92.2", "92.3", "93", "94",
    "98", "99",
}
"""``gcode.c``'s G switch, every build, mill mode (G43/G43.2 and G95 below)."""
M_ACCEPTED = {0, 1, 2, 3, 4, 5, 6, 8, 9, 30, 48, 49, 50, 51, 53, 56, 61, 62, 63, 64, 65, 66, 67, 68, 70, 71, 72, 73}
MOTION = {"0", "1", "2", "3", "5", "5.1", "38.2", "38.3", "38.4", "38.5", "73", "80", "81", "82", "83", "84", "85",
          "86", "89"}
CYCLES = {"73", "81", "82", "83", "84", "85", "86", "89"}
NON_MODAL_AXIS = {"10", "28", "30", "92"}
"""Non-modal commands that take the block's axis words (``AxisCommand_NonModal``)."""
GROUPS = {
    **dict.fromkeys(MOTION, "motion"), **dict.fromkeys(("4", "10", "28", "28.1", "30", "30.1", "53", "92", "92.1",
                                                        "92.2", "92.3"), "non-modal"),
    **dict.fromkeys(("17", "18", "19"), "plane"), **dict.fromkeys(("90", "91"), "distance"),
    **dict.fromkeys(("93", "94", "95"), "feed mode"), **dict.fromkeys(("20", "21"), "units"),
    **dict.fromkeys(("40",), "cutter"), **dict.fromkeys(("43", "43.1", "43.2", "49"), "length"),
    **dict.fromkeys(("54", "55", "56", "57", "58", "59", "59.1", "59.2", "59.3"), "coordinates"),
    **dict.fromkeys(("61",), "path"), **dict.fromkeys(("98", "99"), "return"),
    "33": "motion", **dict.fromkeys(("7", "8"), "lathe diameter"), **dict.fromkeys(("96", "97"), "spindle speed mode"),
}
LATHE_G = {"7", "8", "33", "96", "97"}
"""Codes of the lathe mode (``$32``)."""
M_GROUPS = {**dict.fromkeys((0, 1, 2, 30), "stopping"), **dict.fromkeys((3, 4, 5), "spindle"),
            **dict.fromkeys((7, 8, 9), "coolant"), 6: "tool", 61: "tool"}


def _code(number: str) -> str:
    value = float(number)
    return f"{value:g}"


class _Lathe:
    """What the lathe mode's checks carry from line to line."""

    def __init__(self) -> None:
        self.css = False
        self.spindle_on = False
        self.rpm = 0.0
        self.k = 0.0


def grblhal_problems(text: str, *, tool_table: bool = False, spindle_sync: bool = False, mist: bool = False,
                     m19: bool = False, lathe: bool = False) -> list[str]:
    """The lines of ``text`` grblHAL refuses (see the module docstring), as ``LINE: message``."""
    found: list[str] = []
    turning = _Lathe() if lathe else None
    motion: str | None = "0"  # grblHAL starts in G0; None: unknown (after a line that computes)
    feed = False
    subs: set[int] = set()
    for n, raw in enumerate(text.splitlines(), start=1):
        for ch in raw:
            if ch in REALTIME or ord(ch) > 0x7F:
                found.append(f"{n}: real-time character {ch!r} ({REALTIME.get(ch, 'extended command')})")
        kept = sum(1 for ch in raw.lstrip(" ") if ch >= " ")
        if kept > LINE_BUFFER_SIZE - 1:
            found.append(f"{n}: line overflow ({kept} characters kept, {LINE_BUFFER_SIZE - 1} fit)")
        code = _COMMENT.sub("", raw).upper().replace(" ", "")
        if code.startswith("/"):
            code = code[1:]
        if not code:
            continue
        if code.startswith("O") or "#" in code or "[" in code:
            sub = _SUB.match(code)
            if sub and sub.group(2) == "SUB":
                subs.add(int(sub.group(1)))
            elif sub and int(sub.group(1)) not in subs:
                found.append(f"{n}: o{int(sub.group(1))} call before its sub's definition (flow control syntax error)")
            motion, feed = None, True
            continue
        words = _WORD.findall(code)
        if "".join(letter + number for letter, number in words) != code:
            found.append(f"{n}: not a sequence of words: {code!r}")
            continue
        problem = _block(words, motion, feed, tool_table, spindle_sync, mist, m19, turning)
        if isinstance(problem, str):
            found.append(f"{n}: {problem}")
            continue
        motion, feed = problem
    return found


def _block(words: list[tuple[str, str]], motion: str | None, feed: bool, tool_table: bool, spindle_sync: bool,
           mist: bool, m19: bool, lathe: _Lathe | None = None) -> str | tuple[str | None, bool]:
    """A problem, or the motion mode and whether a feed rate is in force after the block."""
    gs = [_code(number) for letter, number in words if letter == "G"]
    ms = [float(number) for letter, number in words if letter == "M"]
    letters = [letter for letter, _ in words if letter not in "GM"]
    values = {letter: float(number) for letter, number in words if letter not in "GM"}
    if len(set(letters)) != len(letters):
        return "word repeated (error 25)"
    for g in gs:
        if g in ("43", "43.2") and not tool_table:
            return f"G{g} without a tool table (unsupported command, error 20)"
        if g == "95" and not spindle_sync:
            return "G95 without a spindle encoder (unsupported command)"
        if g in ("85", "86", "89"):
            return f"G{g} is parsed but never run by grblHAL's motion control"
        if g in LATHE_G and lathe is None:
            return f"G{g} outside lathe mode (unsupported command, error 20)"
        if g == "33" and not spindle_sync:
            return "G33 without a spindle encoder (unsupported command, error 20)"
        if g not in G_ACCEPTED and g not in ("43", "43.2", "95") and g not in LATHE_G:
            return f"G{g} is no code of grblHAL's (unsupported command, error 20)"
    for m in ms:
        if not (m in M_ACCEPTED or (m == 7 and mist) or (m == 19 and m19)):
            return f"M{m:g} is no code of grblHAL's (unsupported command, error 20)"
    groups = [GROUPS[g] for g in gs] + [M_GROUPS[int(m)] for m in ms if int(m) in M_GROUPS]
    if len(set(groups)) != len(groups):
        return "modal group violation (error 21)"
    if "F" in values:
        feed = values["F"] > 0
    axis_words = AXES.intersection(values)
    non_modal_axis = [g for g in gs if g in NON_MODAL_AXIS]
    new_motion = next((g for g in gs if g in MOTION), None)
    if (new_motion is not None and new_motion != "80" and (non_modal_axis or "43.1" in gs)) \
            or (non_modal_axis and "43.1" in gs):
        return "axis command conflict (error 24/37)"
    changed = new_motion is not None and new_motion != motion
    if new_motion is not None:
        motion = new_motion
    if motion == "80" and axis_words and not non_modal_axis:
        return "axis words while G80 is in force (error 31)"
    uses_motion = axis_words and not non_modal_axis and "43.1" not in gs
    if motion in CYCLES and (uses_motion or changed):
        if changed and ("R" not in values or "Z" not in values):
            return f"G{motion} newly programmed without R and Z (value word missing)"
        if changed and motion in ("82", "84") and "P" not in values:
            return f"G{motion} newly programmed without P (value word missing)"
        if changed and motion in ("73", "83") and "Q" not in values:
            return f"G{motion} newly programmed without Q (value word missing)"
        if "L" in values and values["L"] <= 0:
            return "a repeat count L of 0 or less (error: non-positive value)"
    if lathe is not None:
        problem = _lathe_block(lathe, gs, ms, values, motion, bool(uses_motion) or new_motion is not None)
        if problem is not None:
            return problem
    if uses_motion and motion not in ("0", "80", "33") and not feed:
        return "a feed move with no feed rate (undefined feed rate, error 22)"
    return motion, feed


def _lathe_block(lathe: _Lathe, gs: list[str], ms: list[float], values: dict[str, float], motion: str | None,
                 moves: bool) -> str | None:
    """The lathe mode's checks of a block, and what it changes (``gcode.c``)."""
    if "96" in gs:
        if "S" not in values:
            return "G96 without S (value word missing, error 28)"
        lathe.css = True
    elif "97" in gs:
        lathe.css = False
    if "S" in values:
        lathe.rpm = values["S"]
    for m in ms:
        if m in (3, 4):
            lathe.spindle_on = True
        elif m in (5, 30, 2):
            lathe.spindle_on = False
    if "D" in values and "96" not in gs:
        return "D without G96 (unused word)"
    if motion == "33" and "K" in values:
        lathe.k = values["K"]
    if moves and motion not in ("0", "80", None):
        if lathe.css and (not lathe.spindle_on or lathe.rpm == 0):
            return "a feed move under G96 with the spindle stopped (spindle not running, error 41)"
        if motion == "33" and lathe.k == 0:
            return "G33 with no K (value out of range)"
    return None
