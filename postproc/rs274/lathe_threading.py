"""The reading of a one-block threading cycle ``P Z I J K R Q H E L`` (G76) that LinuxCNC and grblHAL share
(their plugins' ``threading`` modules): the block's words taken as numbers, the spring passes, where the
cycle starts, and its moves put on the block as a ``CompoundMotion``. Each controller's own rules (which
words it needs, what it refuses, the moves it makes) stay in its plugin; this is the glue around them.
"""

from __future__ import annotations

from typing import Any, Callable, Sequence

from postproc.context import Context
from postproc.cycles.lathe_expansion import to_sections
from postproc.cycles.turning.profile import TurnMove
from postproc.errors import ProgramError
from postproc.ir.expr import Expr
from postproc.ir import Block, CompoundMotion, Feed, Motion

Refusal = Callable[..., ProgramError]
"""``refuse(message, letter=None)``: a located error at the word ``letter`` (else at the block's G)."""


def thread_refusal(block: Block, ctx: Context) -> Refusal:
    """The cycle's refusals, located at the word they name, else at the block's G word."""
    col = ctx.column_of(block, "G")

    def refuse(message: str, letter: str | None = None) -> ProgramError:
        return ProgramError(message, ctx.at(block, ctx.column_of(block, letter) if letter else col))

    return refuse


def thread_words(block: Block, motion: Motion, values: dict[str, Any], letters: str, name: str,
                 refuse: Refusal) -> tuple[dict[str, float], dict[str, float]]:
    """The cycle's words among ``letters`` and its axis words, as numbers; the block's ``Motion`` goes (the
    moves replace it; a refused block keeps none). A computed word is refused (``name``: the cycle as
    messages call it)."""
    del block.sections["Motion"]
    given = {letter: values[letter] for letter in letters if letter in values}
    if any(isinstance(v, Expr) for v in [*given.values(), *motion.axes.values()]):
        raise refuse(f"a computed word in {name} is not supported (write the numbers)")
    words = {letter: float(v) for letter, v in given.items()}
    axes = {axis: float(v) for axis, v in motion.axes.items() if not isinstance(v, Expr)}
    return words, axes


def spring_passes(words: dict[str, float], ctx: Context, refuse: Refusal, code: str) -> int:
    """H, the spring passes: a whole number, 0 or more, that leaves the cycle within ``<Limits movesPerBlock>``.
    ``code``: the cycle's code as the dialect spells it, for messages."""
    spring = words.get("H", 0.0)
    if spring != int(spring) or spring < 0:
        raise refuse(f"{code} H must be a whole number of spring passes, 0 or more", "H")
    if spring >= ctx.setup.limits.moves_per_block:
        raise refuse(f"{code} H{spring:g} makes more moves than <Limits movesPerBlock> "
                     f"({ctx.setup.limits.moves_per_block})", "H")
    return int(spring)


def compound_angle(angle: float, refuse: Refusal, code: str) -> float:
    """Q, the compound angle in degrees: within 90 of 0 (a steeper infeed is not modelled)."""
    if not -90.0 < angle < 90.0:
        raise refuse(f"{code} Q{angle:g}: a compound angle of 90 degrees or more is not modelled", "Q")
    return angle


def thread_start(block: Block, ctx: Context, refuse: Refusal, code: str) -> tuple[tuple[float, float], float, bool]:
    """Where the cycle starts as (radius, Z), the factor from a radius to the program's X (2 in diameter mode),
    and whether its axis words are incremental (the block's own distance mode, else the mode in force)."""
    x0, z0 = ctx.state.position.get("X"), ctx.state.position.get("Z")
    if x0 is None or z0 is None:
        raise refuse(f"{code}: the tool's position before the cycle is unknown (program an absolute X and Z first)")
    scale = 2.0 if ctx.diameter else 1.0
    incremental = ctx.state.distance == "incremental"
    distance = block.sections.get("DistanceMode")
    if distance is not None:
        incremental = distance.mode == "incremental"  # type: ignore[attr-defined]
    return (float(x0) / scale, float(z0)), scale, incremental


def place_thread_moves(block: Block, ctx: Context, moves: Sequence[TurnMove], start: tuple[float, float],
                       words: dict[str, float], used: set[str], refuse: Refusal, code: str) -> None:
    """The cycle's moves on the block as its ``CompoundMotion`` (named ``code``), the feed rate in force before
    it said again after them (the cycle sets none); ``words`` count as read."""
    limit = ctx.setup.limits.moves_per_block
    if len(moves) > limit:
        raise refuse(f"{code} makes {len(moves)} moves, more than <Limits movesPerBlock> ({limit})")
    items = to_sections(moves, start, ctx)
    feed = block.sections.get("Feed")
    after = feed.value if isinstance(feed, Feed) else ctx.state.feed
    if after is not None:
        items.append(Feed(after))  # the cycle leaves the feed rate as it was
    ctx.moves_made += len(moves)
    block.add(CompoundMotion(code, items))
    used.update(words)
