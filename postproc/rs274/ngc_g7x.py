"""The moves of LinuxCNC's lathe cycles: ``G70`` (finishing), ``G71``/``G72`` (roughing along Z / along X),
``.1`` without pockets, ``.2`` the pockets only, from a profile given in an O-word subprogram.

The algorithm is the controller's own, followed step by step [V: LinuxCNC ``src/emc/rs274ngc/interp_g7x.cc``
(stored commit 5c41560e), class ``g7x``; every rule below checked against rs274 2.9 by the seeded random
differential of ``tests/test_ngc_g7x.py``]. It is not Fanuc's G70-G73 (``postproc.cycles.turning``): LinuxCNC
offsets the profile by D as a whole (arcs joined where pieces part), cuts each layer up to the profile
and then follows the profile itself up to the next layer's start, and retracts by R at 45 degrees; the
two cycles cut different paths, so neither is written as the other.

* The profile is the approach from the cycle's point (X, Z) to the subprogram's first point, then the
  subprogram's moves (``ngc_g7x_segments``); G72 turns it a quarter first, so that it is a G71 one. It is
  mirrored so that it runs towards -Z and -X (a profile going up in X, or to +Z, is cut the same way,
  mirrored), its corners (A fillets, C chamfers) are made, and it must then never go towards +Z ("Not
  monotonic"); a G70 whose profile would not be monotonic so is turned as a G72.
* G71/G72: the profile is offset by D towards the cycle's point, in steps no longer than half its
  shortest piece; layers I apart from the cycle's X down; each layer cuts from the profile's front to
  where it meets the profile again, then retracts by R (or less, in a short layer) at 45 degrees and
  returns; the tool then follows the profile down to the next layer. ``.1`` follows the profile up
  once the first pass is done; ``.2`` goes straight to the first pocket and cuts the pockets.
* G70: P passes, pass n at (n - 1)(D - E)/P + E from the profile (``offset``), each a rapid to the cycle's
  point, a rapid to the offset profile's first point, then the offset profile.

Versions (``CycleRules``, ``rules_of``): the algorithm changed between LinuxCNC releases in three steps that move the
tool [V: ``interp_g7x.cc`` at the tags v2.9.0-pre1 .. v2.9.10 and master 5c41560e of github:LinuxCNC/linuxcnc]. A
roughing profile that ends short of the cycle's X (turning) or Z (facing) is not closed up to 2.9.0 (the offset
profile is then cut as it ends); from 2.9.1 (03793cc9fa) a line back to the cycle's X/Z is added before the
offset whenever the profile does not end there; from 2.9.4 (bb75d9cc, c38c192f, issue 2939) only when the
profile's last piece runs along Z (X for facing) and it ends on the side of the cycle's X/Z away from where it
starts. The pocket walk moves on from a piece whose end it stands at from 2.9.9 (111fd213) and stops at the
profile's last piece on master (48a3ee4a, not in a 2.9 release). The rs274 installed here is LinuxCNC 2.9.0~pre1
(Debian 12's linuxcnc-uspace, git f1270d6ed7 of 2023-02-08; its ``interp_g7x.cc`` is v2.9.0's, byte for byte):
the oracle checks 2.9.0's rules by it, the later ones from the source alone (over 400 random profiles the pocket
walk fixes changed no move; the closing changes the cut of every profile not closed).
"""

from __future__ import annotations

import math
from typing import Final

from .arc_ends import RS274NGC_ARC_END
from .ngc_g7x_segments import TOLERANCE, Arc, NgcCycleError, Line, Move, Output, Piece, meet

ESCAPE: Final = 1 + 1j
"""The retract's direction, scaled by R: up in X and back in Z at once."""
SAME: Final = 0.0001
"""An arc's end this close to where the tool is, on each axis, is no move [V: ``motion_machine::circular_move``
skips it by the interpreter's ``equal``, ``TOLERANCE_EQUAL``]."""
MAX_STEPS: Final = 1_000_000
"""Steps at most in one pocket walk: the controller's loop has no bound; a profile it would never end is
refused instead of hanging."""


def _frame(state: int, p: complex) -> complex:
    """A point of the cycle's working frame back in the program's (``swapped_motion`` there)."""
    if state == 0:
        return p
    if state == 1:
        return -p.conjugate()
    if state == 2:
        return p.conjugate()
    if state == 3:
        return -p
    if state == 4:
        return 1j * p
    if state == 5:
        return (1j * p).conjugate()
    if state == 6:
        return -(1j * p).conjugate()
    return -1j * p


class CycleRules:
    """The steps of the algorithm that changed between LinuxCNC versions (module docstring)."""

    __slots__ = ("name", "closing", "walk_on_at_end", "walk_stops_at_last")

    def __init__(self, name: str, closing: str | None, walk_on_at_end: bool, walk_stops_at_last: bool) -> None:
        self.name = name
        """The versions, as a message names them."""
        self.closing = closing
        """A roughing profile short of the cycle's X/Z: None not closed, "always" closed when it does not end
        there (2.9.1-2.9.3), "outward" closed when its last piece runs along the cut and it ends short (2.9.4 on)."""
        self.walk_on_at_end = walk_on_at_end
        """The pocket walk moves on from a piece whose end it stands at (111fd213, 2.9.9 on)."""
        self.walk_stops_at_last = walk_stops_at_last
        """The pocket walk stops at the profile's last piece (48a3ee4a, master)."""


V2_9_0: Final = CycleRules("2.9.0", None, False, False)
"""2.9.0 (and 2.9.0~pre1, the rs274 installed here: the same ``interp_g7x.cc``) [V]."""
V2_9_1: Final = CycleRules("2.9.1-2.9.3", "always", False, False)
V2_9_4: Final = CycleRules("2.9.4-2.9.8", "outward", False, False)
V2_9_9: Final = CycleRules("2.9.9-2.9.10", "outward", True, False)
MASTER: Final = CycleRules("2.10.0~pre1 (master 5c41560e)", "outward", True, True)
"""The stored master [V: its ``VERSION`` file says 2.10.0~pre1]: the default of the engine."""
FIRST: Final = (2, 9, 0)
"""The first version with G70-G72 [V: ``interp_g7x.cc`` is in no v2.8 tag; v2.9.0-pre1 has it]."""


def rules_of(version: tuple[int, ...]) -> CycleRules | None:
    """The rules of LinuxCNC ``version`` (major, minor, patch); None before 2.9.0 (no G70-G72) or after 2.10.0,
    whose algorithm is not in the stored source."""
    if version < FIRST or version > (2, 10, 0):
        return None
    if version == (2, 10, 0):
        return MASTER
    patch = version[2] if len(version) > 2 else 0
    return V2_9_0 if patch == 0 else V2_9_1 if patch <= 3 else V2_9_4 if patch <= 8 else V2_9_9


class Profile:
    """The cycle's profile: its pieces, the first being the approach from the cycle's point."""

    __slots__ = ("pieces", "flip", "step", "escape", "pocket_starts", "moves", "here", "rules", "inch")

    def __init__(self, pieces: list[Piece], rules: CycleRules = MASTER, inch: bool = False) -> None:
        self.pieces = pieces
        self.inch = inch
        """Program units are inches (the arc check's tolerance)."""
        self.rules = rules
        """The version's pocket walk (module docstring)."""
        self.flip = 0
        """Bits: 1 mirrored in Z, 2 mirrored in X, 4 turned a quarter."""
        self.step = 0.5
        self.escape = 0.3 + 0.3j
        self.pocket_starts: list[complex] = []
        self.moves: list[Move] = []
        self.here = pieces[0].start if pieces else 0j
        """Where the tool is, in the program's frame: an arc ending there is no move."""

    def copy(self) -> "Profile":
        twin = Profile([p.copy() for p in self.pieces], self.rules, self.inch)
        twin.flip = self.flip
        twin.step = self.step
        twin.escape = self.escape
        return twin

    # -- the output, in the program's frame ---------------------------------------------------------
    def out(self, kind: str, end: complex, centre: complex | None) -> None:
        flip = self.flip
        end = _frame(flip, end)
        if centre is not None:
            here = self.here
            if abs(here.real - end.real) < SAME and abs(here.imag - end.imag) < SAME:
                return  # the controller makes no arc back to where the tool is (``equal`` there)
            if flip in (1, 2, 5, 6):
                kind = "cw" if kind == "ccw" else "ccw"
            centre = _frame(flip, centre)
            r_start, r_end = abs(here - centre), abs(end - centre)
            if not RS274NGC_ARC_END.allows(r_start, r_end, self.inch):
                raise NgcCycleError(f"an arc of the cycle ends off its circle (radius {r_start:.4f} at its start, "
                               f"{r_end:.4f} at its end: the controller refuses it, \"Radius to end of arc differs "
                               "from radius to start\")")
        self.here = end
        self.moves.append((kind, end, centre))

    # -- shaping ------------------------------------------------------------------------------------
    def turn(self) -> None:
        for p in self.pieces:
            p.turn()
        self.flip ^= 4

    def orient(self) -> None:
        """Mirror the profile so that it runs towards -X and -Z (``swap`` there)."""
        dx = (self.pieces[0].end - self.pieces[-1].end).imag
        dz = (self.pieces[0].end - self.pieces[-1].end).real
        if dx > 0:
            for p in self.pieces:
                p.mirror_x()
            self.flip ^= 2
        if dz < 0:
            for p in self.pieces:
                p.mirror_z()
            self.flip ^= 1

    def corners(self) -> None:
        """Make the fillets and chamfers, then drop the pieces too short to cut (``do_finish``)."""
        pieces = self.pieces
        for i in range(1, len(pieces) - 1):
            pieces[i].make_corner(pieces[i - 1], pieces[i + 1])
        self.pieces = [p for p in pieces if p.length() >= 1e-3]

    def check_monotonic(self) -> None:
        first = self.pieces[0]
        if (first.end - first.start).real > 0:
            first.start = complex(first.end.real, first.start.imag)
        for p in self.pieces:
            if not p.monotonic():
                raise NgcCycleError("Not monotonic")

    def needs_turn(self) -> bool:
        trial = self.copy()
        trial.pieces.pop(0)
        trial.orient()
        return any(not p.monotonic() for p in trial.pieces)

    def offset(self, distance: float) -> None:
        """Offset the profile (not its approach) by ``distance`` towards the cycle's point (``add_distance``)."""
        pieces = self.pieces
        v1 = pieces[0].end - pieces[0].start
        v2 = pieces[-1].start - pieces[0].start
        if (v1 / v2).imag < 0:
            distance = -distance
        approach = pieces.pop(0)
        done = 0.0
        while done != distance:
            if not pieces:
                raise NgcCycleError("the profile vanished under its offset")
            step = min(1e9, *(p.length() / 2 for p in pieces)) if pieces else 1e9
            step = min(step, abs(distance - done))
            if distance < 0:
                step = -step
            for p in pieces:
                p.offset(step)
            pieces[:] = [p for p in pieces if p.length() >= 1e-3]
            i = 0
            while i < len(pieces) - 1:  # pieces that parted are joined by an arc about their old corner
                p, n = pieces[i], pieces[i + 1]
                if (p.end - n.start).real > 1e-2:
                    s, e = p.copy(), n.copy()
                    s.offset(-step)
                    e.offset(-step)
                    pieces.insert(i + 1, Arc(distance > 0, p.end, (s.end + e.start) / 2.0, n.start))
                    i += 1
                i += 1
            i = 0
            while i < len(pieces) - 1:
                p = pieces[i]
                if not p.monotonic():
                    if i == 0:
                        raise NgcCycleError("the profile's offset turns back on its first piece")
                    if p.length() < pieces[i - 1].length():
                        del pieces[i]
                    else:
                        del pieces[i - 1]
                    i = 0
                    p = pieces[0]
                    if len(pieces) < 2:
                        raise NgcCycleError("the profile vanished under its offset")
                if p.length() < 1e-3:
                    del pieces[i]
                    i = 0
                    if len(pieces) < 2:
                        raise NgcCycleError("the profile vanished under its offset")
                else:
                    meet(p, pieces[i + 1])
                i += 1
            done += step
        for i in range(len(pieces) - 1):
            mid = (pieces[i].end + pieces[i + 1].start) / 2.0
            pieces[i].end = pieces[i + 1].start = mid
        approach.end = pieces[0].start
        pieces.insert(0, approach)

    # -- the cycles ---------------------------------------------------------------------------------
    def finishing(self, x: float, z: float, d: float, e: float, passes: int) -> list[Move]:
        """G70's moves; the first rapid of each pass is made with compensation off (``first_rapids``)."""
        self.pieces[0].start = complex(z, x)
        if self.needs_turn():
            self.turn()
        self.orient()
        self.corners()
        self.check_monotonic()
        for n in range(passes, 0, -1):
            distance = (n - 1) * (d - e) / passes + e
            path = self.copy()
            path.offset(distance)
            self.out("rapid", path.pieces[0].start, None)
            self.out("rapid", path.pieces[0].end, None)
            for p in path.pieces[1:]:
                p.draw(self.out)
        return self.moves

    def roughing(self, cycle: int, x: float, z: float, d: float, i: float, r: float,
                 facing: bool) -> list[Move]:
        """G71/G72 (``facing``), ``cycle`` 0, 1 or 2 (the code's .0/.1/.2)."""
        self.pieces[0].start = complex(z, x)
        if facing:
            self.turn()
        self.orient()
        self.corners()
        self.check_monotonic()
        self.offset(d)
        self.step = max(i, 2 * TOLERANCE)
        self.escape = r * ESCAPE
        first = self.pieces[0].start
        self.out("rapid", first, None)
        last = self.pieces[-1].end
        if last.imag < first.imag:
            self.pieces.append(Line(last, complex(last.real, first.imag)))
        self.pocket_starts.append(first)
        self._pocket(cycle, first, 0, [0])
        return self.moves

    def _pocket(self, cycle: int, location: complex, index: int, steps: list[int]) -> None:
        """Cut from ``location`` on piece ``index`` (``pocket`` there; recursive, one level a pocket)."""
        pieces = self.pieces
        out = self.out
        at = [location]
        x = self.pocket_starts[-1].imag
        if cycle == 2:  # the first pass is G7x.1's: follow the profile down to the first pocket
            while index < len(pieces):
                if pieces[index].dive(at, -1e9, out, index == 0):
                    break
                index += 1
            cycle = 3
        while index < len(pieces):
            steps[0] += 1
            if steps[0] > MAX_STEPS:
                raise NgcCycleError(f"the roughing makes more than {MAX_STEPS} steps (the controller would not end)")
            while x - TOLERANCE > at[0].imag:
                x -= self.step
            piece = pieces[index]
            if piece.dive(at, x, out, index == 0):
                if cycle == 1:
                    for p in pieces[index:]:
                        p.climb_only(at, out)
                    return
                while index < len(pieces):
                    if pieces[index].climb(at, out):
                        if cycle == 3:
                            if at[0].imag > self.pocket_starts[-1].imag and len(self.pocket_starts) > 1:
                                self.pocket_starts.pop()
                            if len(self.pocket_starts) == 1:
                                self.pocket_starts.append(at[0])
                        self._pocket(cycle, at[0], index, steps)
                        return
                    index += 1
                return
            if self.rules.walk_stops_at_last and index == len(pieces) - 1:
                return
            if abs(at[0].imag - x) > TOLERANCE or self.rules.walk_on_at_end and piece.end == at[0]:
                index += 1
                continue
            for j in range(index, len(pieces)):
                found = pieces[j].crossings(at[0].imag)
                if not found:
                    continue
                dest_z = found[0] if j != index else found[-1]
                distance = abs(dest_z - at[0].real)
                if dest_z - TOLERANCE > at[0].real:
                    continue  # meets the diving piece where it starts only
                if distance < TOLERANCE:
                    if j == index:
                        continue
                    if abs(at[0] - pieces[j].start) < TOLERANCE:
                        index = j  # another piece starts here: go on along it
                        break
                    x -= self.step  # a piece of no length: this layer is done
                    break
                here = at[0]
                dest = complex(dest_z, here.imag)
                out("feed", dest, None)
                scale = min(1.0, distance / 2 / self.escape.real)
                dest += scale * self.escape
                out("rapid", dest, None)
                out("rapid", here - (scale * self.escape).conjugate(), None)
                out("rapid" if index == 0 else "feed", here, None)
                x -= self.step
                break


def cycle_moves(code: str, pieces: list[Piece], x: float, z: float, d: float = 0.0, e: float = 0.0,
                i: float = 1.0, r: float = 0.5, passes: int = 1, rules: CycleRules = MASTER,
                inch: bool = False) -> list[Move]:
    """The moves of ``code`` ("70", "71", "71.1", "71.2", "72", "72.1", "72.2") over ``pieces``, the
    approach from the cycle's point (X ``x``, Z ``z``) first, after the rapid to that point; the words'
    defaults are the controller's [V: ``convert_g7x``: D 0, E 0, I 1, R 0.5, P 1]. A profile of its
    approach alone makes no move. ``rules``: the LinuxCNC version's (module docstring)."""
    if len(pieces) <= 1:
        return []
    if i <= 0:
        raise NgcCycleError("I must be greater than zero.")
    start = pieces[-1].end
    cycle, _, sub = code.partition(".")
    if cycle == "70":
        return Profile(pieces, rules, inch).finishing(x, z, d, e, passes)
    facing = cycle == "72"
    if closes(rules, facing, pieces, x, z):
        # back out to the cycle's X (Z): a line added before the offset [V: convert_g7x, 2.9.1 on]
        pieces.append(Line(start, complex(z, start.imag) if facing else complex(start.real, x)))
    return Profile(pieces, rules, inch).roughing(int(sub or "0"), x, z, d, i, r, facing)


def closes(rules: CycleRules, facing: bool, pieces: list[Piece], x: float, z: float) -> bool:
    """The version adds a line from the roughing profile's end back to the cycle's X (G71) or Z (G72) [V:
    ``convert_g7x``: 2.9.1 ``if(x!=imag(start))``; 2.9.4 ``if(std::abs(real(dback))>0 &&
    imag(dfront)*(x-imag(start))<0)``, Z for G72 with the axes swapped]."""
    if rules.closing is None or len(pieces) <= 1:
        return False
    start = pieces[-1].end
    if rules.closing == "always":
        return z != start.real if facing else x != start.imag
    front = pieces[0].end - pieces[0].start
    back = pieces[-1].end - pieces[-1].start
    if facing:
        return abs(back.imag) > 0 and front.real * (z - start.real) < 0
    return abs(back.real) > 0 and front.imag * (x - start.imag) < 0



def arc_centre_by_radius(start: complex, end: complex, radius: float, ccw: bool) -> complex:
    """The centre of an arc given by R in a profile [V: ``convert_g7x``: the side follows G2/G3 alone, a
    negative R names the same arc]; a radius shorter than half the chord is refused."""
    chord = end - start
    norm = chord.real * chord.real + chord.imag * chord.imag
    reach = (radius * radius - norm / 4) / norm
    if reach < 0:
        raise NgcCycleError(f"an arc's radius R{radius:g} is shorter than half its chord")
    d = 1j * math.sqrt(reach) * chord
    centre = (start + end) / 2.0
    return centre + d if ccw else centre - d


__all__ = ["FIRST", "MASTER", "V2_9_0", "V2_9_1", "V2_9_4", "V2_9_9", "CycleRules", "NgcCycleError", "Output",
           "arc_centre_by_radius", "closes", "cycle_moves", "rules_of"]
