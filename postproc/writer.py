"""WordWriter: writes blocks as address words, for the RS274 family (Fanuc, grbl, LinuxCNC, ...).

A block that is unchanged and read from the same dialect is copied byte for byte. Otherwise the
block is generated from its sections: each section key dispatches through ``TRANSFORMS`` first, then a
``<key>_words`` method, and otherwise fails loudly with an ``UnsupportedError`` naming the construct
and its line (sqlglot's generator order). Dialects override the code tables and what differs.
"""

from __future__ import annotations

from typing import Any, Callable, ClassVar, NoReturn

from .errors import Location, UnsupportedError
from .ir import Block, CompoundMotion, Motion, Section
from .numbers import EXACT, EXACT_INCH, MAX_PLACES, canonical_number_re, format_decimal
from .syntax import Context
from .dialect import Writer


SECTION_ORDER = (
    "BlockDelete", "Sequence", "MachineCoordinates", "PathControl", "Plane", "Units", "DistanceMode",
    "WorkOffset", "FeedMode", "CutterCompensation", "ToolLengthOffset", "ReturnLevel", "CycleCancel",
    "Dwell", "Motion", "CannedCycle", "Feed", "SpindleSpeed", "ToolSelect", "ToolChange", "SpindleControl",
    "SpindleOrientation", "Coolant", "ProgramControl", "NativeCode", "Comments",
)
"""Word order of a generated block; sections that only annotate are skipped by ``IGNORED``."""


class WordWriter(Writer):
    DIALECT: ClassVar[str] = ""
    MOTION: ClassVar[dict[str, str]] = {"rapid": "G00", "linear": "G01", "cw": "G02", "ccw": "G03",
                                        "home": "G28", "home2": "G30"}
    PLANE: ClassVar[dict[str, str]] = {"XY": "G17", "ZX": "G18", "YZ": "G19"}
    UNITS: ClassVar[dict[str, str]] = {"inch": "G20", "mm": "G21"}
    DISTANCE: ClassVar[dict[str, str]] = {"absolute": "G90", "incremental": "G91"}
    FEED_MODE: ClassVar[dict[str, str]] = {"per_min": "G94", "per_rev": "G95"}
    WORK_OFFSET: ClassVar[dict[int, str]] = {1: "G54", 2: "G55", 3: "G56", 4: "G57", 5: "G58", 6: "G59"}
    RETURN_LEVEL: ClassVar[dict[str, str]] = {"initial": "G98", "r": "G99"}
    CUTTER: ClassVar[dict[str, str]] = {"off": "G40", "left": "G41", "right": "G42"}
    LENGTH: ClassVar[dict[str, str]] = {"positive": "G43", "negative": "G44", "cancel": "G49"}
    PATH: ClassVar[dict[str, str]] = {"exact_stop": "G61", "cutting": "G64"}
    PATH_ONCE: ClassVar[str | None] = "G09"
    SPINDLE: ClassVar[dict[str, str]] = {"cw": "M03", "ccw": "M04", "stop": "M05"}
    COOLANT: ClassVar[dict[str, str]] = {"mist": "M07", "flood": "M08", "off": "M09"}
    PROGRAM: ClassVar[dict[str, str]] = {"stop": "M00", "optional_stop": "M01", "end": "M02", "end_rewind": "M30"}
    TOOL_CHANGE: ClassVar[str | None] = "M06"
    ORIENT: ClassVar[str | None] = "M19"
    DWELL: ClassVar[str] = "G04"
    DWELL_WORD: ClassVar[str] = "X"
    """Address and unit of the dwell time: 'X' seconds, 'P' milliseconds, or 'Ps' seconds in P."""
    MACHINE_COORDS: ClassVar[str | None] = "G53"
    CYCLE_CANCEL: ClassVar[str | None] = "G80"
    CYCLES: ClassVar[dict[str, str]] = {
        "peck_chip": "G73", "tap_left": "G74", "fine_bore": "G76", "drill": "G81", "drill_dwell": "G82",
        "peck_deep": "G83", "tap": "G84", "bore_feed": "G85", "bore_stop": "G86", "back_bore": "G87",
        "bore_manual": "G88", "bore_dwell_feed": "G89",
    }
    """Canned cycles the target runs natively, by neutral kind (lowering expands the others)."""
    IGNORED: ClassVar[frozenset[str]] = frozenset()
    """Sections that annotate a block and produce no words of their own."""
    TRANSFORMS: ClassVar[dict[str, Callable[["WordWriter", Any, Block], list[str]]]] = {}

    def __init__(self, ctx: Context, source_dialect: str) -> None:
        super().__init__(ctx, source_dialect)
        out = ctx.setup.output
        self.normalize = out.normalize or bool(out.renumber_start)
        """Renumbering rewrites the words, so it implies normalising."""
        self.renumber = out.renumber_start
        self.renumber_step = out.renumber_step
        self.leading_zero = out.leading_zero
        self.decimals = out.decimals
        self.inch_decimals = out.inch_decimals
        self.copy_ok = source_dialect == self.DIALECT and not self.normalize and not self.renumber
        self.units = "mm"
        self.distance = "absolute"
        self.feed: float | None = None

    # -- numbers -----------------------------------------------------------------------------------
    def number(self, value: float) -> str:
        """A length or feed with an explicit decimal point, trailing zeros dropped ('10.', '0.5').

        Rounds to the output decimals, but never silently: a value that would move by more than
        half a micrometre (or 0.00002 in) keeps up to ``MAX_PLACES`` places instead.
        """
        places = self.decimals if self.units == "mm" else self.inch_decimals
        return format_decimal(value, places, self.leading_zero, EXACT if self.units == "mm" else EXACT_INCH)

    @staticmethod
    def integer(value: float | int) -> str:
        return str(int(value))

    # -- blocks ------------------------------------------------------------------------------------
    def write_block(self, block: Block) -> str | None:
        sections = block.sections
        if block.text is not None and self.copy_ok:
            self._track(sections)
            return block.text + block.eol
        if self.normalize and block.text is not None and self.source_dialect == self.DIALECT:
            self._track(sections)
            return self.normalized(block) + (block.eol or "\n")
        return self.generate(block)

    def _track(self, sections: dict[str, Section]) -> None:
        if not sections:
            return
        s = sections.get("Units")
        if s is not None:
            self.units = s.system  # type: ignore[attr-defined]
        s = sections.get("DistanceMode")
        if s is not None:
            self.distance = s.mode  # type: ignore[attr-defined]
        s = sections.get("Feed")
        if s is not None:
            self.feed = s.value  # type: ignore[attr-defined]

    def normalized(self, block: Block) -> str:
        """Rewrite a block from its words: explicit decimal points, optional renumbering."""
        values = block.values
        sections = block.sections
        if "TapeMark" in sections:
            return "%"
        text = block.text
        if (text is not None and not self.renumber and self.leading_zero
                and "Comments" not in sections and "BlockDelete" not in sections
                and block.canonical):
            return text  # already normal: upper-case words, single spaces, explicit exact numbers
        parts: list[str] = []
        skip = sections.get("BlockDelete")
        if skip is not None:
            parts.append("/" if skip.level == 1 else f"/{skip.level}")  # type: ignore[attr-defined]
        renumber = self.renumber
        canonical = self._canonical
        number = self.number
        for letter, num in block.words:
            up = _UPPER[letter]
            if up == "N" and renumber:
                continue
            value = values.get(up)
            if value.__class__ is float and not canonical(num):
                parts.append(up + number(value))
            else:
                parts.append(up + num)
        if renumber and block.words and "ProgramStart" not in sections:
            parts.insert(1 if skip is not None else 0, f"N{renumber}")
            self.renumber = renumber + self.renumber_step
        comments = sections.get("Comments")
        if comments is not None:
            parts.extend(self.comment(t) for t in comments.texts)  # type: ignore[attr-defined]
        return " ".join(parts)

    def _canonical(self, num: str) -> bool:
        """True when a number as written is already explicit and exact: keep its text (and skip a float
        round trip). Digits the user wrote are never rounded away by normalising."""
        return canonical_number_re(MAX_PLACES, self.leading_zero).fullmatch(num) is not None

    def generate(self, block: Block) -> str:
        """Generate a block (and any lines a compound motion adds) from its sections."""
        sections = block.sections
        compound = sections.get("CompoundMotion")
        if compound is not None:
            return self.compound(block, compound)  # type: ignore[arg-type]
        if "TapeMark" in sections:
            return "%" + (block.eol or "\n")
        words: list[str] = []
        for key in SECTION_ORDER:
            section = sections.get(key)
            if section is not None:
                words.extend(self.section_words(key, section, block))
        for key in sections:
            if key not in SECTION_ORDER and key not in self.IGNORED and key not in ("ProgramStart", "TapeMark"):
                self.unsupported(f"{key}", block)
        start = sections.get("ProgramStart")
        if start is not None:
            words.insert(0, self.program_start(start, block))
        self._track(sections)
        return " ".join(w for w in words if w) + (block.eol or "\n")

    def section_words(self, key: str, section: Section, block: Block) -> list[str]:
        transform = self.TRANSFORMS.get(key)
        if transform is not None:
            return transform(self, section, block)
        method = getattr(self, f"{_snake(key)}_words", None)
        if method is None:
            self.unsupported(key, block)
        return method(section, block)  # type: ignore[no-any-return]

    def unsupported(self, what: str, block: Block) -> NoReturn:
        raise UnsupportedError(f"the {self.DIALECT} dialect cannot express {what}",
                               Location(self.ctx.file, block.line, 1))

    # -- compound motion ---------------------------------------------------------------------------
    def compound(self, block: Block, compound: CompoundMotion) -> str:
        """Write an expansion: the block's own words, a comment naming the source, then each item."""
        lines: list[str] = []
        rest = {k: v for k, v in block.sections.items() if k not in ("CompoundMotion", "CannedCycle", "Comments")}
        head_keys = [k for k in rest if k not in ("SpindleControl", "Coolant", "ProgramControl", "ToolChange")]
        tail_keys = [k for k in rest if k not in head_keys]
        head = Block(block.line, None, "\n")
        head.sections = {k: rest[k] for k in head_keys}
        note = self.comment_line(f"{compound.term} from line {block.line}: {self.source_text(block)}")
        if list(head.sections) == ["Sequence"]:
            note = " ".join(self.sequence_words(head.sections["Sequence"], block)) + " " + note
        elif head.sections:
            lines.append(self.generate(head))
        lines.append(note)
        was_incremental = self.distance == "incremental"
        for item in compound.items:
            lines.append(self.item_line(item, block))
        if was_incremental:
            lines.append(self.DISTANCE["incremental"] + "\n")
            self.distance = "incremental"
        tail = Block(block.line, None, "\n")
        tail.sections = {k: rest[k] for k in tail_keys}
        comments = block.sections.get("Comments")
        if comments is not None:
            tail.sections["Comments"] = comments
        if tail.sections:
            lines.append(self.generate(tail))
        text = "".join(lines)
        if block.eol != "\n" and text.endswith("\n"):
            text = text[:-1] + block.eol
        return text

    def item_line(self, item: Section, block: Block) -> str:
        words: list[str] = []
        if isinstance(item, Motion):
            if self.distance != "absolute":
                words.append(self.DISTANCE["absolute"])
                self.distance = "absolute"
            words.extend(self.motion_words(item, block))
        else:
            words.extend(self.section_words(item.KEY, item, block))
            self._track({item.KEY: item})
        return " ".join(words) + "\n"

    def source_text(self, block: Block) -> str:
        if block.text is not None:
            return block.text.strip()
        return " ".join(letter + num for letter, num in block.words)

    # -- section words -----------------------------------------------------------------------------
    def comment(self, text: str) -> str:
        return "(" + text.replace("(", "[").replace(")", "]") + ")"

    def comment_line(self, text: str) -> str:
        return self.comment(text) + "\n"

    def comments_words(self, s: Any, block: Block) -> list[str]:
        return [self.comment(t) for t in s.texts]

    def program_start(self, s: Any, block: Block) -> str:
        if s.number is None:
            self.unsupported("a named program", block)
        return f"O{int(s.number):04d}"

    def block_delete_words(self, s: Any, block: Block) -> list[str]:
        return ["/" if s.level == 1 else f"/{s.level}"]

    def sequence_words(self, s: Any, block: Block) -> list[str]:
        return [f"N{s.number}"]

    def _code(self, table: dict[Any, str], value: Any, what: str, block: Block) -> list[str]:
        code = table.get(value)
        if code is None:
            self.unsupported(what, block)
        return [code]

    def plane_words(self, s: Any, block: Block) -> list[str]:
        return self._code(self.PLANE, s.plane, f"the {s.plane} plane", block)

    def units_words(self, s: Any, block: Block) -> list[str]:
        self.units = s.system
        return self._code(self.UNITS, s.system, f"{s.system} units", block)

    def distance_mode_words(self, s: Any, block: Block) -> list[str]:
        self.distance = s.mode
        return self._code(self.DISTANCE, s.mode, f"{s.mode} distance mode", block)

    def work_offset_words(self, s: Any, block: Block) -> list[str]:
        return self._code(self.WORK_OFFSET, s.index, f"work offset {s.index}", block)

    def feed_mode_words(self, s: Any, block: Block) -> list[str]:
        return self._code(self.FEED_MODE, s.mode, f"feed mode {s.mode}", block)

    def return_level_words(self, s: Any, block: Block) -> list[str]:
        return self._code(self.RETURN_LEVEL, s.level, f"return to the {s.level} level", block)

    def cutter_compensation_words(self, s: Any, block: Block) -> list[str]:
        words = self._code(self.CUTTER, s.mode, f"cutter compensation {s.mode}", block)
        if s.register is not None:
            words.append(f"D{int(s.register):02d}")
        return words

    def tool_length_offset_words(self, s: Any, block: Block) -> list[str]:
        words = self._code(self.LENGTH, s.mode, f"tool length offset {s.mode}", block)
        if s.register is not None:
            words.append(f"H{int(s.register):02d}")
        return words

    def path_control_words(self, s: Any, block: Block) -> list[str]:
        if s.one_shot:
            if self.PATH_ONCE is None:
                self.unsupported("a one-shot exact stop", block)
            return [self.PATH_ONCE]
        return self._code(self.PATH, s.mode, f"path control {s.mode}", block)

    def machine_coordinates_words(self, s: Any, block: Block) -> list[str]:
        if self.MACHINE_COORDS is None:
            self.unsupported("motion in machine coordinates", block)
        return [self.MACHINE_COORDS]

    def cycle_cancel_words(self, s: Any, block: Block) -> list[str]:
        return [self.CYCLE_CANCEL] if self.CYCLE_CANCEL else []

    def dwell_words(self, s: Any, block: Block) -> list[str]:
        if self.DWELL_WORD == "P":
            return [self.DWELL, f"P{round(s.seconds * 1000)}"]
        if self.DWELL_WORD == "Ps":
            return [self.DWELL, "P" + self.seconds(s.seconds)]
        return [self.DWELL, "X" + self.seconds(s.seconds)]

    def seconds(self, value: float) -> str:
        return format_decimal(value, 3, self.leading_zero)

    def motion_words(self, s: Motion, block: Block) -> list[str]:
        if s.mode is None:
            self.unsupported("a canned-cycle repetition without its cycle", block)
        words = self._code(self.MOTION, s.mode, f"{s.mode} motion", block)
        for axis, value in s.axes.items():
            words.append(axis + self.number(value))
        if s.center is not None:
            for axis, letter in (("X", "I"), ("Y", "J"), ("Z", "K")):
                if axis in s.center:
                    words.append(letter + self.number(s.center[axis]))
        if s.radius is not None:
            words.append("R" + self.number(s.radius))
        return words

    def canned_cycle_words(self, s: Any, block: Block) -> list[str]:
        """A native cycle: its code when the block programs it, then its words as programmed.
        G98/G99 and F come from the block's own ReturnLevel and Feed sections."""
        words: list[str] = []
        if s.call:
            words.extend(self._code(self.CYCLES, s.kind, f"the {s.kind.replace('_', ' ')} cycle", block))
        for letter, value in s.words.items():
            words.append(letter + (str(value) if isinstance(value, int) else self.number(value)))
        return words

    def feed_words(self, s: Any, block: Block) -> list[str]:
        self.feed = s.value
        return ["F" + self.number(s.value)]

    def spindle_speed_words(self, s: Any, block: Block) -> list[str]:
        rpm = s.rpm
        return ["S" + (str(int(rpm)) if float(rpm).is_integer() else self.number(rpm))]

    def tool_select_words(self, s: Any, block: Block) -> list[str]:
        return [f"T{s.number}"]

    def tool_change_words(self, s: Any, block: Block) -> list[str]:
        if self.TOOL_CHANGE is None:
            self.unsupported("a tool change", block)
        return [self.TOOL_CHANGE]

    def spindle_control_words(self, s: Any, block: Block) -> list[str]:
        return self._code(self.SPINDLE, s.direction, f"spindle {s.direction}", block)

    def spindle_orientation_words(self, s: Any, block: Block) -> list[str]:
        """M19 orients to the angle the machine's parameters hold (the set-up's ``orientAngle``);
        any other angle cannot be written with it."""
        if self.ORIENT is None:
            self.unsupported("an oriented spindle stop", block)
        if abs(s.angle - self.ctx.setup.cycles.orient_angle) > 1e-9:
            self.unsupported(f"an oriented spindle stop at {s.angle:g} deg (M19 orients to the set-up's "
                             f"{self.ctx.setup.cycles.orient_angle:g} deg)", block)
        return [self.ORIENT]

    def coolant_words(self, s: Any, block: Block) -> list[str]:
        return self._code(self.COOLANT, s.mode, f"coolant {s.mode}", block)

    def program_control_words(self, s: Any, block: Block) -> list[str]:
        return self._code(self.PROGRAM, s.kind, f"program {s.kind}", block)

    def native_code_words(self, s: Any, block: Block) -> list[str]:
        if s.dialect != self.DIALECT:
            raise UnsupportedError(f"{s.what} from {s.dialect} has no equivalent in {self.DIALECT}",
                                   Location(self.ctx.file, block.line, 1))
        return [s.text]


_UPPER = {c: c.upper() for c in "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz:"}


def _snake(key: str) -> str:
    out = []
    for i, ch in enumerate(key):
        if ch.isupper() and i:
            out.append("_")
        out.append(ch.lower())
    return "".join(out)
