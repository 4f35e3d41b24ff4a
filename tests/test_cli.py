"""The command line: exit status (0 ok, 1 program or configuration errors, 2 wrong usage) and streams."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

import postproc.cli

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
    (["translate", ROOT / "no/such/file.nc", "--from", "fanuc", "--to", "fanuc"], "postproc: cannot read "),
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


def test_a_write_only_dialect_cannot_be_read(cli):
    pytest.importorskip("postproc_example_dialect")
    for args in (["translate", PROGRAM, "--from", "example", "--to", "fanuc"], ["ir", PROGRAM, "--dialect", "example"]):
        result = cli(*args)
        assert (result.status, result.err) == (2, "postproc: the example dialect cannot be read (it is write-only)\n")


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
    pytest.importorskip("postproc_example_dialect")
    path = tmp_path / "orient.nc"
    path.write_text("G21 G90 G00 X0. Y0.\nM19\nM30\n")
    result = cli("translate", path, "--from", "fanuc", "--to", "example", "--on-unsupported", "warn")
    assert result.status == 0
    assert result.err == f"{path}:2:1: warning: the example dialect cannot express an oriented spindle stop; " \
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

    monkeypatch.setattr(postproc.cli, "cmd_dialects", boom)
    monkeypatch.delenv("POSTPROC_DEBUG", raising=False)
    result = cli("dialects")
    assert result.status == 1
    assert result.err == "postproc: internal error: RuntimeError: boom (set POSTPROC_DEBUG=1 for details)\n"


def test_postproc_debug_shows_the_traceback(cli, monkeypatch):
    def boom(args):
        raise RuntimeError("boom")

    monkeypatch.setattr(postproc.cli, "cmd_dialects", boom)
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
