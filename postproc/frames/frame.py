"""The frame a program's points are read in, and how each frame command changes it.

A programmed point ``p`` (program coordinates) reaches the work coordinates (those of the active work
system, G54...) as ``w = map p`` on X, Y, Z, and as ``w = p + offset`` on the other axes. Four rule sets,
named after what they do; a dialect's reading names the one its controller follows (``FrameChange.rules``):

* ``shared_offset`` (RS274/NGC: LinuxCNC, grbl, [V] ``src/emc/rs274ngc/interp_convert.cc`` ``convert_axis_offsets`` and
  ``convert_setup``, checked with rs274's SET_G92_OFFSET/SET_XY_ROTATION): ``w = R(p + o)``, where ``o``
  is the one offset G52 and G92 share (G52 sets it, G92 makes the current point read the programmed
  value: ``o = p + o - value``; G92.1 and G92.2 clear it, G92.1 also its parameters, G92.3 restores it
  from them) and ``R`` is the active work system's XY rotation (G10 L2 R, about the work origin).
* ``layered`` (Fanuc 0i/30i mill, and the ISO dialects that follow it): mirror, scaling, rotation, then the
  offsets, ``w = T(Rot(Scale(Mirror(p))))`` [K: Fanuc 0i-MF operator's manual,
  "programmable mirror image", as in Siemens' ISO-dialect manual 3.2: mirror, then scaling, then
  rotation, commanded in that order and cancelled in reverse]; ``T`` adds the G52 local offset and the
  G92 shift. G68 rotates about its centre in the active plane (R absolute: parameter 5400#0 RIN = 0,
  [V] 0i-A connection manual), G51 scales about its centre (a negative factor mirrors), G51.1 mirrors
  about a line per axis.
* ``rotate_first`` (Beckhoff TwinCAT CNC, ISG): ``w = T(Rot(p))``, G68's rotation about its centre acting on the
  programmed coordinates before any offset (``postproc.frames.commands`` ``rotate_first``).
* ``chain`` (SINUMERIK's programmable frame, ``$P_PFRAME``): ``w = F p`` where each replacing command
  (TRANS, ROT, SCALE, MIRROR) sets ``F`` to its one component, clearing offset, rotation, scaling and
  mirroring alike, and each additive one (ATRANS, AROT, ASCALE, AMIRROR) chains its component onto the
  frame in force, ``F = F . c``: it acts in the coordinates the frame already makes, so an ATRANS after a
  SCALE is scaled and an AROT after a TRANS turns about the shifted zero [K: SINUMERIK 808D programming
  manual 01/2014 p.56 "deletes old instructions for offsetting, rotation, scaling factor, mirroring" and
  "additive to existing instructions"; 840D Function Manual K2 08/2005 1.3 "frame chaining"; ONE NC
  programming 12/2019 p.309: "ASCALE ... based on a previous scaling, rotation, translation or
  mirroring"]. The frame is held as offset, rotation, scale and mirror components [K: K2, "frame
  components"], so a chain whose map is no longer a rotation of a scaling (an AROT after unequal scale
  factors in its plane) is not what the controller holds: refused [?]. The settable frame (G54...) is the
  work system's, outside ``F``: a work system selected later keeps ``F`` [K: K2 $P_ACTFRAME chain].

The program position is tracked beside the frame by the caller (``postproc.frames.lowering``); each
command here says how it moves that position (the tool stays where it is) or makes it unknown (None).
"""

from __future__ import annotations

import math
from typing import Final

from ..errors import ProgramError
from .affine import EXACT, IDENTITY, XYZ, Affine, about, diagonal, rotation, translation

Position = dict[str, "float | None"]
PLANE_AXES: Final = {"XY": ("X", "Y", "Z"), "ZX": ("Z", "X", "Y"), "YZ": ("Y", "Z", "X")}


class Frame:
    """The frame in force (lengths in mm, angles in degrees)."""

    __slots__ = ("rules", "offset", "saved", "applied", "local", "rotation", "last_angle", "scaling", "mirror", "turns",
                 "work", "map", "polar", "pending", "increment_setting")

    def __init__(self, rules: str) -> None:
        self.rules = rules
        self.offset: dict[str, float] = {}
        """G92's offset (shared_offset: shared with G52; layered: the G92 shift of every work system)."""
        self.saved: dict[str, float] = {}
        """shared_offset: the offset's parameters (#5211-#5219), what G92.3 restores."""
        self.applied = False
        """shared_offset: the offset is in force (#5210: G52 and G92 set it, G92.1 and G92.2 clear it, G92.3 sets it
        [V] ``interp_convert.cc`` ``convert_axis_offsets``)."""
        self.local: dict[str, float] = {}
        """layered: the G52 local offset."""
        self.rotation: tuple[str, float, float, float] | None = None
        """layered, rotate_first: G68 (plane, first and second centre coordinate, degrees)."""
        self.last_angle: float | None = None
        """layered: the angle of the program's last G68, kept through G69 (an incremental R's reference)."""
        self.scaling: tuple[tuple[float, float, float], tuple[float, float, float]] | None = None
        """layered: G51 (centre, factor per axis X, Y, Z)."""
        self.mirror: dict[str, float] = {}
        """layered: G51.1 axis -> the coordinate it is mirrored about."""
        self.turns: dict[int, float] = {}
        """shared_offset: each work system's XY rotation (G10 L2 R), by work system (1 = G54)."""
        self.work = 1
        self.map: Affine = IDENTITY
        """X, Y, Z: program point -> work point."""
        self.polar: str | None = None
        """G16 the plane whose first axis word is a radius and second an angle (None: G15)."""
        self.pending: set[str] = set()
        """chain: the axes a frame change moved in program coordinates, until a move programs them
        absolutely (an incremental move there is refused: ``postproc.frames.lowering``)."""
        self.increment_setting = ""
        """chain: what decides whether such a move also travels the change, in the family's words (the last
        change's ``FrameChange.increment_setting``; empty: not named)."""

    # -- the map ----------------------------------------------------------------------------------
    def plain(self) -> bool:
        """Nothing to evaluate: no offset, map or polar coordinates."""
        return self.polar is None and not self.offset and not self.local and self.map.is_identity()

    def linear_active(self) -> bool:
        """A rotation, scaling or mirror is in force (not only offsets)."""
        return self.map.m != IDENTITY.m

    def shift(self, axis: str) -> float:
        """What the frame adds on an axis other than X, Y, Z."""
        return self.offset.get(axis, 0.0) + self.local.get(axis, 0.0)

    def compose(self) -> None:
        if self.rules == "chain":
            return  # the map is the chained frame itself (``chain``)
        offset = tuple(self.offset.get(a, 0.0) + self.local.get(a, 0.0) for a in XYZ)
        if self.rules == "shared_offset":
            turn = self.turns.get(self.work, 0.0)
            self.map = translation(offset).then(Affine(rotation(PLANE_AXES["XY"], turn))) if turn else translation(offset)
            return
        m = IDENTITY
        if self.mirror:
            m = about(tuple(self.mirror.get(a, 0.0) for a in XYZ), diagonal(tuple(-1.0 if a in self.mirror else 1.0 for a in XYZ)))
        if self.scaling is not None:
            m = m.then(about(*reversed_args(self.scaling)))
        if self.rotation is not None:
            plane, c1, c2, degrees = self.rotation
            a1, a2, _ = PLANE_AXES[plane]
            centre = [0.0, 0.0, 0.0]
            centre[XYZ.index(a1)], centre[XYZ.index(a2)] = c1, c2
            m = m.then(about(centre, rotation((a1, a2), degrees)))
        self.map = m.then(translation(offset))

    # -- commands (values in mm; ``p`` is the program position, changed in place) -------------------
    def set_local(self, values: dict[str, float], p: Position) -> None:
        """G52: the local offset is replaced on the named axes; the tool stays, so the program position
        moves by the difference (rs274: the offset G92 shares, [V] convert_axis_offsets)."""
        store = self.offset if self.rules == "shared_offset" else self.local
        for axis, value in values.items():
            old = store.get(axis, 0.0)
            here = p.get(axis)
            p[axis] = None if here is None else here + old - value
            store[axis] = value
        if self.rules == "shared_offset":
            self.saved = dict(self.offset)
            self.applied = True
        self.compose()

    def set_origin(self, values: dict[str, float], p: Position, why: str) -> None:
        """G92: the current point reads ``values``: ``o = p + o - value``. ``why`` names the command for
        the error where the current point is not known."""
        for axis, value in values.items():
            here = p.get(axis)
            if here is None:
                raise ProgramError(f"{why} needs the current position on {axis}, which is not known here "
                                   f"(program an absolute move on {axis} first)")
            self.offset[axis] = here + self.offset.get(axis, 0.0) - value
            p[axis] = value
        if self.rules == "shared_offset":
            self.saved = dict(self.offset)
            self.applied = True
        self.compose()

    def clear_origin(self, p: Position, keep_parameters: bool) -> None:
        """G92.1 / G92.2: the offset is gone (G92.2 keeps its parameters for G92.3)."""
        for axis, value in self.offset.items():
            here = p.get(axis)
            p[axis] = None if here is None else here + value
        self.offset = {}
        self.applied = False
        if not keep_parameters:
            self.saved = {}
        self.compose()

    def restore_origin(self, p: Position) -> None:
        """G92.3: the offset comes back from its parameters."""
        for axis in set(self.offset) | set(self.saved):
            here = p.get(axis)
            p[axis] = None if here is None else here + self.offset.get(axis, 0.0) - self.saved.get(axis, 0.0)
        self.offset = dict(self.saved)
        self.applied = True
        self.compose()

    def rotate(self, plane: str, c1: float, c2: float, degrees: float, p: Position) -> None:
        """G68 (layered): the program position on the plane's axes is unknown until programmed again."""
        self.rotation = (plane, c1, c2, degrees)
        self.last_angle = degrees
        self._forget(PLANE_AXES[plane][:2], p)

    def unrotate(self, p: Position) -> None:
        if self.rotation is not None:
            self._forget(PLANE_AXES[self.rotation[0]][:2], p)
        self.rotation = None
        self.compose()

    def scale(self, centre: tuple[float, float, float], factors: tuple[float, float, float], p: Position) -> None:
        """G51 (layered)."""
        self.scaling = (centre, factors)
        self._forget(tuple(a for a, f in zip(XYZ, factors) if f != 1.0), p)

    def unscale(self, p: Position) -> None:
        if self.scaling is not None:
            self._forget(tuple(a for a, f in zip(XYZ, self.scaling[1]) if f != 1.0), p)
        self.scaling = None
        self.compose()

    def set_mirror(self, lines: dict[str, float], p: Position) -> None:
        """G51.1 (layered): mirrored about ``lines`` on their axes."""
        self.mirror.update(lines)
        self._forget(tuple(lines), p)

    def clear_mirror(self, axes: tuple[str, ...], p: Position) -> None:
        """G50.1 (layered): the named axes are no longer mirrored."""
        for axis in axes:
            if axis in self.mirror:
                del self.mirror[axis]
                p[axis] = None
        self.compose()

    def set_turn(self, work: int, degrees: float) -> None:
        """G10 L2 R (shared_offset): work system ``work``'s XY rotation."""
        self.turns[work] = degrees
        self.compose()

    def select_work(self, work: int) -> None:
        """G54...: the new work system's rotation is in force (shared_offset)."""
        self.work = work
        self.compose()

    def chain(self, component: Affine, additive: bool, p: Position) -> None:
        """chain rules: the programmable frame becomes ``component`` (replacing) or the frame in force
        chained with it (additive). The tool stays; an axis whose program coordinate the change can move
        is unknown until programmed again, and pending for the incremental rule."""
        old = self.map
        new = component.then(old) if additive else component
        if not orthogonal_columns(new.m):
            raise ProgramError("a rotation chained after unequal scale factors in its plane: the controller holds "
                               "its frame as offset, rotation, scaling and mirroring, which cannot express this "
                               "(whether it refuses it or reorders it is not settled [?]): scale equally, or "
                               "rotate before scaling")
        self.map = new
        for i, axis in enumerate(XYZ):
            if not (_alone(old, i) and _alone(new, i) and old.m[4 * i] == new.m[4 * i] and old.t[i] == new.t[i]):
                p[axis] = None
                self.pending.add(axis)

    def _forget(self, axes: tuple[str, ...], p: Position) -> None:
        """Where the program stands on ``axes`` in the new frame is not taken as known: the next move
        programs them [?: Fanuc keeps a 'programmed position' that the manuals do not state for a
        frame change; Mitsubishi's M700 manual asks for an absolute move after G68.1]."""
        for axis in axes:
            p[axis] = None
        self.compose()


_ABOUT: Final = {"A": ("Y", "Z"), "B": ("Z", "X"), "C": ("X", "Y")}
"""A chain rotation's letter -> the plane it turns (right-handed about X, Y, Z)."""


def chain_component(kind: str, words: dict[str, float], plane: str, what: str) -> Affine:
    """A chain command's one component (``postproc.frames.section``), lengths in mm; ``plane`` is the active
    one, ``what`` names the command for errors. A rotation ``R`` turns in the active plane from its first
    axis toward its second, about the plane's third axis, as ``A``, ``B``, ``C`` turn about X, Y, Z:
    right-handed [K: SINUMERIK ONE NC programming 12/2019 p.316, ROT about the named geometry axis, RPL "in
    the current working plane (G17/G18/G19)"; 808D programming manual p.56, positive angles in each plane]."""
    kind = kind.removesuffix("_add")
    if kind == "local":
        return translation(tuple(words.get(a, 0.0) for a in XYZ))
    if kind == "rotate":
        if "R" in words:
            return Affine(rotation(PLANE_AXES[plane][:2], words["R"]))
        for letter, turned in _ABOUT.items():
            if letter in words:
                return Affine(rotation(turned, words[letter]))
        return IDENTITY
    if kind == "scale":
        factors = tuple(words.get(f, 1.0) for f in "IJK")
        if 0.0 in factors:
            raise ProgramError(f"{what}: a scale factor of 0")
        return Affine(diagonal(factors))
    if kind == "mirror":
        return Affine(diagonal(tuple(-1.0 if a in words else 1.0 for a in XYZ)))
    raise ProgramError(f"{what} is not a command of a chained programmable frame")


def orthogonal_columns(m: tuple[float, ...]) -> bool:
    """The linear part is a rotation times a diagonal (its columns are at right angles)."""
    columns = [(m[j], m[3 + j], m[6 + j]) for j in range(3)]
    for j, k in ((0, 1), (0, 2), (1, 2)):
        a, b = columns[j], columns[k]
        size = math.hypot(*a) * math.hypot(*b)
        if abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) > 1e-9 * max(size, 1.0):
            return False
    return True


def _alone(f: Affine, i: int) -> bool:
    """Axis ``i`` neither mixes into another axis nor takes from one under ``f``."""
    return all(abs(f.m[3 * i + j]) <= EXACT and abs(f.m[3 * j + i]) <= EXACT for j in range(3) if j != i)


def reversed_args(scaling: tuple[tuple[float, float, float], tuple[float, float, float]]) -> tuple[
        tuple[float, float, float], tuple[float, float, float, float, float, float, float, float, float]]:
    """(centre, factors) -> the arguments of ``about``."""
    centre, factors = scaling
    return centre, diagonal(factors)
