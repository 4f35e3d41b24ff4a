"""Jumps that a target's spelling of the program could not follow: a program holding one is evaluated for
the target, not kept symbolic (``postproc.api``). Each answers the first such jump, or None."""

from __future__ import annotations

from typing import Callable, Iterable

from .control import CONTROL, LABEL, Goto, GotoLabel
from ..ir.expr import Num
from ..ir import Block


def _targets(blocks: Iterable[Block]) -> tuple[set[int], set[str]]:
    """The sequence numbers and the jump labels that ``blocks`` carry."""
    numbers: set[int] = set()
    labels: set[str] = set()
    for block in blocks:
        sections = block.sections
        sequence = sections.get("Sequence")
        if sequence is not None:
            numbers.add(getattr(sequence, "number", -1))
        label = sections.get(LABEL)
        if label is not None:
            labels.add(getattr(label, "name", ""))
    return numbers, labels


def missing_fallthrough(blocks: list[Block]) -> Goto | GotoLabel | None:
    """The first jump in ``blocks`` whose missing target lets it fall through (SINUMERIK's ``GOTOC``) and
    whose target is indeed not among them, or None. Such a jump does nothing; a target's spelling of it
    would jump nowhere (an alarm), so a program holding one is evaluated for the target, not kept."""
    numbers, labels = _targets(blocks)
    for block in blocks:
        jump = block.sections.get(CONTROL)
        if not isinstance(jump, (Goto, GotoLabel)) or not jump.fallthrough:
            continue
        if isinstance(jump, GotoLabel):
            if jump.label not in labels:
                return jump
        elif isinstance(jump.target, Num) and int(jump.target.value) not in numbers:
            return jump
    return None


def jump_past_end(blocks: list[Block], is_end: Callable[[Block], bool]) -> Goto | GotoLabel | None:
    """The first jump in ``blocks`` that may land after the program's end (the first block ``is_end`` holds):
    one of its targets is there (a dialect that runs on from it: ``SubprogramRules.jumps_past_end``), or
    None. A target's writer comments the blocks after the end out (``postproc.lowering.program_end``), so
    its spelling of the jump would go nowhere: such a program is evaluated for the target, not kept."""
    end = next((pos for pos, block in enumerate(blocks) if is_end(block)), None)
    if end is None:
        return None
    numbers, labels = _targets(blocks[end + 1:])
    for block in blocks:
        control = block.sections.get(CONTROL)
        if isinstance(control, GotoLabel) and control.label in labels:
            return control
        if isinstance(control, Goto) and numbers and (
                not isinstance(control.target, Num) or int(control.target.value) in numbers):
            return control  # a computed number may reach there too
    return None
