"""SINUMERIK instruction words the IR does not model, named for messages (their blocks are kept verbatim).

Sources: SINUMERIK ONE NC programming 12/2019 p.309 (frames) [K]; 840D sl Job planning 02/2011 [K];
the Autodesk ``siemens-840d.cps`` post (``CYCLE832``, ``MCALL CYCLE81``, ``SOFT``) [K]; the
USERS-AND-SIEMENS reference (section 3). A word not listed that starts a block on its own (``MYSUB``,
``MYSUB P3``) is a subprogram call, which is not modelled either.
"""

from __future__ import annotations

INSTRUCTIONS: dict[str, str] = {
    "TRANS": "a programmable frame offset", "ATRANS": "an additive frame offset",
    "ROT": "a frame rotation", "AROT": "an additive frame rotation",
    "ROTS": "a frame rotation by solid angles", "AROTS": "an additive frame rotation by solid angles",
    "CROTS": "a frame rotation by solid angles",
    "SCALE": "a frame scaling", "ASCALE": "an additive frame scaling",
    "MIRROR": "a frame mirroring", "AMIRROR": "an additive frame mirroring",
    "MCALL": "a modal subprogram or cycle call", "EXTERN": "an external subprogram declaration",
    "SOFT": "jerk-limited acceleration", "BRISK": "step acceleration",
    "FFWON": "feedforward control on", "FFWOF": "feedforward control off",
    "COMPCAD": "the compressor", "COMPCURV": "the compressor", "COMPOF": "the compressor off",
    "SPOS": "spindle positioning", "SPOSA": "spindle positioning", "SUPA": "a move without frames",
    "TRAORI": "the 5-axis transformation", "TRAFOOF": "transformations off",
    "DIAMON": "diameter programming", "DIAMOF": "radius programming",
    "MSG": "a message", "STOPRE": "a preprocessing stop", "HOLES1": "a row of holes",
    "HOLES2": "a circle of holes", "CIP": "a circle through an intermediate point", "CT": "a tangential circle",
    "SETMS": "the master spindle", "SAVE": "saved modal state", "DISPLOF": "display off",
    "GROUP_BEGIN": "a program group", "GROUP_END": "a program group",
}
"""Instruction word -> what it does."""


def describe(word: str) -> str | None:
    """What an instruction word at a block's start does, for the message of its verbatim block; None for a
    word that is no instruction (an address, a variable, ``IF``...)."""
    up = word.upper()
    if up in INSTRUCTIONS:
        return f"{up} ({INSTRUCTIONS[up]})"
    if up.startswith("CYCLE") and up[5:].isdigit():
        return f"{up} (a standard cycle)"
    return None
