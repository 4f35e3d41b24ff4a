"""LinuxCNC writer: the RS274 word writer with LinuxCNC's spelling of what differs from Fanuc.

* G4 P and a cycle's P are seconds; the repeat count of a native cycle is L.
* No G44, no one-shot exact stop (G9) and no O-number programs: the first two are unsupported, the
  program number is written as a comment (LinuxCNC reads O as an O-word).
* Work offsets 7-9 are G59.1-G59.3; inverse-time feed is G93; M19 takes its angle as R.
* A native cycle is written from its words as programmed. Only cycles resolved under RS274/NGC rules
  arrive here native: the lowering expands every other family's cycle exactly (``CYCLE_SEMANTICS``),
  because LinuxCNC's start-below-R, G98 and G91 R rules would move differently.
"""

from __future__ import annotations

from typing import Any, ClassVar

from postproc.ir import Block
from postproc.rs274.writer import WordWriter


class LinuxcncWriter(WordWriter):
    DIALECT: ClassVar[str] = "linuxcnc"
    MOTION: ClassVar[dict[str, str]] = {"rapid": "G0", "linear": "G1", "cw": "G2", "ccw": "G3",
                                        "home": "G28", "home2": "G30"}
    WORK_OFFSET: ClassVar[dict[int, str]] = {**WordWriter.WORK_OFFSET, 7: "G59.1", 8: "G59.2", 9: "G59.3"}
    FEED_MODE: ClassVar[dict[str, str]] = {**WordWriter.FEED_MODE, "inverse_time": "G93"}
    LENGTH: ClassVar[dict[str, str]] = {"positive": "G43", "cancel": "G49"}
    PATH_ONCE: ClassVar[str | None] = None
    SPINDLE: ClassVar[dict[str, str]] = {"cw": "M3", "ccw": "M4", "stop": "M5"}
    COOLANT: ClassVar[dict[str, str]] = {"mist": "M7", "flood": "M8", "off": "M9"}
    PROGRAM: ClassVar[dict[str, str]] = {"stop": "M0", "optional_stop": "M1", "end": "M2", "end_rewind": "M30"}
    TOOL_CHANGE: ClassVar[str | None] = "M6"
    DWELL: ClassVar[str] = "G4"
    DWELL_WORD: ClassVar[str] = "Ps"
    CYCLES: ClassVar[dict[str, str]] = {k: v for k, v in WordWriter.CYCLES.items()
                                        if k not in ("fine_bore", "back_bore", "bore_manual")}
    """G76 threads, G87/G88 take other words: never written as Fanuc's cycles."""

    def program_start(self, s: Any, block: Block) -> str:
        """LinuxCNC reads O as an O-word (subprograms, loops): the program number stays a comment."""
        name = f"O{int(s.number):04d}" if s.number is not None else str(s.name)
        return self.comment(name)

    def block_delete_words(self, s: Any, block: Block) -> list[str]:
        if s.level != 1:
            self.unsupported(f"block delete level {s.level} (LinuxCNC has one block delete switch)", block)
        return ["/"]

    def spindle_orientation_words(self, s: Any, block: Block) -> list[str]:
        """M19 R<angle>: a bare M19 leaves the angle to the machine's default."""
        return ["M19", "R" + self.number(float(s.angle))]
