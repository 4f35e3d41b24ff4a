"""``postproc translate`` over many files: every output is the single-file command's output for that file,
one file's failure is that file's alone, the exit status is the worst file's, nothing is half-written."""

from __future__ import annotations

import io
import os
import json
import shutil
from pathlib import Path

import pytest

from postproc.commands.batch.plan import chunks, plan_jobs
from postproc.commands.batch.progress import BatchProgress
from postproc.errors import UsageError

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = sorted((ROOT / "examples/fanuc").glob("*.nc"))
BAD = "G0 X1.\nG1 X2. Q\nM30\n"
"""Line 2 has an address without a value: a located error at 2:8."""
PLAIN = "G21 G90 G17\nG0 X0. Y0. Z5.\nG1 Z-1. F100.\nG1 X10. Y5.\nG0 Z5.\nM30\n"
"""A program grbl runs as it is (no tool length offset, no cycle)."""


@pytest.fixture
def tree(tmp_path: Path) -> Path:
    """``progs/`` with the Fanuc examples, one of them again in ``sub/``, and a hidden file."""
    progs = tmp_path / "progs"
    (progs / "sub").mkdir(parents=True)
    for path in EXAMPLES:
        shutil.copy(path, progs / path.name)
    shutil.copy(EXAMPLES[0], progs / "sub" / "again.nc")
    (progs / ".editor-backup.nc").write_text(BAD)
    return progs


def single(cli, path: Path, *options: object) -> bytes:
    """The single-file command's output for ``path`` (the contract a batch output must equal)."""
    result = cli("translate", path, *options)
    assert result.status == 0, result.err
    return result.out


def report_lines(path: Path) -> list[dict[str, object]]:
    return [json.loads(line) for line in path.read_text().splitlines()]


def leftovers(folder: Path) -> list[Path]:
    return sorted(p for p in folder.rglob("*") if p.name.startswith(".postproc-"))


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_each_output_is_the_single_file_translation(cli, tree, tmp_path, jobs):
    out = tmp_path / "out"
    options = ("--from", "fanuc", "--to", "linuxcnc")
    result = cli("translate", tree, "-o", out, *options, "--ext", "ngc", "--jobs", jobs, "--files-per-task", "2")
    assert result.status == 0, result.err
    written = sorted(p.relative_to(out).as_posix() for p in out.rglob("*") if p.is_file())
    assert written == sorted([p.stem + ".ngc" for p in EXAMPLES] + ["sub/again.ngc"])
    for path in EXAMPLES:
        assert (out / (path.stem + ".ngc")).read_bytes() == single(cli, path, *options), path.name
    assert (out / "sub/again.ngc").read_bytes() == single(cli, EXAMPLES[0], *options)


def test_one_bad_file_is_reported_and_stops_nothing(cli, tree, tmp_path):
    (tree / "sub" / "bad.nc").write_text(BAD)
    out = tmp_path / "out"
    (out / "sub").mkdir(parents=True)
    (out / "sub" / "bad.nc").write_text("an older translation\n")
    report = tmp_path / "report.jsonl"
    result = cli("translate", tree, "-o", out, "--from", "fanuc", "--to", "fanuc", "--report", report, "--jobs", "2")
    assert result.status == 1
    bad_name = f"{tree}/sub/bad.nc"
    assert f"{bad_name}:2:8: error: address Q needs a value" in result.err_lines
    assert (out / "sub" / "bad.nc").read_text() == "an older translation\n"  # not replaced by a failure
    for path in EXAMPLES:
        assert (out / path.name).read_bytes() == path.read_bytes()  # fanuc -> fanuc: byte for byte
    lines = report_lines(report)
    assert sorted(line["file"] for line in lines) == sorted(
        [f"{tree}/{p.name}" for p in EXAMPLES] + [f"{tree}/sub/again.nc", bad_name])
    bad = next(line for line in lines if line["file"] == bad_name)
    assert (bad["status"], bad["exit"], bad["errors"]) == ("error", 1, [f"{bad_name}:2:8: error: address Q needs a value"])
    assert bad["blocks"] == 3
    good = [line for line in lines if line["file"] != bad_name]
    assert {(line["status"], line["exit"]) for line in good} == {("ok", 0)}
    assert all(line["blocks"] > 0 and line["seconds"] >= 0 for line in good)
    summary = result.out.decode()
    assert f"of {len(lines)} files from fanuc to fanuc" in summary
    assert f"  {bad_name}:2:8: error: address Q needs a value" in summary.splitlines()
    assert leftovers(out) == []


def test_the_exit_status_is_the_worst_files(cli, tree, tmp_path):
    out = tmp_path / "out"
    (out / "o1001_plate_drill_tap.nc").mkdir(parents=True)  # this output cannot be written: usage, exit 2
    (tree / "bad.nc").write_text(BAD)  # errors: exit 1
    report = tmp_path / "report.jsonl"
    result = cli("translate", tree, "-o", out, "--from", "fanuc", "--to", "fanuc", "--report", report)
    assert result.status == 2
    status = {Path(str(line["file"])).name: (line["status"], line["exit"]) for line in report_lines(report)}
    assert status["o1001_plate_drill_tap.nc"] == ("usage", 2)
    assert status["bad.nc"] == ("error", 1)
    assert status["o1003_pocket_and_edge.nc"] == ("ok", 0)
    assert (out / "o1003_pocket_and_edge.nc").exists()


def test_verify_writes_only_what_verifies(cli, tree, tmp_path):
    """An oriented spindle stop (M19) reaches grbl, which has none, as a dropped word (--on-unsupported
    warn): verification fails on the orientation left out, and that output is not written, even with
    --allow-ignored (a move of the machine, not a setting). A Fanuc G41 reaches grbl as the compensated path
    (Fanuc's rules are modelled), and verifies. o1001's G43 H offsets are written as G43.1 with the
    machine's lengths, and verify, long tools or not."""
    plain = tmp_path / "plain.nc"
    plain.write_text(PLAIN)
    compensated = tmp_path / "edge.nc"
    compensated.write_text("G21 G90 G00 X-10. Y0. Z5.\nG41 D01 G01 X0. F100.\nG01 Y20.\nG40 G01 X-10.\nM30\n")
    oriented = tmp_path / "oriented.nc"
    oriented.write_text("G21 G90 G00 X-10. Y0. Z5.\nG01 X0. F100. M19\nG01 Y20.\nM30\n")
    out, report = tmp_path / "out", tmp_path / "report.jsonl"
    support = Path(__file__).resolve().parent / "support"
    args = ("translate", tree / "o1001_plate_drill_tap.nc", plain, compensated, oriented, "-o", out,
            "--from", "fanuc", "--to", "grbl", "--on-unsupported", "warn", "--verify", "--report", report)
    result = cli(*args, "--machine", support / "long_tools.xml")
    assert result.status == 1
    lines = {Path(str(line["file"])).name: line for line in report_lines(report)}
    failed = lines["oriented.nc"]
    assert (failed["status"], failed["exit"]) == ("verify", 1)
    assert "spindle orientation" in str(failed["verify"])
    assert failed["warnings"] and "oriented spindle stop" in str(failed["warnings"][0])  # type: ignore[index]
    assert not (out / "oriented.nc").exists()
    for name in ("o1001_plate_drill_tap.nc", "plain.nc", "edge.nc"):
        assert (lines[name]["status"], lines[name]["max_deviation"]) == ("ok", 0.0), lines[name]
        assert str(lines[name]["verify"]).endswith(": ok")
    assert [line.split()[-1] for line in (out / "o1001_plate_drill_tap.nc").read_text().splitlines()
            if "G43.1" in line] == ["Z101.", "Z102.", "Z103."]  # long_tools.xml: tool n is 100 + n mm
    assert (out / "plain.nc").read_bytes() == single(
        cli, plain, "--from", "fanuc", "--to", "grbl", "--on-unsupported", "warn")

    result = cli(*args, "--machine", support / "zero_tools.xml", "--allow-ignored")
    assert result.status == 1, result.err
    assert (out / "edge.nc").exists() and not (out / "oriented.nc").exists()
    assert {Path(str(line["file"])).name: line["status"] for line in report_lines(report)}["oriented.nc"] == "verify"
    assert leftovers(out) == []


def test_a_named_file_and_the_include_filter(cli, tree, tmp_path):
    (tree / "notes.txt").write_text("not a program\n")
    out = tmp_path / "out"
    result = cli("translate", tree, EXAMPLES[1], "-o", out, "--from", "fanuc", "--to", "fanuc", "--include", "o100[13]*",
                 "--include", "again.*")
    # EXAMPLES[1] is named directly and would be written to out/<its name>, as its copy in progs/ would be,
    # but the filter leaves that copy out: no collision.
    assert result.status == 0, result.err
    names = sorted(p.relative_to(out).as_posix() for p in out.rglob("*") if p.is_file())
    assert names == sorted(["o1001_plate_drill_tap.nc", "o1003_pocket_and_edge.nc", EXAMPLES[1].name, "sub/again.nc"])


def test_a_second_run_does_not_take_its_own_outputs_as_inputs(cli, tree):
    out = tree / "translated"
    for _ in range(2):
        result = cli("translate", tree, "-o", out, "--from", "fanuc", "--to", "fanuc")
        assert result.status == 0, result.err
    assert not (out / "translated").exists()
    assert sorted(p.name for p in out.iterdir()) == sorted([p.name for p in EXAMPLES] + ["sub"])


BATCH_USAGE = [
    # (arguments after "translate", with {tree} and {out}; a fragment of the message)
    (["{tree}", "--from", "fanuc", "--to", "fanuc"], "needs -o OUTDIR, a folder"),
    (["{tree}", "-o", "-", "--from", "fanuc", "--to", "fanuc"], "needs -o OUTDIR, a folder"),
    (["{tree}", "-", "-o", "{out}", "--from", "fanuc", "--to", "fanuc"], "'-' (standard input) cannot be one of"),
    (["{tree}/sub", "{tree}/sub/again.nc", "-o", "{out}", "--from", "fanuc", "--to", "fanuc"],
     "would both be written to"),
    (["{tree}", "-o", "{tree}", "--from", "fanuc", "--to", "fanuc"], "the output folder cannot be an input folder"),
    (["{tree}/sub/again.nc", "-o", "{tree}/sub", "--from", "fanuc", "--to", "fanuc", "--jobs", "1"],
     "would overwrite the input"),
    (["{tree}", "-o", "{tree}/o1001_plate_drill_tap.nc", "--from", "fanuc", "--to", "fanuc"],
     "a batch writes into a folder, and this is a file"),
    (["{tree}", "-o", "{out}", "--from", "fanuc", "--to", "fanuc", "--in-place"], "--in-place replaces one file"),
    (["{tree}", "-o", "{out}", "--from", "fanuc", "--to", "nope"], "unknown dialect 'nope'"),
    (["{tree}", "-o", "{out}", "--from", "fanuc", "--to", "fanuc", "--tolerance", "0.1"],
     "--tolerance and --allow-ignored go with --verify"),
    (["{tree}", "-o", "{out}", "--from", "fanuc", "--to", "fanuc", "--scheduler", "somewhere"],
     "--scheduler takes 'local' or an address"),
    (["{tree}/missing", "-o", "{out}", "--from", "fanuc", "--to", "fanuc"], "cannot read"),
    (["{tree}/sub", "-o", "{out}", "--from", "fanuc", "--to", "fanuc", "--include", "*.ngc"], "no files to translate"),
    (["{tree}", "-o", "{out}", "--from", "fanuc", "--to", "fanuc", "--jobs", "0"], "must be at least 1"),
]


@pytest.mark.parametrize("args, fragment", BATCH_USAGE, ids=[" ".join(a[0][:1] + a[0][-2:]) for a in BATCH_USAGE])
def test_batch_usage_errors_touch_nothing(cli, tree, tmp_path, args, fragment):
    out = tmp_path / "out"
    result = cli("translate", *(a.format(tree=tree, out=out) for a in args))
    assert result.status == 2
    assert fragment in result.err
    assert not out.exists()
    assert result.out == b""


def test_one_file_without_batch_options_keeps_the_single_file_contract(cli, tmp_path):
    out = tmp_path / "one.nc"
    result = cli("translate", EXAMPLES[0], "-o", out, "--from", "fanuc", "--to", "fanuc")
    assert (result.status, result.out, result.err) == (0, b"", "")
    assert out.read_bytes() == EXAMPLES[0].read_bytes()


def test_plan_keeps_paths_relative_to_each_folder(tree, tmp_path):
    jobs = plan_jobs([str(tree), str(EXAMPLES[2])], str(tmp_path / "o"), ext=".ngc", include=["again.nc"])
    assert [(job.name, job.output_name) for job in jobs] == [
        (f"{tree}/sub/again.nc", f"{tmp_path}/o/sub/again.ngc"),
        (str(EXAMPLES[2]), f"{tmp_path}/o/{EXAMPLES[2].stem}.ngc")]
    assert jobs[0].size == EXAMPLES[0].stat().st_size
    with pytest.raises(UsageError, match="would both be written"):
        plan_jobs([str(EXAMPLES[0]), str(tree / EXAMPLES[0].name)], str(tmp_path / "o"))


def test_chunks_put_large_files_alone_and_first(tree, tmp_path):
    jobs = plan_jobs([str(tree)], str(tmp_path / "o"))
    sizes = {job.name: job.size for job in jobs}
    groups = chunks(jobs, max_bytes=max(sizes.values()), max_files=3)
    assert sorted(job.name for group in groups for job in group) == sorted(sizes)
    assert all(len(group) <= 3 for group in groups)
    assert all(len(group) == 1 or sum(j.size for j in group) <= max(sizes.values()) for group in groups)
    totals = [sum(job.size for job in group) for group in groups]
    assert totals == sorted(totals, reverse=True)


class FakeTty(io.StringIO):
    def isatty(self) -> bool:
        return True


def test_progress_shows_files_blocks_per_second_and_time_left():
    now = [100.0]
    stream = FakeTty()
    bar = BatchProgress(files=10, total_bytes=1000, stream=stream, clock=lambda: now[0])
    now[0] = 104.0
    bar.advance(files=3, blocks=2000, size=250)  # a quarter of the bytes in 4 s: 12 s left
    assert stream.getvalue() == ("\r\033[Kpostproc: [#######-----------------------] 3/10 files  "
                                 "500 blocks/s  ETA 0:12")
    bar.message("a.nc:1:1: warning: something")
    assert stream.getvalue().endswith("\r\033[Ka.nc:1:1: warning: something\n")
    bar.clear()
    assert not bar.shown


def test_ctrl_c_stops_the_batch_and_leaves_only_whole_outputs(tmp_path):
    """Ctrl-C (SIGINT to the process group, as a terminal sends it) once the first file is reported: exit
    130, the summary counts what was not done, every file in the report is written, each output present
    is complete (fanuc -> fanuc: the input itself), and no temporary file is left."""
    import signal
    import subprocess
    import sys
    import time

    progs = tmp_path / "progs"
    progs.mkdir()
    for n in range(400):  # seconds of work after the first file, even on an idle machine
        shutil.copy(EXAMPLES[n % len(EXAMPLES)], progs / f"o{3000 + n}.nc")
    out, report = tmp_path / "out", tmp_path / "report.jsonl"
    command = [sys.executable, "-m", "postproc", "translate", str(progs), "-o", str(out), "--from", "fanuc",
               "--to", "fanuc", "--jobs", "2", "--files-per-task", "1", "--report", str(report)]
    process = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                               start_new_session=True, cwd=ROOT)
    try:
        deadline = time.monotonic() + 600
        while not (report.exists() and report.read_text().strip()) and process.poll() is None:
            assert time.monotonic() < deadline, "no file finished in 10 minutes"
            time.sleep(0.01)
        os.killpg(process.pid, signal.SIGINT)
        summary, _ = process.communicate(timeout=600)
    finally:
        if process.poll() is None:
            os.killpg(process.pid, signal.SIGKILL)
    assert process.returncode == 130, summary
    done = [Path(str(line["file"])).name for line in report_lines(report)]
    assert "not done (interrupted)" in summary
    assert 0 < len(done) < 400
    assert leftovers(out) == []
    written = sorted(p.name for p in out.iterdir())
    assert set(done) <= set(written)  # a file finishing as Ctrl-C came may be written without its line
    assert len(written) < 400
    for name in written:
        assert (out / name).read_bytes() == (progs / name).read_bytes()


def test_a_file_name_that_is_not_utf8_is_kept_and_reported(cli, tmp_path):
    progs, out, report = tmp_path / "progs", tmp_path / "out", tmp_path / "report.jsonl"
    progs.mkdir()
    name = b"o\xff1.nc"
    with open(bytes(progs) + b"/" + name, "wb") as f:
        f.write(EXAMPLES[0].read_bytes())
    result = cli("translate", progs, "-o", out, "--from", "fanuc", "--to", "fanuc", "--report", report)
    assert result.status == 0, result.err
    with open(bytes(out) + b"/" + name, "rb") as f:
        assert f.read() == EXAMPLES[0].read_bytes()
    (line,) = report_lines(report)  # valid JSON, the name's byte kept as a surrogate escape
    assert os.fsencode(str(line["file"])) == bytes(progs) + b"/" + name
    assert b"1 of 1 files" in result.out


def test_a_file_that_kills_its_worker_fails_alone(cli, tree, tmp_path, monkeypatch):
    """A worker process that dies in the middle of a file (as in a crash: no clean-up at all) breaks the
    pool; that file is found by its temporary output, translated again alone, dies again, and is the
    only file reported as not translated. The others are translated as ever, once each in the report."""
    import multiprocessing

    import postproc.api
    import postproc.commands.batch.local

    real = postproc.api.translate

    def dies_on_crash(lines, out, **kwargs):
        if kwargs["file"].endswith("crash.nc"):
            os._exit(70)
        return real(lines, out, **kwargs)

    monkeypatch.setattr(postproc.api, "translate", dies_on_crash)
    # forked workers run this test's translate (a fork server's would import the real one)
    monkeypatch.setattr(postproc.commands.batch.local, "_start_method", lambda: multiprocessing.get_context("fork"))
    shutil.copy(EXAMPLES[0], tree / "sub" / "crash.nc")
    out, report = tmp_path / "out", tmp_path / "report.jsonl"
    result = cli("translate", tree, "-o", out, "--from", "fanuc", "--to", "fanuc", "--jobs", "2",
                 "--files-per-task", "2", "--report", report)
    assert result.status == 1
    lines = report_lines(report)
    crash = f"{tree}/sub/crash.nc"
    assert sorted(line["file"] for line in lines) == sorted(
        [f"{tree}/{p.name}" for p in EXAMPLES] + [f"{tree}/sub/again.nc", crash])
    (failed,) = [line for line in lines if line["exit"] != 0]
    assert (failed["file"], failed["status"]) == (crash, "internal")
    assert "its worker process died translating it alone" in str(failed["errors"])
    assert not (out / "sub" / "crash.nc").exists()
    for path in EXAMPLES:
        assert (out / path.name).read_bytes() == path.read_bytes()
    assert (out / "sub" / "again.nc").read_bytes() == EXAMPLES[0].read_bytes()
    assert leftovers(out) == []


def test_defines_reach_the_templates_of_every_file(cli, tree, tmp_path):
    """``--define`` in a batch is what it is for one file: each output equals the single-file command's."""
    machine = tmp_path / "m.xml"
    machine.write_text('<?xml version="1.0" encoding="UTF-8"?>\n<MachineSetup name="m">\n  <Templates>\n'
                       "    <Header>(SHOP {{ shop }})\n</Header>\n  </Templates>\n</MachineSetup>\n")
    out = tmp_path / "out"
    options = ("--from", "fanuc", "--to", "fanuc", "--machine", machine, "--define", "shop=ACME")
    result = cli("translate", tree, "-o", out, *options, "--jobs", "1")
    assert result.status == 0, result.err
    for path in EXAMPLES:
        written = (out / path.name).read_bytes()
        assert b"(SHOP ACME)" in written
        assert written == single(cli, path, *options), path.name


def test_the_summary_counts_warnings_among_the_files_ok():
    """"ok N (M with warnings)": M counts the files translated ok that warned, never more than N (a file
    with errors and warnings is counted under errors only)."""
    from postproc.commands.batch.report import Tally
    from postproc.commands.batch.work import FileResult
    tally = Tally(files=4)
    tally.add(FileResult("a.nc", "o/a.nc", "ok", 0, warnings=["a.nc:1:1: warning: w"]))
    tally.add(FileResult("b.nc", "o/b.nc", "ok", 0))
    tally.add(FileResult("c.nc", "o/c.nc", "error", 1, warnings=["c.nc:1:1: warning: w"],
                         errors=["c.nc:2:1: error: e"]))
    tally.add(FileResult("d.nc", "o/d.nc", "error", 1, warnings=["d.nc:1:1: warning: w"],
                         errors=["d.nc:2:1: error: e"]))
    ok_line = next(line for line in tally.summary(source="fanuc", target="fanuc", where="1 job", report=None)
                   .splitlines() if line.strip().startswith("ok"))
    assert ok_line.split()[1:] == ["2", "(1", "with", "warnings)"]


@pytest.mark.parametrize("jobs", ["1", "2"])
def test_units_transform_and_arcs_reach_every_file_and_verify(cli, tmp_path, jobs):
    """Each output is the single-file command's with the same options, and verifies with them (the batch's
    --verify moves each input by the transform and checks each chord against its arc)."""
    progs = tmp_path / "progs"
    progs.mkdir()
    names = ["o1001_plate_drill_tap.nc", "o1002_bracket_inch.nc", "o1005_bolt_circle_macro.nc"]
    for name in names:
        shutil.copy(ROOT / "examples/fanuc" / name, progs / name)
    setup = ROOT / "examples/setups/fanuc_0i_mf_vmc.xml"
    options = ("--from", "fanuc", "--to", "linuxcnc", "--machine", setup, "--units", "inch",
               "--transform", "rotate 30 about 5,5; translate 1,2", "--arcs", "lines:0.01")
    out = tmp_path / "out"
    result = cli("translate", progs, "-o", out, *options, "--verify", "--jobs", jobs, "--files-per-task", "1",
                 "--report", tmp_path / "r.jsonl")
    assert result.status == 0, result.err
    for name in names:
        assert (out / name).read_bytes() == single(cli, progs / name, *options), name
        assert b"G20" in (out / name).read_bytes() and b"G2 " not in (out / name).read_bytes()
    assert all(line["verify"] is not None for line in report_lines(tmp_path / "r.jsonl"))
