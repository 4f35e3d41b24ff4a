"""The command line: exit status (0 ok, 1 program or configuration errors, 2 wrong usage) and streams."""

from __future__ import annotations

import argparse
import io
import os
import subprocess
import sys
from pathlib import Path

import pytest

import postproc.commands.command_line
import postproc.commands.dialect_table
import postproc.commands.progress

ROOT = Path(__file__).resolve().parents[1]
PROGRAM = ROOT / "examples/fanuc/o1003_pocket_and_edge.nc"


USAGE = [
    # (arguments, a fragment of what stderr must say)
    ([], "usage: postproc"),
    (["frobnicate"], "invalid choice: 'frobnicate'"),
    (["translate", PROGRAM, "--from", "fanuc"], "the following arguments are required: --to"),
    (["translate", PROGRAM, "--to", "fanuc"], "the following arguments are required: --from"),
    (["translate", PROGRAM, "--from", "fanuc", "--to", "nope"], "postproc: unknown dialect 'nope' (installed: "),
    (["translate", PROGRAM, "--from", "nope", "--to", "fanuc"], "postproc: unknown dialect 'nope' (installed: "),
    (["translate", PROGRAM, "--from", "fanuc", "--to", "fanuc", "--on-unsupported", "maybe"],
     "invalid choice: 'maybe'"),
    (["translate", PROGRAM, "--from", "fanuc", "--to", "fanuc", "--renumber", "ten"],
     "postproc: --renumber takes START[,STEP], got 'ten'"),
    (["translate", PROGRAM, "--from", "fanuc", "--to", "fanuc", "--renumber", "10,0"],
     "postproc: --renumber takes START[,STEP], got '10,0'"),
    # START 0 asks for nothing the set-up can say (its renumberStart 0 keeps the numbers): before, exit 0 with the
    # numbers as written (same dialect) or numbered from STEP (between dialects)
    (["translate", PROGRAM, "--from", "fanuc", "--to", "fanuc", "--renumber", "0"],
     "postproc: --renumber numbers the blocks from START, at least 1, got '0'"),
    (["translate", PROGRAM, "--from", "fanuc", "--to", "linuxcnc", "--renumber", "0,5"],
     "postproc: --renumber numbers the blocks from START, at least 1, got '0,5'"),
    (["translate", PROGRAM, PROGRAM, "--from", "fanuc", "--to", "fanuc", "--renumber", "0", "-o", ROOT / "no/such"],
     "postproc: --renumber numbers the blocks from START, at least 1, got '0'"),
    (["translate", PROGRAM, "--from", "fanuc", "--to", "fanuc", "--renumber="],
     "postproc: --renumber takes START[,STEP], got ''"),
    (["translate", ROOT / "no/such/file.nc", "--from", "fanuc", "--to", "fanuc"], "postproc: cannot read "),
    # A set-up file named on the command line that cannot be read is usage, as an input is (docs/cli.md)
    (["translate", PROGRAM, "--from", "fanuc", "--to", "fanuc", "--machine", ROOT / "no/such/m.xml"],
     "postproc: cannot read "),
    (["toolpath", PROGRAM, "--dialect", "fanuc", "--machine", ROOT / "no/such/m.xml"], "postproc: cannot read "),
    (["verify", PROGRAM, PROGRAM, "--from", "fanuc", "--to", "fanuc", "--target-machine", ROOT / "no/such/m.xml"],
     "postproc: cannot read "),
    (["config", "check", ROOT / "no/such/m.xml"], "postproc: cannot read "),
    (["translate", PROGRAM, PROGRAM, "-o", ROOT / "no/such/out", "--from", "fanuc", "--to", "fanuc", "--machine",
      ROOT / "no/such/m.xml"], "postproc: cannot read "),
    (["ir", PROGRAM, "--dialect", "nope"], "postproc: unknown dialect 'nope'"),
    (["ir", PROGRAM], "the following arguments are required: --dialect"),
    (["config", "frob", "m.xml"], "invalid choice: 'frob'"),
    (["config", "check"], "the following arguments are required: file"),
]


def _usage_id(args: list[object]) -> str:
    return " ".join(a.name if isinstance(a, Path) else str(a) for a in args) or "<none>"


@pytest.mark.parametrize("args, fragment", USAGE, ids=[_usage_id(u[0]) for u in USAGE])
def test_wrong_usage_exits_2(cli, args, fragment):
    result = cli(*args)
    assert result.status == 2
    assert fragment in result.err
    assert result.out == b""


@pytest.mark.parametrize("command", [[], ["translate"], ["toolpath"], ["ir"], ["config"]])
def test_help_has_one_examples_heading(cli, command):
    result = cli(*command, "--help")
    assert result.status == 0
    text = result.out.decode()
    assert text.count("examples:") + text.count("example:") == 1, text


def test_a_write_only_dialect_cannot_be_read(cli, monkeypatch):
    """The example plugin reads since it became the mach3 dialect: a write-only toy stands in for it."""
    from postproc import plugins
    from postproc.dialect import Dialect
    from postproc.rs274.writer import WordWriter

    class WriteOnly(Dialect):
        NAME = "writeonly"
        WRITER = WordWriter

    registry = plugins.default_registry()
    monkeypatch.setitem(registry.dialects, "writeonly", WriteOnly)
    for args in (["translate", PROGRAM, "--from", "writeonly", "--to", "fanuc"], ["ir", PROGRAM, "--dialect", "writeonly"]):
        result = cli(*args)
        assert (result.status, result.err) == (2, "postproc: the writeonly dialect cannot be read (it is write-only)\n")


def test_output_into_a_missing_directory_is_a_clear_error(cli, tmp_path):
    out = tmp_path / "missing" / "out.nc"
    result = cli("translate", PROGRAM, "--from", "fanuc", "--to", "fanuc", "-o", out)
    assert result.status == 2
    assert str(out) in result.err
    assert "internal error" not in result.err


def test_success_writes_only_the_program(cli):
    result = cli("translate", PROGRAM, "--from", "fanuc", "--to", "fanuc")
    assert (result.status, result.err) == (0, "")
    assert result.out == PROGRAM.read_bytes()


def test_output_file_replaces_an_older_one(cli, tmp_path):
    out = tmp_path / "out.nc"
    out.write_text("old\n")
    result = cli("translate", PROGRAM, "--from", "fanuc", "--to", "fanuc", "-o", out)
    assert (result.status, result.out) == (0, b"")
    assert out.read_bytes() == PROGRAM.read_bytes()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.nc"]


def test_warnings_go_to_stderr_and_keep_status_0(cli, tmp_path):
    pytest.importorskip("postproc_mach3")
    path = tmp_path / "orient.nc"
    path.write_text("G21 G90 G00 X0. Y0.\nM19\nM30\n")
    result = cli("translate", path, "--from", "fanuc", "--to", "mach3", "--on-unsupported", "warn")
    assert result.status == 0
    assert result.err == f"{path}:2:1: warning: the mach3 dialect cannot express an oriented spindle stop; " \
                         "written as a comment\n"
    assert result.out.decode().splitlines()[1] == "(UNSUPPORTED LINE 2: M19)"


def test_errors_exit_1_with_nothing_on_stdout(cli, tmp_path):
    path = tmp_path / "bad.nc"
    path.write_text("G21 G90\nG999\n")
    result = cli("translate", path, "--from", "fanuc", "--to", "fanuc")
    assert (result.status, result.out) == (1, b"")
    assert result.err == f"{path}:2:1: error: unknown G code G999\n"


def test_ir_to_a_file(cli, tmp_path):
    out = tmp_path / "ir.xml"
    result = cli("ir", PROGRAM, "--dialect", "fanuc", "-o", out)
    assert (result.status, result.out, result.err) == (0, b"", "")
    assert out.read_bytes().startswith(b"<?xml version='1.0' encoding='UTF-8'?>\n<Program dialect=\"fanuc\"")


def test_internal_errors_are_reported_briefly(cli, monkeypatch):
    def boom(args):
        raise RuntimeError("boom")

    monkeypatch.setattr(postproc.commands.dialect_table, "cmd_dialects", boom)
    monkeypatch.delenv("POSTPROC_DEBUG", raising=False)
    result = cli("dialects")
    assert result.status == 1
    assert result.err == "postproc: internal error: RuntimeError: boom (set POSTPROC_DEBUG=1 for details)\n"


def test_postproc_debug_shows_the_traceback(cli, monkeypatch):
    def boom(args):
        raise RuntimeError("boom")

    monkeypatch.setattr(postproc.commands.dialect_table, "cmd_dialects", boom)
    monkeypatch.setenv("POSTPROC_DEBUG", "1")
    with pytest.raises(RuntimeError, match="boom"):
        cli("dialects")


def _run(*args: object) -> subprocess.CompletedProcess[bytes]:
    env = {k: v for k, v in os.environ.items() if k != "POSTPROC_DEBUG"}
    return subprocess.run([sys.executable, "-m", "postproc", *map(str, args)], capture_output=True, env=env,
                          cwd=ROOT, timeout=120)


@pytest.mark.parametrize("args, status", [
    (["translate", PROGRAM, "--from", "fanuc", "--to", "fanuc"], 0),
    (["translate", ROOT / "tests/golden/fanuc/invalid/unknown_g_code.nc", "--from", "fanuc", "--to", "fanuc"], 1),
    (["translate", PROGRAM, "--from", "fanuc"], 2),
    ([], 2),
])
def test_exit_status_of_the_real_process(args, status):
    assert _run(*args).returncode == status


def test_the_real_process_writes_bytes_unchanged():
    path = ROOT / "tests/golden/fanuc/roundtrip/non_utf8_comment.nc"
    done = _run("translate", path, "--from", "fanuc", "--to", "fanuc")
    assert (done.returncode, done.stdout) == (0, path.read_bytes())


@pytest.mark.parametrize("command", [["ir", "--dialect", "fanuc"], ["translate", "--from", "fanuc", "--to", "fanuc"]],
                         ids=["ir", "translate"])
def test_a_closed_stdout_is_not_an_error(tmp_path, command):
    """``postproc ir big.nc | head`` ends quietly with status 0 (the output is larger than a pipe holds)."""
    big = tmp_path / "big.nc"
    big.write_text("G21 G90 G00 X0. Y0.\n" + "".join(f"N{i} X{i}. Y{i % 7}.\n" for i in range(1, 20001)))
    env = {k: v for k, v in os.environ.items() if k != "POSTPROC_DEBUG"}
    proc = subprocess.Popen([sys.executable, "-m", "postproc", command[0], big, *command[1:]],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, cwd=ROOT)
    assert proc.stdout is not None
    proc.stdout.read(10)
    proc.stdout.close()
    _, err = proc.communicate(timeout=120)
    assert (proc.returncode, err) == (0, b"")


# -- issue 12, item 7: standard streams, help, the console script, the progress bar ------------------

def _run_input(data: bytes, *args: object, stderr: object = subprocess.PIPE) -> subprocess.CompletedProcess[bytes]:
    env = {k: v for k, v in os.environ.items() if k != "POSTPROC_DEBUG"}
    return subprocess.run([sys.executable, "-m", "postproc", *map(str, args)], input=data, stdout=subprocess.PIPE,
                          stderr=stderr, env=env, cwd=ROOT, timeout=120)  # type: ignore[call-overload,no-any-return]


def test_dash_reads_standard_input_and_writes_standard_output_byte_for_byte():
    data = PROGRAM.read_bytes()
    done = _run_input(data, "translate", "-", "--from", "fanuc", "--to", "fanuc", "-o", "-")
    assert (done.returncode, done.stdout, done.stderr) == (0, data, b"")


def test_errors_in_standard_input_are_located_in_stdin():
    done = _run_input(b"G21\nG01 X1. Y1.\n", "translate", "-", "--from", "fanuc", "--to", "grbl")
    assert done.returncode == 1 and done.stdout == b""
    assert done.stderr.decode() == "<stdin>:2:1: error: a feed move with no feed rate (program F first)\n"


def test_toolpath_and_verify_read_standard_input(tmp_path):
    grbl = tmp_path / "o.gcode"
    assert _run("translate", PROGRAM, "--from", "fanuc", "--to", "grbl", "--on-unsupported", "warn",
                "--machine", ROOT / "tests/support/zero_tools.xml", "-o", grbl).returncode == 0
    done = _run_input(PROGRAM.read_bytes(), "verify", "-", grbl, "--from", "fanuc", "--to", "grbl",
                     "--machine", ROOT / "tests/support/zero_tools.xml",
                     "--allow-ignored")  # grbl has no cutter compensation: the setting is left out
    assert done.returncode == 0 and done.stdout.decode().startswith("max deviation 0.0000 mm")
    path = _run_input(grbl.read_bytes(), "toolpath", "-", "--dialect", "grbl")
    assert path.returncode == 0 and path.stdout.startswith(b'{"toolpath": 1, "units": "mm", "dialect": "grbl"}\n')
    both = _run_input(b"", "verify", "-", "-", "--from", "fanuc", "--to", "grbl")
    assert both.returncode == 2 and b"at most one of IN and OUT" in both.stderr


def test_output_from_standard_input_is_written_with_the_umask(tmp_path):
    out = tmp_path / "o.nc"
    env = {k: v for k, v in os.environ.items() if k != "POSTPROC_DEBUG"}
    done = subprocess.run(["sh", "-c", f'umask 027 && exec "$0" -m postproc translate - --from fanuc --to fanuc -o "$1"',
                           sys.executable, str(out)], input=b"G00 X1.\n", env=env, cwd=ROOT, timeout=120)
    assert done.returncode == 0 and oct(out.stat().st_mode & 0o777) == oct(0o640)


@pytest.mark.parametrize("command", ["translate", "toolpath", "verify", "ir", "dialects", "config"])
def test_help_describes_every_option_and_shows_an_example(cli, command):
    parser = postproc.commands.command_line.build_parser()
    sub = next(a for a in parser._actions if isinstance(a, argparse._SubParsersAction)).choices[command]
    for action in sub._actions:
        assert action.help, f"{command}: {action.dest} has no description"
    result = cli(command, "--help")
    text = result.out.decode()
    assert result.status == 0 and "example" in text and f"postproc {command} " in text.split("example", 1)[1]
    top = cli("--help").out.decode()
    assert command in top


@pytest.mark.parametrize("columns", [None, "", "abc", "0", "-3", "37", "120"])
def test_help_is_as_wide_as_argparse_would_make_it(monkeypatch, columns):
    """The formatter sizes itself without shutil (``command_line._columns``), as argparse does with it."""
    import shutil
    if columns is None:
        monkeypatch.delenv("COLUMNS", raising=False)
    else:
        monkeypatch.setenv("COLUMNS", columns)
    assert postproc.commands.command_line._columns() == shutil.get_terminal_size().columns
    ours = postproc.commands.command_line.build_parser().format_help()
    monkeypatch.setattr(postproc.commands.command_line, "_Formatter", argparse.RawDescriptionHelpFormatter)
    assert ours == postproc.commands.command_line.build_parser().format_help()


def test_the_console_script_is_installed_beside_the_interpreter():
    """``make install``/``make run`` put ``postproc`` in ``.venv/bin`` (README: ``. .venv/bin/activate``)."""
    script = Path(sys.executable).parent / "postproc"
    assert script.exists()
    done = subprocess.run([str(script), "--help"], capture_output=True, timeout=120)
    assert done.returncode == 0 and done.stdout.startswith(b"usage: postproc")


def _long_program(path: Path, lines: int = 80_000) -> None:
    path.write_text("G21 G90 G00 X0. Y0. Z5.\nG01 F500.\n" + "".join(f"X{i % 97}.125 Y{i % 89}.5\n" for i in range(lines)))


def test_a_long_file_shows_a_progress_bar_on_a_terminal_and_erases_it(tmp_path):
    import pty
    big = tmp_path / "big.nc"
    _long_program(big)
    assert big.stat().st_size >= postproc.commands.progress.MIN_BYTES
    parent, child = pty.openpty()
    try:
        done = _run_input(b"", "translate", big, "--from", "fanuc", "--to", "grbl", "-o", tmp_path / "o.gcode",
                          stderr=child)
        os.close(child)
        child = -1
        shown = b""
        while True:
            try:
                chunk = os.read(parent, 65536)
            except OSError:
                break
            if not chunk:
                break
            shown += chunk
    finally:
        if child >= 0:
            os.close(child)
        os.close(parent)
    assert done.returncode == 0
    assert b"\rpostproc: big.nc [" in shown and b"lines" in shown
    assert shown.endswith(b"\r\x1b[K")  # erased: nothing is left on the screen


def test_no_progress_bar_when_standard_error_is_not_a_terminal(tmp_path):
    big = tmp_path / "big.nc"
    _long_program(big)
    done = _run("translate", big, "--from", "fanuc", "--to", "grbl", "-o", tmp_path / "o.gcode")
    assert (done.returncode, done.stderr) == (0, b"")


def test_a_short_file_gets_no_bar_even_on_a_terminal(tmp_path):
    class Tty(io.StringIO):
        def isatty(self) -> bool:
            return True

    assert postproc.commands.progress.progress_for(str(PROGRAM), Tty()) is None
    big = tmp_path / "big.nc"
    _long_program(big)
    assert postproc.commands.progress.progress_for(str(big), Tty()) is not None
    assert postproc.commands.progress.progress_for("-", Tty()) is None
    assert postproc.commands.progress.progress_for(str(big), io.StringIO()) is None


# -- issue 12, item 6: error reports a person can act on ----------------------------------------------

def test_errors_that_follow_from_a_refused_line_are_left_out_and_counted(cli, tmp_path):
    prog = tmp_path / "p.nc"
    prog.write_text("G21 G90 G0 X0 Y0 Z10.\nG1 X1. F1.2.3\nG1 X2.\nG1 X3.\nM30\n")
    result = cli("translate", prog, "--from", "linuxcnc", "--to", "grbl")
    assert result.status == 1
    assert result.err_lines == [f"{prog}:2:12: error: number without an address at '.3'",
                                "postproc: 2 more error(s) left out: they follow from the refused line 2, whose F "
                                "never took effect"]


def test_a_feed_error_after_a_refused_line_without_f_is_reported(cli, tmp_path):
    prog = tmp_path / "p.nc"
    prog.write_text("G21 G90 G0 X0 Y0 Z10.\nG0 X1..2\nG1 X2.\nM30\n")
    result = cli("translate", prog, "--from", "linuxcnc", "--to", "grbl")
    assert result.status == 1 and len(result.err_lines) == 2
    assert result.err_lines[1] == f"{prog}:3:1: error: G1 with no feed rate in force (program F first)"


def test_the_error_cap_says_that_it_cut_the_list(cli, tmp_path):
    prog = tmp_path / "p.nc"
    prog.write_text("G21\n" + "G999\n" * 60)
    result = cli("translate", prog, "--from", "fanuc", "--to", "fanuc")
    assert result.status == 1
    assert len([line for line in result.err_lines if ": error: " in line]) == 50
    assert result.err_lines[-1] == "postproc: stopped at 50 errors: the rest of the program was not checked"


@pytest.mark.parametrize("text", ["", "%\n(ONLY A COMMENT)\n%\n", "\n\n"])
def test_an_empty_program_gets_a_warning(cli, tmp_path, text):
    prog = tmp_path / "p.nc"
    prog.write_text(text)
    for args in (["translate", prog, "--from", "fanuc", "--to", "grbl"], ["toolpath", prog, "--dialect", "fanuc"]):
        result = cli(*args)
        assert result.status == 0
        assert result.err_lines == [f"{prog}:1:1: warning: the program is empty: no line in it programs anything"]
    assert cli("translate", PROGRAM, "--from", "fanuc", "--to", "fanuc").err == ""
