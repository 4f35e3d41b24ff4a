"""The frame commands in the frame evaluation (``postproc.frames.lowering``): a command read into the frame
(``frame`` holds each command's rules), the axes a command leaves to be programmed again, and the rotations.

Functions of the evaluator (``ev``), apart from the carrying of moves and the offset changes
(``offset_changes``): a module of its own so that neither grows past one job (issue 30).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..errors import ProgramError
from ..ir.expr import Expr
from ..ir import Block, Motion, Section
from .affine import XYZ
from .frame import PLANE_AXES, Frame, chain_component
from .section import FrameChange
from .words import COMPUTED, LAYERED_FORBIDDEN, LINEAR, SWAPPED, axes_of

if TYPE_CHECKING:
    from .evaluation import Evaluation


def command(ev: Evaluation, block: Block, change: FrameChange) -> None:
    frame = ev.frame_for(change.rules)
    if frame.rules != change.rules:
        raise ProgramError(f"{change.describe()} beside another controller's frame commands")
    kind, scale, p = change.kind, ev.scale, ev.p
    words: dict[str, float] = {}
    for letter, value in change.words.items():
        if isinstance(value, Expr):
            raise ProgramError(COMPUTED)
        words[letter] = value * scale if letter in LINEAR else value
    layered = frame.rules == "layered"
    if layered and kind in ("local", "origin") and frame.linear_active():
        raise ProgramError(LAYERED_FORBIDDEN.format(what=change.describe()))
    if layered and kind in ("local", "origin") and ev.modal.distance == "incremental":
        raise ProgramError(f"{change.describe()} in incremental mode is not simulated (whether its words are "
                           "increments is not settled [?]): program it in absolute mode")
    compensating = ev.modal.extra.get("frames.cutter") in SWAPPED
    if compensating and (kind in ("local", "origin", "origin_clear", "origin_suspend", "origin_restore")
                         or frame.rules in ("layered", "chain", "rotate_first")):
        # [V] rs274: "Cannot change axis offsets with cutter radius comp"; [K] Fanuc commands mirror,
        # scaling and rotation before compensation starts and cancels them after it ends; a SINUMERIK
        # frame change under G41/G42 is not simulated [?: how the compensated path joins across it]
        raise ProgramError(f"{change.describe()} with cutter compensation on cannot be run (cancel it first)")
    if frame.rules == "chain":
        frame.increment_setting = change.increment_setting  # (the family's words, for ``pending``'s error)
        frame.chain(chain_component(change.kind, words, ev.modal.plane, change.describe()),
                    kind.endswith("_add"), p)
        return
    if kind == "local":
        frame.set_local(axes_of(words), p)
    elif kind == "origin":
        if layered and any(frame.local.values()):
            raise ProgramError(f"{change.describe()} while a local coordinate system is in force is not simulated "
                               "(whether it cancels that system is not settled [?]): cancel it first")
        frame.set_origin(axes_of(words), p, change.describe())
        ev.reached.unsettled.difference_update(words)  # the current point now reads the words
    elif kind in ("origin_clear", "origin_suspend"):
        frame.clear_origin(p, kind == "origin_suspend")
    elif kind == "origin_restore":
        frame.restore_origin(p)
    elif kind == "rotate":
        rotate(ev, frame, change, words)
    elif kind == "rotate_off":
        frame.unrotate(p)
    elif kind == "scale":
        if frame.rotation is not None or frame.scaling is not None:
            # [K] Fanuc: mirror, then scaling, then rotation; cancelled in reverse
            raise ProgramError(f"{change.describe()}: scaling is commanded before coordinate rotation, and "
                               "not again while it is on")
        common = words.get("P")
        factors = tuple(words.get(f, 1.0 if common is None else common) for f in "IJK")
        centre = tuple(words[a] if a in words else 0.0 if f == 1.0 else _here(ev, a, change)
                       for a, f in zip(XYZ, factors))
        frame.scale(centre, factors, p)  # type: ignore[arg-type]
    elif kind == "scale_off":
        if frame.rotation is not None:
            raise ProgramError("scaling is cancelled after coordinate rotation (cancel the rotation first)")
        frame.unscale(p)
    elif kind == "mirror":
        if frame.rotation is not None or frame.scaling is not None:
            # [K] Siemens' ISO-dialect manual 3.2, as Fanuc: no mirror command in scaling or rotation mode
            raise ProgramError(f"{change.describe()} while scaling or coordinate rotation is on cannot be run")
        frame.set_mirror(axes_of(words), p)
    elif kind == "mirror_off":
        if frame.rotation is not None or frame.scaling is not None:
            raise ProgramError(f"{change.describe()} while scaling or coordinate rotation is on cannot be run")
        frame.clear_mirror(tuple(axes_of(words)), p)
    elif kind == "polar":
        frame.polar = ev.modal.plane
    elif kind == "polar_off":
        frame.polar = None


def pending(ev: Evaluation, s: dict[str, Section], frame: Frame) -> None:
    """chain rules: the first incremental move on an axis a frame change moved is refused: whether it
    also travels that change is a setting of the controller, which the family names
    (``FrameChange.increment_setting``: SINUMERIK's in ``dialects.siemens.frames``). An absolute move
    settles the axis."""
    m = s.get("Motion")
    if not isinstance(m, Motion) or m.mode is None or "MachineCoordinates" in s:
        return
    if ev.modal.distance == "incremental":
        for axis in m.axes:
            if axis in frame.pending:
                setting = frame.increment_setting or "a setting of the controller"
                raise ProgramError(f"an incremental {axis} after a frame change: whether it also travels the "
                                   f"change is {setting}: program {axis} absolutely first")
        return
    frame.pending.difference_update(m.axes)


def rotate(ev: Evaluation, frame: Frame, change: FrameChange, words: dict[str, float]) -> None:
    if frame.rules == "rotate_first":
        rotate_first(ev, frame, change, words)
        return
    plane = ev.modal.plane
    if plane != "XY":
        raise ProgramError(f"{change.describe()} in the {plane} plane is not simulated (the sense of a rotation "
                           "there is not settled [?]): only in the XY plane")
    if frame.rotation is not None:
        raise ProgramError(f"{change.describe()} while coordinate rotation is already on (cancel it first)")
    if "R" not in words:
        source = change.omitted or "the controller's settings"  # (the family's words: ``FrameChange.omitted``)
        raise ProgramError(f"{change.describe()} without R takes its angle from {source}, not known here: program R")
    a1, a2, _ = PLANE_AXES[plane]
    if ev.modal.distance == "incremental" and (a1 in words or a2 in words):
        raise ProgramError(f"{change.describe()} in incremental mode is not simulated (whether its centre words "
                           "are increments is not settled [?]): program the centre in absolute mode")
    c1 = words[a1] if a1 in words else _here(ev, a1, change)
    c2 = words[a2] if a2 in words else _here(ev, a2, change)
    degrees = words["R"]
    if ev.ctx.setup.controller.rotation_incremental and ev.modal.distance == "incremental":
        # [V] Fanuc 0i-A connection manual, parameter 5400#0 RIN = 1: R follows G90/G91; [K] Haas setting
        # 73: "each G68 command changes the rotation angle by the value in R"
        if frame.last_angle is None:
            raise ProgramError(f"{change.describe()}: an incremental angle needs a rotation before it (its "
                               "reference at the program's start is not settled [?]): program R absolutely")
        degrees += frame.last_angle
    frame.rotate(plane, c1, c2, degrees, ev.p)


def rotate_first(ev: Evaluation, frame: Frame, change: FrameChange, words: dict[str, float]) -> None:
    """ISG G68 [V: Beckhoff TF5200 programming manual, "Rotate the coordinate system in the plane
    (G68/G69)"]: R in degrees, absolute (none: 0); the centre's absolute coordinates on the plane's two
    main axes (G17 X and Y, G18 Z and X, G19 Y and Z; G91 or not), an omitted one the current position; a
    G68 replaces the rotation in force. The rotation acts on the programmed coordinates before every
    offset and mirror, which stay in the machine's axis directions: ``w = offsets(R p)``. A positive angle
    turns from the plane's first main axis toward its second (G17: X toward Y, as the manual's figure
    draws; G18: Z toward X; G19: Y toward Z), counter-clockwise seen from the third axis, the sense G03
    runs in that plane [K: the G17 figure and the planes' axis order of "Selection of planes (G17/G18/G19)";
    the sense in G18/G19 is not drawn]. Refused [?]: an omitted centre while a rotation is on (whether "the
    current position" is then read turned is not stated)."""
    plane = ev.modal.plane
    a1, a2, _ = PLANE_AXES[plane]
    if frame.rotation is not None and (a1 not in words or a2 not in words):
        raise ProgramError(f"{change.describe()} without its centre while a rotation is on: whether the current "
                           f"position is read turned is not settled [?]: program {a1} and {a2}")
    c1 = words[a1] if a1 in words else _here(ev, a1, change)
    c2 = words[a2] if a2 in words else _here(ev, a2, change)
    frame.rotate(plane, c1, c2, words.get("R", 0.0), ev.p)


def _here(ev: Evaluation, axis: str, change: FrameChange) -> float:
    """The current point as a centre the command omits ([V] Fanuc 15i/16i: the tool position)."""
    here = ev.p.get(axis)
    if here is None:
        raise ProgramError(f"{change.describe()} without {axis} takes the current position as its centre, "
                           f"which is not known here: program {axis}")
    return here

# -- moves ---------------------------------------------------------------------------------------
