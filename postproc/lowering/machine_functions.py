"""Machine-specific codes towards a controller of another family: under ``--on-unsupported warn`` the
code alone is left out, with a warning and a comment in its block, and the rest of the block is kept
(``M31``: the part counter does not count). Under 'error' the block reaches the writer unchanged, which
reports the code with its location.

A code whose action is ``rigid-tap`` (Fanuc ``M29 S..``) is never left out here: it makes the tap cycles
after it follow the spindle, and the same cycle fed without the spindle in step breaks the tap. Towards a
target that writes a synchronised tap (LinuxCNC's G33.1) ``postproc.lowering.synchronised_tap`` has already taken it
(its taps carry its meaning); towards any other family it is refused in either mode, by
``refused_rigid_tap``'s message.

The set-up's ``<ForeignCodes>`` (``postproc.setup.foreign_codes``) says what a code of another family becomes
on the target machine, in either mode: left out with a comment in its block (``omit``, only for a code whose
action is ``none``), or the target's own machine code, read back by the target's reader (one place decides
what the target reads it as: a code its reader takes as anything but a machine-specific one is refused).
"""

from __future__ import annotations

import copy
import io

from mypy_extensions import mypyc_attr

from ..context import Context
from ..dialect import Dialect
from ..errors import UnsupportedError
from ..ir import Block, Comments, MachineFunction, Section
from ..setup.foreign_codes import OMIT, ForeignCode, foreign_table
from .lower import BlockStep, LoweringStep

RIGID_TAP = "rigid-tap"
"""The action of a code that makes the following tap cycles spindle-synchronised."""
_READ_BACK = "foreign_codes_read_back"
"""``ctx.run_data`` key: target code -> what the target's reader made of it (``_target_code``)."""
_MACHINE_KEYS = frozenset(("MachineFunction", "NativeCode"))
"""What a target's reader makes of one of its own machine codes: a machine builder's function, or a code
kept verbatim for the dialect (LinuxCNC's user M codes)."""


def refused_rigid_tap(code: MachineFunction, target: str) -> str:
    """Why a rigid-tapping code cannot go to ``target`` (a controller of another family)."""
    return (f"{code.describe()} of the {code.family} family makes the tap cycles after it follow the spindle; "
            f"this translation writes no spindle-synchronised tap for {target}, and fed "
            "without the spindle in step a tap breaks: refused, even with --on-unsupported warn")


def foreign_hint(code: MachineFunction) -> str:
    """What a refusal of ``code`` adds: the set-up element that would say what it becomes (M codes only;
    ``omit`` offered only where the code may be left out, its action ``none``)."""
    letter, number = code.code[:1], code.code[1:]
    if letter != "M" or not number.isdigit():
        return ""
    element = f'<ForeignCodes><{letter} family="{code.family}" number="{number}" to=".."/></ForeignCodes>'
    if code.action == "none":
        return (f" (the target machine's set-up can say what it becomes there: {element}, to=\"omit\" leaves it "
                "out with a comment, or to= a machine code of the target)")
    return f" (the target machine's set-up can say which of its machine codes it becomes: {element})"


def comment_out(block: Block, note: str) -> None:
    """The block's machine-specific code goes; ``note`` joins its comments, saying why or where its meaning went."""
    del block.sections["MachineFunction"]
    comments = block.sections.get("Comments")
    texts = list(comments.texts) if isinstance(comments, Comments) else []
    block.sections["Comments"] = Comments([*texts, note])
    block.changed()


@mypyc_attr(allow_interpreted_subclasses=True)
class DropForeignMachineFunctions(LoweringStep):
    """Apply the set-up's ``<ForeignCodes>`` to each machine-specific code of another family, and leave out
    (with a warning and a comment) an undeclared one with ``--on-unsupported warn``; otherwise the writer
    refuses it, and the blocks pass with no step each."""

    def start(self, ctx: Context, target: type[Dialect]) -> BlockStep | None:
        if ctx.on_unsupported != "warn" and not ctx.setup.foreign_codes:
            return None
        return _Drop(ctx, target, foreign_table(ctx.setup.foreign_codes))


drop_foreign_machine_functions = DropForeignMachineFunctions()


@mypyc_attr(allow_interpreted_subclasses=True)
class _Drop(BlockStep):
    """One run of ``drop_foreign_machine_functions``: a block that is only a move holds no machine code."""

    def __init__(self, ctx: Context, target: type[Dialect], declared: dict[tuple[str, str], ForeignCode]) -> None:
        super().__init__()
        self.ctx = ctx
        self.target = target
        self.declared = declared
        self.family = target.family()
        self.warn = ctx.on_unsupported == "warn"
        self.moves = False

    def take(self, block: Block) -> list[Block] | None:
        code = block.sections.get("MachineFunction")
        if not isinstance(code, MachineFunction) or code.family == self.family:
            return None
        ctx, target = self.ctx, self.target
        mapped = self.declared.get((code.family, code.code))
        if code.action == RIGID_TAP:
            ctx.diagnostics.error(UnsupportedError(refused_rigid_tap(code, target.NAME),
                                                   ctx.at(block, _column(block, code.code))))
            del block.sections["MachineFunction"]  # refused once, here: the writer would warn of it again
            block.changed()
        elif mapped is not None:
            _apply(block, code, mapped, ctx, target)
        elif self.warn:
            ctx.diagnostics.warn(f"{code.describe()}, a machine-specific code of the {code.family} family, has "
                                 f"no equivalent in {target.NAME}; left out, its block kept{foreign_hint(code)}",
                                 ctx.at(block, _column(block, code.code)))
            comment_out(block, f"{code.text} NOT WRITTEN: {code.describe()} of the {code.family} family has no equivalent")
        return None


def _apply(block: Block, code: MachineFunction, mapped: ForeignCode, ctx: Context, target: type[Dialect]) -> None:
    """What the set-up says the code becomes: left out with a note, or the target's code (a refusal, located
    at the code, when the set-up asks for what cannot be)."""
    becomes = mapped.becomes()
    where = ctx.at(block, _column(block, code.code))
    problem: str | None = None
    section: Section | None = None
    if becomes == OMIT:
        if code.action != "none":
            problem = (f"it acts on the machine ({code.action}): only a code that moves nothing and changes no "
                       "spindle, coolant, feed or tool data may be omitted")
    elif len(code.text.split()) > 1:  # (``M031`` alone is the code: its text is as written)
        problem = f"it carries words ({code.text}) a code of {target.NAME} would not take over"
    else:
        section, problem = _target_code(becomes, ctx, target)
    if problem is not None:
        ctx.diagnostics.error(UnsupportedError(
            f"{code.describe()} of the {code.family} family: the set-up's <ForeignCodes> makes it {becomes} on "
            f"{target.NAME}, but {problem}", where))
        del block.sections["MachineFunction"]  # refused once, here: the writer would report it again
        block.changed()
        return
    if section is None:
        comment_out(block, f"{code.text} omitted: {code.name or 'a machine code'} of the {code.family} family, left "
                     "out by the set-up (ForeignCodes)")
        return
    del block.sections["MachineFunction"]
    block.sections[section.KEY] = copy.copy(section)  # a block's own: later steps may change their block's sections
    block.changed()


def _target_code(becomes: str, ctx: Context, target: type[Dialect]) -> tuple[Section | None, str | None]:
    """The section the target's own reader makes of the code ``becomes`` (read once a run), or why it is
    none of the target's machine-specific codes."""
    cache: dict[str, tuple[Section | None, str | None]] = ctx.run_data.setdefault(_READ_BACK, {})
    found = cache.get(becomes)
    if found is not None:
        return found
    from ..errors import Diagnostics, ErrorLevel, ErrorList, PostprocError
    from ..reading import read_blocks
    answer: tuple[Section | None, str | None]
    if target.READER is None:
        answer = None, f"{target.NAME} cannot be read back to confirm it is a machine code there"
    else:
        diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
        try:
            _, blocks = read_blocks([becomes + "\n"], "<ForeignCodes>", target, ctx.setup, diagnostics)
            # read alone at a program's start, the code also carries the set-up's power-on units
            # (``postproc.syntaxes.power_on_units``), which are no part of it
            sections = [s for b in blocks for s in b.sections.values() if s.KEY != "Units"]
            diagnostics.check()
        except ErrorList as err:
            first = err.errors[0]
            answer = None, f"{target.NAME} does not read it: {getattr(first, 'message', str(first))}"
        except PostprocError as err:
            answer = None, f"{target.NAME} does not read it: {getattr(err, 'message', str(err))}"
        else:
            kept = [s for s in sections if s.KEY in _MACHINE_KEYS]
            if len(kept) == 1 and len(sections) == 1:
                answer = kept[0], None
            else:
                what = ", ".join(type(s).__name__ for s in sections) or "nothing"
                answer = None, f"{target.NAME} reads it as {what}, not as a machine-specific code of its own"
    cache[becomes] = answer
    return answer


def _column(block: Block, code: str) -> int:
    i = (block.text or "").upper().find(code)
    return i + 1 if i >= 0 else 1
