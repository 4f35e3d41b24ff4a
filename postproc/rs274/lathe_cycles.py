"""LatheCycleSyntax: a lathe cycle block -> its ``LatheCycle`` and motion, with the profile it runs.

Runs after ``ModalStateSyntax`` (so the profile blocks are read with the modal state they are written
in), as the last step of a lathe reading pipeline. For G71/G72/G73 it holds the blocks from the cycle
to the profile's last block (nf): bounded look-ahead, that construct only. The controller runs the
profile through the cycle and then continues after nf, so the profile blocks are marked ``InProfile``
(the simulator skips them) and the modal state the profile left is put back to what the cycle left:
the tool is where the cycle ended. A G70 runs a profile read by an earlier roughing cycle.

Each expansion is exact: the moves come from the turning geometry (``postproc.cycles.turning``)
through ``postproc.cycles.lathe_expansion``; the block keeps both the resolved ``LatheCycle`` (for a
target that runs the cycle) and its ``CompoundMotion`` (for one that does not, and the simulator).
"""

from __future__ import annotations

import copy
import dataclasses
from typing import TYPE_CHECKING, Iterable, Iterator

from postproc.block_rules import ZERO_FEED, per_rev_problem
from postproc.context import Context
from postproc.compensation.nose import TIPS
from postproc.compensation.tool_table import ToolTable
from postproc.cycles.lathe_expansion import (expand, finishing_split, nose_shape, profile_segments, start_point,
                                             to_sections)
from postproc.cycles.lathe_lowering import NOSE_PROFILE, THREAD_CHAMFER
from postproc.errors import PostprocError, ProgramError, UnsupportedError
from postproc.ir.expr import Expr
from postproc.interp.variables import RUN_INTERPRETER_KEY
from postproc.ir import (Block, CompoundMotion, CutterCompensation, CycleCall, DataSetting, Feed, MachineFunction,
                         Motion, NativeCode, Sequence)
from postproc.ir.lathe_sections import InProfile, LatheCycle
from postproc.syntaxes.syntax import Syntax

from .lathe_words import defaults, read_cycle

if TYPE_CHECKING:
    from postproc.cycles.turning.profile import Seg

PROFILES_KEY = "LatheCycleSyntax.profiles"
"""``ctx.state.extra`` key: (ns, nf) -> the profile segments a roughing cycle read (for a later G70)."""
PROFILE_BLOCKS_KEY = "LatheCycleSyntax.profile_blocks"
"""``ctx.run_data`` key: (ns, nf) -> the profile's blocks, for a G70 that starts elsewhere than the roughing cycle
did (``_finishing_profile``); in the run's data, not the modal state, which is copied at every roughing cycle."""
CHAMFER_OFF_KEY = "LatheCycleSyntax.chamfer_off"
"""``ctx.state.extra`` key: True after a code declared ``thread-chamfer-off`` (no angled pull-out at a thread's
end) until one declared ``thread-chamfer-on``."""
NOSE_KEY = "LatheCycleSyntax.nose"
"""``ctx.state.extra`` key: (ns, nf) -> the nose compensation its first block turns on (mode, register)."""
ROUGHING = frozenset(("turn_rough", "face_rough", "pattern_repeat"))
OFFSETS_KEY = "LatheCycleSyntax.offsets"
"""``ctx.state.extra`` key: the offset memory once a ``G10`` wrote into it (``_note_offsets``)."""
MODAL_NOSE_KEY = "LatheCycleSyntax.modal_nose"
"""``ctx.state.extra`` key: the tool nose radius compensation in force outside the cycles (mode, register), absent
while none is (``_note_compensation``)."""
MAX_PROFILE_BLOCKS = 100_000
"""Blocks held at most while looking for a profile's last block."""
_QUIET = frozenset(("Sequence", "Comments"))


class LatheCycleSyntax(Syntax):
    XNAME = "LatheCycleSyntax"
    __slots__ = ()

    def build(self, block: Block, ctx: Context) -> None:  # the stream form does the work
        raise NotImplementedError("LatheCycleSyntax runs as a stream (process)")

    def process(self, blocks: Iterable[Block], ctx: Context) -> Iterator[Block]:
        report = ctx.diagnostics.error
        stream = iter(blocks)
        for block in stream:
            if "MachineFunction" in block.sections:
                _thread_chamfer_switch(block, ctx)
            if "CutterCompensation" in block.sections:
                _note_compensation(block, ctx)
            if "DataSetting" in block.sections:
                _note_offsets(block, ctx)
            call = block.sections.get("CycleCall")
            if not isinstance(call, CycleCall) or call.kind not in LatheCycle.CYCLE_KINDS:
                yield block
                continue
            if _haas_finishing_extras(block, ctx, call.kind):
                yield block
                continue
            try:
                cycle, code = self._read(block, ctx, call.kind)
            except PostprocError as err:
                report(err.located(ctx.at(block)))
                block.sections.pop("CycleCall", None)
                yield block
                continue
            if cycle.form in ("second", "one") and cycle.kind in ROUGHING:
                yield from self._roughing(block, ctx, cycle, code, stream)
                continue
            after: Block | None = None
            try:
                after = self._run(block, ctx, cycle, code, None, "I")
            except PostprocError as err:
                report(err.located(ctx.at(block)))
            yield block
            if after is not None:
                yield after

    # -- one cycle -----------------------------------------------------------------------------------
    def _read(self, block: Block, ctx: Context, kind: str) -> tuple[LatheCycle, str]:
        code = next(("G" + num for letter, num in block.words if letter in "Gg"), None) \
            or ctx.state.extra.get("LatheCycleSyntax.code", kind)
        if code.startswith("G") and kind in ("turn_single", "thread_single", "face_single"):
            ctx.state.extra["LatheCycleSyntax.code"] = code
        start = {"X": ctx.state.position.get("X"), "Z": ctx.state.position.get("Z")}
        cycle = read_cycle(kind, block, ctx, code, start)
        if kind == "thread_multi" and ctx.state.extra.get(CHAMFER_OFF_KEY):
            cycle.params["chamfer"] = 0  # no angle out of the thread (Haas M24)
        elif kind == "thread_single" and ctx.setup.controller.variant == "haas" \
                and not ctx.state.extra.get(CHAMFER_OFF_KEY):
            # Haas M23, its power-on default (``_thread_chamfer_switch``)
            cycle.params["chamfer"] = int(defaults(ctx)["thread_chamfer"])
        del block.sections["CycleCall"]
        block.add(cycle)
        return cycle, code

    def _run(self, block: Block, ctx: Context, cycle: LatheCycle, code: str, profile: list[Seg] | None,
             rough_type: str) -> Block | None:
        """Expand a cycle that moves (not a first block) and put the tool where it ends; a finishing cycle
        whose profile turns nose compensation off in its last block returns that block's part, to follow."""
        if cycle.form == "first":
            return None
        if cycle.kind == "turn_finish" and _copied(ctx) and \
                (int(cycle.params["ns"]), int(cycle.params["nf"])) in ctx.state.extra.get(KEPT_KEY, ()):
            _keep_as_written(block, ctx, code, "it finishes a profile that computes")
            return None
        start = start_point(ctx)
        if start is None:
            raise ProgramError(f"{code}: the tool's position before the cycle is unknown (program an absolute "
                               "X and Z first)", ctx.at(block))
        if cycle.kind == "turn_finish":
            profiles = ctx.state.extra.get(PROFILES_KEY, {})
            key = (int(cycle.params["ns"]), int(cycle.params["nf"]))
            profile = profiles.get(key)
            if profile is None:
                raise ProgramError(f"{code} P{key[0]} Q{key[1]}: no roughing cycle before it read the profile "
                                   f"N{key[0]}..N{key[1]}", ctx.at(block))
            nose = ctx.state.extra.get(NOSE_KEY, {}).get(key)
            profile = _finishing_profile(profile, key, start, ctx, code, nose is not None)
            if nose is not None:
                return self._finish_with_nose(block, ctx, cycle, code, start, profile, nose)
        try:
            moves = expand(cycle, start, profile, ctx.state.feed, ctx, rough_type)
        except ProgramError as err:
            raise ProgramError(f"{err.message}" if err.message.startswith(code) else f"{code}: {err.message}",
                               ctx.at(block)) from None
        if cycle.kind == "turn_finish" and MODAL_NOSE_KEY in ctx.state.extra and moves \
                and (moves[-1].kind != "rapid" or (moves[-1].x, moves[-1].z) != start):
            raise UnsupportedError(f"{code}: under tool nose radius compensation the offset is temporarily cancelled "
                                   "on the return to the start point [K], and this profile ends at it (no return): "
                                   "where the tool then stands is not modelled; end the profile away from the start "
                                   "point", ctx.at(block))
        if any(move.kind != "rapid" and move.feed == 0.0 for move in moves):
            # a cycle cuts at F as a G01 does: Fanuc alarms on F0 (PS0011 FEED ZERO, Fanuc T manual [K]; GSK
            # 980TDc alike [?]), rs274 and grbl refuse the expanded G1 (block_rules.ZERO_FEED) [V]
            raise ProgramError(f"{code}: {ZERO_FEED}", ctx.at(block, ctx.column_of(block, "F")))
        problem = per_rev_problem(ctx.state.spindle, ctx.state.spindle_rpm) \
            if ctx.state.feed_mode == "per_rev" and any(move.kind != "rapid" for move in moves) else None
        if problem is not None:  # its cuts feed per revolution as a G01's do (modal_state._check_turning)
            raise ProgramError(f"{code}: {problem}", ctx.at(block, ctx.column_of(block, "G")))
        limit = ctx.setup.limits.moves_per_block
        if len(moves) > limit:
            raise ProgramError(f"{code} makes {len(moves)} moves, more than <Limits movesPerBlock> ({limit})",
                               ctx.at(block))
        ctx.moves_made += len(moves)
        block.add(CompoundMotion(cycle.kind, to_sections(moves, start, ctx)))
        if moves:
            last = moves[-1]
            ctx.state.position["X"] = last.x * (2.0 if ctx.diameter else 1.0)
            ctx.state.position["Z"] = last.z
        return None

    def _finish_with_nose(self, block: Block, ctx: Context, cycle: LatheCycle, code: str, start: tuple[float, float],
                          profile: list[Seg], nose: tuple[str, int | None]) -> Block:
        """G70 over a profile that turns nose compensation on in its first block and off in its last: the
        controller runs the blocks as programmed, compensated [K: Haas, G70 finishes the P..Q path with its
        G41/G42 and G40; as known, not re-read here]. The cycle's block turns compensation on and makes every move but the last; a block
        after it turns compensation off and makes the last (the departure) and the return."""
        if "CutterCompensation" in block.sections:
            raise ProgramError(f"{code}: the cycle's block sets tool nose radius compensation and its profile turns "
                               "it on and off too", ctx.at(block))
        try:
            head, tail = finishing_split(start, profile, ctx.state.feed)
        except ProgramError as err:
            raise ProgramError(f"{code}: {err.message}", ctx.at(block)) from None
        if any(move.kind != "rapid" and move.feed == 0.0 for move in head + tail):
            raise ProgramError(f"{code}: {ZERO_FEED}", ctx.at(block, ctx.column_of(block, "F")))
        cycle.params[NOSE_PROFILE] = 1
        mode, register = nose
        ctx.moves_made += len(head) + len(tail)
        block.add(CutterCompensation(mode, register))
        block.add(CompoundMotion(cycle.kind, to_sections(head, start, ctx)))
        end = (head[-1].x, head[-1].z) if head else start
        after = Block(block.line, None, "\n", list(block.words))  # its source, for the expansion's note
        after.add(CutterCompensation("off"))
        after.add(CompoundMotion(cycle.kind, to_sections(tail, end, ctx)))
        after.changed()
        last = tail[-1] if tail else head[-1] if head else None
        if last is not None:
            ctx.state.position["X"] = last.x * (2.0 if ctx.diameter else 1.0)
            ctx.state.position["Z"] = last.z
        return after

    def _roughing(self, block: Block, ctx: Context, cycle: LatheCycle, code: str,
                  stream: Iterator[Block]) -> Iterator[Block]:
        """Hold the blocks up to nf, read them as the profile, expand, then let everything go."""
        ns, nf = int(cycle.params["ns"]), int(cycle.params["nf"])
        saved = copy.deepcopy(ctx.state)
        held: list[Block] = []
        profile: list[Block] = []
        found = False
        problem: PostprocError | None = None
        for later in stream:
            held.append(later)
            number = later.sections.get("Sequence")
            if not profile:
                if isinstance(number, Sequence) and number.number == ns:
                    profile.append(later)
                elif set(later.sections) - _QUIET:
                    problem = ProgramError(f"{code}: the profile N{ns} must follow the cycle block (line "
                                           f"{later.line} comes first)", ctx.at(block))
                    break
            else:
                profile.append(later)
            if profile and isinstance(number, Sequence) and number.number == nf:
                found = True
                break
            if len(held) > MAX_PROFILE_BLOCKS:
                problem = ProgramError(f"{code}: no block N{nf} within {MAX_PROFILE_BLOCKS} blocks", ctx.at(block))
                break
        _restore(ctx, saved)
        if problem is None and not found:
            problem = ProgramError(f"{code}: the profile's last block N{nf} is not in the program"
                                   if profile else f"{code}: the profile's first block N{ns} is not in the program",
                                   ctx.at(block))
        if problem is None:
            for later in profile:
                if "LatheCycle" in later.sections or "CycleCall" in later.sections:
                    problem = ProgramError(f"{code}: the profile block at line {later.line} programs a cycle",
                                           ctx.at(later))
                    break
        if problem is None and _copied(ctx) and _computes(profile):
            _keep_as_written(block, ctx, code, "its profile computes")
            ctx.state.extra.setdefault(KEPT_KEY, set()).add((ns, nf))
            for later in profile:
                later.add(InProfile(block.line))
            yield block
            yield from held
            return
        if problem is None:
            try:
                start = start_point(ctx)
                if start is None:
                    raise ProgramError(f"{code}: the tool's position before the cycle is unknown (program an "
                                       "absolute X and Z first)", ctx.at(block))
                nose = _profile_nose(profile, ctx, code)
                segs = profile_segments(profile, start, ctx, code, nose is not None)
                _check_monotonic(cycle, segs, profile, ctx, code)
                rough_type = _rough_type(profile, cycle.kind)
                shape = segs
                if nose is not None:
                    shape = _nose_shape(segs, start, nose, cycle, rough_type, ctx, code)
                    cycle.params[NOSE_PROFILE] = 1
                elif MODAL_NOSE_KEY in ctx.state.extra:
                    shape = _modal_nose_shape(segs, start, ctx.state.extra[MODAL_NOSE_KEY], cycle, rough_type,
                                              ctx, code) or segs
                ctx.state.extra.setdefault(PROFILES_KEY, {})[(ns, nf)] = segs
                # a copy: the blocks go on down the stream, where later steps rewrite them
                ctx.run_data.setdefault(PROFILE_BLOCKS_KEY, {})[(ns, nf)] = copy.deepcopy(profile)
                ctx.state.extra.setdefault(NOSE_KEY, {})[(ns, nf)] = nose
                self._run(block, ctx, cycle, code, shape, rough_type)
            except PostprocError as err:
                problem = err
        if problem is not None:
            ctx.diagnostics.error(problem.located(ctx.at(block)))
        for later in profile:
            later.add(InProfile(block.line))
        yield block
        yield from held


KEPT_KEY = "LatheCycleSyntax.kept"
"""``ctx.state.extra`` key: the (ns, nf) of the roughing cycles a copy kept as written (``_keep_as_written``), so a
finishing cycle on the same profile is kept too."""
KEPT_CYCLE = "kept as written (its moves are known where it runs)"
"""What the ``NativeCode`` of a kept cycle says, after its reason."""


def _copied(ctx: Context) -> bool:
    """The program goes to its own dialect as written: a copy (``program_mode`` 'keep') in which nothing runs and
    which is no dry run of a translation elsewhere (``postproc.api._keep_check``, which must find that another
    target needs the moves), as LinuxCNC's lathe cycles and polar lines decide."""
    return (ctx.program_mode == "keep" and RUN_INTERPRETER_KEY not in ctx.run_data
            and not ctx.run_data.get("dry_run"))


def _computes(profile: list[Block]) -> bool:
    """A profile block has a computed move or feed word (``X[#1]``, ``R#2``, ``F#3``): its moves are known only
    where the program runs, so ``profile_segments`` refuses it."""
    for block in profile:
        feed = block.sections.get("Feed")
        if isinstance(feed, Feed) and isinstance(feed.value, Expr):
            return True
        motion = block.sections.get("Motion")
        if isinstance(motion, Motion) and (any(isinstance(v, Expr) for v in motion.axes.values())
                                           or isinstance(motion.radius, Expr)
                                           or any(isinstance(v, Expr) for v in (motion.center or {}).values())):
            return True
    return False


def _keep_as_written(block: Block, ctx: Context, code: str, why: str) -> None:
    """A cycle of a copy whose moves are known only where the program runs: its line goes out as written
    (``NativeCode``, which only its own dialect writes) and its profile blocks with it, as ever; the controller
    reads the profile when the cycle runs, as it would have in the source [K: Fanuc T G70-G73, the blocks ns..nf
    read by the cycle; GSK 980TDc alike [?]]. Where the tool ends is not known here: X and Z are unknown after it,
    and a later step that needs them refuses with its own located error. ``verify`` and ``toolpath`` run the
    program (``program_mode`` 'execute'), so they read the moves; a translation elsewhere flattens or refuses."""
    block.sections.pop("LatheCycle", None)
    block.add(NativeCode(ctx.dialect, f"{code}: {why}, {KEPT_CYCLE}", block.text or ""))
    ctx.state.position["X"] = None
    ctx.state.position["Z"] = None


def _finishing_profile(segs: list[Seg], key: tuple[int, int], start: tuple[float, float], ctx: Context, code: str,
                       nose: bool) -> list[Seg]:
    """The profile a finishing cycle runs: the blocks ns..nf run from where the tool stands at the G70, as a
    subprogram would, which need not be where the roughing cycle started (the tool may have moved between them:
    tests/heldout/haas/cadekiely_l5_lathe.nc chamfers with ``U.1 W-.1`` and starts its G70 at Z-0.1, its G71 at
    Z0.1) [K: Fanuc T and Haas G70, the blocks ns..nf executed from the start point, then a rapid back to it;
    GSK's manual alike]. The segments the roughing cycle read are kept where they start there; otherwise the
    blocks are read again from this start."""
    if not segs or (abs(segs[0].x0 - start[0]) <= 1e-9 and abs(segs[0].z0 - start[1]) <= 1e-9):
        return segs
    blocks = ctx.run_data.get(PROFILE_BLOCKS_KEY, {}).get(key)
    if blocks is None:
        return segs  # (read elsewhere: the chain check names the gap)
    return profile_segments(blocks, start, ctx, code, nose)


HAAS_FINISHING_WORDS = "UWD"
"""Letters a Haas lathe's G70 is written with in public programs (``G70 P45 Q49 U0.009 D0.01 F0.005``, copied from
the G71 block before it: tests/heldout/haas/cadekiely_*) whose meaning there is not in our sources [?]."""


def _haas_finishing_extras(block: Block, ctx: Context, kind: str) -> bool:
    """A Haas lathe's finishing cycle written with U, W or D: kept verbatim for its own dialect (``NativeCode``), so
    a copy for a Haas runs what the machine runs, and refused by name everywhere else (the simulation stops there).
    Haas documents G70 with P and Q (the profile's first and last blocks), the F, S and T inside the profile in
    effect and a rapid back to the start point after the Q block [K: Haas lathe operator's manual, "G70 Finishing
    Cycle", as known, not re-read here]; U, W and D are G71's finishing allowances and depth of cut [V: Haas G71
    page, staging-diy.haascnc.com, "G71 Address Relationships"]. What the control does with them on a G70 (ignore
    them, leave the allowances, alarm) is not in our sources [?], so no toolpath is guessed for the block (issue 29,
    searched again: the docs, pages and code corpora hold Haas's G71 and TNC pages and the Productivity/Haas lathe
    workbooks' covers, not the G70 page's text; the third-party G70 summaries reached give P Q F S only). Fanuc
    T reads no such words in G70 (an address error, ``lathe_words.SECOND_WORDS``)."""
    if kind != "turn_finish" or ctx.setup.controller.variant != "haas":
        return False
    letters = sorted({letter.upper() for letter, _ in block.words if letter.upper() in HAAS_FINISHING_WORDS})
    if not letters:
        return False
    del block.sections["CycleCall"]
    block.add(NativeCode(ctx.dialect, f"a Haas finishing cycle with {', '.join(letters)} (the roughing cycle's "
                         "finishing allowances and depth of cut: what the Haas does with them in a finishing cycle "
                         "is not in our sources [?])",
                         block.text or ""))
    return True


def _thread_chamfer_switch(block: Block, ctx: Context) -> None:
    """A code declared ``thread-chamfer-off`` turns the angled pull-out off for the multiple threading cycles
    after it, ``thread-chamfer-on`` back on with the set-up's ``threadChamfer`` (Haas M24 and M23, the
    Fanuc dialect's Haas lathe defaults; another family gets the code as a comment, the cycles carrying
    their chamfer: ``postproc.cycles.lathe_lowering``). On a Haas lathe the same codes switch the single
    threading cycle's (G92) pull-out too, and M23 is in force at power-on [K: Haas lathe operator's manual,
    M23 "Angle Out of Thread On": "M23 commands the control to perform a chamfer at the end of a thread
    executed by G76 or G92", M24 none, each in force until the other, M23 the default at power-on and reset;
    Settings 95 and 96 the chamfer's size (in leads) and angle; as known, not re-read here]: a Haas G92 pulls
    out at 45 degrees over the set-up's ``threadChamfer`` tenths of the lead (Setting 95 = threadChamfer / 10
    [?: its factory value 1.000 and Setting 96's 45 degrees are from a third-party page,
    industrialmonitordirect.com "Fixing G76 threading tool pull-off groove on Haas lathe"; another angle is
    not modelled]), as its G76 does, and square under M24. Fanuc T's own G92 chamfers only on a machine
    signal [K: 0i-F, "Threading cycle (G92)": "a signal from the machine tool initiates thread chamfering"]:
    read square."""
    function = block.sections.get("MachineFunction")
    if isinstance(function, MachineFunction) and function.action in THREAD_CHAMFER:
        ctx.state.extra[CHAMFER_OFF_KEY] = function.action == THREAD_CHAMFER[1]


def _restore(ctx: Context, saved: object) -> None:
    """Put back the modal state the cycle block left (the profile blocks run only inside the cycle)."""
    state = ctx.state
    extra = state.extra
    for f in dataclasses.fields(state):
        if f.name not in ("extra", "symbolic", "computes"):
            setattr(state, f.name, getattr(saved, f.name))
    state.extra = extra


def _profile_nose(profile: list[Block], ctx: Context, code: str) -> tuple[str, int | None] | None:
    """The nose compensation a profile turns on in its first block and off in its last (the Haas form:
    ``G42`` in the P block, ``G40`` in the Q block, both with a move) [K: Haas lathe operator's manual,
    TNC with G70-G73, as known, not re-read here; the public Haas programs of tests/heldout are written so];
    None when the profile has none. Any
    other placement, or this form on another controller (Fanuc T alarms on G40-G42 inside ns..nf [K]),
    is left to ``profile_segments`` to refuse by name."""
    found = [(i, b.sections["CutterCompensation"]) for i, b in enumerate(profile)
             if isinstance(b.sections.get("CutterCompensation"), CutterCompensation)]
    if not found or ctx.setup.controller.variant != "haas":
        return None
    last = len(profile) - 1
    if len(found) != 2 or found[0][0] != 0 or found[1][0] != last or last == 0:
        return None
    on, off = found[0][1], found[1][1]
    assert isinstance(on, CutterCompensation) and isinstance(off, CutterCompensation)
    if on.mode not in ("left", "right") or off.mode != "off" or isinstance(on.register, Expr) \
            or not isinstance(profile[0].sections.get("Motion"), Motion) \
            or not isinstance(profile[last].sections.get("Motion"), Motion):
        return None
    return on.mode, on.register if isinstance(on.register, int) else None


def _nose_shape(segs: list[Seg], start: tuple[float, float], nose: tuple[str, int | None], cycle: LatheCycle,
                rough_type: str, ctx: Context, code: str) -> list[Seg]:
    """The shape a roughing cycle roughs to under the profile's nose compensation: the radius and tip of
    the offset the T code selected (``T0101``: 1) or the one G41/G42 names, from the set-up's ``<Tool>``."""
    mode, register = nose
    radius, tip = _nose_offset(register, ctx, code, "the profile's")
    if radius == 0.0:
        return list(segs[:-1])
    rules = ctx.cutter_rules
    if rules is None:
        raise ProgramError(f"{code}: the profile's tool nose radius compensation cannot be simulated: the "
                           "controller's compensation rules are not modelled")
    return nose_shape(segs, start, mode, radius, tip, cycle.kind, rough_type, code, rules)


def _nose_offset(register: int | None, ctx: Context, code: str, whose: str) -> tuple[float, tuple[int, int]]:
    """The nose radius (program units) and tip direction of the offset G41/G42 names, else of the one the T
    code selected (``T0101``: 1), from the set-up's ``<Tool>``."""
    if register is None:
        tool = ctx.state.tool
        register = tool % 100 if isinstance(tool, int) else None
    if not register:
        raise ProgramError(f"{code}: {whose} tool nose radius compensation takes the radius of the offset "
                           "the T code selected, and none is (program T with its offset number, T0101)")
    table = _offsets(ctx)
    return table.radius(register) / (25.4 if ctx.state.units == "inch" else 1.0), TIPS[table.tip(register)]


def _offsets(ctx: Context) -> ToolTable:
    """The program's offset memory as far as it is read: the set-up's ``<Tool>``s and what a ``G10`` before
    wrote (``_note_offsets``), as the simulation's compensation reads it."""
    table = ctx.state.extra.get(OFFSETS_KEY)
    return table if isinstance(table, ToolTable) else ToolTable(ctx.setup)


def _note_offsets(block: Block, ctx: Context) -> None:
    """A programmable data input into the offset memory (Fanuc T ``G10 P X Z R Q``) is read where it stands."""
    setting = block.sections["DataSetting"]
    if isinstance(setting, DataSetting) and not any(isinstance(v, Expr) for v in setting.values.values()):
        table = _offsets(ctx)
        if table.write(setting, 25.4 if ctx.state.units == "inch" else 1.0):
            ctx.state.extra[OFFSETS_KEY] = table


def _note_compensation(block: Block, ctx: Context) -> None:
    """Follow G40/G41/G42 outside the cycles (``MODAL_NOSE_KEY``); one in a cycle's own block is refused by the
    block syntax (``lathe_block_syntax``: PS0325 on Fanuc T [K: ``cutter_rules.FANUC_T``])."""
    cc = block.sections["CutterCompensation"]
    if not isinstance(cc, CutterCompensation):
        return
    if cc.mode in ("left", "right") and not isinstance(cc.register, Expr):
        ctx.state.extra[MODAL_NOSE_KEY] = (cc.mode, cc.register if isinstance(cc.register, int) else None)
    else:
        ctx.state.extra.pop(MODAL_NOSE_KEY, None)


def _modal_nose_shape(segs: list[Seg], start: tuple[float, float], modal: tuple[str, int | None],
                      cycle: LatheCycle, rough_type: str, ctx: Context, code: str) -> list[Seg] | None:
    """The shape a roughing cycle roughs to under the compensation in force before it, where the controller's
    rules run it so (``CutterRules.roughing_cycles``: Fanuc T's G71/G72 [K]): the finishing shape with the
    compensation applied, started up at its first block from the start point and ending square to its last
    block (the offset is temporarily cancelled for the return to the start point), as the imaginary tip's path
    (``turning.nose_path`` over the profile and that return). None where the rules do not say (the lowering
    refuses the cycle by name)."""
    rules = ctx.cutter_rules
    if rules is None or cycle.kind not in rules.roughing_cycles:
        return None
    if rough_type == "II":
        raise UnsupportedError(f"{code}: a type II cycle (its first profile block names both axes) under tool nose "
                               "radius compensation: how the controller roughs pockets to the compensated shape is "
                               "not in our sources [?]; cancel compensation before the cycle, or program a type I "
                               "profile")
    mode, register = modal
    try:
        radius, tip = _nose_offset(register, ctx, code, "the")
    except ProgramError:
        # no radius to rough by: a copy for this controller writes the cycle as it is, and the simulation of
        # the program refuses the G41/G42 before it for want of the same radius (``simulate.moves``)
        return None
    if radius == 0.0:
        return segs
    if len(segs) < 2:
        raise ProgramError(f"{code}: the profile under tool nose radius compensation has no block after its first "
                           "that moves")
    from postproc.cycles.turning.profile import Seg as Segment
    last = segs[-1]
    back = Segment("line", last.x1, last.z1, start[0], start[1], None, None, None, last.line, True)
    return nose_shape([*segs, back], start, mode, radius, tip, cycle.kind, rough_type, code, rules)


def _rough_type(profile: list[Block], kind: str) -> str:
    """Type II when the ns block names both axes (``W0`` counts), type I when only the infeed axis (Haas: "If the P
    block contains only an X-Axis position, then Type 1 roughing is assumed. If the P block contains both an X-Axis
    and Z-Axis position, then Type 2 roughing is assumed" [V: Haas lathe G71 page, staging-diy.haascnc.com])."""
    motion = next((b.sections["Motion"] for b in profile if isinstance(b.sections.get("Motion"), Motion)), None)
    if not isinstance(motion, Motion):
        return "I"
    other = ("Z", "W") if kind != "face_rough" else ("X", "U")
    return "II" if any(a in motion.axes for a in other) else "I"


def _check_monotonic(cycle: LatheCycle, segs: list[Seg], profile: list[Block], ctx: Context, code: str) -> None:
    """GSK's K1: from the ns block's end on, every profile block keeps the direction of the ones before
    it, on both axes (the ns block is the infeed from the start point)."""
    if int(cycle.params.get("check", 0)) != 1:
        return
    for axis in ("x", "z"):
        direction = 0.0
        for seg in segs[1:]:
            step = getattr(seg, axis + "1") - getattr(seg, axis + "0")
            if abs(step) <= 1e-9:
                continue
            if direction and (step > 0) != (direction > 0):
                block = next(b for b in profile if b.line == seg.line)
                raise ProgramError(f"{code} K1: the profile is not monotonic in {axis.upper()} at line {seg.line}",
                                   ctx.at(block))
            direction = step
