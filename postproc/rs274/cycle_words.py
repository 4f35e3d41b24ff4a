"""The RS274 family's hole-cycle words: the bottom is the axis normal to the plane, R the level,
Q the peck or shift, P the dwell; cycles are named by the dialect's own code table."""

from __future__ import annotations

from postproc.cycle_words import CycleWords

from .codes import CodeTable


def rs274_cycle_words(codes: CodeTable, repeat: tuple[str, ...] | None,
                      max_repeat: int | None = None) -> CycleWords:
    """The family's cycle words, named from ``codes``; ``repeat`` None takes the repeat letters from
    the set-up (K, L or K+L), else those letters; ``max_repeat`` the controller's largest count."""
    names = {str(kind): spelling for kind, spelling in codes.arguments("cycle").items()}
    spindle = {str(direction): spelling for direction, spelling in codes.arguments("spindle").items()}
    return CycleWords(names=names, return_to_r=codes.spell("return", "r") or "return to R",
                      level="R", peck="Q", shift="Q", dwell="P", spindle=spindle, repeat=repeat,
                      max_repeat=max_repeat)


NEUTRAL_CYCLE_WORDS = CycleWords(names={}, return_to_r="return to R", level="R", peck="Q", shift="Q", dwell="P")
"""The letters of a cycle made in the IR with no reading dialect (a program built from sections, as the
conformance suite's probes are): the RS274 family's, which ``CannedCycle.words`` then holds."""
