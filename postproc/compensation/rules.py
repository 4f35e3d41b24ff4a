"""A controller's cutter radius compensation rules, as data: the reading dialect names its value
(``Dialect.CUTTER_RULES``, ``Dialect.cutter_rules``), the geometry (``cutter_radius``) reads it. A dialect without
rules leaves compensation unsimulated (``verify`` then compares the setting, as before).

Only the shape of the rules is here: each family's values, with their sources, are in its family base
(``postproc.rs274.cutter_rules``: Fanuc, Haas, GSK, LinuxCNC, the NIST interpreter), so the core holds no
controller's rules.
"""

from __future__ import annotations

import dataclasses

from ..records import record


@record(frozen=True)  # made at every start (the LinuxCNC plugin's): a dataclass's generated methods cost ~0.4 ms
class CutterRules:
    """How one controller family starts, runs and ends cutter radius compensation."""

    name: str
    """Who follows these rules (for messages and documentation)."""
    register_absent: str
    """Where the radius comes from when the block names no register: ``"tool"``, the register of the tool
    in the spindle; ``"modal"``, the register named last; ``"offset"``, the offset register a lathe's T
    code selected last (``T0102``: 2), whose columns hold the nose radius and tip."""
    entry: str
    """The first move after compensation starts: ``"tangent"``, the tool ends beside the move's end point,
    perpendicular to the line from the start point (an arc: beside its end, on its radius);
    ``"touching"``, the tool ends beside the end point, perpendicular to the line from the end point that
    touches the tool's circle about the start point (an entry arc is not modelled: refused);
    ``"perpendicular"``, the tool ends beside the start of the *next* move, square to it (start-up type A,
    with ``outside_corner="extend"``); ``"corner"``, the start-up move ends as a corner of offset mode
    would (start-up type B)."""
    outside_corner: str
    """``"arc"``: the tool rolls around an outside corner on an arc about the programmed corner (a rapid
    cuts the arc short with a straight traverse to the arc's end, or goes straight to the move's
    compensated end: ``rapid_corner``); ``"extend"``: the offset paths are extended to their
    intersection, an acute corner by the radius along both moves and a straight move between
    (``extended_corners``)."""
    corner_tolerance: float
    """Radians within which two directions count as one (no corner)."""
    arc_after_cancel: bool
    """Whether the move after a cancel (the exit move) may be an arc."""
    planes: tuple[str, ...] = ("XY",)
    """The planes compensation runs in (``state.PLANE_AXES`` names); another is a program error."""
    inside_corner: str = "meet"
    """``"meet"``: the two compensated moves are cut short where they meet (the first waits for the second);
    ``"error"``: an inside (concave) corner is a program error."""
    rapid_corner: str = "to_arc_end"
    """A rapid around an outside corner: ``"to_arc_end"``, a traverse to where the corner's arc would end,
    then the move; ``"direct"``, one traverse to the move's compensated end."""
    exit_arc_known: bool = True
    """Whether the rules for an arc right after a cancel are known (``arc_after_cancel`` says which); when
    not, such an arc is refused as not simulated."""
    profile_cycles: frozenset[str] = frozenset()
    """The lathe cycles (``LatheCycle`` kinds) the controller runs under G41/G42, compensating the moves
    of their profile as any others (Fanuc T's G70); any other cycle under compensation is refused."""
    roughing_cycles: frozenset[str] = frozenset()
    """The roughing cycles (``LatheCycle`` kinds) the controller runs under G41/G42 by roughing to the
    finishing shape offset by the compensation (Fanuc T's G71/G72 type I): the move to the cycle's start
    point ends there uncompensated, the cycle's moves are the imaginary tip's (``CutterRadius.suspend``), and
    the next move after the cycle starts compensation up again (``resume``). What a controller does there is
    a matter of its cycles, not of its compensation's geometry: ``cuts_like`` leaves it out."""
    look_ahead: int = 10_000
    """Blocks without motion in the plane the controller looks past to find the next move (the corner it
    makes past more is not modelled: refused). LinuxCNC's queue has no such bound (``cutter_radius``'s
    ``QUEUE_LIMIT`` bounds the memory)."""
    startup_arc_known: bool = True
    """Whether the rules for an arc as the start-up move are known (straight corners, ``extended_corners``:
    Fanuc's is an alarm); when not, such an arc is refused as not simulated."""
    acute_corner_known: bool = True
    """Whether the moves of an acute outer corner are known (straight corners: the radius extensions and the
    straight move between them); when not, such a corner is refused as not simulated."""

    def cuts_like(self, other: "CutterRules") -> bool:
        """Every rule but the name is the same: the two controllers compensate a program alike (a Haas lathe
        and Fanuc T, ``HAAS_T``)."""
        return dataclasses.replace(other, name=self.name, roughing_cycles=self.roughing_cycles) == self
