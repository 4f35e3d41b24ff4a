"""The conformance suite for dialect plugins, as a pytest plugin.

Enabled for every pytest run once postproc is installed (entry point ``pytest11``; without it, put
``pytest_plugins = ["postproc.testing"]`` in a ``conftest.py``). A plugin runs it against its own
example programs with one test module::

    from postproc.testing import ConformanceTests

    class TestMyDialect(ConformanceTests):
        pass

and its settings in ``pyproject.toml`` (paths relative to the rootdir)::

    [tool.pytest.ini_options]
    postproc_dialect = "mydialect"
    postproc_examples = "examples"            # programs that must read back byte for byte
    postproc_invalid = "examples/invalid"     # programs that must fail with located errors
    postproc_setup = ""                       # optional machine set-up XML
    postproc_max_examples = "25"              # hypothesis examples per generated check

or by overriding the ``postproc_conformance`` fixture (returning a ``DialectUnderTest``), e.g. to run
several dialects. ``postproc.testing.strategies`` holds the hypothesis strategies the suite draws from.
See docs/plugins.md.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings

from .. import native
native.install()  # the compiled hot path, before any of its modules is imported

from .checks import (
    DialectUnderTest, cross_problems, garbage_problems, generated_problems, hook_problems, invalid_problems,
    ir_xml_problems, pipeline_problems, read_text, round_trip_problems, targets,
)
from ..errors import PostprocError
from ..cycles.semantics import semantics_named, semantics_names
from .neutral import NeutralProgram
from .probes import PROBES, probe_problems
from .strategies import garbage, neutral_programs

__all__ = ["ConformanceTests", "DialectUnderTest", "pytest_addoption", "postproc_conformance"]

INI = {
    "postproc_dialect": "the dialect the conformance suite checks (its NAME)",
    "postproc_examples": "folder of the dialect's example programs (each must read back byte for byte)",
    "postproc_invalid": "folder of known-bad programs (each must fail with located errors); default EXAMPLES/invalid",
    "postproc_setup": "machine set-up XML the examples are read under (optional)",
    "postproc_max_examples": "hypothesis examples per generated check (default 25)",
}


def pytest_addoption(parser: pytest.Parser) -> None:
    for name, help_text in INI.items():
        parser.addini(name, help_text, default="")


@pytest.fixture
def postproc_conformance(request: pytest.FixtureRequest) -> DialectUnderTest:
    """The dialect under test, from the ini options; override this fixture to choose it in code."""
    config = request.config
    dialect = str(config.getini("postproc_dialect"))
    examples = str(config.getini("postproc_examples"))
    if not dialect or not examples:
        pytest.fail("the postproc conformance suite needs postproc_dialect and postproc_examples in "
                    "[tool.pytest.ini_options] (or a postproc_conformance fixture returning a DialectUnderTest)",
                    pytrace=False)
    root = config.rootpath
    invalid = str(config.getini("postproc_invalid"))
    setup = str(config.getini("postproc_setup"))
    return DialectUnderTest(dialect, root / examples, root / (invalid or Path(examples) / "invalid"),
                            root / setup if setup else None)


def max_examples(request: pytest.FixtureRequest) -> int:
    text = str(request.config.getini("postproc_max_examples")) or "25"
    try:
        return max(1, int(text))
    except ValueError:
        pytest.fail(f"postproc_max_examples must be a whole number, got {text!r}", pytrace=False)


def _report(problems: list[str], case: DialectUnderTest) -> None:
    if problems:
        pytest.fail(f"{case.name}: {len(problems)} problem(s)\n\n" + "\n\n".join(problems), pytrace=False)


class ConformanceTests:
    """Subclass as ``Test...`` in a test module; every method is one conformance check."""

    def test_examples_exist(self, postproc_conformance: DialectUnderTest) -> None:
        case = postproc_conformance
        dialect = case.cls()  # an unknown dialect is an error naming the installed ones
        if dialect.READER is not None:
            try:
                dialect.pipeline(case.machine())
                dialect.file_pipeline(case.machine())  # the file, also where python_pipeline stands for it
                broken = ""
            except PostprocError as err:
                broken = str(err)
            if broken:
                pytest.fail(f"{case.name}: its reading pipeline does not load (PIPELINE_FILE = "
                            f"{dialect.PIPELINE_FILE!r}, a file beside the module of {dialect.__name__}, "
                            f"listing registered syntax objects):\n{broken}", pytrace=False)
        if not case.programs():
            pytest.fail(f"{case.name}: no example programs in {case.examples} "
                        f"(files ending in .nc, .ngc, .tap, ...)", pytrace=False)
        if not case.bad_programs():
            pytest.fail(f"{case.name}: no known-bad programs in {case.invalid}: give a few (a malformed word, "
                        "a missing cycle word...), each must fail with located errors", pytrace=False)

    def test_python_pipeline_is_the_pipeline_file(self, postproc_conformance: DialectUnderTest) -> None:
        case = postproc_conformance
        dialect = case.cls()
        if dialect.READER is None:
            pytest.skip(f"{case.name} is write-only: it has no reading pipeline")
        _report(pipeline_problems(dialect, case.machine()), case)

    def test_block_syntax_hooks_are_declared(self, postproc_conformance: DialectUnderTest) -> None:
        case = postproc_conformance
        dialect = case.cls()
        if dialect.READER is None:
            pytest.skip(f"{case.name} is write-only: it has no reading pipeline")
        _report(hook_problems(dialect, case.machine()), case)

    def test_examples_read_back_byte_for_byte(self, postproc_conformance: DialectUnderTest) -> None:
        case = postproc_conformance
        _report([p for path in case.programs() for p in round_trip_problems(case, path)], case)

    def test_ir_survives_xml(self, postproc_conformance: DialectUnderTest) -> None:
        case = postproc_conformance
        _report([p for path in case.programs() for p in ir_xml_problems(case, path)], case)

    def test_invalid_programs_fail_with_located_errors(self, postproc_conformance: DialectUnderTest) -> None:
        case = postproc_conformance
        _report([p for path in case.bad_programs() for p in invalid_problems(case, path)], case)

    def test_garbage_fails_with_located_errors(self, postproc_conformance: DialectUnderTest,
                                               request: pytest.FixtureRequest) -> None:
        case = postproc_conformance
        if case.cls().READER is None:
            pytest.skip(f"{case.name} is write-only: it reads nothing")
        lines = [line for path in case.programs() for line in read_text(path).splitlines()]
        with tempfile.TemporaryDirectory() as tmp:
            @settings(max_examples=max_examples(request), deadline=None, database=None,
                      suppress_health_check=list(HealthCheck))
            @given(text=garbage(lines))
            def check(text: str) -> None:
                _report(garbage_problems(case, text, Path(tmp)), case)

            check()

    def test_capability_flags_match_the_writer(self, postproc_conformance: DialectUnderTest) -> None:
        case = postproc_conformance
        dialect = case.cls()
        if dialect.reads_lathe(case.machine()):
            pytest.skip(f"{case.name}: the probes are milling blocks (the examples are read as a lathe's)")
        rules = [] if not dialect.NATIVE_CYCLES or semantics_named(dialect.CYCLE_SEMANTICS) is not None else [
            f"{case.name}: NATIVE_CYCLES without CYCLE_SEMANTICS ({' or '.join(semantics_names())}): every cycle "
            f"read elsewhere would be expanded for it"]
        _report(rules + [p for probe in PROBES for p in probe_problems(dialect, probe, case.machine())], case)

    def test_translations_verify_or_are_refused(self, postproc_conformance: DialectUnderTest) -> None:
        case = postproc_conformance
        _report([p for path in case.programs() for target in targets(case) for expand in (False, True)
                 for p in cross_problems(case, path, target, expand)], case)

    def test_generated_programs_round_trip(self, postproc_conformance: DialectUnderTest,
                                           request: pytest.FixtureRequest) -> None:
        case = postproc_conformance
        dialect = case.cls()
        lathe = dialect.reads_lathe(case.machine())

        @settings(max_examples=max_examples(request), deadline=None, database=None,
                  suppress_health_check=list(HealthCheck))
        @given(program=neutral_programs(dialect, lathe=lathe))
        def check(program: NeutralProgram) -> None:
            _report(generated_problems(case, program), case)

        check()
