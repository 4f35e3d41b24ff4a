"""Hypothesis strategies for dialect authors: neutral programs a writer must spell, and garbage a reader
must refuse with located errors.

``neutral_programs(dialect)`` draws programs from the IR (moves, arcs, a hole cycle, dwells, spindle,
coolant, comments, block numbers) within what the dialect's capability table says it can express;
``garbage(lines)`` mutates real program lines into malformed ones. Coordinates are on a 0.001 mm grid,
so any writer with three or more decimals spells them exactly.
"""

from __future__ import annotations

from typing import Sequence

from hypothesis import strategies as st

from ..dialect import Dialect
from .neutral import NeutralProgram, Op, cycle_rules, drill_cycle

GRID = 1000
"""Coordinates are whole multiples of 1/GRID mm."""


def coordinate(lo: float, hi: float) -> st.SearchStrategy[float]:
    """A coordinate in [lo, hi] on the 0.001 mm grid."""
    return st.integers(int(lo * GRID), int(hi * GRID)).map(lambda n: n / GRID)


FEEDS = st.sampled_from([50.0, 120.0, 300.0, 1000.0])
COMMENT = st.text(alphabet="ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789 ", min_size=1, max_size=20).map(str.strip).filter(bool)
"""Comment text every dialect keeps: capitals, digits and inner spaces."""


@st.composite
def _mill_ops(draw: st.DrawFn, dialect: type[Dialect], cycles: bool) -> tuple[dict[str, float], list[Op]]:
    pos = {"X": 0.0, "Y": 0.0, "Z": draw(coordinate(20, 50))}
    start = dict(pos)
    ops: list[Op] = []
    for _ in range(draw(st.integers(1, 8))):
        choice = draw(st.sampled_from(["rapid", "linear", "arc", "dwell", "spindle", "coolant", "comment"]
                                      + (["cycle"] if cycles else [])))
        if choice in ("rapid", "linear"):
            axes = {a: draw(coordinate(-100, 100)) for a in draw(st.sets(st.sampled_from("XYZ"), min_size=1))}
            if "Z" in axes:
                axes["Z"] = draw(coordinate(-10, 50))
            pos.update(axes)
            ops.append((choice, axes, draw(FEEDS)) if choice == "linear" else (choice, axes))
        elif choice == "arc":
            # a half circle: the centre halfway to the end point, so the radius is exact by construction
            dx, dy = draw(coordinate(-20, 20)), draw(coordinate(-20, 20))
            if abs(dx) + abs(dy) < 0.5:
                continue
            end = {"X": round(pos["X"] + 2 * dx, 3), "Y": round(pos["Y"] + 2 * dy, 3)}
            ops.append(("arc", draw(st.sampled_from(["cw", "ccw"])), end, {"X": dx, "Y": dy}, draw(FEEDS)))
            pos.update(end)
        elif choice == "cycle":
            top = pos["Z"]
            if top < 5:
                continue
            r = draw(coordinate(1, min(top - 1, 5)))
            bottom = -draw(coordinate(1, 15))
            hole = (draw(coordinate(-50, 50)), draw(coordinate(-50, 50)))
            ops.append(("cycle", drill_cycle("drill", pos, hole, bottom=bottom, r=r, feed=draw(FEEDS),
                                             semantics=cycle_rules(dialect))))
            pos.update({"X": hole[0], "Y": hole[1]})
        else:
            ops.append(_common(draw, choice, dialect))
    return start, ops


@st.composite
def _lathe_ops(draw: st.DrawFn, dialect: type[Dialect]) -> tuple[dict[str, float], list[Op]]:
    start = {"X": draw(coordinate(20, 100)), "Z": draw(coordinate(2, 50))}
    ops: list[Op] = [_common(draw, "spindle", dialect)]  # a lathe feeds per revolution: the spindle turns first
    for _ in range(draw(st.integers(1, 8))):
        choice = draw(st.sampled_from(["rapid", "linear", "dwell", "spindle", "coolant", "comment"]))
        if choice in ("rapid", "linear"):
            axes = {a: draw(coordinate(0, 100) if a == "X" else coordinate(-80, 50))
                    for a in draw(st.sets(st.sampled_from("XZ"), min_size=1))}
            ops.append((choice, axes, draw(FEEDS)) if choice == "linear" else (choice, axes))
        else:
            ops.append(_common(draw, choice, dialect))
    return start, ops


def _common(draw: st.DrawFn, choice: str, dialect: type[Dialect]) -> Op:
    if choice == "dwell":
        return ("dwell", draw(st.sampled_from([0.5, 1.0, 1.5, 2.0])))
    if choice == "spindle":
        return ("spindle", draw(st.sampled_from(["cw", "ccw"])), float(draw(st.integers(1, 60)) * 100))
    if choice == "coolant":
        return ("coolant", draw(st.sampled_from(["flood", "off"])))
    return ("comment", draw(COMMENT))


@st.composite
def neutral_programs(draw: st.DrawFn, dialect: type[Dialect], lathe: bool | None = None) -> NeutralProgram:
    """Programs in the IR that ``dialect`` can express: a lathe's (ZX plane, X and Z) when ``lathe``
    (default: when the dialect has no mill), else a mill's, with a drilling cycle where the dialect runs
    one or has it expanded (every mill dialect can: an expanded cycle is plain moves)."""
    if lathe is None:
        lathe = "mill" not in dialect.MACHINE_TYPES
    start, ops = draw(_lathe_ops(dialect) if lathe else _mill_ops(dialect, True))
    return NeutralProgram(ops, lathe=lathe, numbered=draw(st.booleans()), start=start)


NOISE = st.sampled_from(list("!\"#$&'()*+,-./0123456789:;<=>?@[\\]^_`{|}~ ") + list("ABCDEFGHIJKLMNOPQRSTUVWXYZ")
                        + ["\t", "\x00", "\x7f", "\u00e9", "\uff38", "1e999", "9" * 40, ".", "--", "[", "]"])
"""What garbage is made of: punctuation, letters, digits, control and non-ASCII characters, huge numbers."""


@st.composite
def garbage(draw: st.DrawFn, lines: Sequence[str]) -> str:
    """A program made by mutating real lines (``lines``: a dialect's own examples): characters inserted,
    deleted or replaced, lines dropped or duplicated. Most are invalid; all must be read or refused with
    located errors, never crash."""
    if not lines:
        lines = [""]
    picked = draw(st.lists(st.sampled_from(list(lines)), min_size=1, max_size=12))
    out: list[str] = []
    for line in picked:
        for _ in range(draw(st.integers(0, 3))):
            where = draw(st.integers(0, len(line)))
            action = draw(st.sampled_from(["insert", "delete", "replace"]))
            noise = draw(NOISE)
            if action == "insert":
                line = line[:where] + noise + line[where:]
            elif action == "delete":
                line = line[:where] + line[where + 1:]
            else:
                line = line[:where] + noise + line[where + 1:]
        out.append(line)
    return "\n".join(out) + draw(st.sampled_from(["\n", "", "\r\n"]))
