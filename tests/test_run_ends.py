"""A program's run leaves nothing of itself in ``ctx.run_data`` once it has ended.

The interpreter step keeps its running ``Variables`` and ``Interpreter`` there while the run's blocks stream
through the later steps (a LinuxCNC G70-G72 reads its profile subprogram there). A program that computes may be
run on trial first and then kept as written (ISG, Fagor, SINUMERIK: ``RUN_BEFORE_KEEP``; Fanuc's vacant-word
check): a later step must not find the trial run's parameters, as they stood at its end, and evaluate words of
the kept program with them. Checked on both paths: the trial run of a program then kept, and a run written out.
"""

from __future__ import annotations

import io

from postproc.context import Context
from postproc.errors import Diagnostics, ErrorLevel
from postproc.interp.variables import RUN_INTERPRETER_KEY, RUN_VARIABLES_KEY
from postproc.ir import Block
from postproc.plugins import default_registry
from postproc.reading import read_blocks
from postproc.setup.machine_setup import MachineSetup

ISG = "%1\nP1 = 2\n$FOR P2 = 1, 3, 1\nG1 X[P1*P2] F100\n$ENDFOR\nM30\n"
"""An ISG program that computes: ISG runs such a program on trial before keeping it as written."""


def _read(text: str, dialect: str, mode: str, prepare: object = None) -> tuple[Context, list[bool]]:
    """The run's context, and for each block streamed whether the running parameters stood in ``run_data``."""
    diagnostics = Diagnostics(ErrorLevel.RAISE, warn_stream=io.StringIO())
    ctx, blocks = read_blocks(io.StringIO(text), "prog.nc", default_registry().dialect(dialect), MachineSetup(),
                              diagnostics, program_mode=mode, prepare=prepare)  # type: ignore[arg-type]
    seen: list[bool] = []
    block: Block
    for block in blocks:
        seen.append(RUN_VARIABLES_KEY in ctx.run_data)
    assert not diagnostics.errors
    return ctx, seen


def test_a_run_written_out_leaves_no_parameters_behind() -> None:
    """While the run streams its parameters stand there (else this test could not fail); after it, nothing."""
    ctx, seen = _read(ISG, "isg", "execute")
    assert any(seen)
    assert RUN_VARIABLES_KEY not in ctx.run_data and RUN_INTERPRETER_KEY not in ctx.run_data


def test_a_trial_run_leaves_no_parameters_to_the_program_kept_as_written() -> None:
    """ISG's trial run before keeping (a keep check that finds nothing to refuse): the program's kept blocks
    stream after the trial run has ended, and neither they nor the steps after see its parameters."""
    trial: list[bool] = []

    def prepare(ctx: Context) -> None:
        def keep_check(copies: list[Block]) -> None:
            return None

        ctx.keep_check = keep_check
        runs = ctx.run_data

        class Watch(dict):  # type: ignore[type-arg]
            def __setitem__(self, key: str, value: object) -> None:
                trial.append(key == RUN_VARIABLES_KEY)
                super().__setitem__(key, value)

        ctx.run_data = Watch(runs)

    ctx, seen = _read(ISG, "isg", "auto", prepare)
    assert any(trial)  # a trial run set them
    assert seen and not any(seen)
    assert RUN_VARIABLES_KEY not in ctx.run_data and RUN_INTERPRETER_KEY not in ctx.run_data
