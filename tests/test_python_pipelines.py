"""Reading pipelines declared in Python (``Dialect.python_pipeline``): a run reads no pipeline XML and so
imports no XML parser, while each dialect's pipeline file stays the definition a set-up's own pipeline
starts from. For every installed dialect, under each machine type it reads, the two are the same
(``postproc.testing.checks.pipeline_problems``, which the conformance suite runs for every plugin)."""

from __future__ import annotations

import pytest

from dialects.fanuc import Fanuc
from postproc.cycles.resolve import CannedCycleResolveSyntax
from postproc.plugins import default_registry
from postproc.setup.machine_setup import InputSettings, MachineSetup
from postproc.syntaxes.syntax import Pipeline
from postproc.syntaxes.modal_state import ModalStateSyntax
from postproc.testing.checks import pipeline_problems, pipeline_setups

SHIPPED = ("fanuc", "gsk", "isg", "fagor", "grbl", "linuxcnc", "mach3")
"""The built-in dialects and the plugins in plugins/: each declares its pipeline in Python."""


def _readers() -> list[str]:
    return sorted(name for name, cls in default_registry().dialects.items() if cls.READER is not None)


@pytest.mark.parametrize("name", _readers())
def test_the_python_pipeline_is_the_file(name: str) -> None:
    assert pipeline_problems(default_registry().dialect(name)) == []


@pytest.mark.parametrize("name", SHIPPED)
def test_every_shipped_dialect_declares_its_pipeline_in_python(name: str) -> None:
    dialect = default_registry().dialect(name)
    for what, setup in pipeline_setups(dialect):
        declared = dialect.python_pipeline(setup)
        assert declared is not None, f"{name} under {what}"
        assert dialect.pipeline(setup) == declared == dialect.file_pipeline(setup)


def test_fanuc_reads_a_lathe_with_the_lathe_pipeline() -> None:
    lathe = MachineSetup(input=InputSettings(machine_type="lathe"))
    assert Fanuc.pipeline_file(lathe) == "fanuc_lathe.xml" and Fanuc.pipeline_file(MachineSetup()) == "fanuc.xml"
    names = [type(step).XNAME for step in Fanuc.pipeline(lathe).steps]
    assert names == ["FanucProgramSyntax", "FanucLatheBlockSyntax", "ModalStateSyntax", "LatheCycleSyntax"]


def test_each_call_builds_new_steps() -> None:
    """Steps may keep a run's state (the cycle resolver's cache): no two runs share one."""
    first, second = Fanuc.pipeline(MachineSetup()), Fanuc.pipeline(MachineSetup())
    assert first == second and all(a is not b for a, b in zip(first.steps, second.steps))


# -- the check finds a pipeline that drifted from its file ------------------------------------------
# (Each variant says it is of Fanuc's package: a dialect's pipeline file lies beside its module.)

class _OtherSemantics(Fanuc):
    """The file says Fanuc's cycle semantics; this declaration says RS274's."""

    __module__ = Fanuc.__module__

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        from dialects.fanuc.block_syntax import FanucBlockSyntax
        from dialects.fanuc.program import FanucProgramSyntax
        return Pipeline(cls.NAME, [FanucProgramSyntax(), FanucBlockSyntax(), CannedCycleResolveSyntax("rs274"),
                                   ModalStateSyntax()])


class _StepMissing(Fanuc):
    __module__ = Fanuc.__module__

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        return Pipeline(cls.NAME, [step for step in super().python_pipeline(setup).steps
                                   if not isinstance(step, CannedCycleResolveSyntax)])


class _Renamed(Fanuc):
    __module__ = Fanuc.__module__

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        return Pipeline("other", super().python_pipeline(setup).steps)


class _SubclassedStep(Fanuc):
    """The same element names, but a step of another class than the file's."""

    __module__ = Fanuc.__module__

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        class Modal(ModalStateSyntax):
            pass

        steps = super().python_pipeline(setup).steps
        return Pipeline(cls.NAME, steps[:-1] + [Modal()])


class _NoFile(Fanuc):
    __module__ = Fanuc.__module__

    PIPELINE_FILE = None
    LATHE_PIPELINE_FILE = None  # type: ignore[assignment]

    @classmethod
    def pipeline_file(cls, setup: MachineSetup) -> str | None:
        return None


class _Broken(Fanuc):
    __module__ = Fanuc.__module__

    @classmethod
    def python_pipeline(cls, setup: MachineSetup) -> Pipeline:
        raise RuntimeError("typo")


@pytest.mark.parametrize("dialect, says", [
    (_OtherSemantics, 'fanuc: python_pipeline under a mill set-up is not the pipeline of fanuc.xml\n'
                      '--- python_pipeline:\n'),
    (_StepMissing, "fanuc: python_pipeline under a mill set-up is not the pipeline of fanuc.xml"),
    (_Renamed, '<Pipeline dialect="other">'),
    (_SubclassedStep, "(the same XML, but steps of other classes: "),
    (_NoFile, "but there is no pipeline file (PIPELINE_FILE) for it to match"),
    (_Broken, "fanuc: python_pipeline fails under a lathe set-up: RuntimeError: typo"),
])
def test_a_python_pipeline_that_is_not_the_file_is_reported(dialect: type[Fanuc], says: str) -> None:
    problems = pipeline_problems(dialect)
    assert problems and any(says in p for p in problems), problems


def test_a_dialect_that_declares_none_reads_its_file() -> None:
    class FileOnly(Fanuc):
        __module__ = Fanuc.__module__

        @classmethod
        def python_pipeline(cls, setup: MachineSetup) -> Pipeline | None:
            return None

    assert FileOnly.pipeline(MachineSetup()) == Fanuc.file_pipeline(MachineSetup())
    assert pipeline_problems(FileOnly) == []
