"""The RS274 family's lathe-cycle words (Fanuc T system A/B/C numbering aside, and GSK 980TDc alike).

Which letter means what depends on the cycle and on which of its blocks is read (DIALECTS.md 2.2):
``G71 U(depth) R(retract)`` then ``G71 P(ns) Q(nf) U(allowance X) W(allowance Z) F``; in the one-block
form (10/11/15-T, set-up ``latheCycleFormat="one-block"``) ``G71 P Q U W D F``. ``read_cycle`` turns a
cycle block's words into ``LatheCycle`` parameters with neutral names, in program units: X values and the X
allowance as programmed (diameters on a diameter machine), depths and reliefs as radii; U/W end points
are made absolute from the cycle's start. A word a block omits takes the controller's data parameter
(the set-up's ``<LatheCycles>``), and a value programmed in a first block replaces it for later cycles,
as the controller rewrites its parameter (GSK No.051-060, Fanuc 5130-5143).
"""

from __future__ import annotations

from typing import Any

from postproc.context import Context
from postproc.errors import ParseError, ProgramError
from postproc.ir import Block
from postproc.ir.lathe_sections import LatheCycle
from postproc.setup.record import values

DEFAULTS_KEY = "lathe_words.defaults"
"""``ctx.state.extra`` key: the data parameters in force (a dict, from the set-up, then as programmed)."""
SINGLE_KEY = "lathe_words.single"
"""``ctx.state.extra`` key: the parameters of the single cycle in force (a repeat block changes some)."""

TWO_BLOCK = frozenset(("turn_rough", "face_rough", "pattern_repeat", "face_peck", "groove", "thread_multi"))
ONE_BLOCK_FORM = frozenset(("turn_rough", "face_rough", "pattern_repeat", "thread_multi", "face_peck", "groove"))
"""Cycles the set-up's one-block format reads as one block: G74/G75 too (``G75 X Z I K D F``, the retract
from the controller's setting) [K: Haas lathe operator's manual, G74 "End Face Grooving" and G75 "O.D./I.D.
Grooving": I the X increment, K the Z increment, D the clearance, as known, not re-read here; the public Haas
programs of tests/heldout write ``G75 X0. I0.005``; [?] Fanuc 10/11/15-T's one-block format alike]."""
SINGLE = frozenset(("turn_single", "thread_single", "face_single"))

FIRST_WORDS: dict[str, dict[str, tuple[str, str]]] = {
    "turn_rough": {"U": ("depth", "length"), "R": ("retract", "length")},
    "face_rough": {"W": ("depth", "length"), "R": ("retract", "length")},
    "pattern_repeat": {"U": ("relief_x", "length"), "W": ("relief_z", "length"), "R": ("passes", "count")},
    "face_peck": {"R": ("retract", "length")},
    "groove": {"R": ("retract", "length")},
    "thread_multi": {"P": ("packed", "packed"), "Q": ("min_depth", "increments"), "R": ("allowance", "length")},
}
"""First block of a two-block cycle: letter -> (parameter, how it is read)."""

SECOND_WORDS: dict[str, dict[str, tuple[str, str]]] = {
    "turn_rough": {"P": ("ns", "count"), "Q": ("nf", "count"), "U": ("allow_x", "length"),
                   "W": ("allow_z", "length"), "K": ("check", "count")},
    "pattern_repeat": {"P": ("ns", "count"), "Q": ("nf", "count"), "U": ("allow_x", "length"),
                       "W": ("allow_z", "length")},
    "turn_finish": {"P": ("ns", "count"), "Q": ("nf", "count")},
    "face_peck": {"X": ("x", "length"), "Z": ("z", "length"), "U": ("x", "increment"), "W": ("z", "increment"),
                  "P": ("step_x", "increments"), "Q": ("step_z", "increments"), "R": ("relief", "length")},
    "thread_multi": {"X": ("x", "length"), "Z": ("z", "length"), "U": ("x", "increment"), "W": ("z", "increment"),
                     "R": ("taper", "length"), "P": ("height", "increments"), "Q": ("first_depth", "increments")},
    "turn_single": {"X": ("x", "length"), "Z": ("z", "length"), "U": ("x", "increment"), "W": ("z", "increment"),
                    "R": ("taper", "length")},
}
"""The cycle block (second of two, or the only one): letter -> (parameter, how it is read)."""
SECOND_WORDS["face_rough"] = SECOND_WORDS["turn_rough"]

SECOND_WORDS["groove"] = SECOND_WORDS["face_peck"]
SECOND_WORDS["thread_single"] = SECOND_WORDS["turn_single"]
SECOND_WORDS["face_single"] = SECOND_WORDS["turn_single"]

ONE_WORDS: dict[str, dict[str, tuple[str, str]]] = {
    "turn_rough": {"P": ("ns", "count"), "Q": ("nf", "count"), "U": ("allow_x", "length"),
                   "W": ("allow_z", "length"), "D": ("depth", "length")},
    "pattern_repeat": {"P": ("ns", "count"), "Q": ("nf", "count"), "U": ("allow_x", "length"),
                       "W": ("allow_z", "length"), "I": ("relief_x", "length"), "K": ("relief_z", "length"),
                       "D": ("passes", "count")},
    "thread_multi": {"X": ("x", "length"), "Z": ("z", "length"), "U": ("x", "increment"), "W": ("z", "increment"),
                     "I": ("taper", "length"), "K": ("height", "length"), "D": ("first_depth", "length"),
                     "A": ("angle", "count"), "P": ("infeed", "count")},
}
"""The one-block forms: ``G71 P Q U W D F``, ``G73 P Q I K U W D F``, ``G76 X Z I K D F A P`` (G74/G75 below)."""
ONE_WORDS["face_rough"] = ONE_WORDS["turn_rough"]
ONE_WORDS["face_peck"] = {"X": ("x", "length"), "Z": ("z", "length"), "U": ("x", "increment"), "W": ("z", "increment"),
                          "I": ("step_x", "length"), "K": ("step_z", "length"), "D": ("relief", "length")}
"""``G74 X Z I K D F``: I the X shift between pecking columns, K the Z peck, D the relief at the bottom; I, K
and D radius values with a decimal point [K: Haas G74 (see ``ONE_BLOCK_FORM``); [?] that I is a radius]."""
ONE_WORDS["groove"] = ONE_WORDS["face_peck"]
"""``G75 X Z I K D F``: I the X peck, K the Z shift between grooves, D the relief [K: Haas G75]."""

PERSISTENT = {
    "depth": "rough_depth", "retract": "rough_retract", "relief_x": "pattern_relief_x",
    "relief_z": "pattern_relief_z", "passes": "pattern_passes", "finish_passes": "thread_finish_passes",
    "chamfer": "thread_chamfer", "angle": "thread_angle", "min_depth": "thread_min_depth",
    "allowance": "thread_allowance",
}
"""Parameters a first block (or a one-block cycle) makes the new default -> the set-up field it starts from."""
LENGTHS = frozenset(("depth", "retract", "relief_x", "relief_z", "min_depth", "allowance"))
"""Persistent parameters that are lengths (kept in mm, converted for an inch program)."""
PECK_RETRACT = "peck_retract"
"""G74/G75 keep their own retract (GSK No.056), apart from the G71/G72 one (No.052)."""

REQUIRED: dict[str, tuple[str, ...]] = {
    "turn_rough": ("ns", "nf"), "face_rough": ("ns", "nf"), "pattern_repeat": ("ns", "nf"),
    "turn_finish": ("ns", "nf"), "face_peck": ("z",), "groove": ("x",), "thread_multi": ("x", "z", "height", "first_depth"),
    "turn_single": ("x", "z"), "thread_single": ("x", "z"), "face_single": ("x", "z"),
}
"""Words a cycle cannot run without (a missing one is a located error naming its letter)."""


def defaults(ctx: Context) -> dict[str, Any]:
    """The data parameters in force for this run (created from the set-up on first use)."""
    extra = ctx.state.extra
    found = extra.get(DEFAULTS_KEY)
    if found is None:
        found = extra[DEFAULTS_KEY] = values(ctx.setup.lathe_cycles)
    return found


def cycle_form(kind: str, block: Block, ctx: Context) -> str:
    """Which block of its cycle ``block`` is: 'first', 'second', 'one' or 'single'."""
    letters = {w[0].upper() for w in block.words}
    if kind in SINGLE or kind == "turn_finish":
        return "single"
    if ctx.one_block and kind in ONE_BLOCK_FORM:
        return "one"
    if kind in ("turn_rough", "face_rough", "pattern_repeat"):
        return "second" if "P" in letters else "first"
    if kind == "thread_multi" or kind in ("face_peck", "groove"):
        return "second" if letters & set("XZUW") else "first"
    return "single"


def read_cycle(kind: str, block: Block, ctx: Context, code: str, start: dict[str, float | None]) -> LatheCycle:
    """The block's ``LatheCycle``: its words read per cycle and form, omitted ones from the defaults."""
    form = cycle_form(kind, block, ctx)
    table = {"first": FIRST_WORDS, "one": ONE_WORDS}.get(form, SECOND_WORDS)[kind]
    params: dict[str, float | int] = {}
    given: set[str] = set()
    for letter, num in block.words:
        up = letter.upper()
        if up in "NOGMFST":
            continue
        entry = table.get(up)
        if entry is None:
            raise ProgramError(f"address {up} has no meaning in {code} ({_form_name(form)})",
                               ctx.at(block, ctx.column_of(block, up)))
        name, how = entry
        if name in given:
            other = "U" if up == "X" else "X" if up == "U" else "W" if up == "Z" else "Z"
            raise ProgramError(f"{code} takes {other} or {up}, not both", ctx.at(block, ctx.column_of(block, up)))
        given.add(name)
        params[name] = _value(block, ctx, code, up, num, how, start, name)
    if kind == "thread_multi" and "packed" in params:
        packed = int(params.pop("packed"))
        params["finish_passes"], params["chamfer"], params["angle"] = packed // 10000, packed // 100 % 100, packed % 100
    _check_values(kind, params, block, ctx, code)
    state = defaults(ctx)
    to_mm = 25.4 if ctx.state.units == "inch" else 1.0  # the data parameters are kept in mm
    if form in ("first", "one"):
        for name, value in params.items():
            if name in PERSISTENT:
                state[PERSISTENT[name]] = value * to_mm if name in LENGTHS else value
        if kind in ("face_peck", "groove") and "retract" in params:
            state[PECK_RETRACT] = params["retract"] * to_mm
    if form == "first":
        # every parameter of the block, resolved: a target that omits none writes them all
        for entry in FIRST_WORDS[kind].values():
            params.setdefault(entry[0], _default(entry[0], kind, state, to_mm))
        if kind == "thread_multi":
            params.pop("packed", None)
            for name in ("finish_passes", "chamfer", "angle"):
                params.setdefault(name, state[PERSISTENT[name]])
        return LatheCycle(kind, form, params)
    if kind in SINGLE:
        params = _single(kind, params, block, ctx, code, given)
    if form != "first" and kind in ("face_peck", "groove"):
        # G74 without X drills on the spot; G75 without Z cuts one groove
        axis, name = ("X", "x") if kind == "face_peck" else ("Z", "z")
        if name not in params and start.get(axis) is not None:
            params[name] = start[axis]  # type: ignore[assignment]
    for name in REQUIRED[kind]:
        if name not in params:
            raise ProgramError(f"{code} needs {_letters(table, name)}", ctx.at(block, _code_col(block, ctx)))
    for name in _resolved(kind):
        params.setdefault(name, _default(name, kind, state, to_mm))
    return LatheCycle(kind, form, params)


def _resolved(kind: str) -> tuple[str, ...]:
    """Parameters the cycle uses besides those of its block (data parameters and omitted words)."""
    return {
        "turn_rough": ("allow_x", "allow_z", "depth", "retract"),
        "face_rough": ("allow_x", "allow_z", "depth", "retract"),
        "pattern_repeat": ("allow_x", "allow_z", "relief_x", "relief_z", "passes"),
        "face_peck": ("x", "step_x", "step_z", "relief", "retract"),
        "groove": ("z", "step_x", "step_z", "relief", "retract"),
        "thread_multi": ("taper", "finish_passes", "chamfer", "angle", "min_depth", "allowance"),
        "turn_single": ("taper",), "thread_single": ("taper",), "face_single": ("taper",),
    }.get(kind, ())


def _default(name: str, kind: str, state: dict[str, Any], to_mm: float) -> float | int:
    """An omitted parameter's value in program units (the data parameters are kept in mm)."""
    if name == "retract" and kind in ("face_peck", "groove"):
        return float(state[PECK_RETRACT]) / to_mm
    if name in PERSISTENT:
        value = state[PERSISTENT[name]]
        return float(value) / to_mm if name in LENGTHS else int(value)
    return 0 if name == "check" else 0.0


def _single(kind: str, params: dict[str, float | int], block: Block, ctx: Context, code: str,
            given: set[str]) -> dict[str, float | int]:
    """A single cycle's X, Z and R stay in force while it does: a repeat block changes what it gives."""
    extra = ctx.state.extra
    previous = extra.get(SINGLE_KEY)
    if previous is not None and previous[0] == kind:
        params = {**previous[1], **params}
    extra[SINGLE_KEY] = (kind, dict(params))
    return params


def _value(block: Block, ctx: Context, code: str, up: str, num: str, how: str,
           start: dict[str, float | None], name: str) -> float | int:
    where = ctx.at(block, ctx.column_of(block, up))
    if how in ("count", "packed"):
        if "." in num:
            whole, _, frac = num.partition(".")
            if frac.strip("0") or not whole.lstrip("+-").isdigit():
                raise ParseError(f"address {up} of {code} is a whole number ({up}{num})", where)
            num = whole
        try:
            count = int(num)
        except ValueError:
            raise ParseError(f"address {up} needs a number ({up}{num})", where) from None
        if count < 0:
            raise ProgramError(f"address {up} of {code} cannot be negative ({up}{num})", where)
        return count
    units = ctx.state.units
    if how == "increments":
        if "." in num:
            raise ParseError(f"address {up} of {code} takes no decimal point: it counts least input "
                             f"increments ({up}{num})", where)
        return _int(num, up, where) * ctx.setup.input.increment(units)
    value: float
    if "." in num:
        value = _float(num, up, where)
    elif ctx.setup.input.decimal_point == "calculator":
        value = float(_int(num, up, where))
    else:
        value = _int(num, up, where) * ctx.setup.input.increment(units)
    if how == "increment":
        axis = "X" if up == "U" else "Z"
        origin = start.get(axis)
        if origin is None:
            raise ProgramError(f"{code} {up}{num}: the {axis} position before the cycle is unknown (program an "
                               f"absolute {axis} first)", where)
        return origin + value
    return value


def _check_values(kind: str, params: dict[str, float | int], block: Block, ctx: Context, code: str) -> None:
    """Refuse values the controller refuses, each at its word."""
    positive = ("depth", "height", "first_depth", "min_depth")
    letters = {name: letter for table in (FIRST_WORDS, SECOND_WORDS, ONE_WORDS)
               for letter, (name, _) in table.get(kind, {}).items()}
    for name in positive:
        value = params.get(name)
        if value is not None and value <= 0:
            letter = letters.get(name, "")
            raise ProgramError(f"{code}: {letter} ({name.replace('_', ' ')}) must be greater than 0",
                               ctx.at(block, ctx.column_of(block, letter) if letter else 1))
    for name in ("retract", "relief", "allowance", "step_x", "step_z"):
        value = params.get(name)
        if value is not None and value < 0:
            letter = letters.get(name, "")
            raise ProgramError(f"{code}: {letter} ({name}) cannot be negative", ctx.at(block, ctx.column_of(block, letter)))
    if "passes" in params and params["passes"] < 1:
        raise ProgramError(f"{code}: the number of passes must be at least 1", ctx.at(block, ctx.column_of(block, "R")))
    if "angle" in params and params["angle"] not in (0, 29, 30, 55, 60, 80):
        raise ProgramError(f"{code}: tool angle {params['angle']} is not one of 0, 29, 30, 55, 60, 80",
                           ctx.at(block, ctx.column_of(block, "P")))


def _letters(table: dict[str, tuple[str, str]], name: str) -> str:
    return " or ".join(letter for letter, (n, _) in table.items() if n == name) or name


def _code_col(block: Block, ctx: Context) -> int:
    return ctx.column_of(block, "G")


def _form_name(form: str) -> str:
    return {"first": "its first block", "second": "its second block", "one": "its one-block form"}.get(form, "its block")


def _int(num: str, up: str, where: Any) -> int:
    try:
        return int(num)
    except ValueError:
        raise ParseError(f"address {up} needs a number ({up}{num})", where) from None


def _float(num: str, up: str, where: Any) -> float:
    try:
        return float(num)
    except ValueError:
        raise ParseError(f"address {up} needs a number ({up}{num})", where) from None


def profile_letters(cycle: Any) -> dict[str, str]:
    """A lathe cycle's letter of each parameter that names a block of its profile (``P`` ``ns``, ``Q`` ``nf``):
    what a renumbering rewrites."""
    table = ONE_WORDS if getattr(cycle, "form", "") == "one" else SECOND_WORDS
    words = table.get(getattr(cycle, "kind", ""), {})
    return {param: letter for letter, (param, _) in words.items() if param in ("ns", "nf")}
