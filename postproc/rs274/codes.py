"""CodeTable: one dialect's G and M codes, read and written from the same rows.

A dialect of the RS274 family declares its codes once, as rows ``(spelling, modal group, kind,
argument)``, e.g. ``("G00", "01", "motion", "rapid")``. The reader looks a code up by its number as
written (``G0``, ``G00`` and ``G000`` are one code, see ``g_key``); the writer inverts the same rows
(the first row of a ``(kind, argument)`` pair is how the dialect writes it), as sqlglot derives its
inverse tables. What a dialect has no row for, its writer cannot write: an ``UnsupportedError``, never
another dialect's spelling.

Kinds and their arguments (the neutral meaning of a row):

=============  ========================================================  ==========================
kind           argument                                                  IR section
=============  ========================================================  ==========================
motion         rapid, linear, cw, ccw                                    Motion
home           home (first reference return), home2 (second)             Motion
dwell          None                                                      Dwell
path_once      exact_stop (one-shot)                                     PathControl(one_shot)
path           exact_stop, cutting                                       PathControl
plane          XY, ZX, YZ                                                Plane
units          inch, mm                                                  Units
distance       absolute, incremental                                     DistanceMode
feed_mode      per_min, per_rev, inverse_time                            FeedMode
offset         work offset index 1, 2, ...                               WorkOffset
return         initial, r                                                ReturnLevel
cutter         off, left, right                                          CutterCompensation
length         positive, negative, cancel                                ToolLengthOffset
machine        None                                                      MachineCoordinates
cycle          a neutral cycle kind (drill, peck_deep, ...)              CycleCall / CannedCycle
cycle_cancel   None                                                      CycleCancel
program        stop, optional_stop, end, end_rewind (M rows)             ProgramControl
spindle        cw, ccw, stop (M rows)                                    SpindleControl
orient         None (M rows)                                             SpindleOrientation
tool_change    None (M rows)                                             ToolChange
coolant        mist, flood, off (M rows)                                 Coolant
=============  ========================================================  ==========================

M rows carry an empty modal group: M codes conflict by kind (two spindle codes in one block). The
family's block syntaxes read a few G groups by label, Fanuc's numbering: "00" one-shot codes, "01"
motion, "06" units, "08" tool length offset, "09" canned cycles, "15" path control; a dialect's rows
give those meanings those labels (other groups only need to differ from each other).
"""

from __future__ import annotations

from typing import Iterable, Mapping

Row = tuple[str, str, str, object]
"""(spelling, modal group, kind, argument), e.g. ("G00", "01", "motion", "rapid")."""


def g_key(text: str) -> str:
    """Canonical key of a G code number as written: '00' -> '0', '043.40' -> '43.4', '+1' -> '1'. A
    negative number or a lone point is no G code: it keeps its text, so the lookup fails and the reader
    says so.

    The plus sign is read as every other word's number reads it (``M+3``, ``X+1.``: the family's
    readers take a signed number): LinuxCNC's rs274 runs ``G+1`` as ``G1`` and ``G+80`` as ``G80``
    and refuses ``G-1`` ("Negative g code used") [V: rs274 2.9]; the EMC handbook's word is "a letter
    followed by a real_value" [K]; Fanuc's manuals show no signed G code [?], read alike here.
    """
    digits = text[1:] if text[:1] == "+" else text
    if not digits.replace(".", "", 1).isdigit():
        return text
    if "." in digits:
        whole, _, frac = digits.partition(".")
        frac = frac.rstrip("0")
        return f"{int(whole or '0')}.{frac}" if frac else str(int(whole or "0"))
    return str(int(digits))


class CodeTable:
    """A dialect's codes, indexed for reading (``g``, ``m``) and for writing (``spell``).

    Besides the rows whose meaning the IR models, a table holds the codes the dialect keeps verbatim
    (``native_g``/``native_m``: number -> what it does; they round-trip to this dialect only), the codes
    its reader refuses with a message (``refused_g``/``refused_m``), the user M codes it keeps
    verbatim (``user_m``), and the meanings it writes with another row's code (``aliases``: Fagor's ``G81``
    without a dwell is Fanuc's plain drill; the reader reads the row's meaning and the cycle resolution
    tells the two apart, ``CycleWords.undwelled``).
    """

    __slots__ = ("rows", "g", "m", "native_g", "native_m", "refused_g", "refused_m", "user_m", "_spelling")

    def __init__(self, rows: Iterable[Row], *, native_g: Mapping[str, str] | None = None,
                 native_m: Mapping[int, str] | None = None, refused_g: Mapping[str, str] | None = None,
                 refused_m: Mapping[int, str] | None = None, user_m: range = range(0),
                 aliases: Mapping[tuple[str, object], str] | None = None) -> None:
        self.rows: tuple[Row, ...] = tuple(rows)
        self.g: dict[str, tuple[str, str, object]] = {}
        """G number key (``g_key``) -> (modal group, kind, argument)."""
        self.m: dict[int, tuple[str, object]] = {}
        """M number -> (kind, argument)."""
        self._spelling: dict[tuple[str, object], str] = {}
        for spelling, group, kind, arg in self.rows:
            letter, number = spelling[:1], spelling[1:]
            if letter == "G":
                key = g_key(number)
                if key in self.g:
                    raise ValueError(f"code table: G{key} appears twice")
                self.g[key] = (group, kind, arg)
            elif letter == "M" and number.isdigit():
                if int(number) in self.m:
                    raise ValueError(f"code table: M{int(number)} appears twice")
                self.m[int(number)] = (kind, arg)
            else:
                raise ValueError(f"code table: {spelling!r} is neither a G nor an M code")
            self._spelling.setdefault((kind, arg), spelling)
        spellings = {spelling for spelling, _, _, _ in self.rows}
        for meaning, spelling in (aliases or {}).items():
            if spelling not in spellings or meaning in self._spelling:
                raise ValueError(f"code table: alias {meaning} -> {spelling!r} is not another row's code")
            self._spelling[meaning] = spelling
        self.native_g: dict[str, str] = {g_key(k): v for k, v in (native_g or {}).items()}
        self.native_m: dict[int, str] = dict(native_m or {})
        self.refused_g: dict[str, str] = {g_key(k): v for k, v in (refused_g or {}).items()}
        self.refused_m: dict[int, str] = dict(refused_m or {})
        self.user_m = user_m

    def spell(self, kind: str, arg: object = None) -> str | None:
        """How the dialect writes ``(kind, arg)`` (the first row that reads as it), or None."""
        return self._spelling.get((kind, arg))

    def arguments(self, kind: str) -> dict[object, str]:
        """Every argument of ``kind`` the dialect writes, with its spelling (e.g. the cycles it runs)."""
        return {arg: spelling for (k, arg), spelling in self._spelling.items() if k == kind}

    def __repr__(self) -> str:
        return f"CodeTable({len(self.rows)} rows)"
