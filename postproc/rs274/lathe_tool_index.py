"""index_turret: a lathe program whose controller changes tools as a mill does (LinuxCNC, grblHAL: ``T2 M6``, its
X and Z offsets applied by the tool length offset code, ``G43``/``G43 H5``, cancelled by ``G49``) written for a
turret lathe (Fanuc T, GSK: ``Dialect.LATHE_TURRET``), whose T word indexes the turret and selects the offset
register at once (``T0205``: station 2, offset 5).

Each is a choice of one register of the machine's offset table: LinuxCNC's lathe tool table gives each entry an
X and a Z offset, ``G43`` applies the loaded tool's, ``G43 H5`` entry 5's [K: LinuxCNC G-code reference, G43 "the
tool table entry ... X and Z offsets on a lathe"; V: rs274 2.9, lathe ``G43 H2`` prints ``USE_TOOL_LENGTH_OFFSET``
with entry 2's X and Z]; a Fanuc T offset number selects the geometry (and wear) offset of that number, X and Z
[K: Fanuc 0i-TF operator's manual, "Tool offset", T code = tool number and offset number]. So the register is
the same number on both: the translation takes the target's offset n to hold what the source's entry n holds,
as the reverse translation (``postproc.cycles.lathe_lowering``: ``T0102`` -> ``T1 M6 G43 H2``) does. The
simulation applies the set-up's ``<Tool>`` X and Z for the register on both sides, so ``verify`` checks it.

* ``T2 M6`` becomes ``T02nn``: nn the register the block's own ``G43 [H]`` selects (00 for ``G49``), else the
  one in force (M6 changes no offset); the tool change goes.
* ``G43 [H n]``/``G49`` in a block of its own next to the change, with nothing between them that moves the tool,
  reads a position, writes a table or runs a construct (``QUIET``), is folded into the change's index: after it
  (``T2 M6`` then ``G43 H2``: ``T0202``; the source's offset applies at its next move, the index's too) or before
  it (``G49`` then ``T0 M6``: ``T0000``, the register the index takes being the one the code put in force). A
  program's usual ``T7 M6`` / ``G43 H9`` becomes ``T0709``. Anywhere else it is refused: its turret form
  re-indexes the station (``T0205``), which moves nothing on the machine but is a tool change to the simulation,
  so ``verify`` could not check it.
* A ``T3`` without ``M6`` only prepares the next change: it goes, noted in a comment (a turret would index).

Refused, located: a change while the spindle turns (the source's M6 stops it first [V: rs274 prints
``STOP_SPINDLE_TURNING`` before ``CHANGE_TOOL``], the turret indexes with it turning), a computed tool or
register, a negative offset (``G44`` has no turret form), a station
or register above 99, and a dynamic length (``G43.1``), which the target has not.
"""

from __future__ import annotations

from typing import Final, Iterator, Mapping

from postproc.context import Context
from postproc.dialect import Dialect
from postproc.errors import UnsupportedError
from postproc.compensation.tool_table import ToolTable
from postproc.ir import Block, Comments, Motion, SpindleControl, ToolChange, ToolLengthOffset, ToolSelect

__all__ = ["index_turret"]


def index_turret(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """Lowering transform (module docstring); any other program passes untouched."""
    if not ctx.lathe or ctx.lathe_turret or not target.LATHE_TURRET or "lathe" not in target.MACHINE_TYPES \
            or target.WRITER is None:
        return blocks
    return _index(blocks, ctx)


QUIET: Final = frozenset(("Comments", "Sequence", "ToolSelect", "ToolChange", "ToolLengthOffset", "SpindleControl",
                          "SpindleSpeed", "Coolant", "Feed", "FeedMode", "Plane", "DistanceMode", "Units", "PathControl"))
"""Sections of a block that neither moves the tool nor reads or writes what a length code changes: a length code
and a tool change with only such blocks between them act at the same point of the path."""
HELD: Final = 1000
"""Blocks held at most while a length code waits for its change (or a change for its code): memory stays flat."""
LONE: Final = ("a tool offset changed without a tool change: a turret lathe selects the offset with the station's "
               "index, which the simulation counts as a tool change (put the length code in the block of the change, "
               "or next to it with no move between)")


def _index(blocks: Iterator[Block], ctx: Context) -> Iterator[Block]:
    selected: int | None = None
    register = 0
    turning = False
    held: list[Block] = []
    """Blocks since the last index or lone length code, none of which moves (``QUIET``)."""
    index: tuple[Block, int] | None = None
    """The held index (block, station) a length code after it may still set the register of."""
    lone: Block | None = None
    """A held length code without a change, which a change before the next move takes."""
    table = ToolTable(ctx.setup)
    applied: tuple[float, float] | None = (0.0, 0.0)
    """The X and Z offsets the last index written put in force (None: not known here)."""
    shifted: set[str] = set()
    """Axes whose offset the last index changed, until the first move after it (``_moved_after_index``)."""
    absolute = True
    for block in blocks:
        sections = block.sections
        if held and (not QUIET.issuperset(sections) or len(held) >= HELD):
            for out in _flush(held, lone, ctx):
                index_now = out.sections.get("ToolSelect")
                if isinstance(index_now, ToolSelect) and isinstance(index_now.number, int):
                    applied, shifted = _offsets_change(table, applied, index_now.number % 100)
                yield out
            held, index, lone = [], None, None
        distance = sections.get("DistanceMode")
        if distance is not None:
            absolute = getattr(distance, "mode", "absolute") == "absolute"
        if shifted and not held and _moves(sections):
            try:
                _moved_after_index(block, ctx, shifted, absolute)
            except UnsupportedError as err:
                ctx.diagnostics.error(err)
            shifted = set()
        try:
            select = sections.get("ToolSelect")
            change = sections.get("ToolChange")
            length = sections.get("ToolLengthOffset")
            control = sections.get("SpindleControl")
            if isinstance(select, ToolSelect):
                if not isinstance(select.number, int):
                    raise UnsupportedError("a computed tool number on a turret lathe (its station is known when "
                                           "the program runs)", ctx.at(block))
                selected = select.number
            if isinstance(length, ToolLengthOffset):
                register = _register(block, ctx, length, selected)
            if isinstance(change, ToolChange):
                if turning:
                    raise UnsupportedError("a tool change with the spindle turning: the source's change stops it "
                                           "first, a turret indexes with it turning (stop the spindle before the "
                                           "change)", ctx.at(block))
                if selected is None:
                    raise UnsupportedError("a tool change with no tool selected", ctx.at(block))
                _index_here(block, ctx, selected, register)
                del sections["ToolChange"]
                if lone is not None:  # the code before the change: the index takes its register
                    lone.sections.pop("ToolLengthOffset", None)
                    lone.changed()
                    lone = None
                index = (block, selected)
            elif isinstance(length, ToolLengthOffset) and index is not None:
                _index_here(index[0], ctx, index[1], register)  # the code after the change: into its index
                del sections["ToolLengthOffset"]
            elif isinstance(length, ToolLengthOffset):
                if lone is not None:  # the first of two: no change took it
                    ctx.diagnostics.error(UnsupportedError(LONE, ctx.at(lone)))
                    held.remove(lone)
                lone = block
            elif isinstance(select, ToolSelect):
                del sections["ToolSelect"]  # prepared for the next change; a turret would index now
                comments = sections.get("Comments")
                texts = comments.texts if isinstance(comments, Comments) else []
                sections["Comments"] = Comments([*texts, f"TOOL {select.number} PREPARED"])
            if isinstance(control, SpindleControl):
                turning = control.direction in ("cw", "ccw")
            if isinstance(change, ToolChange) or isinstance(length, ToolLengthOffset) or isinstance(select, ToolSelect):
                block.changed()
        except UnsupportedError as err:
            ctx.diagnostics.error(err)
            continue
        if index is not None or lone is not None:
            held.append(block)
        else:
            yield block
    yield from _flush(held, lone, ctx)


_MOVING: Final = frozenset(("Motion", "CompoundMotion", "CycleCall", "CannedCycle", "LatheCycle", "RigidTap"))


def _moves(sections: Mapping[str, object]) -> bool:
    return not _MOVING.isdisjoint(sections)


def _offsets_change(table: ToolTable, applied: tuple[float, float] | None,
                    register: int) -> tuple[tuple[float, float] | None, set[str]]:
    """The offsets an index of ``register`` puts in force, and the axes on which they differ from ``applied``
    (none where either is not known here: the simulation then compares the selection, not the path)."""
    new = table.lathe(register, False)
    if new is None or applied is None:
        return new, set()
    return new, {axis for axis, a, b in (("X", applied[0], new[0]), ("Z", applied[1], new[1])) if abs(a - b) > 1e-12}


def _moved_after_index(block: Block, ctx: Context, shifted: set[str], absolute: bool) -> None:
    """The first move after an index that changed the offsets on ``shifted``: the source's ``G43`` applies each
    axis's offset where that axis is next programmed [V: LinuxCNC, ``postproc.lowering.length_timing``], the
    turret's index on every axis at this move [K: Fanuc T]; they agree only where the move programs each such
    axis absolutely, else a located error (was: translated, the unnamed axis moved by its offset change)."""
    motion = block.sections.get("Motion")
    named = set(motion.axes) if isinstance(motion, Motion) and motion.mode in ("rapid", "linear", "cw", "ccw") \
        and absolute else set()
    missing = sorted(shifted - named)
    if missing:
        raise UnsupportedError(
            f"the first move after a turret index leaves {' and '.join(missing)} unprogrammed (or is not an absolute "
            "move): the source applies the new offset on an axis where it is next programmed, the turret's index on "
            "every axis at this move (program " + " and ".join(sorted(shifted)) + " in the first move after the tool "
            "change)", ctx.at(block))


def _flush(held: list[Block], lone: Block | None, ctx: Context) -> Iterator[Block]:
    """The held blocks; a length code no change took is refused at its line (``LONE``)."""
    for block in held:
        if block is lone:
            ctx.diagnostics.error(UnsupportedError(LONE, ctx.at(block)))
            continue
        yield block


def _register(block: Block, ctx: Context, length: ToolLengthOffset, tool: int | None) -> int:
    """The offset register the block's length code puts in force (0: cancelled)."""
    if length.mode == "cancel":
        return 0
    if length.mode != "positive":
        raise UnsupportedError(f"a tool length offset '{length.mode}' on a turret lathe: its T word selects a "
                               "register of X and Z offsets, added", ctx.at(block))
    number = length.register if length.register is not None else tool
    if number is None or not isinstance(number, int):
        raise UnsupportedError("a computed or unknown offset register on a turret lathe (write H with a number)",
                               ctx.at(block))
    return number


def _index_here(block: Block, ctx: Context, tool: int, register: int) -> None:
    """The block indexes station ``tool`` with offset ``register`` (``T0205``); its length code goes."""
    if not 0 <= tool <= 99 or not 0 <= register <= 99:
        raise UnsupportedError(f"tool {tool} with offset {register}: a turret's T word takes two digits each",
                               ctx.at(block))
    block.sections.pop("ToolLengthOffset", None)
    block.sections["ToolSelect"] = ToolSelect(tool * 100 + register)
