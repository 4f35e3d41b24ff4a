"""GSK 980TDc lathe dialect (G-code system A numbering): reader, writer, reading pipeline, capabilities.

Built in, and registered through the ``postproc`` entry points like any plugin; it shares the RS274
family's lathe base (``postproc.rs274.lathe_*``) with Fanuc T. Every program is a lathe's: X is a
diameter (or a radius per the set-up's ``xProgramming``), U/W are incremental, G50 sets coordinates or
clamps the spindle, G98/G99 are feed per minute/revolution, and G70-G76 and G90/G92/G94 are lathe cycles
whose omitted words take the data parameters of the set-up's ``<LatheCycles>`` (No.051-060).
GSK's macro language (``G65 H``) is kept verbatim, not executed.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable

from postproc.syntaxes.comments import CommentSyntax
from postproc.lowering.lower import BlockStep, LoweringStep
from postproc.rs274.cutter_rules import GSK_T
from postproc.dialect import Dialect, Lazy, Reader
from postproc.hookspecs import hookimpl
from postproc.rs274.arc_ends import FANUC_ARC_END
from postproc.rs274.lathe_axes import LATHE_INCREMENTS
from postproc.setup.machine_setup import MachineSetup
from postproc.syntaxes.syntax import Pipeline
from postproc.output.writer_base import Writer
from postproc.xmlio import XFactory

if TYPE_CHECKING:
    from postproc.context import Context


class _ResolveMachineMoves(LoweringStep):
    """``postproc.lowering.machine_positions.resolve_machine_moves``, imported when first used."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        from postproc.lowering.machine_positions import resolve_machine_moves as step
        return step.start(ctx, target)


resolve_machine_moves = _ResolveMachineMoves()


class Gsk(Dialect):
    NAME = "gsk"
    DESCRIPTION = "GSK 980TDc lathe (system A: G71-G76, G90/G92/G94, U/W, G50, G98/G99)"
    READER = Lazy[type[Reader]](".reader:GskReader")
    """Imported when a run first reads GSK (``Lazy``), as are the writer and the block syntax."""
    WRITER = Lazy[type[Writer]](".writer:GskWriter")
    PIPELINE_FILE = "gsk.xml"
    MACHINE_TYPES = frozenset({"lathe"})
    """A lathe control only: every program is read with lathe meanings, whatever the set-up says."""
    DIAMETER_PROGRAMMING = True
    """X is a diameter (the set-up's ``xProgramming`` may say radius)."""
    LATHE_CYCLES = frozenset(("turn_finish", "turn_rough", "face_rough", "pattern_repeat", "face_peck", "groove",
                              "thread_multi", "turn_single", "thread_single", "face_single"))
    """G70-G76, G90, G92, G94."""
    INCREMENTAL_AXES = LATHE_INCREMENTS
    """U and W are incremental X (a diameter) and Z (``postproc.rs274.lathe_axes``)."""
    LATHE_FEED_AT_START = "per_min"
    """The 980TDc starts in G98 (feed per minute)."""
    LATHE_PATH_CONTROL = False
    """The code table has no G61/G64 [?: the writer's ``PATH_CONTROL_LACK``]."""
    SPINDLE_ORIENTATION = False
    """No M19 on the 980TDc."""
    COMMENTS = CommentSyntax(parens=True, nested=False, semicolon=False)
    """``( )`` comments, as Fanuc's [K?: DIALECTS.md 1.2, to confirm with the TDc manual]."""
    TOOL_LENGTH_OFFSET = False
    """Tool offsets come with T (T0101), not G43 H."""
    TOOL_CHANGER = False
    """A turret indexed by T; no M06."""
    TAPE_MARKS = True
    """``%`` opens and closes a program, as on Fanuc."""
    PROGRAM_NUMBERS = True
    """``O0001``: the number the control stores the program under."""
    CUTTER_RULES = GSK_T
    """Tool nose radius compensation by Fanuc T's rules, start-up type A, the radius and the imaginary tool
    nose direction from the offset the T code selected (``postproc.compensation.rules``, tagged there)."""
    ARC_END = FANUC_ARC_END
    """As Fanuc's parameter 3410 [?] (``postproc.rs274.arc_ends``)."""
    LOWERING = (resolve_machine_moves,)
    """The code table has no machine-coordinate move (G53) [?: the 980TDc G-code list was not reached; the
    980TDi pages read (DIALECTS.md 1.2) show none]: a source's ``G53`` move is written in work coordinates from
    the set-up's work and tool offsets, or refused naming the one to declare
    (``postproc.lowering.machine_positions``)."""

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        """``gsk.xml``, built in Python."""
        from postproc.rs274.lathe_cycles import LatheCycleSyntax
        from postproc.syntaxes.modal_state import ModalStateSyntax
        from .block_syntax import GskBlockSyntax
        return Pipeline(cls.NAME, [GskBlockSyntax(), ModalStateSyntax(), LatheCycleSyntax()])


@hookimpl
def postproc_register_dialects(register: Callable[[type], None]) -> None:
    register(Gsk)


@hookimpl
def postproc_register_xml(factory: XFactory) -> None:
    factory.register_lazy("GskBlockSyntax", f"{__name__}.block_syntax:GskBlockSyntax")
