"""The core's own plugin: registers the neutral syntax objects and configuration nodes, and the lowering steps
every translation runs.

Each hook imports what it registers when it runs, not this module at its top: the plugin is registered with
every manager, and ``postproc dialects`` (``postproc.plugins.installed_dialects``) runs no hook of it, so it
does not import the syntax objects, cycles, frames and lowering steps (about a fifth of its start-up).
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Callable, Iterator

from .hookspecs import hookimpl

if TYPE_CHECKING:
    from .context import Context
    from .dialect import Dialect
    from .ir import Block
    from .lowering.lower import Lowering
    from .xmlio import XFactory


@hookimpl
def postproc_register_xml(factory: XFactory) -> None:
    from . import cycles, patterns
    from .interp.control import register_control
    from .lowering.synchronised_tap import RigidTap
    from .ir.expr import register_expressions
    from .frames import register_frames
    from .ir import register_sections
    from .ir.lathe_sections import register_lathe_sections
    from .rs274 import cycle_semantics as cycle_semantics  # registers the family's hole-cycle rules by name (an IR file names them)
    from .setup.machine_setup import MachineSetup
    from .syntaxes.syntax import Pipeline
    from .syntaxes.modal_state import ModalStateSyntax
    from .syntaxes.program import ProgramSyntax
    register_sections(factory)
    register_lathe_sections(factory)
    register_expressions(factory)
    register_frames(factory)
    register_control(factory)
    for cls in (Pipeline, MachineSetup, ModalStateSyntax, ProgramSyntax, RigidTap):
        cls.reg(factory)
    # A template's text, imported with the templates' module: a translation imports it anyway, a toolpath never.
    factory.register_lazy("Generated", "postproc.lowering.sequences:GeneratedText")
    # A lathe's cycle reader (with the cycles' words and the nose compensation it names), imported when a
    # pipeline names it: a mill's run never does.
    factory.register_lazy("LatheCycleSyntax", "postproc.rs274.lathe_cycles:LatheCycleSyntax")
    cycles.register(factory)
    patterns.register(factory)



@hookimpl
def postproc_register_lowerings(register: Callable[[Lowering], None]) -> None:
    from . import patterns
    from .lowering.feed_first import check_blocks
    from .cycles.lowering import expand_canned_cycles
    from .cycles.rigid_tap_lowering import resolve_rigid_taps
    from .frames import evaluate_frames
    from .lowering.deferred import resolve_dynamic_cutter_compensation
    from .lowering.inverse_time import convert_inverse_time
    from .lowering.length_timing import time_length_changes
    from .lowering.machine_functions import drop_foreign_machine_functions
    from .frames.measured_entries import write_measured_entries
    from .lowering.path_at_start import carry_path_at_start
    from .lowering.program_end import comment_after_end
    from .lowering.program_frame import frame_program
    from .lowering.sideways_offsets import write_sideways_offsets
    from .lowering.stored_offsets import hold_stored_offsets
    from .lowering.tool_entries import write_tool_entries
    from .lowering.units_at_start import write_units_at_start
    register(check_blocks)  # first: it sees every expansion before a native target's are dropped
    register(patterns.expand_hole_patterns)  # before the cycles: it makes a repeat of the cycle per point
    register(evaluate_frames)  # before the cycles: a cycle under a frame is expanded at carried points
    register(expand_canned_cycles)
    register(expand_lathe_cycles)
    register(index_turret)  # after the lathe cycles: an M6 tool change becomes a turret index (T0202)
    register(resolve_dynamic_cutter_compensation)  # before inverse time: its feeds follow the resolved moves
    register(convert_inverse_time)  # after the expansions: it follows the moves they leave
    register(comment_after_end)
    register(write_measured_entries)  # after the frames (it reads their point), before the two below
    register(write_sideways_offsets)  # before the entries: it takes their X and Y into the path
    register(write_tool_entries)  # before the target's steps: grbl's read the registers it writes
    register(resolve_rigid_taps)  # after the cycles: an expanded rigid tap cycle shows its taps
    register(time_length_changes)  # after the cycles: a change is carried to the move that applies it
    register(carry_path_at_start)  # after the expansions: it goes before the first block that moves
    register(write_units_at_start)  # after the expansions: it goes before the first block that reads a length
    register(hold_stored_offsets)  # after the frames (they follow the setting where the source has it)
    register(drop_foreign_machine_functions)
    register(frame_program)  # last: the frame goes around what the steps before made


# The lathe's generic lowering steps as the registry holds them: each imports its work when a lathe program is first
# lowered. Both pass a mill's program untouched (``ctx.lathe`` False, the first thing each decides), so a mill's
# run imports neither the lathe cycles' expansion (and the offsets and tool geometry it reads) nor the turret's
# indexing. Here, above both the cycles and the RS274 family, which they load.


def expand_lathe_cycles(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """``postproc.cycles.lathe_lowering.expand_lathe_cycles``."""
    if not ctx.lathe:
        return blocks
    from .cycles.lathe_lowering import expand_lathe_cycles as step
    return step(blocks, ctx, target)


def index_turret(blocks: Iterator[Block], ctx: Context, target: type[Dialect]) -> Iterator[Block]:
    """``postproc.rs274.lathe_tool_index.index_turret``."""
    if not ctx.lathe:
        return blocks
    from .rs274.lathe_tool_index import index_turret as step
    return step(blocks, ctx, target)
