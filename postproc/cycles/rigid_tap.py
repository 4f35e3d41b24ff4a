"""Rigid tapping mode of the Fanuc family: which tap cycles are spindle-synchronised, and their pitch.

A machine code declared ``action="rigid-tap"`` (Fanuc ``M29 S..``) puts the control in rigid tapping mode
[K: Fanuc 0i-MF operator's manual, "Rigid tapping": M29 S.. before G84/G74]; the tap cycles (G84, G74) that
follow then cut in step with the spindle, and the cycle resolution gives them a ``pitch``
(``CannedCycle.pitch``), which ``TappingExpansion`` expands into ``RigidTap`` moves. The mode ends with the
cycle cancel or a group-01 motion code [K: same manual, "Rigid tapping mode is cancelled by G80, a G code of
group 01, or reset"]; a hole cycle other than a tap while it is on is refused [?: Fanuc raises an alarm], and
so is an axis move between the code and its tap cycle [K: Fanuc 0i alarm PS0204 "illegal axis operation",
an axis moved between the M29 block and the G84/G74 block]: no program is read as a floating tap that the
control would have refused or tapped rigidly.

The pitch is F in feed per revolution, and F/S in feed per minute, S the spindle speed in force (the one
``M29 S..`` gives) [V: Fanuc Series 0i connection manual (function) B-63833EN-1/02, 9.x "Rigid tapping",
page 540: "In feed per minute mode, F/S determines the thread lead"; in feed per rotation F is the lead].
"""

from __future__ import annotations

from typing import Any, Callable, Final

from postproc.errors import ProgramError
from postproc.ir import MachineFunction
from postproc.lowering.machine_functions import RIGID_TAP
from postproc.ir.state import ModalState

RIGID_KEY: Final = "RigidTapMode"
"""``ctx.state.extra`` key: present while rigid tapping mode is on (its value: the code, e.g. 'M29')."""
_GROUP_01: Final = frozenset(("rapid", "linear", "cw", "ccw"))


def rigid_code(sections: dict[str, Any]) -> str | None:
    """The rigid-tapping code of a block (``M29``), or None."""
    code = sections.get("MachineFunction")
    if isinstance(code, MachineFunction) and code.action == RIGID_TAP:
        return code.code
    return None


def note_rigid_mode(sections: dict[str, Any], state: ModalState) -> None:
    """Outside a cycle: the block's rigid-tapping code puts the mode on, a cancel ends it; an axis move before
    the tap cycle is a ``ProgramError`` (the module docstring), a group-01 code without one ends the mode."""
    code = rigid_code(sections)
    motion = sections.get("Motion")
    if code is not None:
        state.extra[RIGID_KEY] = code
    elif "CycleCancel" in sections:
        state.extra.pop(RIGID_KEY, None)
    elif motion is not None and RIGID_KEY in state.extra and state.cycle is None and getattr(motion, "axes", None):
        raise ProgramError(f"an axis move between {state.extra[RIGID_KEY]} (rigid tapping) and its tap cycle: the "
                           "control refuses it (Fanuc alarm PS0204); position the tool before the rigid tapping "
                           "code")
    elif getattr(motion, "mode", None) in _GROUP_01:
        state.extra.pop(RIGID_KEY, None)


def end_rigid_mode(state: ModalState) -> None:
    """The cycle is cancelled: so is rigid tapping mode."""
    state.extra.pop(RIGID_KEY, None)


def rigid_pitch(sections: dict[str, Any], state: ModalState, kind: str, code: str, feed: float | None,
                rpm: float | None, feed_mode: str, peck: str | None, fail: Callable[..., ProgramError]) -> float | None:
    """The pitch of this block's tap when rigid tapping mode is on (or set in the block), else None; ``feed``,
    ``rpm`` and ``feed_mode`` are those in force for the block (its own words included); ``peck``: the peck
    word in force (Q), which a rigid tap refuses [K: Fanuc 0i peck rigid tapping, G84 with Q, whose return
    per peck a parameter chooses: not modelled]."""
    mode = rigid_code(sections) or state.extra.get(RIGID_KEY)
    if mode is None:
        return None
    state.extra[RIGID_KEY] = mode
    if kind not in ("tap", "tap_left"):
        raise fail(f"{code} while rigid tapping mode ({mode}) is on: only a tap cycle may follow it (cancel "
                   "the mode with the cycle cancel first)")
    if peck is not None:
        raise fail(f"peck rigid tapping ({mode} then {code} with {peck}) is not modelled: its return per peck is a "
                   "machine parameter", peck)
    if feed is None or feed <= 0.0:
        raise fail(f"a rigid tap ({mode} then {code}) needs its feed F (the pitch, or the pitch times S)", "F")
    if feed_mode == "per_rev":
        return feed
    if feed_mode != "per_min":
        raise fail(f"a rigid tap ({mode} then {code}) in inverse time feed has no pitch")
    if rpm is None or rpm <= 0.0:
        raise fail(f"a rigid tap ({mode} then {code}) in feed per minute needs the spindle speed ({mode} S..): "
                   "its pitch is F/S")
    return feed / rpm
