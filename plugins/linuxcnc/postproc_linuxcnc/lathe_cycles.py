"""LinuxCNC's lathe cycles ``G70 Q X Z D E P`` (finishing) and ``G71``/``G72`` (``.1``, ``.2``) ``Q X Z D I R``
(roughing), read on a lathe set-up into the moves they make (a ``CompoundMotion``: the simulation runs them,
another controller gets them written as its own moves; a LinuxCNC program keeps its line).

The profile is the subprogram ``o<Q> sub`` .. ``endsub``, kept as written by the reader
(``ProfileCollector``); the controller reads its G0-G3 moves alone, G0 as G1, each with an optional A (a
fillet at its end) or C (a chamfer), U/W as increments of X/Z [V: LinuxCNC ``docs/src/gcode/g-code.adoc``
"G70", "G71 G72"; ``src/emc/rs274ngc/interp_g7x.cc`` ``convert_g7x``]. The moves are
``postproc.rs274.ngc_g7x``'s (the controller's algorithm). Before them, a rapid to the cycle's X and Z; the
tool stays where the last move ends; the feed rate in force cuts.

In diameter mode (G7) the profile's and the cycle's X and U are diameters; arc centres, R, D, E, I (the depth)
and R (the retract) are radial [V: rs274 2.9.0~pre1, a G7 program with X and U doubled cuts the G8 one's moves].

Refused where read, rs274's own refusals (``ProgramError``): no Q ("G7x.x requires a Q word"), a plane other
than ZX, I not above 0, G71/G72 under cutter compensation, a profile arc given by neither I/K nor R or by
both, a profile not monotonic. Where the program runs (``RUN_INTERPRETER_KEY``), the profile is run as LinuxCNC
runs it, as a call from the cycle through its o-word loops, branches, calls and parameter assignments, its words
evaluated with the parameters' values then (``_run_profile``; a read of the current position reads the profile's own
point); there the cycle's line is written as its moves (the flattened program has no subprograms). In a program
kept as written (not run), its words alone are read (``_kept_words``). A plain copy to LinuxCNC keeps a cycle with a
computed word or whose profile computes as written, its moves unknown here (``_kept_as_written``). Not modelled, so
refused (``UnsupportedError``): in a program kept as written for another purpose, any computed word in a profile
(what it reads has no value without the program's run) and a control statement or parameter assignment in a
profile (read past before issue 26: a loop's moves were taken once); a profile with any word but those (a feed or
speed is ignored there: said rather than dropped), a subprogram not
defined before the cycle, the cycle in incremental mode (G91), a P of G70 that is no whole number from 1,
G70 under cutter compensation (``read_g7x``, any version), and, where the set-up names no LinuxCNC version
(``<Controller version>``), a roughing profile that some version closes back to the cycle's X (G71) or Z (G72):
2.9.0 leaves it open, 2.9.1-2.9.3 and 2.9.4 on close it under different conditions (``postproc.rs274.ngc_g7x``,
``CycleRules``), so its cut depends on the version (``_check_closed``). With a version, its rules cut it; a version
before 2.9.0 has no G70-G72 (refused), one after 2.10.0 is not modelled.
"""

from __future__ import annotations

from typing import Any, Callable, Final, Generator, Iterator

from postproc.context import Context
from postproc.interp.control import ASSIGN, SubEnd, SubStart
from postproc.cycles.turning.profile import TurnMove
from postproc.errors import Location, PostprocError, ProgramError, UnsupportedError
from postproc.ir.expr import Expr
from postproc.interp.variables import RUN_INTERPRETER_KEY, RUN_VARIABLES_KEY
from postproc.reading import READER_FOUND
from postproc.ir import Block, Motion, NativeCode
from postproc.rs274.arc_ends import RS274NGC_ARC_END
from postproc.rs274.codes import g_key
from postproc.rs274.lathe_threading import place_thread_moves, thread_refusal
from postproc.rs274.ngc_g7x import (FIRST, MASTER, V2_9_1, V2_9_4, NgcCycleError, arc_centre_by_radius, closes,
                                   cycle_moves, rules_of)
from postproc.rs274.ngc_g7x_segments import Arc, Chamfer, Fillet, Line, Piece

from . import arc_centres

MODES: Final = {"70": "ngc_g70", "71": "ngc_g71", "71.1": "ngc_g71.1", "71.2": "ngc_g71.2", "72": "ngc_g72",
                "72.1": "ngc_g72.1", "72.2": "ngc_g72.2"}
"""Code -> the motion kind the code table gives it on a lathe (replaced by its moves where read)."""
CODE_OF: Final = {mode: code for code, mode in MODES.items()}
WORDS: Final = {"70": "QDEP", "71": "QDIR", "72": "QDIR"}
"""The cycle's words besides X and Z [V: g-code.adoc]."""
PROFILES_KEY: Final = "ngc.g7x_profiles"
"""Key in what the reader found (``postproc.reading.READER_FOUND``): subprogram name -> its blocks as written
(``ProfileCollector``, ``profiles``)."""
COMPENSATING_KEY: Final = "ngc.g7x_compensating"
"""``ctx.state.extra`` key: cutter (tool nose) compensation is on (``follow_compensation``)."""
CORNER_BLOCK: Final = "a G70-G72 profile block with a fillet (A) or chamfer (C)"
"""What the ``NativeCode`` of such a block says: it travels as written, inert (the controller runs it only
through its cycle, which reads its words from the subprogram as written)."""
IN_SUB_KEY: Final = "ngc.g7x_in_sub"
"""``ctx.state.extra`` key: a subprogram's definition is being read (keep mode: its blocks pass here)."""
PROFILE_LETTERS: Final = frozenset("NGXZUWIKRAC")
IGNORED: Final = frozenset("FS")
"""Words the controller reads past in a profile [V: g-code.adoc: "All other commands are ignored, including
feed and speed settings"]: refused here, as a word the translation would drop."""


Written = tuple[int, list[tuple[str, str]], dict[str, Any]]
"""A profile block as written: its line, its words (letter, number text) and its computed values."""
STATEMENT: Final = "statement"
"""The one word of a ``Written`` that stands for a control statement (an o-word loop, branch, call or return)
or a parameter assignment in a subprogram's definition: the cycle refuses it (``_profile``)."""


class ProfileCollector:
    """The reader's bookkeeping: each ``o<n> sub`` .. ``endsub``'s blocks as written, by name, in
    ``ctx.run_data``. A block there with A or C, which this lathe has not as axes, is a fillet or chamfer
    of a G70-G72 profile: it travels as written (an inert ``NativeCode``, ``CORNER_BLOCK``: its words are
    read by the cycle alone), the controller runs it only through its cycle (``check_profile_block``)."""

    __slots__ = ("profiles", "name", "body", "corner")

    def __init__(self, ctx: Context) -> None:
        found: dict[str, Any] = ctx.run_data.setdefault(READER_FOUND, {})
        self.profiles: dict[str, list[Written]] = found.setdefault(PROFILES_KEY, {})
        self.name: str | None = None
        self.body: list[Written] = []
        axes = ctx.setup.machine.axes
        self.corner = frozenset(letter for letter in "AC" if letter not in axes)

    def see(self, block: Block) -> None:
        control = block.sections.get("Control")
        if isinstance(control, SubStart):
            self.name, self.body = control.name, []
            return
        if isinstance(control, SubEnd):
            if self.name is not None:
                self.profiles[self.name] = self.body
            self.name = None
            return
        if self.name is None:
            return
        if control is not None or ASSIGN in block.sections:
            self.body.append((block.line, [(STATEMENT, (block.text or "").strip())], {}))
            return
        if not block.words:
            return
        self.body.append((block.line, list(block.words), dict(block.values or {})))
        if self.corner and any(letter.upper() in self.corner for letter, _ in block.words):
            block.add(NativeCode("linuxcnc", CORNER_BLOCK, block.text or "", inert=True))
            block.words = []


def profiles(ctx: Context) -> dict[str, list[Written]]:
    """The subprograms the reader found (``ProfileCollector``), by name: in the program's run, and in a dry run of
    the later steps (``READER_FOUND``)."""
    found: dict[str, list[Written]] = ctx.run_data.get(READER_FOUND, {}).get(PROFILES_KEY, {})
    return found


def check_profile_block(block: Block, ctx: Context) -> None:
    """Follow the subprogram definitions through the block syntax (a program kept as written passes them
    there); a profile block with A or C run outside a definition is refused: only a cycle runs it."""
    control = block.sections.get("Control")
    extra = ctx.state.extra
    if isinstance(control, SubStart):
        extra[IN_SUB_KEY] = True
    elif isinstance(control, SubEnd):
        extra.pop(IN_SUB_KEY, None)
    elif _corner_block(block) and not extra.get(IN_SUB_KEY):
        raise ProgramError("a block with A or C (a fillet or chamfer of a G70-G72 profile) run as a move: "
                           "this lathe has no such axis, and only a G70-G72 cycle reads the words so",
                           ctx.at(block))


def follow_compensation(block: Block, ctx: Context) -> None:
    """Whether compensation is on after the block: G41/G42 (and their dynamic forms) on, G40 off."""
    sections = block.sections
    cc = sections.get("CutterCompensation")
    extra = ctx.state.extra
    if cc is not None:
        extra[COMPENSATING_KEY] = cc.mode != "off"  # type: ignore[attr-defined]
    native = sections.get("NativeCode")
    if "DynamicCutterCompensation" in sections or native is not None and \
            str(getattr(native, "what", "")).split(" ", 1)[0] in ("G41.1", "G42.1"):
        extra[COMPENSATING_KEY] = True


def _compensating(block: Block, ctx: Context) -> bool:
    cc = block.sections.get("CutterCompensation")
    if cc is not None:
        return bool(cc.mode != "off")  # type: ignore[attr-defined]
    return bool(ctx.state.extra.get(COMPENSATING_KEY))


def _corner_block(block: Block) -> bool:
    native = block.sections.get("NativeCode")
    return native is not None and getattr(native, "what", None) == CORNER_BLOCK


def read_g7x(block: Block, ctx: Context, motion: Motion, values: dict[str, Any], used: set[str]) -> None:
    """The block's cycle (``motion``, read with its code table kind ``MODES``) -> its ``CompoundMotion``;
    the tool where the cycle leaves it, and no motion mode a later block may repeat (module docstring)."""
    code = CODE_OF[str(motion.mode)]
    name = f"G{code}"
    refuse = thread_refusal(block, ctx)

    def unmodelled(message: str, letter: str | None = None) -> UnsupportedError:
        """A form the controller may run but this reading does not model."""
        return UnsupportedError(message, ctx.at(block, ctx.column_of(block, letter or "G")))

    release = ctx.setup.controller.release()
    version_rules = None if release is None else rules_of(release)
    if release is not None and release < FIRST:
        raise refuse(f"{name}: LinuxCNC {ctx.setup.controller.version} (the set-up's <Controller version>) has no "
                     "G70-G72 (they came with 2.9.0)")
    if release is not None and version_rules is None:
        raise unmodelled(f"{name} of LinuxCNC {ctx.setup.controller.version} (the set-up's <Controller version>) is "
                         "not modelled: its algorithm is read from 2.9.0 to 2.10.0~pre1 (interp_g7x.cc)")

    del block.sections["Motion"]
    state = ctx.state
    state.motion = None  # (the profile's last code stays in force there: a block of axis words alone is refused)
    letters = WORDS[code[:2]]
    given = {letter: values[letter] for letter in letters if letter in values}
    extra = sorted(letter for letter in "UW" if letter in values)
    if extra:
        raise unmodelled(f"{extra[0]} in {name}: the cycle takes X and Z (U and W belong in its profile)", extra[0])
    running = ctx.run_data.get(RUN_INTERPRETER_KEY)
    copied = running is None and ctx.program_mode == "keep"
    """A plain copy to LinuxCNC: a cycle whose moves are not known here is kept as written (``_kept_as_written``)."""
    computed = any(isinstance(v, Expr) for v in [*given.values(), *motion.axes.values()])
    if computed and not copied:
        raise unmodelled(f"a computed word in {name} is not supported (write the numbers)")
    words = {letter: float(v) for letter, v in given.items() if not isinstance(v, Expr)}
    if "Q" not in given:
        raise refuse(f"{name} needs Q, the subprogram of its profile (rs274: \"G7x.x requires a Q word\")")
    if _compensating(block, ctx):
        if code != "70":  # rs274 names the cycle with its sub-cycle, ".0" included [V: interp_g7x.cc "G%d.%d"]
            shown = code if "." in code else f"{code}.0"
            raise refuse(f"{name} with cutter compensation on (rs274: \"G{shown} cannot be used with cutter "
                         "compensation enabled\"): cancel it (G40) before the cycle")
        # Three behaviours by version [V: interp_g7x.cc at the tags v2.9.0, v2.9.2, v2.9.3, v2.9.4 of
        # github:LinuxCNC/linuxcnc]: up to 2.9.2 the cycle's rapids and passes are all compensated, from where the
        # profile ends (reading the profile moved the interpreter's current point there, not the compensation's)
        # [V: rs274 2.9.0~pre1 run here: not the cut of the cycle's moves written out under G41/G42, with or
        # without a move to the profile's end first]; 2.9.3 (b1f3e7d8, "Fix unintended move when using G42 for
        # G70") puts the current point back at the cycle's start before the passes; 2.9.4 (f648d01c and
        # 0b80d453da) also turns compensation off for the rapid to the cycle's X Z and for each pass's first
        # rapid. None of the three is modelled, whatever <Controller version> says: refused.
        raise unmodelled(f"{name} with cutter compensation on is not modelled (any LinuxCNC version): up to 2.9.2 "
                         "the cycle is compensated from where its profile ends [V: rs274 2.9.0~pre1 run here], 2.9.3 "
                         "starts its passes from the cycle's start point (interp_g7x.cc, commit b1f3e7d8), 2.9.4 and "
                         "later also turn compensation off for the approach to the start point and each pass's first "
                         "rapid (commits f648d01c, 0b80d453da); cancel compensation (G40) before the cycle, or write "
                         "its profile under G41/G42 as moves")
    if state.plane != "ZX":
        raise refuse(f"{name} runs in the ZX plane only (rs274: \"can only be used in XZ plane (G18)\")")
    incremental = state.distance == "incremental"
    distance = block.sections.get("DistanceMode")
    if distance is not None:
        incremental = distance.mode == "incremental"  # type: ignore[attr-defined]
    if incremental:
        raise unmodelled(f"{name} in incremental mode (G91) is not modelled (program it in G90)")
    if computed:
        _kept_as_written(block, ctx, name, given, used)
        return
    scale = 2.0 if ctx.diameter else 1.0
    """In diameter mode (G7) X and U are diameters, everything else radial [V: rs274 2.9.0~pre1 run here: a
    profile and cycle X doubled under G7 make the moves of G8; I, K, R, D, E and the depth I unchanged]."""
    x0, z0 = state.position.get("X"), state.position.get("Z")
    x0 = None if x0 is None else float(x0) / scale
    axes = {axis: float(v) for axis, v in motion.axes.items() if not isinstance(v, Expr)}  # (refused above)
    x = axes["X"] / scale if "X" in axes else x0
    z = axes.get("Z", z0)
    if code != "70" and words.get("I", 1.0) <= 0:
        raise refuse(f"{name} I{words['I']:g}: the cut's depth must be above 0 (rs274: \"I must be greater "
                     "than zero\")", "I")
    passes = words.get("P", 1.0)
    if code == "70" and (passes != int(passes) or passes < 1):
        raise refuse(f"{name} P{passes:g}: the number of passes must be a whole number from 1", "P")
    if state.feed is None or state.feed <= 0:
        raise refuse(f"{name} cuts at the feed rate in force, and none is (program F first)")
    label = str(int(words["Q"])) if words["Q"] == int(words["Q"]) else str(words["Q"])
    written = profiles(ctx).get(label)
    if written is None:
        raise unmodelled(f"{name} Q{label}: no subprogram o{label} is defined before the cycle", "Q")
    if copied and _computes(written):
        _kept_as_written(block, ctx, name, words, used)
        return
    if x is None or z is None:
        raise refuse(f"{name}: the tool's position before the cycle is unknown (give the cycle X and Z)")
    start = complex(float(z), float(x))
    at = ctx.at(block, ctx.column_of(block, "Q"))
    point = {"X": start.imag, "Z": start.real}
    run = None if running is None else _run_profile(running, label, block, ctx, name, at, point)
    try:
        pieces = _profile(iter(written) if run is None else run, start, ctx, name, at, scale, point)
    finally:  # a refusal stops the run inside the profile: it leaves the call and the readings now
        if run is not None:
            run.close()
    rules = MASTER if version_rules is None else version_rules  # (no version: a profile any version closes is refused)
    if code != "70" and release is None:
        _check_closed(pieces, float(x), float(z), code, name, unmodelled)
    try:
        moves = cycle_moves(code, pieces, float(x), float(z), d=words.get("D", 0.0), e=words.get("E", 0.0),
                            i=words.get("I", 1.0), r=words.get("R", 0.5), passes=int(passes), rules=rules,
                            inch=state.units == "inch")
    except NgcCycleError as err:
        raise refuse(f"{name}: {err} (rs274: \"G7X error\")") from None
    turn = [TurnMove("rapid", float(x), float(z))]  # the rapid to the cycle's point
    for kind, end, centre in moves:
        turn.append(TurnMove(kind, end.imag, end.real,  # type: ignore[arg-type]
                             None if centre is None else centre.imag, None if centre is None else centre.real))
    origin = (float(x0) if x0 is not None else float(x), float(z0) if z0 is not None else float(z))
    place_thread_moves(block, ctx, turn, origin, words, used, refuse, name)
    if running is not None:  # the program runs: flattened, its subprograms are not written, so neither is the line
        block.changed()  # that names one (was: a --units copy wrote `G70 Q100` without its o100, exit 0)
    last = turn[-1]
    state.position["X"] = last.x * scale
    state.position["Z"] = last.z


KEPT_CYCLE: Final = "a G70-G72 cycle that computes, kept as written (its moves are known where it runs)"
"""What the ``NativeCode`` of such a cycle says (``_kept_as_written``)."""


def _computes(written: list[Written]) -> bool:
    """The profile has a computed word or a control statement or parameter assignment (``_kept_words``)."""
    from postproc.interp.run_state import is_number  # (the interpreter's modules: a profile's cost only)

    return any(words and words[0][0] == STATEMENT
               or any(isinstance(values.get(letter.upper()), Expr) and not is_number(text) for letter, text in words)
               for _, words, values in written)


def _kept_as_written(block: Block, ctx: Context, name: str, words: dict[str, Any], used: set[str]) -> None:
    """A cycle with a computed word or whose profile computes, in a LinuxCNC program copied as written
    (``program_mode`` 'keep': the target is LinuxCNC itself, nothing is flattened and nothing is run,
    ``postproc.api``): its line goes out as written (``NativeCode``), the profile's subprogram with it, and LinuxCNC
    evaluates the profile where the cycle runs, as it would have in the source [V: ``interp_g7x.cc`` reads ``O<q>
    CALL`` when the cycle runs]. Its moves are not known here, so neither is where the tool ends: X and Z are
    unknown after it, and a later step that needs them refuses with its own located error. ``verify`` and
    ``toolpath`` run the program (``program_mode`` 'execute'), so they read the cycle's moves (``_run_profile``).
    Another target, or a copy with ``--units``/``--transform`` (mode 'auto'), needs the moves: the refusal
    (``_kept_words``) stands, and a program that computes is then flattened (``postproc.api._keep_check``)."""
    block.add(NativeCode(ctx.dialect, f"{name} ({KEPT_CYCLE})", block.text or ""))
    used.update(words)
    state = ctx.state
    state.position["X"] = None
    state.position["Z"] = None


def _check_closed(pieces: list[Piece], x: float, z: float, code: str, name: str, unmodelled: Any) -> None:
    """Without a version in the set-up, a roughing profile is read only where no LinuxCNC version closes it back
    to the cycle's X (G71) or Z (G72): 2.9.0 never does, 2.9.1-2.9.3 whenever it ends elsewhere, 2.9.4 on when it
    ends short (``postproc.rs274.ngc_g7x.closes``), so the cut would depend on the version."""
    facing = code.startswith("72")
    if len(pieces) <= 1 or not any(closes(rules, facing, pieces, x, z) for rules in (V2_9_1, V2_9_4)):
        return
    end = pieces[-1].end
    axis, at, cycle = ("Z", end.real, z) if facing else ("X", end.imag, x)
    raise unmodelled(f"{name}: the profile ends at {axis}{at:g}, not at the cycle's {axis}{cycle:g}: LinuxCNC versions "
                     f"cut it differently (interp_g7x.cc: 2.9.0 leaves it open, 2.9.1 adds a move to the cycle's "
                     f"{axis}, commit 03793cc9fa, 2.9.4 only when the profile ends short of it, commit c38c192fdd); "
                     "name the version in the set-up (<Controller version=\"2.9.0\"/>) or end the profile at the "
                     f"cycle's {axis}")


def _run_profile(running: Any, label: str, block: Block, ctx: Context, name: str, at: Location,
                 point: dict[str, float]) -> Generator[Written, None, None]:
    """The profile's blocks as the controller reads them when the cycle runs: the subprogram run as a call from
    the cycle by the program's own interpreter (``Interpreter.call_apart``), through its o-word loops, branches,
    calls and parameter assignments, each block's words evaluated with the parameters as they then stand [V:
    ``interp_g7x.cc`` ``convert_g7x``: ``read("O<q> CALL")``, then ``convert_control_functions`` and the block's
    parameter settings at each block read, until the call level is back to the cycle's; rs274 2.9.0~pre1 run
    here cuts ``nc_files/lathe_g7x_face_boring.ngc``'s ``REPEAT [3]`` three times, tests/test_ngc_g7x.py]. A read
    of the current position (``#<_x>``, ``#5420``..) reads the profile's own point (``point``, which ``_profile``
    moves on before the next block is read: ``_profile_readings``). A fillet or chamfer block, whose words travel
    inert (``ProfileCollector``), gives its words as written, evaluated here. An error of the run is located at
    the cycle's Q and names the profile's line."""
    from postproc.interp.evaluation import evaluate_number  # (the interpreter's modules: a profile's cost only)

    corners = {line: (words, values) for body in profiles(ctx).values()
               for line, words, values in body if words and words[0][0] != STATEMENT}
    variables = running.vars
    errors: list[PostprocError] = []
    with _profile_readings(ctx, variables, point):
        for concrete in running.call_apart(label, block, errors.append):
            origin = getattr(concrete, "origin", None)
            if not _corner_block(concrete):
                yield concrete.line, list(concrete.words), {}
                continue
            found = corners.get(concrete.line)
            if found is None or origin is not None and origin.file != ctx.file:
                raise UnsupportedError(f"{name}'s profile, line {concrete.line}: a fillet or chamfer block of another "
                                       "file's subprogram is not modelled", at)
            words, values = found
            out: list[tuple[str, str]] = []
            for letter, text in words:
                value = values.get(letter.upper())
                if isinstance(value, Expr):
                    try:
                        text = repr(evaluate_number(value, variables, f"{letter}{text}"))
                    except PostprocError as err:
                        raise ProgramError(f"{name}'s profile, line {concrete.line}: {err.message}", at) from None
                out.append((letter, text))
            yield concrete.line, out, {}
    if errors:
        where = errors[0].location
        line = f", line {where.line}" if where is not None else ""
        raise ProgramError(f"{name}'s profile{line}: {errors[0].message}", at)


class _profile_readings:
    """While a profile is read: the current position (``#<_x>``, ``#<_z>``, #5420, #5422) reads the profile's
    own ``point`` (in program units, X a radius): where the profile's moves so far end, from the cycle's X and Z
    [V: rs274 2.9.0~pre1 run here: a profile's first ``X[#<_x>-5] Z[#<_z>-1]`` after ``G0 X40 Z5`` and ``G72 .. X30
    Z2`` ends at X25 Z1; under G7 with the cycle's X60 ``X[#<_x>-10]`` ends at the radius 10 (``#<_x>`` reads the
    radius 30); LinuxCNC's ``nc_files/lathe_g7x_face_boring.ngc`` steps its profile by ``#<_x>``,
    tests/test_ngc_g7x.py]. The other axes and offsets read as the machine stands (``FrameReadings``)."""

    def __init__(self, ctx: Context, variables: Any, point: dict[str, float]) -> None:
        self.ctx, self.variables, self.point = ctx, variables, point
        self.saved: Any = None

    def __enter__(self) -> None:
        # imported here: the interpreter's modules import decimal, which a plain translation to LinuxCNC must not
        # pay for at start-up (tests/test_startup_imports.py); only a cycle's profile comes here
        from postproc.frames.parameters import FrameReadings
        from postproc.rs274.variables import NgcVariables

        point = self.point

        class ProfileReadings(FrameReadings):
            """The frame as the profile's words read it: the profile's point on X and Z, the rest as it stands."""

            __slots__ = ()

            def position(self, axis: str) -> float | None:
                return point[axis] if axis in point else super().position(axis)

            def state(self) -> Any:  # a loop that moves the profile's point on is not repeating itself
                return (super().state(), point["X"], point["Z"])

        if isinstance(self.variables, NgcVariables):
            self.saved = self.variables.frames
            self.variables.frames = ProfileReadings(self.ctx)

    def __exit__(self, *exc: object) -> None:
        from postproc.rs274.variables import NgcVariables
        if isinstance(self.variables, NgcVariables):
            self.variables.frames = self.saved


def _kept_words(words: list[tuple[str, str]], values: dict[str, Any],
                unmodelled: Callable[[str], UnsupportedError]) -> list[tuple[str, str]]:
    """A profile block's words in a program kept as written (not run here: no ``RUN_INTERPRETER_KEY``): numbers
    only. A computed word, whatever it reads (a global or a local parameter, the current position) or gives (the
    G code), is refused: LinuxCNC evaluates it as it reads the profile where the cycle runs [V: rs274 2.9.0~pre1,
    a global parameter set between the ``o100 sub`` and the ``G71 Q100`` shifts the cut by its new value,
    tests/test_ngc_g7x.py], and without the program's run no parameter has a value here. Where the program runs,
    the profile is run with it (``_run_profile``) and nothing comes here."""
    from postproc.interp.run_state import is_number  # (the interpreter's modules: a profile's cost only)

    for letter, text in words:
        if isinstance(values.get(letter.upper()), Expr) and not is_number(text):
            raise unmodelled(f"{letter}{text}: a computed word in a G70-G72 profile of a program kept as written is "
                             "not modelled (the controller evaluates it where the cycle runs, and the program is not "
                             "run here: write the numbers)")
    return words


def _profile(written: Iterator[Written], start: complex, ctx: Context, name: str, at: Location,
             scale: float, point: dict[str, float]) -> list[Piece]:
    """The cycle's pieces: the approach from ``start``, then the subprogram's moves (module docstring), read
    one block at a time: ``point`` is moved on to each move's end before the next block is read (where a
    read of the current position reads it: ``_profile_readings``, ``_run_profile``); a refusal is located at the
    cycle's Q and names the profile's line."""
    pieces: list[Piece] = []
    mode: str | None = None
    absolute_centres = arc_centres.STATE_KEY in ctx.state.extra
    here = start
    for line, words, values in written:
        def fail(message: str) -> ProgramError:
            return ProgramError(f"{name}'s profile, line {line}: {message}", at)

        def unmodelled(message: str) -> UnsupportedError:
            return UnsupportedError(f"{name}'s profile, line {line}: {message}", at)

        if words and words[0][0] == STATEMENT:
            raise unmodelled(f"'{words[0][1]}': a control statement or parameter assignment in a profile of a "
                             "program kept as written is not modelled (the controller runs it as it reads the "
                             "profile, and the program is not run here: write the moves it makes)")
        if values:
            words = _kept_words(words, values, unmodelled)
        got: dict[str, float] = {}
        for letter, num in words:
            up = letter.upper()
            if up == "G":
                key = g_key(num)
                if key not in ("0", "1", "2", "3"):
                    raise unmodelled(f"G{num} in a profile: the cycle reads G0-G3 moves only")
                mode = key
                continue
            if up in IGNORED:
                raise unmodelled(f"{up} in a profile: the controller ignores it there (set it before the cycle)")
            if up not in PROFILE_LETTERS:
                raise unmodelled(f"{up} in a profile: the cycle reads G0-G3 with X, Z, U, W, I, K, R, A and C only")
            if up in got:
                raise fail(f"address {up} appears twice in one block")
            got[up] = float(num)
        got.pop("N", None)
        if not got:
            continue
        if mode is None:
            raise unmodelled("a move without its G0-G3 in a profile (write the code)")
        if "U" in got and "X" in got or "W" in got and "Z" in got:
            raise fail("U beside X or W beside Z (rs274: \"Cannot use U and X in the same block\")")
        end = complex(here.real + got["W"] if "W" in got else got.get("Z", here.real),
                      here.imag + got["U"] / scale if "U" in got else got["X"] / scale if "X" in got else here.imag)
        if "A" in got and "C" in got:
            raise fail("both A and C on a corner (rs274: \"Both A and C parameters on a corner\")")
        if end == here:
            continue
        if mode in ("0", "1"):
            if "I" in got or "K" in got or "R" in got:
                raise fail("I, K or R on a straight move")
            pieces.append(Line(here, end))
        else:
            ccw = mode == "3"
            if "R" in got:
                if "I" in got or "K" in got:
                    raise fail("both R and I or K on an arc (rs274: \"both R and I or K flag used for arc\")")
                try:
                    centre = arc_centre_by_radius(here, end, got["R"], ccw)
                except NgcCycleError as err:
                    raise fail(str(err)) from None
            else:
                if "I" not in got and "K" not in got:
                    raise fail("an arc without I, K or R (rs274: \"either I or K must be present for arc\")")
                offset = complex(got.get("K", 0.0), got.get("I", 0.0))
                centre = offset if absolute_centres else here + offset
                r_start, r_end = abs(here - centre), abs(end - centre)
                if not RS274NGC_ARC_END.allows(r_start, r_end, ctx.state.units == "inch"):
                    raise fail(f"the arc's end is off its circle (radius {r_start:.4f} at its start, {r_end:.4f} "
                               "at its end)")
            pieces.append(Arc(ccw, here, centre, end))
        if "A" in got:
            pieces.append(Fillet(got["A"], end))
        if "C" in got:
            pieces.append(Chamfer(got["C"], end))
        here = end
        point["X"], point["Z"] = here.imag, here.real
    return pieces
