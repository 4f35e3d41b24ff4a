"""Values from users never become code (issue 31, item 1): what a template's ``{{ ... }}`` writes - the input
file's name, ``--define`` values, program and set-up text - stands only inside a passive comment of the target,
made safe for its comment syntax, or the set-up is refused at the template's line. Comments written from
another dialect never become LinuxCNC's active ones."""

from __future__ import annotations

import io
import re
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

from postproc.api import translate
from postproc.syntaxes.comments import CommentSyntax
from postproc.errors import ConfigError, Location
from postproc.plugins import default_registry
from postproc.setup.machine_setup import load_setup
from postproc.output.template_values import CLOSE, OPEN, mark, seal
from postproc.simulate.verify import verify_lines

from tests.support.rs274 import available as rs274_available, run_rs274

ROOT = Path(__file__).resolve().parents[1]
TEMPLATES = ROOT / "examples/setups/fanuc_0i_mf_templates.xml"
DECLARATION = "<?xml version='1.0' encoding='UTF-8'?>\n"
PROGRAM = "G90 G21\nG0 X1. Y2.\nG1 Z-1. F100.\nM30\n"
REGISTRY = default_registry()
HOSTILE = ["x) G0 X-999. (", "X) G0 X999 (", "a\nG0 X-999.", "a\rG0 X-999.", "MSG, hi", " LOGOPEN,/tmp/x",
           "ABORT, stop", "%", "a;G0 X5", "a!b?c~d", "caf\u00e9 \u2014 \u00d8", "\u0085G0 X1", "((x))", ")",
           f"{CLOSE}) G0 X-999. ({OPEN}"]
"""Values that would place a live word, end a comment, make it act or trigger grbl, if written raw."""
COMMENTED = {"fanuc": "(JOB {{ job }})", "linuxcnc": "(JOB {{ job }})", "grbl": "(JOB {{ job }})",
             "isg": "(JOB {{ job }})", "mach3": "(JOB {{ job }})", "fagor": ";JOB {{ job }}"}
"""A header that writes the value inside a comment of each milling target."""


def _setup(tmp_path: Path, header: str, dialect: str = "fanuc") -> Path:
    path = tmp_path / "m.xml"
    path.write_text(DECLARATION + f'<MachineSetup name="vmc" dialect="{dialect}">\n  <Templates>\n'
                    f"    <Header>{header}</Header>\n  </Templates>\n</MachineSetup>\n")
    return path


def _translate(setup: Path, target: str, defines: dict[str, str] | None = None, file: str = "in.nc") -> str:
    out = io.StringIO()
    translate(io.StringIO(PROGRAM), out, file=file, source="fanuc", target=target, setup=load_setup(setup),
              defines=defines or {})
    return out.getvalue()


def _same_toolpath(text: str, target: str, setup: Path) -> None:
    report = verify_lines(io.StringIO(PROGRAM), io.StringIO(text), file_in="in.nc", file_out="out",
                          source="fanuc", target=target, setup=load_setup(setup), tolerance=0.0)
    assert report.ok, report.summary() + "\n" + text


def test_a_file_name_does_not_add_a_move(cli, tmp_path: Path) -> None:
    """The issue's case: a file named ``x) G0 X-999. (.nc`` with the example set-up wrote a live G0 X-999."""
    source = tmp_path / "x) G0 X-999. (.nc"
    source.write_text(PROGRAM)
    result = cli("translate", source, "--from", "fanuc", "--to", "fanuc", "--machine", TEMPLATES)
    assert result.status == 0, result.err
    text = result.out.decode()
    assert "(PROGRAM x] G0 X-999. [ POSTED FOR" in text and "(END OF x] G0 X-999. [)" in text
    _same_toolpath(text, "fanuc", TEMPLATES)


@pytest.mark.parametrize("target", sorted(COMMENTED))
@pytest.mark.parametrize("value", HOSTILE)
def test_a_defined_value_stays_in_its_comment_on_every_target(tmp_path: Path, target: str, value: str) -> None:
    setup = _setup(tmp_path, COMMENTED[target])
    text = _translate(setup, target, {"job": value})
    head = text.splitlines()[0]
    assert head.startswith("(JOB " if target != "fagor" else ";JOB ") and "\n" not in head
    assert OPEN not in text and CLOSE not in text
    if target == "grbl":
        assert text.isascii() and not re.search(r"[?!~]", text), text
    _same_toolpath(text, target, setup)


@pytest.mark.parametrize("header", ["T{{ job }}", "G0 X{{ job }}", "{{ job }}", "(A) {{ job }}",
                                    "{{ '(' ~ job ~ ')' }}"])
def test_a_value_outside_a_comment_is_refused_at_the_template(cli, tmp_path: Path, header: str) -> None:
    setup = _setup(tmp_path, header)
    (tmp_path / "in.nc").write_text(PROGRAM)
    result = cli("translate", tmp_path / "in.nc", "--from", "fanuc", "--to", "fanuc", "--machine", setup,
                 "--define", "job=1")
    assert result.status == 1
    assert result.err.startswith(f"{setup}:4:1: error: template header writes the value ")
    assert "outside a comment" in result.err


def test_config_check_finds_a_value_outside_a_comment(cli, tmp_path: Path) -> None:
    setup = _setup(tmp_path, "(PROGRAM)\nO{{ program }}")
    result = cli("config", "check", setup)
    assert result.status == 1
    assert result.err == (f"{setup}:4:1: error: template header writes the value 'o1001' outside a comment "
                          "(output line 2): values (file names, --define, set-up and program text) are written "
                          "only inside a plain comment, or as a plain number (|int, |float)\n")


def test_a_plain_number_stands_anywhere(tmp_path: Path) -> None:
    setup = _setup(tmp_path, "(T {{ job|int }})\nG4 P{{ job|int }}\n(OK {{ 1.5 }} {{ tools|length }})")
    assert _translate(setup, "fanuc", {"job": "2 G0 X9"}).startswith("(T 0)\nG4 P0\n(OK 1.5 0)\n")


def test_fagor_takes_values_only_in_semicolon_comments(tmp_path: Path) -> None:
    """Parenthesised text is not a confirmed 8070 comment [?]: a value there is refused, by name."""
    with pytest.raises(ConfigError, match="outside a comment"):
        _translate(_setup(tmp_path, "(JOB {{ job }})"), "fagor", {"job": "1"})


def test_a_value_may_not_make_a_linuxcnc_comment_act(tmp_path: Path) -> None:
    """A comment that acts only because of its value gets a '-' at its head; a value in the template's own
    active comment is refused; a value in a ';' comment is inert."""
    text = _translate(_setup(tmp_path, "({{ job }})\n( {{ job }} AND MORE)"), "linuxcnc", {"job": "LOGOPEN,/tmp/x"})
    assert text.startswith("(-LOGOPEN,/tmp/x)\n(- LOGOPEN,/tmp/x AND MORE)\n")
    if rs274_available():
        assert not any("LOGOPEN(" in call for call in run_rs274(text))
    with pytest.raises(ConfigError, match="inside a comment the controller acts on"):
        _translate(_setup(tmp_path, "(MSG, JOB {{ job }})"), "linuxcnc", {"job": "1"})
    text = _translate(_setup(tmp_path, "(MSG, posted)\n; {{ job }}"), "linuxcnc", {"job": "MSG, x"})
    assert text.startswith("(MSG, posted)\n; MSG, x\n")


@pytest.mark.skipif(not rs274_available(), reason="LinuxCNC's rs274 is not installed")
def test_comments_from_another_dialect_do_not_act_in_linuxcnc(tmp_path: Path) -> None:
    """rs274 acted on ``( MSG,`` ``(LOGOPEN,`` ``(ABORT,`` read from Fanuc or ISG comments."""
    source = "G90\n( MSG, hi)\n(debug, x)\n(LOGOPEN,/tmp/never.log)\n(ABORT, stop)\nG0 X1.\nM30\n"
    for dialect in ("fanuc", "isg"):
        out = io.StringIO()
        translate(io.StringIO(source), out, file="in.nc", source=dialect, target="linuxcnc")
        calls = " ".join(run_rs274(out.getvalue()))
        assert "COMMENT(\"- MSG, hi\")" in calls, calls
        assert not re.search(r"\.\.\.\.\. (MESSAGE|LOGOPEN|LOG)\(", calls), calls
        assert "STRAIGHT_TRAVERSE(1.0000" in calls and "PROGRAM_END()" in calls  # not aborted


def test_grbl_writes_no_real_time_character_from_grbl_itself(tmp_path: Path) -> None:
    """A comment copied grbl -> grbl kept its em dash (0x94, a feed override, among its UTF-8 bytes)."""
    out = io.StringIO()
    translate(io.StringIO("G21 G90\nG0 X1 (stop \u2014 now!)\nM30\n"), out, file="in.nc", source="grbl",
              target="grbl")
    assert out.getvalue() == "G21 G90\nG0 X1 (stop - now_)\nM30\n"


@settings(max_examples=300, deadline=None)
@given(value=st.text(max_size=30), head=st.sampled_from(["", "V ", " "]), comments=st.sampled_from([
    CommentSyntax(), CommentSyntax(nested=True, semicolon=True), CommentSyntax(parens=False, semicolon=True),
    CommentSyntax(semicolon=True, active_words=("MSG", "LOGOPEN"))]))
def test_a_sealed_value_is_inside_one_passive_comment(value: str, head: str, comments: CommentSyntax) -> None:
    """Property: whatever the value, the sealed line is one comment from its first character to its end
    (nothing outside it, no line break), and not one the controller acts on."""
    rendered = ("(" if comments.parens else ";") + head + mark(value) + (")" if comments.parens else "")
    line = seal("header", rendered, comments, Location("m.xml", 4, 1))
    assert "\n" not in line and "\r" not in line
    assert comments.comments(line) == [(0, len(line), True)]


def test_a_value_cut_apart_by_a_filter_is_still_a_value() -> None:
    """A stray end mark (a filter reversed or sliced a marked text) counts everything before it as value."""
    with pytest.raises(ConfigError, match="outside a comment"):
        seal("header", "G0 X1" + CLOSE, CommentSyntax(), Location("m.xml", 4, 1))


def test_every_writer_declares_its_comments() -> None:
    """The default knows no comment (every value refused): each installed writer's dialect says how it
    writes comments, so its templates can write values."""
    assert [name for name, d in REGISTRY.dialects.items() if d.WRITER is not None
            and not (d.COMMENTS.parens or d.COMMENTS.semicolon)] == []
