"""The RS274 family's variable models: the ``Variables`` tables its dialects' ``ProgramSyntax.VARIABLES`` name.

- ``MacroBVariables`` (Custom Macro B: Fanuc, Haas): locals ``#1``-``#33`` per macro level (G65 and modal
  calls open a level, M98 shares the caller's), commons ``#100``-``#199`` and ``#500``-``#999``, ``#0``
  always vacant, unset variables vacant, ``#3000=n`` the program's own alarm. Every other number is a
  system variable only the machine knows.
- ``NgcVariables`` (LinuxCNC o-words): ``#1``-``#30`` per call, ``#31``-``#5000`` global, named locals
  per call, ``#<_name>`` globals; ``#5001`` and above are the machine's.
Reading or writing a variable only the machine knows is an ``EvalError`` naming it (``MACHINE_ONLY``).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable, ClassVar, Final, Hashable

from ..ir.expr import Arithmetic, EvalError, Vacancy, Value, VarKey
from ..interp.variables import MACHINE_ONLY, ProgramAlarm, SystemRanges, system_variable

if TYPE_CHECKING:  # an annotation only: the frames are loaded where a run evaluates them
    from ..frames.parameters import FrameReadings

ALARM = 3000
"""Custom Macro B's alarm variable: ``#3000=n (MESSAGE)`` stops the machine with alarm n and the block's
comment as its message [K: Fanuc 0i-F operator's manual, custom macro system variables; zappettiniconsulting
.com wiki "Alarms & Timers"; Haas NGC system variables, the same #3000]."""


def macro_alarm(number: float) -> ProgramAlarm:
    """``#3000=n``: the program's own alarm n (the interpreter adds the block's comment as its message)."""
    return ProgramAlarm(f"the program raises its alarm #{ALARM}={number:g}", f"#{ALARM}")


MACRO_B_SYSTEM: SystemRanges = (
    (1000, 1999, "interface signal"),
    (2000, 2999, "tool compensation value"),
    (3000, 3000, "alarm"),
    (3001, 3002, "clock"),
    (3003, 3004, "automatic operation control"),
    (3005, 3005, "setting data"),
    (3006, 3006, "stop with message"),
    (3007, 3007, "mirror image"),
    (3011, 3012, "date and time"),
    (3901, 3902, "parts count"),
    (4000, 4999, "modal information"),
    (5001, 5008, "block end position"),
    (5021, 5028, "current machine position"),
    (5041, 5048, "current work position"),
    (5061, 5068, "skip signal position"),
    (5081, 5088, "tool length offset value"),
    (5101, 5108, "servo position deviation"),
    (5201, 5999, "work offset"),
    (7000, 7999, "extended work offset"),
    (10000, 99999, "tool compensation value"),
)
"""Custom Macro B system variables by range (what a message calls them) [K: Fanuc 0i-F operator's manual,
custom macro system variables]."""

NGC_SYSTEM: SystemRanges = (
    (5061, 5070, "probe result"),
    (5161, 5169, "first reference point position"),
    (5181, 5189, "second reference point position"),
    (5211, 5219, "origin offset"),
    (5220, 5220, "active coordinate system"),
    (5221, 5399, "work offset"),
    (5400, 5419, "tool data"),
    (5420, 5428, "current position"),
    (5001, 5602, "machine parameter"),
)
"""LinuxCNC's numbered parameters above 5000 (the first matching range names one)."""

NGC_AXES = "XYZABCUVW"
"""The axis order of LinuxCNC's offset parameters (#5211-#5219, and a work system's first nine)."""
NGC_ORIGIN_APPLIED = 5210
"""1 while the G52/G92 offset is in force, else 0; #5211-#5219 hold its value, kept by G92.2 and cleared by
G92.1 [V: ``interp_parameter_def.hh``, ``interp_convert.cc`` ``convert_axis_offsets``]."""
NGC_WORK_FIRST, NGC_WORK_STRIDE, NGC_WORK_SYSTEMS = 5221, 20, 9
"""Work system n (1 = G54 .. 9 = G59.3): X at 5221 + 20 (n - 1), then Y Z A B C U V W, R (its XY rotation,
degrees) the tenth [V: ``interp_parameter_def.hh``]."""
NGC_WORK_WORDS = 10
"""A work system's parameters: its nine axes and R; the other ten of its stride are unused."""
NGC_FRAME_PARAMETERS = range(NGC_ORIGIN_APPLIED,
                             NGC_WORK_FIRST + NGC_WORK_STRIDE * (NGC_WORK_SYSTEMS - 1) + NGC_WORK_WORDS)
"""Every offset parameter (#5210-#5219, #5220, each work system's #5221..#5390)."""
NGC_POSITION_FIRST = 5420
"""#5420-#5428: the current position on X Y Z A B C U V W, in the active coordinate system with every offset
(G5x, G52/G92, tool offset) and in the program's units, set from ``current_x``.. as each block is read; refused
with cutter compensation on [V: ``interp_parameter_def.hh``, ``rs274ngc_pre.cc`` ``Interp::read``,
``interp_read.cc`` ``read_integer_parameter``; LinuxCNC docs "Parameters"]."""
NGC_POSITION = range(NGC_POSITION_FIRST, NGC_POSITION_FIRST + len(NGC_AXES))
NGC_POSITION_READS: Final = {axis: NGC_POSITION_FIRST + i for i, axis in enumerate(NGC_AXES)}
"""Axis -> its current position parameter (``Dialect.POSITION_READS``)."""
NGC_POSITION_NAMES = {f"_{axis.lower()}": axis for axis in NGC_AXES}
"""``#<_x>``..``#<_w>``: the same current position, read where the expression is evaluated, without the
cutter compensation check [V: ``interp_namedparams.cc`` ``NP_X``..: ``_setup.current_x``..]."""
NGC_MACHINE_READS = frozenset((*NGC_FRAME_PARAMETERS, *NGC_POSITION))
"""The parameters a run reads from the frame evaluation: its offsets and the current position."""


class MacroBVariables:
    """Custom Macro B variables (Fanuc, Haas; vacancy: ``Vacancy.NULL``)."""

    __slots__ = ("levels", "commons", "_increment")
    LOCALS = 33

    def __init__(self, increment: Callable[[], float]) -> None:
        self.levels: list[dict[int, float]] = [{}]
        self.commons: dict[int, float] = {}
        self._increment = increment

    @property
    def vacancy(self) -> Vacancy:
        return Vacancy.NULL

    @property
    def arithmetic(self) -> Arithmetic:
        """IEEE double (15i/30i manuals: "double-precision real data, as laid down in the applicable IEEE
        standard" [K]); how a Fanuc reduces an angle is not published: the trigonometric functions'
        "absolute error is guaranteed", not their relative error, so ``SIN[180]`` is a small residual of
        unknown sign there too [K]. Parameter 6004#1 (MFZ) may set tiny results to 0 [?]: not modelled."""
        return Arithmetic.DOUBLE

    @property
    def increment(self) -> float:
        return self._increment()

    def read(self, key: VarKey) -> Value:
        if isinstance(key, str):
            raise EvalError(f"#<{key}>: Custom Macro B has no named variables")
        if 1 <= key <= self.LOCALS:
            return self.levels[-1].get(key)
        if 100 <= key <= 199 or 500 <= key <= 999:
            return self.commons.get(key)
        if key == 0:
            return None
        raise self._unknown(key)

    def snapshot(self) -> Hashable | None:
        """The locals of the running level and the commons: all a program can read (a system variable is
        refused, ``MACHINE_ONLY``); the least increment, which rounds what is read, beside them."""
        return (len(self.levels), tuple(sorted(self.levels[-1].items())), tuple(sorted(self.commons.items())),
                self._increment())

    def plain(self, key: VarKey) -> bool:
        """The locals and commons (``#3000`` raises an alarm; the rest is the machine's)."""
        return isinstance(key, int) and (1 <= key <= self.LOCALS or 100 <= key <= 199 or 500 <= key <= 999)

    def exists(self, key: VarKey) -> bool:
        """Custom Macro B has no test of existence: a variable that is read is vacant or not."""
        raise EvalError("Custom Macro B has no test of whether a variable exists")

    def write(self, key: VarKey, value: Value) -> None:
        if isinstance(key, str):
            raise EvalError(f"#<{key}>: Custom Macro B has no named variables")
        if 1 <= key <= self.LOCALS:
            store = self.levels[-1]
        elif 100 <= key <= 199 or 500 <= key <= 999:
            store = self.commons
        elif key == 0:
            raise EvalError("#0 is always vacant: it cannot be assigned")
        elif key == ALARM and value is not None:
            raise macro_alarm(value)
        else:
            raise self._unknown(key)
        if value is None:
            store.pop(key, None)
        else:
            store[key] = value

    def _unknown(self, key: int) -> EvalError:
        if key < 0 or 34 <= key <= 99 or 200 <= key <= 499:
            return EvalError(f"#{key} is not a Custom Macro B variable")
        return EvalError(f"#{key} ({system_variable(MACRO_B_SYSTEM, key)}) {MACHINE_ONLY}")

    def enter(self, args: dict[int, Value], new_level: bool) -> None:
        """A call: a new level of locals set from ``args`` (G65), or the caller's (M98)."""
        if not new_level:
            return
        self.levels.append({k: v for k, v in args.items() if v is not None})

    def leave(self, new_level: bool, value: Value = None) -> None:
        if new_level and len(self.levels) > 1:
            self.levels.pop()

    def returned(self, value: Value) -> None:
        """Custom Macro B has no returned value."""


class NgcVariables:
    """LinuxCNC parameters (vacancy: LinuxCNC, an unset number reads 0, an unset name is an error).

    ``frames``: the run's frame, which the offset parameters read (``read_frame``); without it they are
    known only to the machine."""

    __slots__ = ("numbered", "named", "globals_", "_increment", "frames", "machine_mm")
    LOCALS = 30
    LAST_GLOBAL = 5000
    RETURNED: ClassVar[frozenset[str]] = frozenset(("_value", "_value_returned"))
    """What a return sets (``postproc.interp.returns``)."""
    RETURN_RULE: ClassVar[str] = ("a call leaves #<_value> and #<_value_returned> as they are, a return without a "
                                  "value sets both to 0")
    """When they change (``leave``; a definition the flow passes: ``SubprogramRules.definition_runs_its_end``)."""

    def __init__(self, increment: Callable[[], float], frames: FrameReadings | None = None,
                 machine_mm: float = 1.0) -> None:
        self.frames = frames
        self.machine_mm = machine_mm
        """mm per machine length unit: the offset parameters are stored in the machine's units, whatever
        the program's (``PROGRAM_TO_USER_LEN`` [V: ``units.h``, ``interp_convert.cc``]; a standalone rs274
        without an INI file stores inches)."""
        self.numbered: list[dict[int, float]] = [{}]
        self.named: list[dict[str, float]] = [{}]
        self.globals_: dict[VarKey, float] = {"_value": 0.0, "_value_returned": 0.0}
        """``#<_value>`` and ``#<_value_returned>`` read 0 before any call returns (rs274)."""
        self._increment = increment

    @property
    def vacancy(self) -> Vacancy:
        return Vacancy.ZERO

    @property
    def arithmetic(self) -> Arithmetic:
        """rs274 scales angles with ``M_PIl`` in ``long double`` (src: ``interp_execute.cc`` ``execute_unary``,
        ``interp_read.cc`` ``read_atan``) [V: rs274 on x86-64, ``tests/test_long_double.py``]."""
        return Arithmetic.X86_64_C

    @property
    def increment(self) -> float:
        return self._increment()

    def _store(self, key: VarKey) -> dict[int, float] | dict[str, float] | dict[VarKey, float]:
        if isinstance(key, str):
            return self.globals_ if key.startswith("_") else self.named[-1]
        if 1 <= key <= self.LOCALS:
            return self.numbered[-1]
        if self.LOCALS < key <= self.LAST_GLOBAL:
            return self.globals_
        if key > self.LAST_GLOBAL:
            raise EvalError(f"#{key} ({system_variable(NGC_SYSTEM, key)}) {MACHINE_ONLY}")
        raise EvalError(f"#{key} is not a LinuxCNC parameter (1 to 5602)")

    def read(self, key: VarKey) -> Value:
        if isinstance(key, int) and key in NGC_FRAME_PARAMETERS:
            found = self.read_frame(key)
            if found is not None:
                return found
        elif isinstance(key, int) and key in NGC_POSITION:
            return self.read_position(key)
        elif isinstance(key, str) and key in NGC_POSITION_NAMES:
            return self.read_position(key)
        return self._store(key).get(key)  # type: ignore[arg-type]

    def read_position(self, key: int | str) -> float:
        """#5420-#5428 or ``#<_x>``..: the current point where the run's frame evaluation knows it
        (``FrameReadings.position``), else the machine's (an error naming it)."""
        axis = NGC_POSITION_NAMES[key] if isinstance(key, str) else NGC_AXES[key - NGC_POSITION_FIRST]
        frames = self.frames
        if isinstance(key, int) and frames is not None and frames.compensating():
            raise EvalError(f"#{key} (current position) cannot be read with cutter radius compensation on "
                            "(rs274 refuses it)")
        found = None if frames is None or (isinstance(key, str) and frames.compensating()) \
            else frames.position(axis)
        if found is None:
            raise EvalError(f"{_spell(key)} (current position) {MACHINE_ONLY}: {POSITION_UNKNOWN}")
        return found

    def snapshot(self) -> Hashable | None:
        """The parameters the running level reads (numbered, named and global), and where the run's frame
        answers the offset parameters (``read_frame``), all it can answer (G10 and G92 change those)."""
        frames = None if self.frames is None else self.frames.state()
        return (len(self.numbered), tuple(sorted(self.numbered[-1].items())),
                tuple(sorted(self.named[-1].items())), tuple(sorted(self.globals_.items(), key=str)),
                self._increment(), frames)

    def plain(self, key: VarKey) -> bool:
        """Every parameter up to #5000 and every name but ``#<_value>``/``#<_value_returned>`` (a call's
        return sets them); the offset parameters are the frame's (``G10`` changes them)."""
        if isinstance(key, str):
            return key not in ("_value", "_value_returned")
        return 1 <= key <= self.LAST_GLOBAL

    def read_frame(self, key: int) -> float | None:
        """An offset parameter the run's frame knows (None: the machine's, reported by ``_store``)."""
        frames = self.frames
        if frames is None:
            return None
        if key == NGC_ORIGIN_APPLIED:
            applied = frames.origin_applied()
            return None if applied is None else float(applied)
        if key < NGC_WORK_FIRST - 1:
            axis = NGC_AXES[key - NGC_ORIGIN_APPLIED - 1]
            return self._in_machine_units(axis, frames.origin_parameter(axis))
        if key < NGC_WORK_FIRST:
            # #5220, the active work system, 1 (G54) to 9 (G59.3) [V: interp_parameter_def.hh], once the program
            # selected one
            work = frames.work_system()
            return None if work is None else float(work)
        system, item = divmod(key - NGC_WORK_FIRST, NGC_WORK_STRIDE)
        if item < len(NGC_AXES):
            axis = NGC_AXES[item]
            return self._in_machine_units(axis, frames.work_offset(system + 1, axis))
        if item == len(NGC_AXES):
            return frames.work_rotation(system + 1)
        return None

    def _in_machine_units(self, axis: str, mm: float | None) -> float | None:
        """A length stored from its mm as LinuxCNC stores it: ``TO_EXT_LEN(mm)`` multiplies by the external
        units, mm -> machine unit, which an inch INI gives as ``1/25.4`` [V: ``units.h``, ``emccanon.cc``
        ``GET_EXTERNAL_LENGTH_UNITS``, ``inifile.cc``'s units table]. So ``G20 G10 L2 P1 X1`` reads
        0.9999999999999999 (``25.4 * (1/25.4)``) where ``25.4 / 25.4`` is 1: ``[#5221 LT 1]`` holds on the
        machine. A standalone rs274 uses 0.03937007874016 instead [V: ``sai/driver.cc``] and reads
        1.000000000000064."""
        if mm is None or axis in "ABC":
            return mm
        return mm * (1.0 / self.machine_mm)

    def exists(self, key: VarKey) -> bool:
        """EXISTS[#<name>]: the name has a value; a numbered parameter always exists (rs274, src)."""
        return not isinstance(key, str) or self.read(key) is not None

    def write(self, key: VarKey, value: Value) -> None:
        if value is None:
            raise EvalError(f"{_spell(key)} cannot be set to a vacant value")
        self._store(key)[key] = value  # type: ignore[index]

    def enter(self, args: dict[int, Value], new_level: bool) -> None:
        """A call: ``#1``-``#30`` are the arguments (0 where none), named locals start empty. An ``M98``
        call (``new_level`` false) shares the caller's ``#1``-``#30`` (the same level: what it sets, the
        caller sees) but still starts its own named locals: rs274 reports the caller's ``#<a>`` as "not
        defined" inside it, and its own as not defined after ``M99``."""
        if new_level:
            self.numbered.append({k: v for k, v in args.items() if v is not None})
        else:
            self.numbered.append(self.numbered[-1])
        self.named.append({})

    def leave(self, new_level: bool, value: Value = None) -> None:
        """Back in the caller: ``#<_value>`` is the returned value and ``#<_value_returned>`` says if
        there was one (LinuxCNC 2.8+); a return without a value, ``M99`` too, sets both to 0 (rs274:
        ``endsub [5]`` then a plain ``endsub`` or ``M99`` leaves ``#<_value>`` 0, not 5)."""
        if len(self.numbered) > 1:
            self.numbered.pop()
            self.named.pop()
        self.returned(value)

    def returned(self, value: Value) -> None:
        self.globals_["_value_returned"] = 0.0 if value is None else 1.0
        self.globals_["_value"] = 0.0 if value is None else value


POSITION_UNKNOWN = ("the axis is not programmed absolutely since the start or the last tool offset change, or a "
                    "move in machine coordinates, a reference return, a cycle or a change of work system left "
                    "its point unknown here")


def _spell(key: VarKey) -> str:
    return f"#<{key}>" if isinstance(key, str) else f"#{key}"
