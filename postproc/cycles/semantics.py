"""The neutral type of a controller family's hole-cycle rules (``Semantics``), and the registry of them.

Families differ in a handful of rules (DIALECTS.md §2.1): where the tool positions, which level G98 returns
to, what a dwell P counts, which words a new cycle code carries over, and how some cycles move out of the
hole. Each rule is a field named after the behaviour; a family base defines its tables (the RS274 family's,
Fanuc's and RS274/NGC's, in ``postproc.rs274.cycle_semantics``) and registers them by name
(``register_semantics``). The resolve step and the expansions look a cycle's rules up by the name it was
resolved under (``CannedCycle.semantics``, ``Dialect.CYCLE_SEMANTICS``); the core has no family's table
and no default one.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Final

from mypy_extensions import mypyc_attr

PECK: Final = frozenset(("peck_chip", "peck_deep"))
TAP: Final = frozenset(("tap", "tap_left"))
SHIFT: Final = frozenset(("fine_bore", "back_bore"))
DWELLING: Final = frozenset(("drill_dwell", "bore_stop", "bore_manual", "bore_dwell_feed"))
"""Cycles RS274/NGC refuses without a P when newly commanded."""


@mypyc_attr(allow_interpreted_subclasses=True)
@dataclass(frozen=True, slots=True)
class Semantics:
    """The rules of one family: a field per rule, named after the behaviour (a family's table with its
    sources: ``postproc.rs274.cycle_semantics``)."""

    name: str
    rise_to_r: bool
    clear_above_r: bool
    position_at_clear: bool
    dwell_ms: bool
    carry_over: bool
    any_axis_repeats: bool
    zero_repeat_error: bool
    sticky_tap_dwell: bool
    unsupported: frozenset[str]
    """Cycles with no meaning under this family's words."""
    dwell_required: bool
    """G82, G86, G88, G89 (``DWELLING``) are refused without a dwell P."""
    spindle_checked: bool
    """A tapping cycle is refused unless the spindle turns its direction, G86/G88 unless it turns at all."""
    dwell_always: bool
    """Every cycle that dwells makes a dwell, a zero one without P (G86 included); else only with a P."""
    spindle_resumes: bool
    """After a spindle stop in the hole (G86, G88) the spindle restarts in the direction it had; else CW."""
    feeds_out_to_clear: bool
    """G89 feeds from the bottom straight out to the clear level; else it feeds to R and rapids on."""
    stops_to_reverse: bool
    """Tapping stops the spindle, reverses it, dwells, feeds out to the clear level, stops and restarts it
    forward; else it dwells, reverses, feeds to R, rapids to the clear level and turns forward again."""
    manual_retracts: bool
    """G88 rapids out after the program stop (the spindle restarted CW after); else no retract move: the
    tool is taken to be at the clear level."""

    # A family's rules are one constant shared by every run: a copy of the state that reaches them (the
    # dry run of a loop copies the modal state, whose next-hole memo holds its resolve step) shares them
    # too. Copying field by field is also what fails compiled: mypyc's __setstate__ assigns through the
    # frozen class's refusing __setattr__ (FrozenInstanceError).
    def __copy__(self) -> Semantics:
        return self

    def __deepcopy__(self, memo: dict[int, object]) -> Semantics:
        return self




_KNOWN: Final[dict[str, Semantics]] = {}
"""Name -> rules, as the family bases registered them."""


def register_semantics(rules: Semantics) -> None:
    """Make ``rules`` known by its name (a family base, once at import); a second table of the same name is
    a programming error."""
    known = _KNOWN.get(rules.name)
    if known is not None and known != rules:
        raise ValueError(f"cycle rules {rules.name!r} registered twice, with different rules")
    _KNOWN[rules.name] = rules


def semantics_named(name: str) -> Semantics | None:
    """The registered rules of that name, or None."""
    return _KNOWN.get(name)


def semantics_names() -> list[str]:
    """The names of every registered family's rules, in registration order (for messages)."""
    return list(_KNOWN)
