"""The LinuxCNC interpreter (``rs274``, Debian package ``linuxcnc-uspace``) as a test oracle.

``run_rs274(text)`` runs a program through the real interpreter and returns its canonical calls
(one ``N..... NAME(args)`` line per call); ``canonical_moves(lines)`` turns such lines -- or the
``expected`` files of the shared conformance cases -- into events in postproc's toolpath vocabulary
(DESIGN.md, "Toolpath JSON lines"), so the two can be compared directly.

Facts about the packaged interpreter that this module relies on are in ``RS274_NOTES.md`` beside it.

Event vocabulary produced by ``canonical_moves`` (all lengths absolute, in millimetres):

- motion ``{"move": "rapid"|"feed"|"cw"|"ccw", "x", "y", "z"}``; arcs add the absolute centre
  ``"cx", "cy", "cz"`` (on the axis normal to the plane: the arc's start value, as postproc's toolpath does)
  and ``"plane"``: ``"XY"|"ZX"|"YZ"``; an arc of more than one full turn (G2/G3 with P>1) adds ``"turns"``.
  Spindle-synchronised feeds (G33/G76, between ``START_SPEED_FEED_SYNC`` and ``STOP_SPEED_FEED_SYNCH``)
  are plain ``"feed"`` moves. A rigid tap (G33.1: ``RIGID_TAP(x, y, z)`` after ``START_SPEED_FEED_SYNC(K, ..)``)
  is two ``"tap"`` moves, to its end point and back to where it started, ``"f"`` the K pitch in mm (with
  ``feeds``), as postproc's toolpath writes them.
- ``{"event": "dwell", "seconds": s}`` (LinuxCNC also prints ``DWELL(0)`` inside G84/G74/G86 without P)
- ``{"event": "spindle", "dir": "cw"|"ccw"|"stop"}`` (note: M2/M30 and M6 print a spindle stop too)
- ``{"event": "orient", "angle": a}`` (M19 with an R/Q/P word; a bare ``M19`` prints nothing)
- ``{"event": "stop", "optional": bool}`` (M0 / M1)
- ``{"event": "tool", "number": n}`` (M6; the ``expected`` files print ``CHANGE_TOOL()`` without the number),
  ``{"event": "coolant", "on": bool}`` (emitted when flood-or-mist changes), ``{"event": "end"}`` (M2/M30)

Coordinates are LinuxCNC's canonical ones: work offsets (G5x/G92) applied, tool length offset NOT
applied (``USE_TOOL_LENGTH_OFFSET`` is ignored here on purpose); in lathe diameter mode (G7) X is the radius.
Only X, Y, Z are reported; rotary and UVW axes are ignored.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
from pathlib import Path
from typing import Any, Iterable, Iterator

__all__ = [
    "RS274",
    "RS274Error",
    "RS274Timeout",
    "RS274Unavailable",
    "assert_same_moves",
    "available",
    "canonical_moves",
    "motions",
    "run_rs274",
]

MM_PER_INCH = 25.4
ZERO_LENGTH_TOL = 1e-9
"""A straight move shorter than this on every axis (in program units) is dropped."""
PLACES = 6
"""Decimals kept after unit conversion (matches postproc's toolpath)."""

RS274: str | None = os.environ.get("POSTPROC_RS274") or shutil.which("rs274") or (
    "/usr/bin/rs274" if os.access("/usr/bin/rs274", os.X_OK) else None
)
"""Path of the interpreter, or None. ``POSTPROC_RS274`` overrides the discovery."""


def available() -> bool:
    """True when the LinuxCNC interpreter can be run."""
    return RS274 is not None and os.access(RS274, os.X_OK)


class RS274Unavailable(RuntimeError):
    """The interpreter is not installed."""


class RS274Error(RuntimeError):
    """The interpreter reported an error (non-zero exit status)."""

    def __init__(self, message: str, *, returncode: int | None, stderr: str, calls: list[str]):
        super().__init__(message)
        self.returncode = returncode
        self.stderr = stderr
        self.calls = calls


class RS274Timeout(RS274Error):
    """The interpreter did not finish in time (some LinuxCNC versions loop forever on bad G71 profiles)."""


# "    12 N..... STRAIGHT_FEED(1.0000, ...)"  (rs274 output: a line counter, then the N-word placeholder)
# " N..... STRAIGHT_FEED(1.0000, ...)"       (the conformance ``expected`` files)
_CALL = re.compile(r"^\s*(?:\d+\s+)?(?:N\S*\s+)?([A-Z_][A-Z0-9_.]*)\((.*)\)\s*$")
_COUNTER = re.compile(r"^\s*\d+\s+(?=N\S*\s)")
_UNIT_SCALE = {"CANON_UNITS_MM": 1.0, "CANON_UNITS_INCHES": MM_PER_INCH, "CANON_UNITS_CM": 10.0}
_PLANES = {"CANON_PLANE_XY": "XY", "CANON_PLANE_XZ": "ZX", "CANON_PLANE_YZ": "YZ"}
# Per plane: indices into (x, y, z) of the first and second ARC_FEED axis, and of the normal axis.
# G18 prints its arcs in (Z, X) order (conformance/README.md).
_ARC_AXES = {"XY": (0, 1, 2), "ZX": (2, 0, 1), "YZ": (1, 2, 0)}
_MOTION = ("rapid", "feed", "cw", "ccw", "tap")


def run_rs274(
    program_text: str,
    *,
    timeout: float = 20,
    tool_table: str | None = None,
    name: str = "prog.ngc",
    ini: str | None = None,
) -> list[str]:
    """Run ``rs274 -g`` on a program and return its canonical call lines (``N..... NAME(args)``).

    The program is written to a fresh temporary directory which is also the working directory and
    ``HOME``, so nothing leaks between runs: rs274 may write a ``sim.var`` parameter file there, and
    it keeps its tool table in ``$HOME/.tool.mmap``, which two runs sharing a HOME corrupt (bus
    errors, wrong Z, "tool not found"). The directory goes when the run ends. stdin is closed.
    The program must end with M2/M30 or ``%``, as LinuxCNC requires ("File ended with no percent sign
    or program end" otherwise). ``tool_table`` is the text of a LinuxCNC tool table (``T1 P1 Z.. D..``
    lines; lengths in inches as rs274 reads them); without it rs274 uses a built-in table. ``ini`` is the text
    of an INI file rs274 reads (``-i``: the interpreter's settings, e.g. ``[EMCIO] TOOL_CHANGE_WITH_SPINDLE_ON``).

    Lines the interpreter prints that are not canonical calls (e.g. ``(print,...)`` output) are left out.
    Raises RS274Unavailable, RS274Error (message = the interpreter's error text and the offending block)
    or RS274Timeout.
    """
    if not available():
        raise RS274Unavailable("the LinuxCNC interpreter rs274 is not installed (apt-get install linuxcnc-uspace)")
    with tempfile.TemporaryDirectory(prefix="rs274-") as tmp:
        work = Path(tmp)
        prog = work / name
        prog.write_text(program_text if program_text.endswith("\n") else program_text + "\n", encoding="utf-8")
        cmd = [RS274]
        if tool_table is not None:
            (work / "tool.tbl").write_text(tool_table, encoding="utf-8")
            cmd += ["-t", "tool.tbl"]
        if ini is not None:
            (work / "machine.ini").write_text(ini, encoding="utf-8")
            cmd += ["-i", "machine.ini"]
        cmd += ["-g", name]
        out_path, err_path = work / "stdout.txt", work / "stderr.txt"
        with open(out_path, "wb") as out, open(err_path, "wb") as err:
            try:
                proc = subprocess.run(cmd, cwd=work, env=_private_env(work), stdin=subprocess.DEVNULL,
                                      stdout=out, stderr=err, timeout=timeout, check=False)
                returncode: int | None = proc.returncode
            except subprocess.TimeoutExpired:
                returncode = None
        stderr = _clean_stderr(err_path.read_text(encoding="utf-8", errors="replace"))
        if returncode is None:
            head = _read_head(out_path, 20)
            raise RS274Timeout(
                f"rs274 did not finish within {timeout:g} s (endless loop in the interpreter?)"
                + (f"\nstderr:\n{stderr}" if stderr else ""),
                returncode=None, stderr=stderr, calls=head)
        calls = [_COUNTER.sub("", line) for line in out_path.read_text(encoding="utf-8", errors="replace")
                 .splitlines() if _CALL.match(line)]
    if returncode != 0:
        tail = "\n".join(calls[-5:])
        raise RS274Error(
            f"rs274 reported an error (exit status {returncode}):\n{stderr or '(no error text)'}"
            f"\nlast canonical calls:\n{tail}",
            returncode=returncode, stderr=stderr, calls=calls)
    return calls


def _private_env(home: Path) -> dict[str, str]:
    """The environment of one run: this run's own HOME (rs274 maps its tool table at ``$HOME/.tool.mmap``)."""
    env = dict(os.environ)
    env["HOME"] = str(home)
    return env


def _clean_stderr(text: str) -> str:
    """rs274 prints "executing" on stderr for every run; the rest is the error and the offending block."""
    return "\n".join(line for line in text.splitlines() if line.strip() and line.strip() != "executing")


def _read_head(path: Path, n: int) -> list[str]:
    out: list[str] = []
    with open(path, encoding="utf-8", errors="replace") as fh:
        for line in fh:
            if _CALL.match(line):
                out.append(_COUNTER.sub("", line.rstrip("\n")))
                if len(out) >= n:
                    break
    return out


def _numbers(args: str) -> list[float]:
    out = []
    for tok in re.split(r"[,\s]+", args.strip()):
        try:
            out.append(float(tok))
        except ValueError:
            pass
    return out


def _mm(v: float, scale: float) -> float:
    r = round(v * scale, PLACES)
    return 0.0 if r == 0 else r  # no negative zero


def canonical_moves(lines: Iterable[str] | str, *, start: tuple[float, float, float] | None = None,
                    feeds: bool = False, synced: bool = False, modes: bool = False) -> list[dict[str, Any]]:
    """Parse canonical call lines (rs274 output or an ``expected`` file) into toolpath events (see module doc).

    With ``feeds``, feed moves and arcs carry ``"f"``: the last ``SET_FEED_RATE``, read in the units in
    force when it was called (LinuxCNC keeps the physical rate across a unit change), in mm per
    minute, or mm per revolution under G95 (inverse time, G93, is not modelled).

    With ``synced``, a spindle-synchronised feed (G33, G76: between ``START_SPEED_FEED_SYNC`` and
    ``STOP_SPEED_FEED_SYNCH``) carries ``"sync"``: its distance per revolution along the path, in mm.

    With ``modes``, feed moves and arcs carry ``"per_rev"``: whether the feed is per revolution, the last
    ``SET_FEED_MODE(spindle, mode)`` (mode 1 under G95, 0 under G94 and G93 [V: rs274 2.9, run here]) or a
    spindle-synchronised move.

    ``start`` is the position in mm (canonical frame) before the first call; by default it is unknown, so the first straight move is never dropped as zero-length and an arc as the
    very first motion takes its normal-axis centre from its end point. (Standalone rs274 starts at 0, 0, 0.)
    """
    if isinstance(lines, str):
        lines = lines.splitlines()
    events: list[dict[str, Any]] = []
    scale = 1.0
    plane = "XY"
    pos: tuple[float, float, float] | None = None  # last end point, in mm (unrounded)
    if start is not None:
        pos = (float(start[0]), float(start[1]), float(start[2]))
    flood = mist = False
    feed: float | None = None  # mm per minute (or per rev)
    sync: float | None = None  # the pitch of a spindle-synchronised move (START_SPEED_FEED_SYNC), mm
    in_sync = False  # between START_SPEED_FEED_SYNC and STOP_SPEED_FEED_SYNCH
    per_rev = False  # the last SET_FEED_MODE's: G95
    for line in lines:
        m = _CALL.match(line)
        if not m:
            continue
        name, args = m.group(1), m.group(2).strip()
        if name == "USE_LENGTH_UNITS":
            scale = _UNIT_SCALE.get(args, scale)
        elif name == "SET_FEED_RATE":
            feed = _numbers(args)[0] * scale
        elif name == "SET_FEED_MODE":
            per_rev = _numbers(args)[-1] == 1
        elif name == "START_SPEED_FEED_SYNC":
            sync = _numbers(args)[0] * scale
            in_sync = True
        elif name == "STOP_SPEED_FEED_SYNCH":
            in_sync = False
        elif name == "RIGID_TAP":
            v = _numbers(args)
            back = pos or (0.0, 0.0, 0.0)
            for x, y, z in ((v[0] * scale, v[1] * scale, v[2] * scale), back):
                events.append({"move": "tap", "x": _mm(x, 1.0), "y": _mm(y, 1.0), "z": _mm(z, 1.0)})
                if feeds and sync is not None:
                    events[-1]["f"] = round(sync, PLACES)
        elif name == "SELECT_PLANE":
            plane = _PLANES.get(args, plane)
        elif name in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED"):
            v = _numbers(args)
            new = (v[0] * scale, v[1] * scale, v[2] * scale)
            tol = ZERO_LENGTH_TOL * scale
            if pos is not None and all(abs(a - b) <= tol for a, b in zip(pos, new)):
                continue
            pos = new
            events.append({"move": "rapid" if name == "STRAIGHT_TRAVERSE" else "feed",
                           "x": _mm(v[0], scale), "y": _mm(v[1], scale), "z": _mm(v[2], scale)})
            if feeds and name == "STRAIGHT_FEED" and feed is not None:
                events[-1]["f"] = round(feed, PLACES)
            if synced and in_sync and name == "STRAIGHT_FEED" and sync is not None:
                events[-1]["sync"] = round(abs(sync), PLACES)
            if modes and name == "STRAIGHT_FEED":
                events[-1]["per_rev"] = per_rev or in_sync
        elif name == "ARC_FEED":
            v = _numbers(args)
            first, second, c_first, c_second, rotation, normal_end = v[:6]
            i1, i2, i_n = _ARC_AXES[plane]
            end = [0.0, 0.0, 0.0]
            end[i1], end[i2], end[i_n] = first, second, normal_end
            centre = [0.0, 0.0, 0.0]
            centre[i1], centre[i2] = c_first, c_second
            centre[i_n] = pos[i_n] / scale if pos is not None else normal_end
            turns = int(abs(rotation))
            ev: dict[str, Any] = {"move": "ccw" if rotation > 0 else "cw",
                                  "x": _mm(end[0], scale), "y": _mm(end[1], scale), "z": _mm(end[2], scale),
                                  "cx": _mm(centre[0], scale), "cy": _mm(centre[1], scale),
                                  "cz": _mm(centre[2], scale), "plane": plane}
            if turns > 1:
                ev["turns"] = turns
            if feeds and feed is not None:
                ev["f"] = round(feed, PLACES)
            if modes:
                ev["per_rev"] = per_rev or in_sync
            events.append(ev)
            pos = (end[0] * scale, end[1] * scale, end[2] * scale)
        elif name == "DWELL":
            events.append({"event": "dwell", "seconds": _numbers(args)[0]})
        elif name == "START_SPINDLE_CLOCKWISE":
            events.append({"event": "spindle", "dir": "cw"})
        elif name == "START_SPINDLE_COUNTERCLOCKWISE":
            events.append({"event": "spindle", "dir": "ccw"})
        elif name == "STOP_SPINDLE_TURNING":
            events.append({"event": "spindle", "dir": "stop"})
        elif name == "ORIENT_SPINDLE":
            v = _numbers(args)  # (spindle, angle in degrees, direction mode)
            events.append({"event": "orient", "angle": v[1] if len(v) > 1 else 0.0})
        elif name == "PROGRAM_STOP":
            events.append({"event": "stop", "optional": False})
        elif name == "OPTIONAL_PROGRAM_STOP":
            events.append({"event": "stop", "optional": True})
        elif name == "PROGRAM_END":
            events.append({"event": "end"})
        elif name == "CHANGE_TOOL":
            v = _numbers(args)
            events.append({"event": "tool", "number": int(v[0])} if v else {"event": "tool"})
        elif name in ("FLOOD_ON", "FLOOD_OFF", "MIST_ON", "MIST_OFF"):
            # Two channels (M8 flood, M7 mist; M9 prints MIST_OFF and FLOOD_OFF) -> one on/off state.
            was = flood or mist
            if name.startswith("FLOOD"):
                flood = name.endswith("_ON")
            else:
                mist = name.endswith("_ON")
            if (flood or mist) != was:
                events.append({"event": "coolant", "on": flood or mist})
        # Everything else (feed rate, offsets, path mode, overrides, comments, tool length offset...) is
        # not part of the toolpath.
    return events


def motions(events: Iterable[dict[str, Any]]) -> list[dict[str, Any]]:
    """Only the motion events."""
    return [e for e in events if e.get("move") in _MOTION]


def assert_same_moves(ours: list[dict[str, Any]], theirs: list[dict[str, Any]], *context: str,
                      tolerance: float = 2e-4) -> None:
    """``ours`` (a toolpath's moves) are ``theirs`` (rs274's): as many, of the same kinds, every end point within
    ``tolerance`` mm on X, Y and Z (rs274 prints 4 decimals); ``context`` (the programs) goes into a failure."""
    assert len(ours) == len(theirs), f"{len(ours)} moves here, {len(theirs)} in rs274\n" + "\n".join(context)
    for n, (a, b) in enumerate(zip(ours, theirs)):
        assert a["move"] == b["move"], (n, a, b, *context)
        assert max(abs(float(a[k]) - float(b[k])) for k in "xyz") <= tolerance, (n, a, b, *context)


_STRAIGHT = re.compile(r"(STRAIGHT_TRAVERSE|STRAIGHT_FEED)\(([^)]*)\)")
_LENGTH_OFFSET = re.compile(r"USE_TOOL_LENGTH_OFFSET\(\s*([-\d.]+)\s+([-\d.]+)\s+([-\d.]+)")


def straight_moves_with_length(calls: Iterable[str]) -> Iterator[tuple[float, float, float, float, float]]:
    """(X, Y, Z, length offset X, length offset Z) of each straight move rs274 printed (its canonical calls, in
    its units): the programmed end and the offset of the last ``USE_TOOL_LENGTH_OFFSET`` before it (zero before
    one), so a test adds the two for the controlled point it compares."""
    ox = oz = 0.0
    for call in calls:
        if offset := _LENGTH_OFFSET.search(call):
            ox, oz = float(offset.group(1)), float(offset.group(3))
        elif move := _STRAIGHT.search(call):
            x, y, z = (float(v) for v in move.group(2).split(",")[:3])
            yield x, y, z, ox, oz
