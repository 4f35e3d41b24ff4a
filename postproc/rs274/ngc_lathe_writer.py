"""Writing a lathe program in the RS274/NGC lathe words (LinuxCNC, grblHAL in lathe mode): the mode line,
constant surface speed with its clamp, and G33. Each controller's lathe writer is a class of its own (picked
by its ``writer_class`` for a lathe run), so a mill program keeps the family's fast lane (``postproc.fast``: it
serves only a writer that overrides none of the word writer's block methods); it calls these helpers.

The rules, each checked with rs274 (2.9) [V] (see ``ngc_lathe`` for the reading side); grblHAL's ``gcode.c``
(stored commit f80fc34) runs them alike [V: G96 without D clamps at the spindle's maximum, G33's K is the
planner's distance per revolution along the path]:

* A translated lathe program starts with ``G18 G7`` (or ``G8`` when it programs radii): a LinuxCNC lathe's
  start-up code may leave either mode, so the program says it (``LatheModes.preamble``). A mill program on a
  lathe set-up starts with ``G17 G8``: its source's plane at start is XY (``NgcLatheWriting.mode_line``).
* A program that switches how X reads (``XProgramming``, read from LinuxCNC's G7/G8) keeps its switches on a
  controller with ``X_MODE_CODES``: the IR's X (the set-up's mode) is written halved or doubled while the
  program's mode differs, on a move; any other section with an X, and a compound motion (a G76 rewritten),
  is refused there (``NgcLatheWriting.generate``); a repeated switch is not written again. A copied line is
  written as it was.
* ``G96 S.. D..``: the Fanuc-family clamp (``G50 S``) is a state of its own; LinuxCNC clamps only on the
  G96 line, and a G96 without D lifts the clamp. So every G96 gets the clamp in force, and a new clamp
  while constant surface speed is on is written as ``G96 S<the speed in force> D<clamp>`` (a clamp while it
  is off waits for the next G96). G96 needs S: the surface speed in force is written where the block has
  none.
* A thread move is ``G33 X.. Z.. K..``, K the distance per revolution along the path
  (``postproc.geometry.thread_lead``). G33 refuses an F beside it, so a thread block's F goes on a line of its own
  before it (``feed_apart``, a lowering step); F is then the lead, as the source's F is. A thread whose
  major axis is X (a face thread) is refused: LinuxCNC's K along such a path in diameter mode is not in
  our sources [?].
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, ClassVar

from postproc.context import Context
from postproc.dialect import Dialect
from postproc.ir.expr import Expr
from postproc.ir import Block, Motion
from postproc.geometry.thread_lead import lead_along_path, major_is_z

from postproc.lowering.lower import BlockStep, LoweringStep

from .codes import g_key
from .ngc_lathe import X_MODE_WORDS
from .writer import WordWriter

_QUIET = frozenset(("TapeMark", "ProgramStart", "Comments", "Sequence"))
"""Sections of the lines that may stand before the mode line (the program's opening)."""


class FeedApart(LoweringStep):
    """Lowering step: a thread block's F on a line of its own before it (rs274: "F word used with a
    g33/g33.1"). Only a lathe program has thread moves."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        return _FeedApart() if ctx.lathe else None


feed_apart = FeedApart()


class _FeedApart(BlockStep):
    def __init__(self) -> None:
        super().__init__()
        self.moves = False  # a block that is only a move holds no F

    def take(self, block: Block) -> list[Block] | None:
        sections = block.sections
        motion = sections.get("Motion")
        if isinstance(motion, Motion) and motion.mode == "thread" and "Feed" in sections:
            first = Block(block.line, None, "\n")
            first.sections = {"Feed": sections.pop("Feed")}
            block.changed()
            return [first, block]
        return None


class LatheModes:
    """What the writer keeps of a lathe program: the clamp in force, constant surface speed, where X and Z
    were written last (for a taper thread's K)."""

    __slots__ = ("preamble", "clamp", "css", "x", "z", "diameter", "written", "said")

    def __init__(self, ctx: Context, mode_line: str | None) -> None:
        self.diameter = ctx.diameter
        self.written = 1.0
        """What an X of the IR (the set-up's mode) is multiplied by to be written in the mode the program
        switched to (``XProgramming``): 2 (radius IR, diameter written), 0.5, or 1."""
        self.said: str | None = ("diameter" if ctx.diameter else "radius") if mode_line is not None else None
        """The mode the written program last said (the mode line's; None: not known, a copy of the source's
        own lines), so a switch that repeats it is not written again."""
        self.preamble: str | None = mode_line
        """The mode line, until it is written before the first block that acts."""
        self.clamp: float | None = None
        self.css = False
        self.x: float | None = None
        self.z: float | None = None

    def opening(self, block: Block, text: str | None) -> str | None:
        """``text`` with the mode line before it when ``block`` is the first that acts."""
        if self.preamble is None or not text or _QUIET.issuperset(block.sections):
            return text
        line, self.preamble = self.preamble, None
        return line + "\n" + text

    def switch(self, mode: str) -> None:
        """The program writes X as ``mode`` ("diameter", "radius") from here (``XProgramming``)."""
        ir = "diameter" if self.diameter else "radius"
        self.written = 1.0 if mode == ir else 2.0 if mode == "diameter" else 0.5

    def follow(self, s: Motion, incremental: bool) -> None:
        """Where the move leaves X and Z (None where it is not known)."""
        axes = s.axes
        if s.mode in ("home", "home2"):
            if "X" in axes:
                self.x = None
            if "Z" in axes:
                self.z = None
            return
        for axis in ("X", "Z"):
            value = axes.get(axis)
            if value is None:
                continue
            known = self.x if axis == "X" else self.z
            new = None if isinstance(value, Expr) or incremental and known is None else \
                float(value) + (known or 0.0) if incremental else float(value)
            if axis == "X":
                self.x = new
            else:
                self.z = new

    def thread_k(self, s: Motion, lead: float, incremental: bool) -> float | str:
        """G33's K for a move with major-axis lead ``lead``, or why it cannot be written."""
        def travel(axis: str, known: float | None) -> float | None:
            value = s.axes.get(axis)
            if value is None:
                return 0.0
            if isinstance(value, Expr):
                return None
            if incremental:
                return float(value)
            return None if known is None else float(value) - known
        dx, dz = travel("X", self.x), travel("Z", self.z)
        if dx is None or dz is None and dx != 0.0:
            return "a thread move from a position not known here (its K along the path needs the start)"
        dx = dx / 2.0 if self.diameter else dx
        dz = dz or 0.0
        if not major_is_z(dx, dz):
            return ("a thread whose major axis is X (a face thread: LinuxCNC's distance per revolution K along such "
                    "a path in diameter mode is not in our sources)")
        return lead_along_path(lead, dx, dz)


def clamp_words(writer: Any, modes: LatheModes, rpm: float | Expr, block: Block) -> list[str]:
    """A new clamp: ``G96 S.. D..`` while constant surface speed is on and the block does not set the mode,
    else nothing yet (the next G96 writes it)."""
    if isinstance(rpm, Expr):
        writer.unsupported("a computed spindle clamp (the clamp D takes a number)", block)
        return []
    modes.clamp = float(rpm)
    if not modes.css or "SpindleMode" in block.sections:
        return []
    words = [writer.code("spindle_mode", "css", "constant surface speed", block)]
    if "SpindleSpeed" not in block.sections:
        words.append(surface_speed(writer, block))
    return [*words, "D" + writer.speed(modes.clamp)]


def css_words(writer: Any, modes: LatheModes, mode: str, block: Block) -> list[str]:
    """``G96 [S..] D..`` or ``G97``."""
    modes.css = mode == "css"
    words = [writer.code("spindle_mode", mode, "constant surface speed" if modes.css else "spindle speed in rpm",
                         block)]
    if not modes.css:
        return words
    clamp = block.sections.get("SpindleClamp")
    if clamp is not None and not isinstance(clamp.rpm, Expr):  # type: ignore[attr-defined]
        modes.clamp = float(clamp.rpm)  # type: ignore[attr-defined]
    if "SpindleSpeed" not in block.sections:
        words.append(surface_speed(writer, block))
    if modes.clamp is not None:
        words.append("D" + writer.speed(modes.clamp))
    return words


def surface_speed(writer: Any, block: Block) -> str:
    """The S in force, for a G96 whose block has none (LinuxCNC: "S word missing with G96"; grblHAL: error
    ``Status_GcodeValueWordMissing``)."""
    rpm = writer.modal.spindle_rpm
    if rpm is None:
        writer.unsupported("constant surface speed with no surface speed S programmed (its code needs S)", block)
    return "S" + str(writer.expression(rpm, block) if isinstance(rpm, Expr) else writer.speed(rpm))


if TYPE_CHECKING:
    _OnWordWriter = WordWriter
else:
    _OnWordWriter = object


class NgcLatheWriting(_OnWordWriter):
    """The lathe words on a controller's word writer: ``class XLatheWriter(NgcLatheWriting, XWriter)``. The
    mode line before the first block that acts when the program comes from another dialect, G96 with its clamp,
    G33 with K.

    A mixin: typed as a ``WordWriter`` but, run, a subclass of ``object`` only, so the controller's writer is
    the one compiled line of bases the lathe writer has. Over two compiled lines (``WordWriter`` here and
    ``GrblFamilyWriter`` under grblHAL's writer) an object of the lathe writer was laid out as the first line's
    class, and the compiled ``GrblFamilyWriter``'s methods crashed on it (a segmentation fault in
    ``super().write_block``, tests/test_grblhal_lathe.py)."""

    IGNORED: ClassVar[frozenset[str]] = frozenset(("ThreadLead",))
    """A thread move's lead is written as its K (``motion_words``)."""
    X_MODE_CODES: ClassVar[dict[str, str]] = {}
    """The controller's code for each way X reads ("diameter", "radius"), where a program may switch
    (``Dialect.X_MODE_SWITCH``)."""
    MODE_LINES: ClassVar[dict[str, str]]
    """The controller's mode line, by how X reads ("diameter", "radius"): set by each controller's writer."""

    def __init__(self, ctx: Context, source_dialect: str, target: type[Dialect] | None = None) -> None:
        super().__init__(ctx, source_dialect, target)
        foreign = source_dialect != self.DIALECT
        self.lathe = LatheModes(ctx, self.mode_line(ctx) if foreign else None)

    def mode_line(self, ctx: Context) -> str:
        """``MODE_LINES``'s line; for a mill program on a lathe set-up (#20) with the XY plane in it of the ZX:
        its source starts in XY (G17), where a lathe's start-up code may leave G18, so an XY arc it programs
        without a plane code stays in XY (before, ``G18 G8`` then ``G2 X1 I0.5 J0``, which the target reads
        in ZX and verify refuses)."""
        line = self.MODE_LINES["diameter" if ctx.diameter else "radius"]
        if ctx.lathe:
            return line
        zx, xy = self.codes.spell("plane", "ZX"), self.codes.spell("plane", "XY")
        return " ".join(xy if word == zx and xy is not None else word for word in line.split())

    def write_block(self, block: Block) -> str | None:
        """A lathe program translated here opens with its mode line (``LatheModes.opening``); a switch of how X
        reads is followed (a copied line included)."""
        switch = block.sections.get("XProgramming")
        if switch is None:
            return self.lathe.opening(block, super().write_block(block))
        mode: str = switch.mode  # type: ignore[attr-defined]
        self.lathe.switch(mode)
        text = self.lathe.opening(block, super().write_block(block))
        self.lathe.said = mode
        return text

    def generate(self, block: Block) -> str:
        """A block written from its sections: in the switched mode it may carry X only on its move."""
        if self.lathe.written != 1.0:
            for key, section in block.sections.items():
                if key == "CompoundMotion" or key != "Motion" and "X" in (getattr(section, "axes", None) or ()):
                    self.unsupported(f"{key} while the program writes X in the mode other than the set-up's: "
                                     "only a move's X is converted", block)
        return super().generate(block)

    def normalized(self, block: Block) -> str:
        """A copied line rewritten from its words' values: in the switched mode those are the set-up's numbers
        (``postproc.rs274.ngc_lathe.program_x_mode``), written back as the line's own."""
        factor = self.lathe.written
        values = block.values
        if factor == 1.0:
            return super().normalized(block)
        thread_cycle = any(letter in "Gg" and g_key(num) == "76" for letter, num in block.words)
        letters = X_MODE_WORDS | {"X"} if thread_cycle else frozenset("X")
        block.values = {k: v * factor if k in letters and isinstance(v, (int, float)) else v for k, v in values.items()}
        try:
            return super().normalized(block)
        finally:
            block.values = values

    def coordinate_set_words(self, s: Any, block: Block) -> list[str]:
        """A Fanuc T or GSK coordinate setting (``G50 X.. Z..``, the ``CoordinateSet`` section): the tool's present
        point gets these coordinates, the tool does not move. RS274/NGC's ``G92`` does the same: the offset it sets
        makes the current point read the words given, an axis it does not name keeps its offset, a second one sets
        the offset again from the current point rather than adding to it, and X is a diameter in G7 [V: rs274
        2.9.0~pre1 run here, lathe G7 at X40 Z2: ``G92 X100 Z50`` prints ``SET_G92_OFFSET(-30, 0, -48)``, then at
        X90 Z40 ``G92 X60`` prints ``SET_G92_OFFSET(-15, 0, -48)``; tests/test_lathe_coordinate_set.py]; grblHAL
        halves every X word in diameter mode before the block's command, G92's included, and its G92 is grbl's
        [V: grblHAL core ``gcode.c``]. Its one
        offset applies in every work system, as a Fanuc coordinate setting shifts every workpiece coordinate system
        [K: Fanuc 0i-TF operator's manual, "Setting a workpiece coordinate system" by G50]. A source's own frame
        command (``FrameChange``) never reaches a lathe target of another family (``frame_change_words`` refuses
        it), so the G92 offset is not shared with a G52 the source meant apart."""
        code = self.code("frame", "origin", "a coordinate setting", block)
        return [code, *(axis + self.length(value, block, axis) for axis, value in s.axes.items())]

    def x_programming_words(self, s: Any, block: Block) -> list[str]:
        """How X reads from here (``X_MODE_CODES``; followed in ``write_block``), where the written program has not
        said it already."""
        if s.mode == self.lathe.said:
            return []
        code = self.X_MODE_CODES.get(s.mode)
        if code is None:
            self.unsupported(f"a switch to X as a {s.mode} inside the program", block)
            return []
        return [code]

    def motion_words(self, s: Any, block: Block) -> list[str]:
        """A thread move is ``G33 .. K..`` (``LatheModes.thread_k``); every move is followed."""
        lathe = self.lathe
        incremental = self.modal.distance == "incremental" and not self.expanding
        k: float | None = None
        if s.mode == "thread":
            given = block.sections.get("ThreadLead")
            feed = block.sections.get("Feed")
            lead = given.lead if given is not None else feed.value if feed is not None else self.modal.feed  # type: ignore[attr-defined]
            if not isinstance(lead, (int, float)):
                self.unsupported("a thread move without a known lead (F)", block)
                return []
            along = lathe.thread_k(s, float(lead), incremental)
            if isinstance(along, str):
                self.unsupported(along, block)
                return []
            k = along
        written = s
        if lathe.written != 1.0 and "X" in s.axes:
            x = s.axes["X"]
            if isinstance(x, Expr):
                self.unsupported("a computed X while the program writes X in the mode other than the set-up's", block)
                return []
            written = Motion(s.mode, {**s.axes, "X": float(x) * lathe.written}, s.center, s.radius)
        words = super().motion_words(written, block)
        lathe.follow(s, incremental)
        if k is not None:
            words.append("K" + self.length(k, block, "K"))
        return words

    def spindle_mode_words(self, s: Any, block: Block) -> list[str]:
        return css_words(self, self.lathe, s.mode, block)

    def spindle_clamp_words(self, s: Any, block: Block) -> list[str]:
        """A spindle clamp goes with G96 (``clamp_words``)."""
        return clamp_words(self, self.lathe, s.rpm, block)
