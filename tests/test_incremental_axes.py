"""The neutral modal step and the simulator read a lathe's incremental addresses from the dialect's
declaration (``Dialect.INCREMENTAL_AXES`` through ``Context.increments``), never from letters of their own.

Expected positions are worked by hand from the blocks: ``X10.`` then ``U4.`` is X 14 where U is an
increment of X, and X 10 with U at 4 where U is an axis of its own.
"""

from __future__ import annotations

from postproc.context import Context
from postproc.errors import Diagnostics, ErrorLevel
from postproc.ir import Block, Feed, Motion
from postproc.plugins import default_registry
from postproc.setup.machine_setup import MachineSetup
from postproc.syntaxes.modal_state import ModalStateSyntax
from postproc.simulate.toolpath import simulate


def _context(increments: dict[str, str]) -> Context:
    setup = MachineSetup()
    setup.machine.axes = "XYZUW"  # U and W are axes here unless the dialect declares them increments
    ctx = Context("t.nc", setup, Diagnostics(ErrorLevel.RAISE), "probe")
    ctx.lathe = True
    ctx.increments = increments
    ctx.state.plane = "ZX"
    return ctx


def _blocks() -> list[Block]:
    out = []
    for line, axes in enumerate(({"X": 10.0, "Z": 2.0}, {"U": 4.0, "W": -3.0}), start=1):
        block = Block(line, None)
        block.add(Motion("linear", dict(axes)))
        out.append(block)
    return out


def test_the_modal_step_applies_the_declared_increments():
    ctx = _context({"U": "X", "W": "Z"})
    step = ModalStateSyntax()
    ctx.state.feed = 100.0
    for block in _blocks():
        step.build(block, ctx)
    assert (ctx.state.position.get("X"), ctx.state.position.get("Z"), "U" in ctx.state.position) == (14.0, -1.0, False)


def test_without_a_declaration_u_and_w_are_axes_of_their_own():
    ctx = _context({})
    step = ModalStateSyntax()
    ctx.state.feed = 100.0
    for block in _blocks():
        step.build(block, ctx)
    position = ctx.state.position
    assert (position.get("X"), position.get("Z"), position.get("U"), position.get("W")) == (10.0, 2.0, 4.0, -3.0)


def test_the_simulator_applies_the_declared_increments():
    ctx = _context({"U": "X", "W": "Z"})
    ctx.state.feed = 100.0
    blocks = _blocks()
    blocks[0].add(Feed(100.0))
    moves = [ev for ev in simulate(iter(blocks), ctx) if "move" in ev]
    assert [(ev["x"], ev["z"]) for ev in moves] == [(10, 2), (14, -1)]


def test_the_lathe_dialects_declare_u_and_w():
    registry = default_registry()
    for name in ("fanuc", "gsk"):
        assert dict(registry.dialect(name).INCREMENTAL_AXES) == {"U": "X", "W": "Z"}
