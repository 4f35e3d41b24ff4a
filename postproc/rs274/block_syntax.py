"""WordBlockSyntax: gives a lexed RS274-family block its neutral sections, through the dialect's code table.

The ISO/Fanuc reading of words: the decimal-point rule (a point-less value is least input increments
unless the set-up says calculator input), K/L repeats per the set-up, G04 P in milliseconds or X in
seconds. It checks modal-group conflicts and duplicate addresses, maps G and M codes to neutral
sections through ``CODES`` (a ``CodeTable``) and refuses any word that would otherwise be dropped
without meaning. A dialect subclasses it with its ``XNAME``, ``DIALECT`` and ``CODES``.

Computed words (``X[#1*2.]``: the reader put an ``Expr`` in ``block.values``) reach here only when the
program is kept symbolically (in execution the interpreter evaluated them first). The sections then
carry the ``Expr`` as it is: it is in program units already (Fanuc counts a macro value as having a
decimal point, so the decimal-point rule applies to written numbers only). A computed G or M code
(``G#10``) has no neutral meaning: its block is kept verbatim as ``NativeCode``.
"""

from __future__ import annotations

from mypy_extensions import mypyc_attr

from typing import Any, ClassVar, Mapping, Final

from postproc.errors import ParseError, ProgramError
from postproc.ir.expr import Binary, Expr, Num
from postproc.ir import (
    Block, MachineFunction, Coolant, CutterCompensation, CycleCall, CycleCancel, DistanceMode, Dwell, Feed, FeedMode,
    MachineCoordinates, Motion, NativeCode, PathControl, Plane, ProgramControl, ReturnLevel,
    SpindleControl, SpindleOrientation, SpindleSpeed, ToolChange, ToolLengthOffset, ToolSelect, Units,
    WorkOffset,
)
from postproc.context import Context
from .frame_words import read_frame
from postproc.syntaxes.syntax import Syntax

from .codes import CodeTable, g_key
from .machine_codes import Defaults, cutter_register_from_h, dwell_in_seconds, machine_table
from .point_mix import point_mix
from .data_setting import read_data_setting
from .length_words import LENGTH_REGISTER, bare_length, dynamic_length, length_register
from .word_values import increments_divisor, milliseconds, real, whole
from .words import UPPER
from .words import AXIS_LETTERS as AXIS_LETTERS, DATA_KEY as DATA_KEY  # (the names other modules import here)
from .words import col_of_word as col_of_word, second_col as second_col

DECIMAL_LETTERS: Final = frozenset("XYZABCUVWIJKRQ")
"""Addresses that follow the decimal-point rule (no point: least input increments)."""
INTEGER_LETTERS: Final = frozenset("NOTHDLP")
_UPPER: Final = UPPER
CENTER_AXIS: Final = {"I": "X", "J": "Y", "K": "Z"}


@mypyc_attr(allow_interpreted_subclasses=True)
class WordBlockSyntax(Syntax):
    """Lexed words -> neutral sections, ISO/Fanuc word rules; subclasses give the code table."""

    __slots__ = ()
    DIALECT: ClassVar[str] = ""
    """Tag of the verbatim (NativeCode) sections this syntax makes."""
    TITLE: ClassVar[str] = ""
    """How messages name the dialect ("address Q is not used by the <TITLE> dialect")."""
    CODES: ClassVar[CodeTable] = CodeTable(())
    """The dialect's code table: every G and M code the reader knows."""
    NATIVE_M_WORDS: ClassVar[str] = "PL"
    """Words a verbatim M code takes with it (M98 P.. L..), and an undeclared machine M code."""
    FAMILY: ClassVar[str] = ""
    """The controller family machine-specific codes travel in ('': the dialect alone)."""
    MACHINE_DEFAULTS: ClassVar[Defaults] = {}
    """Machine-specific codes per controller variant (``postproc.rs274.machine_codes``); the set-up's
    ``<MachineCodes>`` adds to them and wins."""
    DATA_TABLES: ClassVar[Mapping[int, tuple[str, int, int]]] = {}
    """Programmable data input (G10): L number -> (neutral table, first and last entry P may name); a G10
    with another L is kept verbatim. Empty: every G10 is."""
    LATHE_OFFSET_INPUT: ClassVar[bool] = False
    """G10 without L sets a lathe tool offset (Fanuc T ``G10 P X Z R Q``: ``lathe_offset_input``)."""
    DATA_INCREMENTAL: ClassVar[bool] = True
    """A G10 in incremental mode adds to the entry (Fanuc); False: it sets it whatever the mode (LinuxCNC)."""
    DATA_P0_ACTIVE: ClassVar[bool] = False
    """G10 L2 P0 names the active work system (LinuxCNC), not an offset common to all (Fanuc)."""
    DATA_ROTATION: ClassVar[bool] = False
    """A work offset setting takes R, the work system's XY rotation (LinuxCNC ``G10 L2 P1 R30``:
    ``postproc.frames``)."""
    BASE_VARIANT: ClassVar[str] = ""
    """The variant whose machine codes every variant of the family has."""
    MACHINE_MOVE_INCREMENTAL: ClassVar[str] = "verbatim"
    """What the controller makes of a ``G53`` move's axis words under ``G91``: ``absolute`` (machine positions,
    the distance mode ignored), ``error`` (it refuses the block), ``verbatim`` (not known: the block is kept as
    ``NativeCode`` for this dialect and refused elsewhere by name; its writer refuses to write one). The family
    differs where documented (9/Series ignores G53 and its words, Mitsubishi M700V moves by the increments,
    Yaskawa iCube goes to the machine position, SINUMERIK's ISO mode and ISG take G53 in G90 only:
    tests/heldout/corpus.toml, cadekiely_o78239_3x3_face_smile.nc, has the sources); no Fanuc or Haas text
    was found [?]."""
    """Words a verbatim M code takes with it (M98 P.. L..)."""
    CYCLE_K_COUNTS: ClassVar[bool] = True
    """``K`` in a cycle block is a whole repeat count (Fanuc); False: a real number of the cycle's own
    (Fagor's dwell)."""
    FRAME_RULES: ClassVar[str] = ""
    """The rule set the table's frame codes (kind ``frame``) follow (``postproc.frames.section``: ``LAYERED``,
    ``SHARED_OFFSET``, ``ROTATE_FIRST``); '' where the table has none."""
    WHOLE_SPINDLE_SPEED: ClassVar[bool] = False
    """S takes a whole number: a written ``S1000.5`` (or ``S1000.``) is a located error, as the controller's
    alarm (``Dialect.WHOLE_SPINDLE_SPEED`` of the dialect whose syntax this is); a computed S reaches here
    already rounded by the interpreter (``ProgramSyntax.spell_evaluated``)."""
    DYNAMIC_LENGTH_BARE: ClassVar[bool] = False
    """A dynamic tool length offset (``G43.1``) without a Z word keeps the length in force (LinuxCNC: it replaces
    the offsets of the axes it names only); False: it is an error (grbl)."""
    POINTLESS_IN_UNITS: ClassVar[bool] = False
    """A number without a decimal point is in program units whatever the set-up's ``Input`` says
    (DIN 66025 controls such as ISG: ``X10`` is 10 mm), instead of least input increments."""

    def _dynamic_length(self, block: Block, ctx: Context, num: str, codes: dict[str, Any], values: dict[str, Any],
                        used: set[str]) -> None:
        """``G43.1 Z<length>`` (``postproc.rs274.length_words.dynamic_length``)."""
        dynamic_length(self, block, ctx, num, codes, values, used)

    def table(self, ctx: Context) -> CodeTable:
        """The code table a program is read with (a dialect with one table per machine type or G-code
        system picks it from the set-up here)."""
        return self.CODES

    def build(self, block: Block, ctx: Context) -> None:
        if block.marks:  # a canonical line whose words the reader left unmade: the lane reads it from its line
            lane = ctx.block_lane
            if lane is not None and lane.read_marked(block, ctx):
                return
        words = block.words
        if not words:
            return
        values = block.values
        if values:
            ctx.state.symbolic = True  # the reader left computed values: a program kept symbolically
            if "G" in values or "M" in values:
                up = "G" if "G" in values else "M"
                block.add(NativeCode(self.DIALECT, f"a computed {up} code", block.text or ""))
                return
        else:
            lane = ctx.block_lane  # the run's plain-block lane, where it applies (``postproc.fast.plain``)
            if lane is not None and lane.read(block, ctx, words):
                return
        codes: dict[str, tuple[str, str, object, str]] = {}
        natives: list[str] = []
        mcodes: list[tuple[int, str]] = []
        machine_g: list[str] = []
        raw: dict[str, str] = {}
        for letter, num in words:
            up = _UPPER[letter]
            if up == "G":
                key = g_key(num)
                if key not in self.table(ctx).g and ("G", key) in self.machine_codes(ctx):
                    machine_g.append(num)
                else:
                    self._g_code(ctx, block, num, codes, natives, key)
            elif up == "M":
                if "." in num:
                    raise ParseError(f"M code M{num} takes no decimal point", ctx.at(block, col_of_word(block, "M", num)))
                mcodes.append((int(num), num))
            elif up in raw:
                raise ParseError(f"address {up} appears twice in one block", ctx.at(block, second_col(block, up)))
            else:
                raw[up] = num
        state = ctx.state
        data_setting = natives == [DATA_KEY] and (bool(self.DATA_TABLES) or self.LATHE_OFFSET_INPUT)
        if natives and not data_setting:
            self._native(block, ctx, natives, raw)
            return
        if self._machine_move_kept(block, ctx, codes, raw, state.distance):
            return
        if machine_g:
            self._machine_g(block, ctx, machine_g, raw)
        units = state.units
        unit = codes.get("06")
        if unit is not None:
            units = unit[2]  # type: ignore[assignment]
        cycle_block = "09" in codes and codes["09"][1] == "cycle" or (
            state.cycle is not None and "01" not in codes and "09" not in codes)
        divisor = 0 if self.POINTLESS_IN_UNITS else increments_divisor(ctx, units)
        mix = point_mix(ctx) if divisor else None
        for up, num in raw.items():
            if up in values:
                if up not in DECIMAL_LETTERS and up not in INTEGER_LETTERS and up not in "FSK":
                    raise ParseError(f"address {up} is not used by the {self.TITLE} dialect",
                                     ctx.at(block, ctx.column_of(block, up)))
                continue  # a computed value: already in program units
            if up in DECIMAL_LETTERS and not (up == "K" and cycle_block and self.CYCLE_K_COUNTS):
                if "." in num:
                    values[up] = float(num)
                    if mix is not None and up in AXIS_LETTERS:
                        mix.saw_pointed(ctx, up, block.line)
                elif divisor:
                    value = values[up] = int(num) / divisor
                    if mix is not None and up in AXIS_LETTERS:
                        mix.saw_bare(ctx, block, up, num, value, units)
                else:
                    values[up] = float(int(num))
            elif up == "P" and "." in num and dwell_in_seconds(ctx.setup.controller):
                values[up] = milliseconds(block, ctx, num)
            elif up in INTEGER_LETTERS or up == "K":
                if "." in num:
                    if up == "K" and block.text is None:
                        # a repeat count the run evaluated (K#2): spelled with a point, as the interpreter
                        # spells every K (an arc's K is a length); Fanuc rounds a macro value to the
                        # address's digits (Custom Macro B) [K], here only a whole one is taken
                        if not float(num).is_integer():
                            raise ProgramError(f"K (the repeat count) takes a whole number, the expression gives "
                                               f"{num}", ctx.at(block, ctx.column_of(block, up)))
                        values[up] = int(float(num))
                        continue
                    hint = DWELL_SECONDS_HINT if up == "P" and _dwells(codes, cycle_block) else ""
                    raise ParseError(f"address {up} takes no decimal point ({up}{num}){hint}",
                                     ctx.at(block, ctx.column_of(block, up)))
                values[up] = int(num)
            elif up == "F":
                values[up] = float(num)
            elif up == "S":
                if "." in num and self.WHOLE_SPINDLE_SPEED:
                    raise ParseError(f"address S takes no decimal point (S{num})", ctx.at(block, ctx.column_of(block, up)))
                values[up] = float(num) if "." in num else int(num)
            else:
                raise ParseError(f"address {up} is not used by the {self.TITLE} dialect",
                                 ctx.at(block, ctx.column_of(block, up)))
        used = {"N", "O"}
        if data_setting and not self._data_setting(block, ctx, codes, values, used):
            return  # a G10 the IR does not model: kept verbatim
        self.g_sections(block, ctx, codes, values, used, cycle_block)
        self.m_sections(block, ctx, mcodes, values, used)
        self.finish_words(block, ctx, values, used)

    def finish_words(self, block: Block, ctx: Context, values: dict[str, Any], used: set[str]) -> None:
        """F, S and T sections, then refuse any word no section took: nothing is dropped silently."""
        if "F" in values:
            block.add(Feed(real(values["F"])))
            used.add("F")
        if "S" in values:
            block.add(SpindleSpeed(real(values["S"])))
            used.add("S")
        if "T" in values:
            block.add(ToolSelect(whole(values["T"])))
            used.add("T")
        unused = [k for k in values if k not in used]
        if unused:
            up = unused[0]
            raise ProgramError(f"address {up} has no meaning in this block", ctx.at(block, ctx.column_of(block, up)))

    def _g_code(self, ctx: Context, block: Block, num: str, codes: dict[str, Any], natives: list[str],
                key: str | None = None) -> None:
        """Read G``num`` (``key``: its ``g_key`` when the caller has it) into ``codes`` or ``natives``."""
        if key is None:
            key = g_key(num)
        table = self.table(ctx)
        entry = table.g.get(key)
        if entry is None:
            if key in table.native_g:
                natives.append(key)
                return
            raise ParseError(f"unknown G code G{num}", ctx.at(block, col_of_word(block, "G", num)))
        group = entry[0]
        other = codes.get(group)
        if other is not None:
            name = group
            raise ParseError(f"G codes G{other[3]} and G{num} are both in modal group {name}",
                             ctx.at(block, col_of_word(block, "G", num)))
        if group == "09" and "01" in codes or group == "01" and "09" in codes and codes["09"][1] == "cycle":
            first = codes.get("01") or codes["09"]
            if entry[1] == "cycle" or first[1] == "cycle":
                raise ParseError(f"G{first[3]} and G{num} in one block: a motion code and a canned cycle",
                                 ctx.at(block, col_of_word(block, "G", num)))
        codes[group] = (group, entry[1], entry[2], num)

    def _native(self, block: Block, ctx: Context, natives: list[str], raw: dict[str, str]) -> None:
        """Keep a block with a code the IR does not model verbatim, tagged with its meaning."""
        key = natives[0]
        what = f"G{key} ({self.table(ctx).native_g[key]})"
        block.add(NativeCode(self.DIALECT, what, block.text or ""))
        for up, num in raw.items():
            if up not in block.values:
                block.values[up] = float(num) if "." in num else int(num)

    def _machine_move_kept(self, block: Block, ctx: Context, codes: dict[str, tuple[str, str, object, str]],
                           raw: dict[str, str], modal_distance: str) -> bool:
        """A ``G53`` move under ``G91`` where the dialect's meaning is not known: kept verbatim (True); a
        located error where the controller refuses it; False where its words are machine positions."""
        if self.MACHINE_MOVE_INCREMENTAL == "absolute" or not any(c[1] == "machine" for c in codes.values()):
            return False
        if not any(up in AXIS_LETTERS for up in raw):
            return False
        mode = next((str(c[2]) for c in codes.values() if c[1] == "distance"), modal_distance)
        if mode != "incremental":
            return False
        num = next(c[3] for c in codes.values() if c[1] == "machine")
        if self.MACHINE_MOVE_INCREMENTAL == "error":
            raise ParseError(f"G{num} in incremental distance mode: the controller refuses it (program absolute "
                             "distance in the block)", ctx.at(block, col_of_word(block, "G", num)))
        block.add(NativeCode(self.DIALECT, f"G{num} in incremental distance mode (machine positions, increments or "
                             "ignored: not known for this controller [?])", block.text or ""))
        for up, num in raw.items():
            if up not in block.values:
                block.values[up] = float(num) if "." in num else int(num)
        return True

    def _data_setting(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                      used: set[str]) -> bool:
        """``G10 L2 P1 X.. Y..`` and the tool-offset forms -> ``DataSetting`` (``postproc.rs274.data_setting``);
        False: the block is kept as ``NativeCode``."""
        return read_data_setting(self, block, ctx, codes, values, used)

    def machine_codes(self, ctx: Context) -> dict[tuple[str, str], Any]:
        """This run's machine-specific codes (the family's defaults for the set-up's variant, then the
        set-up's own)."""
        return machine_table(ctx, self.MACHINE_DEFAULTS, self.BASE_VARIANT)

    def family(self) -> str:
        return self.FAMILY or self.DIALECT

    def _machine_g(self, block: Block, ctx: Context, machine_g: list[str], raw: dict[str, str]) -> None:
        """A declared machine G code (G187 P1 E0.01): kept verbatim with the words it takes; the rest of
        the block is read as usual."""
        if len(machine_g) > 1:
            raise ParseError(f"G{machine_g[1]}: only one machine-specific function per block is supported",
                             ctx.at(block, col_of_word(block, "G", machine_g[1])))
        num = machine_g[0]
        code = self.machine_codes(ctx)[("G", g_key(num))]
        parts = [f"G{num}"] + [up + raw.pop(up) for up in code.words if up in raw]
        block.add(MachineFunction(self.family(), f"G{g_key(num)}", " ".join(parts), code.action, code.name))

    def g_sections(self, block: Block, ctx: Context, codes: dict[str, Any], values: dict[str, Any],
                    used: set[str], cycle_block: bool) -> None:
        state = ctx.state
        motion_mode: str | None = None
        home: str | None = None
        for group, kind, arg, num in codes.values():
            if kind == "motion":
                motion_mode = arg
            elif kind == "plane":
                block.add(Plane(arg))
            elif kind == "units":
                block.add(Units(arg))
            elif kind == "distance":
                block.add(DistanceMode(arg))
            elif kind == "feed_mode":
                block.add(FeedMode(arg))
            elif kind == "return":
                block.add(ReturnLevel(arg))
            elif kind == "offset":
                block.add(WorkOffset(arg))
            elif kind == "path":
                block.add(PathControl(arg))
            elif kind == "path_once":
                block.add(PathControl(arg, True))
            elif kind == "cycle":
                block.add(CycleCall(arg))
                used.update("XYZABCUVWF" + self.cycle_data_letters(ctx))
            elif kind == "cycle_cancel":
                block.add(CycleCancel())
            elif kind == "cutter":
                register = None
                if arg != "off" and "D" in values:
                    used.add("D")
                    register = values["D"]
                elif arg != "off" and "H" in values and "08" not in codes:
                    if not cutter_register_from_h(ctx.setup.controller):
                        h = self._word_text(block, "H")
                        raise ProgramError(f"G{num} takes its radius register from D, not H{h}{CUTTER_H_HINT}",
                                           ctx.at(block, ctx.column_of(block, "H")))
                    used.add("H")  # Fanuc 0M: G42 H19 takes the radius from offset 19
                    register = values["H"]
                block.add(CutterCompensation(arg, register))
            elif kind == "length" and arg == "dynamic":  # G43.1 Z<length> (grbl, RS274/NGC)
                self._dynamic_length(block, ctx, num, codes, values, used)
            elif kind == "length":
                if arg != "cancel":
                    if "H" not in values:
                        self._bare_length(block, ctx, num)
                    ctx.run_data[LENGTH_REGISTER] = True
                    used.add("H")
                block.add(ToolLengthOffset(arg, values.get("H") if arg != "cancel" else None))
            elif kind == "dwell":
                self._dwell(block, ctx, values, used, num)
            elif kind == "home":
                home = arg
            elif kind == "machine":
                block.add(MachineCoordinates())
            elif kind == "frame":
                block.add(read_frame(block, ctx, arg, f"G{num}", values, used, self.FRAME_RULES, self.family(),
                                     col_of_word(block, "G", num)))
        if "H" in values and "H" not in used and "08" not in codes:
            self._length_register(block, ctx, values, used)
        if "CycleCall" in block.sections:
            return
        if cycle_block and "CycleCancel" not in block.sections:
            _use_present(used, values, "F" + self.cycle_data_letters(ctx))
        axes = {k: v for k, v in values.items() if k in AXIS_LETTERS and k not in used}
        if home is not None:
            block.add(Motion(home, axes))
            used.update(axes)
            return
        if "Dwell" in block.sections and motion_mode is None and not axes:
            return
        if "MachineCoordinates" in block.sections and axes:
            # G53 positions at rapid whatever the modal motion; a motion code beside it still sets the mode
            # (ModalStateSyntax leaves the mode alone for machine-coordinate blocks); under G91 its axis words
            # are machine positions here (MACHINE_MOVE_INCREMENTAL, ``_machine_move_kept``).
            if motion_mode is not None:
                state.motion = motion_mode
            block.add(Motion("rapid", {k: real(v) for k, v in axes.items()}))
            used.update(axes)
            return
        mode = motion_mode
        if mode is None and axes:
            if cycle_block and "CycleCancel" not in block.sections:
                mode = None
            elif state.motion is None:
                raise ProgramError("axis words with no motion mode in force (program "
                                   f"{self.spell('motion', 'rapid')} or {self.spell('motion', 'linear')} first)",
                                   ctx.at(block, ctx.column_of(block, next(iter(axes)))))
            else:
                mode = state.motion
        if mode is None and not axes:
            return
        used.update(axes)
        center = None
        radius = None
        if mode in ("cw", "ccw"):
            center = {CENTER_AXIS[k]: real(values[k]) for k in "IJK" if k in values}
            used.update(k for k in "IJK" if k in values)
            if "R" in values:
                radius = real(values["R"])
                used.add("R")
                if center:
                    raise ProgramError("an arc takes either I/J/K or R, not both",
                                       ctx.at(block, ctx.column_of(block, "R")))
                center = None
            elif not center:
                raise ProgramError("an arc needs a centre (I/J/K) or a radius R",
                                   ctx.at(block, _motion_col(block, ctx, codes, axes)))
        block.add(Motion(mode, {k: real(v) for k, v in axes.items()}, center, radius))

    def _length_register(self, block: Block, ctx: Context, values: dict[str, Any], used: set[str]) -> None:
        """An H without G43/G44/G49 in its block (``postproc.rs274.length_words.length_register``)."""
        length_register(self, block, ctx, values, used)

    def _bare_length(self, block: Block, ctx: Context, num: str) -> None:
        """G43/G44 without H (``postproc.rs274.length_words.bare_length``)."""
        bare_length(block, ctx, num)

    def cycle_data_letters(self, ctx: Context) -> str:
        """The addresses a hole cycle takes besides the axes and F (the family's R, Q, P and the repeat
        count K, or L too when the set-up says so); the cycle resolve step reads them."""
        return "RQPK" + ("L" if ctx.setup.input.repeat_address != "K" else "")

    def _dwell(self, block: Block, ctx: Context, values: dict[str, Any], used: set[str], num: str) -> None:
        seconds: Any
        if "P" in values:
            p = values["P"]
            seconds = Binary("div", p, Num(1000.0)) if isinstance(p, Expr) else int(p) / 1000.0
            used.add("P")
        elif "X" in values:
            seconds = real(values["X"])
            used.add("X")
        else:
            raise ProgramError(f"{self.spell('dwell')} needs a dwell time X (seconds) or P (milliseconds)",
                               ctx.at(block, col_of_word(block, "G", num)))
        if not isinstance(seconds, Expr) and seconds < 0:
            raise ProgramError("a dwell time cannot be negative", ctx.at(block, col_of_word(block, "G", num)))
        block.add(Dwell(seconds))

    def m_sections(self, block: Block, ctx: Context, mcodes: list[tuple[int, str]], values: dict[str, Any],
                   used: set[str]) -> None:
        """M codes -> sections, through the code table; dialects of the family override ``unknown_m``
        and ``orient`` where they differ."""
        seen: dict[str, str] = {}
        table = self.table(ctx).m
        for number, num in mcodes:
            entry = table.get(number)
            if entry is None:
                if "NativeCode" in block.sections or "MachineFunction" in block.sections:
                    raise ParseError(f"M{num}: only one machine-specific function per block is supported",
                                     ctx.at(block, col_of_word(block, "M", num)))
                what = self.unknown_m(block, ctx, number, num)
                if what is not None:
                    block.add(NativeCode(self.DIALECT, what, f"M{num}"))
                    used.update(self.NATIVE_M_WORDS)
                else:
                    self.machine_m(block, ctx, number, num, values, used)
                continue
            kind, arg = entry
            if kind in seen:
                raise ParseError(f"M codes M{seen[kind]} and M{num} conflict in one block",
                                 ctx.at(block, col_of_word(block, "M", num)))
            seen[kind] = num
            if kind == "program":
                block.add(ProgramControl(str(arg)))
            elif kind == "spindle":
                block.add(SpindleControl(str(arg)))
            elif kind == "orient":
                self.orient(block, ctx, num, values, used)
            elif kind == "tool_change":
                block.add(ToolChange())
            elif kind == "coolant":
                block.add(Coolant(str(arg)))

    def spell(self, kind: str, arg: object = None) -> str:
        """The dialect's spelling of a code, for messages."""
        return self.CODES.spell(kind, arg) or kind

    def unknown_m(self, block: Block, ctx: Context, number: int, num: str) -> str | None:
        """What an M code outside the table is when the dialect keeps it as native code (a description),
        or None: a machine builder's code (``machine_m``)."""
        native = self.table(ctx).native_m.get(number)
        return None if native is None else f"M{num} ({native})"

    def machine_m(self, block: Block, ctx: Context, number: int, num: str, values: dict[str, Any],
                  used: set[str]) -> None:
        """An M code outside the table is the machine builder's (the ISO rule): kept verbatim with the
        words it takes (its declaration's, else P and L), simulated by its declared action."""
        code = self.machine_codes(ctx).get(("M", str(number)))
        letters = code.words if code is not None else self.NATIVE_M_WORDS
        parts = [f"M{num}"]
        for up in letters:
            if up in values and up not in used:
                parts.append(up + self._word_text(block, up))
                used.add(up)
        if code is None:
            block.add(MachineFunction(self.family(), f"M{number}", " ".join(parts), declared=False))
        else:
            block.add(MachineFunction(self.family(), f"M{number}", " ".join(parts), code.action, code.name))

    @staticmethod
    def _word_text(block: Block, up: str) -> str:
        for letter, num in block.words:
            if _UPPER[letter] == up:
                return num
        return ""

    def orient(self, block: Block, ctx: Context, num: str, values: dict[str, Any], used: set[str]) -> None:
        """An orient code without an angle word: the angle the machine's parameters hold (the set-up's
        ``orientAngle``)."""
        block.add(SpindleOrientation(ctx.setup.cycles.orient_angle))


DWELL_SECONDS_HINT: Final = (": a dwell P counts milliseconds; if it means seconds (Haas), set "
                             "<Controller dwellSeconds=\"true\"/> (or variant=\"haas\") in the machine set-up")
"""What an error about a dwell P with a decimal point adds: the set-up option under which it reads."""
CUTTER_H_HINT: Final = ("; if the controller takes it from H (Fanuc 0M), set <Controller cutterRegisterH=\"true\"/> "
                        "(or variant=\"fanuc-0m\") in the machine set-up")
"""What an error about ``G42 H19`` adds: the set-up option under which it reads."""




def _dwells(codes: dict[str, tuple[str, str, object, str]], cycle_block: bool) -> bool:
    """The block's P is a dwell time (G04, or a hole cycle's P)."""
    if cycle_block:
        return True
    for entry in codes.values():
        if entry[1] == "dwell":
            return True
    return False


def _motion_col(block: Block, ctx: Context, codes: dict[str, Any], axes: dict[str, Any]) -> int:
    """Column of the block's motion code, or of its first axis word when the motion is modal."""
    if "01" in codes:
        return col_of_word(block, "G", codes["01"][3])
    return ctx.column_of(block, next(iter(axes))) if axes else 1


def _use_present(used: set[str], values: dict[str, Any], letters: str) -> None:
    """Mark the block's words among ``letters`` used: a loop over its few words, not a set update with
    every letter (a block repeating a cycle asks it once per hole)."""
    for letter in values:
        if len(letter) == 1 and letter in letters:  # a one-letter address among them, not a substring
            used.add(letter)
