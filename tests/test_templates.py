"""Header and footer templates: sandboxed jinja2, strict about undefined names, errors located in the set-up."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from postproc.errors import ConfigError
from postproc.setup.machine_setup import MachineSetup, Templates, load_setup
from postproc.output.bounded import MEMORY_LIMIT, _mapped_bytes, run_bounded
from postproc.lowering.sequences import check_templates, sample_variables
from postproc.output.templates import MAX_OUTPUT, TIME_LIMIT, render

ROOT = Path(__file__).resolve().parents[1]
DECLARATION = "<?xml version='1.0' encoding='UTF-8'?>\n"


def test_render_substitutes_and_ends_with_a_newline():
    assert render("header", "(PROGRAM {{ program }} FOR {{ machine | upper }})", {"program": "o1", "machine": "vmc"},
                  "m.xml") == "(PROGRAM o1 FOR VMC)\n"


def test_render_keeps_a_trailing_newline_and_adds_none():
    assert render("footer", "(A)\n(B)\n", {}, "m.xml") == "(A)\n(B)\n"


def test_an_empty_template_renders_nothing():
    assert render("footer", "", {}, "m.xml") == ""


def test_control_structures_work_in_the_sandbox():
    text = "{% for t in tools %}(T{{ t }}){% if not loop.last %} {% endif %}{% endfor %}"
    assert render("header", text, {"tools": [1, 2, 3]}, "m.xml") == "(T1) (T2) (T3)\n"


@pytest.mark.parametrize("text, line", [
    ("{{ nope }}", 10),
    ("(A)\n{{ program }} {{ nope }}", 11),
    ("(A)\n(B)\n{% if nope %}x{% endif %}", 12),
    ("{{ program.nope }}", 10),
])
def test_undefined_names_are_errors_at_their_line(text, line):
    with pytest.raises(ConfigError) as info:
        render("header", text, {"program": "o1"}, "m.xml", first_line=10)
    assert info.value.message.startswith("template header: ")
    assert "undefined" in info.value.message or "has no attribute" in info.value.message
    assert (info.value.location.file, info.value.location.line) == ("m.xml", line)


ESCAPES = [
    "{{ ''.__class__.__mro__ }}",
    "{{ ''.__class__.__mro__[1].__subclasses__() }}",
    "{% for c in [].__class__.__base__.__subclasses__() %}{{ c }}{% endfor %}",
    "{{ cycler.__init__.__globals__ }}",
    "{{ lipsum.__globals__['os'] }}",
    "{{ self.__init__.__globals__ }}",
    "{{ program | attr('__class__') }}",
    "{{ '{0.__class__}'.format(program) }}",
    "{{ program.__len__ }}",
]


@pytest.mark.parametrize("expression", ESCAPES)
def test_sandbox_blocks_escapes_with_a_located_error(expression):
    with pytest.raises(ConfigError) as info:
        render("header", "(SAFE LINE)\n" + expression, {"program": "o1"}, "m.xml", first_line=4)
    assert info.value.message.startswith("template header: ")
    assert "unsafe" in info.value.message
    assert str(info.value.location) == "m.xml:5:1"


def test_syntax_errors_are_located():
    with pytest.raises(ConfigError) as info:
        render("footer", "(A)\n{% for %}", {}, "m.xml", first_line=7)
    assert info.value.message.startswith("template footer: ")
    assert str(info.value.location) == "m.xml:8:1"


def test_output_size_is_limited():
    with pytest.raises(ConfigError, match=f"renders more than {MAX_OUTPUT} characters"):
        render("header", "{% for i in range(n) %}{{ 'x' * 1000 }}{% endfor %}", {"n": MAX_OUTPUT // 1000 + 1},
               "m.xml")


@pytest.mark.parametrize("text, message", [
    ("{{ 9**99999999 }}", "exponent 99999999 is larger than 256"),
    ("{% set n = 99999999 %}{{ 2**n }}", "exponent 99999999 is larger than 256"),
    ("{{ 'x' * 10**8 }}", "repetition would make more than"),
    ("{{ [0] * 10**8 }}", "repetition would make more than"),
])
def test_operators_that_exhaust_memory_are_refused(text, message):
    with pytest.raises(ConfigError, match=message):
        render("header", text, {}, "m.xml", 4)


def test_a_runaway_loop_is_stopped(monkeypatch):
    import postproc.output.templates as templates
    monkeypatch.setattr(templates, "TIME_LIMIT", 0.2)
    loops = "{% for i in range(100000) %}{% for j in range(100000) %}{% endfor %}{% endfor %}"
    with pytest.raises(ConfigError, match="ran longer than 0.2 s"):
        render("footer", loops, {}, "m.xml", 7)


def test_small_powers_and_repetitions_still_work():
    assert render("header", "{{ 2**10 }} {{ 'ab' * 3 }}", {}, None) == "1024 ababab\n"


def test_check_templates_points_into_the_setup_file(tmp_path):
    path = tmp_path / "m.xml"
    path.write_text(DECLARATION + '<MachineSetup name="m">\n  <Templates>\n    <Header>(OK)</Header>\n'
                    "    <Footer>(A)\n(B {{ x }\n</Footer>\n  </Templates>\n</MachineSetup>\n")
    setup = load_setup(path)
    with pytest.raises(ConfigError) as info:
        check_templates(setup)
    assert (info.value.location.file, info.value.location.line) == (str(path), 6)


def test_check_templates_accepts_the_example():
    check_templates(load_setup(ROOT / "examples/setups/fanuc_0i_mf_templates.xml"))


def test_check_templates_without_templates():
    check_templates(MachineSetup(templates=Templates()))


# -- through translate -------------------------------------------------------------------------------

def test_translate_writes_header_and_footer_inside_the_tape_marks(cli):
    """Fanuc ignores what comes before the first '%' and after the last: the header and footer belong
    between them, or the control never sees them."""
    result = cli("translate", ROOT / "examples/fanuc/o1003_pocket_and_edge.nc", "--from", "fanuc", "--to", "fanuc",
                 "--machine", ROOT / "examples/setups/fanuc_0i_mf_templates.xml")
    assert result.status == 0, result.err
    lines = result.out.decode().splitlines()
    assert "(MACHINE: VMC 850 - FANUC 0I-MF)" in lines
    assert "(PROGRAM o1003_pocket_and_edge POSTED FOR FANUC 0I-MF VMC 850, IS-B LEAST INCREMENT)" in lines
    assert "(END OF o1003_pocket_and_edge)" in lines
    assert lines[0] == "%" and lines[-1] == "%"


def test_translate_template_errors_point_into_the_setup_file(cli, tmp_path):
    machine = tmp_path / "m.xml"
    machine.write_text(DECLARATION + '<MachineSetup name="m">\n  <Templates>\n'
                       "    <Header>(LINE ONE)\n{{ ''.__class__ }}</Header>\n  </Templates>\n</MachineSetup>\n")
    result = cli("translate", ROOT / "examples/fanuc/o1003_pocket_and_edge.nc", "--from", "fanuc", "--to", "fanuc",
                 "--machine", machine, "-o", tmp_path / "out.nc")
    assert result.status == 1
    assert result.err.startswith(f"{machine}:5:1: error: template header: ")
    assert "unsafe" in result.err
    assert not (tmp_path / "out.nc").exists()


# -- bounded memory and time; every failure located (issue 8) -------------------------------------------

MIB = f" needs more than {MEMORY_LIMIT >> 20} MiB of memory"


@pytest.mark.parametrize("text, message, line", [
    ("(A)\n{{ 'x'|center(10**9) }}", MIB, 5),
    ("(A)\n{{ '%999999999d' % 1 }}", MIB, 5),
    ("(A)\n{{ '%-*s' % (10**9, 'x') }}", MIB, 5),
    ("(A)\n{{ '{:>999999999}'.format(1) }}", MIB, 5),
    ("(A)\n{{ 'x'|indent(10**9) }}", MIB, 5),
    ("{% set ns = namespace(s='x') %}\n{% for i in range(40) %}\n{% set ns.s = ns.s ~ ns.s %}\n{% endfor %}", MIB, 6),
    ("(A)\n{{ range(10**9)|list }}",
     ": Range too big. The sandbox blocks ranges larger than MAX_RANGE (100000).", 5),
    ("(A)\n(B)\n{{ 1/0 }}", ": division by zero", 6),
    ("(A)\n{% include 'other.j2' %}", ": no loader for this environment specified", 5),
    ("(A)\n{% macro f(n) %}{{ f(n + 1) }}{% endmacro %}\n{{ f(1) }}", ": recursion too deep", 5),
    ("{{ 'x'|replace('', 'y' * 1000000)|replace('y', 'yy') }}", f" renders more than {MAX_OUTPUT} characters", 4),
])
def test_every_template_failure_is_a_located_config_error(text: str, message: str, line: int) -> None:
    """These escaped as internal errors or took 3-6 GB; now the set-up file's line and a reason."""
    with pytest.raises(ConfigError) as info:
        render("header", text, {}, "m.xml", first_line=4)
    assert str(info.value) == f"m.xml:{line}:1: error: template header{message}"


def test_the_render_child_stays_within_its_memory_bound() -> None:
    """Counted in bytes: the child's peak resident set never exceeds what it inherited plus the bound
    (``'x'.center(10**9)`` alone needs 1 GB)."""
    inherited = _mapped_bytes()
    outcome = run_bounded(lambda: len("x".center(10**9)), seconds=10.0)
    assert outcome.failure == "memory"
    assert 0 < outcome.peak_rss <= inherited + MEMORY_LIMIT


def test_a_function_that_fits_returns_its_value_from_the_child() -> None:
    outcome = run_bounded(lambda: {"n": len("x".center(1000)), "s": "\udcff"}, seconds=10.0)
    assert (outcome.value, outcome.failure) == ({"n": 1000, "s": "\udcff"}, None)


@pytest.mark.parametrize("footer, line, message", [
    ("(A)\n{{ 1/0 }}", 6, "template footer: division by zero"),
    ("(END {{ nope }})", 5, "template footer: 'nope' is undefined"),
    ("{% if units == 'inch' %}{{ 1/0 }}{% endif %}", 5, "template footer: division by zero"),
])
def test_config_check_renders_the_templates_with_sample_values(cli, tmp_path: Path, footer: str, line: int,
                                                                message: str) -> None:
    """``config check`` only parsed the templates and said ok; a render error surfaced at translation."""
    path = tmp_path / "m.xml"
    path.write_text(DECLARATION + '<MachineSetup name="m">\n  <Templates>\n    <Header>(OK {{ program }})</Header>\n'
                    f"    <Footer>{footer}</Footer>\n  </Templates>\n</MachineSetup>\n")
    result = cli("config", "check", path)
    assert (result.status, result.err) == (1, f"{path}:{line}:1: error: {message}\n")


def test_sample_values_cover_every_variable_the_writer_passes() -> None:
    """``config check`` renders with exactly the names a translation passes (tools included), and the block
    templates with the names of a tool change too."""
    from postproc.errors import Diagnostics
    from postproc.plugins import default_registry
    from postproc.lowering.sequences import Sequences
    fanuc = default_registry().dialect("fanuc")
    sequences = Sequences(fanuc.context("o1.nc", MachineSetup(), Diagnostics()), "fanuc", fanuc)
    sequences.tools = []
    names = set(sequences.variables())
    assert names == {"program", "source_file", "source_dialect", "target_dialect", "machine", "units", "date",
                     "setup", "tools"}
    assert all(set(v) == names for v in sample_variables(MachineSetup()))
    assert {v["units"] for v in sample_variables(MachineSetup())} == {"mm", "inch"}
    block_names = names | {"tool", "previous_tool", "operation", "line", "name", "first_use"}
    assert all(set(v) == block_names for v in sample_variables(MachineSetup(), "tool_change"))


# -- every command bounds its rendering (issue 31, item 11) -------------------------------------------------

_MEASURED = """
import resource, subprocess, sys, time
start = time.monotonic()
done = subprocess.run([sys.executable, "-m", "postproc", *sys.argv[1:]], capture_output=True, text=True)
print(done.returncode, time.monotonic() - start, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024)
print(done.stderr, end="")
"""
"""Runs a postproc command and reports its status, seconds and the peak resident set of it and its children."""


@pytest.mark.parametrize("command", ["translate", "batch", "check"])
def test_every_command_renders_within_the_bounds(tmp_path: Path, command: str) -> None:
    """``config check`` stopped ``'x'|center(10**9)`` at the bound; ``translate`` was reported to take 3 GB and
    30 s first. Measured from outside: the command's whole process tree, not the child alone."""
    machine = tmp_path / "m.xml"
    machine.write_text(DECLARATION + '<MachineSetup name="m">\n  <Templates>\n'
                       "    <Header>(A)\n{{ 'x'|center(10**9) }}</Header>\n  </Templates>\n</MachineSetup>\n")
    programs = tmp_path / "in"
    programs.mkdir()
    for name in ("a.nc", "b.nc"):
        (programs / name).write_text("G0 X1. Y2.\n")
    args = {"translate": ["translate", programs / "a.nc", "--from", "fanuc", "--to", "fanuc", "--machine", machine],
            "batch": ["translate", programs, "--from", "fanuc", "--to", "fanuc", "--machine", machine, "-j", "2",
                      "-o", tmp_path / "out"],
            "check": ["config", "check", machine]}[command]
    done = subprocess.run([sys.executable, "-c", _MEASURED, *map(str, args)], capture_output=True, text=True,
                          cwd=ROOT, timeout=120)
    status, seconds, peak = done.stdout.splitlines()[0].split()
    assert int(status) == 1
    assert f"{machine}:5:1: error: template header{MIB}" in done.stdout
    assert float(seconds) < TIME_LIMIT + 10
    assert int(peak) < MEMORY_LIMIT + (256 << 20)
