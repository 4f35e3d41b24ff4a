"""A family base's hooks that run only for what a subclass declares (``HOOK_DECLARATIONS``): the conformance
suite reports a block syntax that overrides one and declares nothing (``postproc.testing.checks.hook_problems``),
since such a hook is never called and the reading it adds silently does not happen."""

from __future__ import annotations

from typing import Any

import pytest

from postproc.ir import Block
from postproc.plugins import default_registry
from postproc.rs274.ngc_block_syntax import NgcWordBlockSyntax
from postproc.setup.machine_setup import MachineSetup
from postproc.testing.checks import hook_problems


@pytest.mark.parametrize("name", sorted(default_registry().dialects))
def test_every_installed_dialect_declares_its_hooks(name: str) -> None:
    assert hook_problems(default_registry().dialect(name)) == []


class _Steps:
    def __init__(self, *steps: object) -> None:
        self.steps = list(steps)


def _dialect_with(step: object) -> type:
    mach3 = default_registry().dialect("mach3")

    class WithStep(mach3):  # type: ignore[valid-type, misc]
        __module__ = mach3.__module__

        @classmethod
        def file_pipeline(cls, setup: MachineSetup) -> _Steps:
            return _Steps(step)

    return WithStep


def _mach3_syntax() -> type[NgcWordBlockSyntax]:
    mach3 = default_registry().dialect("mach3")
    return type(mach3.file_pipeline(MachineSetup()).steps[0])


def test_a_special_g_hook_without_special_g_is_reported() -> None:
    base = _mach3_syntax()

    class ReadsG5(base):  # type: ignore[valid-type, misc]
        __slots__ = ()

        def special_g_code(self, ctx: Any, block: Block, num: str, key: str, natives: list[str]) -> bool:
            return True

    problems = hook_problems(_dialect_with(ReadsG5()))
    assert len(problems) == 1 and "overrides special_g_code but declares none of SPECIAL_G" in problems[0]


def test_a_sections_hook_is_reported_until_something_selects_it() -> None:
    base = _mach3_syntax()

    class After(base):  # type: ignore[valid-type, misc]
        __slots__ = ()

        def after_sections(self, *args: Any) -> None:
            return None

    problems = hook_problems(_dialect_with(After()))
    assert len(problems) == 1 and "OWN_CODES, OWN_STATE, OWN_MOTION" in problems[0]

    class AfterMotion(After):
        __slots__ = ()
        OWN_MOTION = frozenset({"cw"})

    assert hook_problems(_dialect_with(AfterMotion())) == []
