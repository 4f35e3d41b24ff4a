"""``-o``: devices, FIFOs and symlinks are written through, never replaced; modes kept; the input protected;
Ctrl-C and SIGTERM end quietly without leaving the temporary output behind (issue 8)."""

from __future__ import annotations

import os
import signal
import stat
import subprocess
import sys
import threading
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PROGRAM = ROOT / "examples/fanuc/o1001_plate_drill_tap.nc"
TRANSLATE = ("translate", "--from", "fanuc", "--to", "fanuc")


def _big_program(lines: int) -> bytes:
    return ("G21 G90 G00 X0. Y0.\n" + "".join(f"G01 X{i}. Y{i % 7}. F100.\n" for i in range(lines))).encode()


def _reader(fifo: Path, limit: int | None = None) -> tuple[threading.Thread, list[bytes]]:
    """A thread reading a FIFO (everything, or ``limit`` bytes and then closing it)."""
    got: list[bytes] = []

    def run() -> None:
        with open(fifo, "rb") as f:
            got.append(f.read() if limit is None else f.read(limit))

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    return thread, got


def _device(tmp_path: Path, name: str, minor: int) -> Path:
    """A private copy of /dev/NAME (memory device 1, ``minor``) where we may create one (root), else the
    system's own. A regression then replaces only the private node: run as root, the old code deleted
    the machine's /dev/null."""
    node = tmp_path / name
    try:
        os.mknod(node, stat.S_IFCHR | 0o666, os.makedev(1, minor))
    except PermissionError:
        return Path("/dev") / name
    return node


def test_a_device_stays_a_device(cli, tmp_path: Path) -> None:
    """As root, ``-o /dev/null`` renamed the temporary file over the device and so deleted it."""
    device = _device(tmp_path, "null", 3)
    result = cli(TRANSLATE[0], PROGRAM, *TRANSLATE[1:], "-o", device)
    assert (result.status, result.err) == (0, "")
    assert stat.S_ISCHR(os.lstat(device).st_mode)
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".postproc-")] == []


def test_a_fifo_is_written_through_and_stays_a_fifo(cli, tmp_path: Path) -> None:
    fifo = tmp_path / "out.fifo"
    os.mkfifo(fifo)
    thread, got = _reader(fifo)
    result = cli(TRANSLATE[0], PROGRAM, *TRANSLATE[1:], "-o", fifo)
    thread.join(60)
    assert (result.status, result.err) == (0, "")
    assert got == [PROGRAM.read_bytes()]
    assert stat.S_ISFIFO(os.lstat(fifo).st_mode)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.fifo"]


def test_a_fifo_closed_by_its_reader_is_a_usage_error(cli, tmp_path: Path) -> None:
    program = tmp_path / "big.nc"
    program.write_bytes(_big_program(100_000))  # far more than a pipe holds
    fifo = tmp_path / "out.fifo"
    os.mkfifo(fifo)
    thread, got = _reader(fifo, limit=10)
    result = cli(TRANSLATE[0], program, *TRANSLATE[1:], "-o", fifo)
    thread.join(60)
    assert (result.status, result.err) == (2, f"postproc: cannot write {fifo}: the reading end of the pipe is closed\n")
    assert got == [program.read_bytes()[:10]]


def test_a_symlink_is_written_through_to_its_target(cli, tmp_path: Path) -> None:
    target = tmp_path / "real.nc"
    target.write_text("old\n")
    link = tmp_path / "link.nc"
    link.symlink_to(target.name)
    result = cli(TRANSLATE[0], PROGRAM, *TRANSLATE[1:], "-o", link)
    assert (result.status, result.err) == (0, "")
    assert link.is_symlink() and os.readlink(link) == "real.nc"
    assert target.read_bytes() == PROGRAM.read_bytes()


def test_an_existing_file_keeps_its_mode_and_a_new_one_follows_the_umask(cli, tmp_path: Path) -> None:
    """Every output used to be 0600 (the temporary file's mode)."""
    old = tmp_path / "old.nc"
    old.write_text("old\n")
    old.chmod(0o754)
    new = tmp_path / "new.nc"
    mask = os.umask(0o027)
    try:
        assert cli(TRANSLATE[0], PROGRAM, *TRANSLATE[1:], "-o", old).status == 0
        assert cli(TRANSLATE[0], PROGRAM, *TRANSLATE[1:], "-o", new).status == 0
    finally:
        os.umask(mask)
    assert (stat.S_IMODE(old.stat().st_mode), stat.S_IMODE(new.stat().st_mode)) == (0o754, 0o640)
    assert old.read_bytes() == new.read_bytes() == PROGRAM.read_bytes()


def test_a_directory_is_a_usage_error(cli, tmp_path: Path) -> None:
    result = cli(TRANSLATE[0], PROGRAM, *TRANSLATE[1:], "-o", tmp_path)
    assert (result.status, result.err) == (2, f"postproc: cannot write {tmp_path}: it is a directory\n")


def test_an_unwritable_place_is_a_usage_error(cli) -> None:
    result = cli(TRANSLATE[0], PROGRAM, *TRANSLATE[1:], "-o", "/proc/postproc-out.nc")
    assert result.status == 2
    assert result.err.startswith("postproc: cannot write /proc/postproc-out.nc: ")


def _spellings(tmp_path: Path, program: Path) -> list[Path]:
    (tmp_path / "sub").mkdir()
    (tmp_path / "link.nc").symlink_to(program)
    os.link(program, tmp_path / "hard.nc")
    return [program, tmp_path / "sub" / ".." / program.name, tmp_path / "link.nc", tmp_path / "hard.nc"]


def test_output_over_the_input_is_refused(cli, tmp_path: Path) -> None:
    program = tmp_path / "p.nc"
    program.write_bytes(PROGRAM.read_bytes())
    for out in _spellings(tmp_path, program):
        result = cli(TRANSLATE[0], program, *TRANSLATE[1:], "--normalize", "-o", out)
        assert (result.status, result.err) == (
            2, f"postproc: -o {out} would overwrite the input {program} (give --in-place to do that)\n")
    assert program.read_bytes() == PROGRAM.read_bytes()


def test_in_place_replaces_the_input(cli, tmp_path: Path) -> None:
    program = tmp_path / "p.nc"
    program.write_text("G21 G90\nG0 X1.50 Y2\nM30\n")
    result = cli(TRANSLATE[0], program, "--from", "fanuc", "--to", "linuxcnc", "--in-place", "-o", program)
    assert (result.status, result.err) == (0, "")
    assert program.read_text() == "G21 G90\nG0 X1.5 Y0.002\nM30\n"


# -- signals, with a real process ------------------------------------------------------------------

@pytest.mark.parametrize("sig, status", [(signal.SIGINT, 130), (signal.SIGTERM, 143)])
def test_a_signal_ends_quietly_and_leaves_no_temporary_file(tmp_path: Path, sig: int, status: int) -> None:
    """The input is a FIFO: once a write of several pipe-fulls returns, the process is inside translate,
    reading (its temporary output exists). No sleeps: the FIFO orders the steps."""
    fifo = tmp_path / "in.nc"
    os.mkfifo(fifo)
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    env = {k: v for k, v in os.environ.items() if k != "POSTPROC_DEBUG"}
    proc = subprocess.Popen([sys.executable, "-m", "postproc", "translate", str(fifo), "--from", "fanuc",
                             "--to", "linuxcnc", "-o", str(out_dir / "o.nc")],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env, cwd=ROOT)
    with open(fifo, "wb") as feed:
        feed.write(_big_program(50_000))  # ~1.3 MB: returns only when the process has read most of it
        feed.flush()
        assert [p.name[:10] for p in out_dir.iterdir()] == [".postproc-"]  # writing is under way
        proc.send_signal(sig)
        out, err = proc.communicate(timeout=60)
    assert (proc.returncode, out, err) == (status, b"", b"")
    assert list(out_dir.iterdir()) == []


def test_a_toolpath_over_its_program_is_refused(cli, tmp_path: Path) -> None:
    program = tmp_path / "p.nc"
    program.write_bytes(PROGRAM.read_bytes())
    result = cli("toolpath", program, "--dialect", "fanuc", "-o", program)
    assert (result.status, result.err) == (2, f"postproc: -o {program} would overwrite the input {program}\n")
    assert program.read_bytes() == PROGRAM.read_bytes()


def test_a_full_device_is_a_usage_error(cli, tmp_path: Path) -> None:
    device = _device(tmp_path, "full", 7)
    if not device.exists():
        pytest.skip("no /dev/full on this system")
    result = cli(TRANSLATE[0], PROGRAM, *TRANSLATE[1:], "-o", device)
    assert (result.status, result.err) == (2, f"postproc: cannot write {device}: No space left on device\n")
    assert stat.S_ISCHR(os.stat(device).st_mode)


# -- the temporary file, made with os alone (tempfile costs a one-line translation ~3 ms) -----------

def test_the_temporary_file_is_new_private_and_beside_the_target(tmp_path: Path) -> None:
    from postproc.output.outfile import TEMPORARY_PREFIX, temporary_file
    fd, name = temporary_file(str(tmp_path))
    os.close(fd)
    assert os.path.dirname(name) == str(tmp_path) and os.path.basename(name).startswith(TEMPORARY_PREFIX)
    assert stat.S_IMODE(os.stat(name).st_mode) == 0o600 and os.path.getsize(name) == 0
    fd2, other = temporary_file(str(tmp_path))
    os.close(fd2)
    assert other != name


def test_a_taken_name_is_drawn_again_and_left_alone(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A file or a symlink already under the drawn name is never opened (O_EXCL): another name is drawn."""
    from postproc.output import outfile
    draws = iter([b"\0" * 8, b"\0" * 8, b"\1" * 8])
    monkeypatch.setattr(outfile.os, "urandom", lambda n: next(draws))
    taken = tmp_path / (outfile.TEMPORARY_PREFIX + "00" * 8)
    (tmp_path / "elsewhere").write_text("keep\n")
    taken.symlink_to(tmp_path / "elsewhere")
    fd, name = outfile.temporary_file(str(tmp_path))
    os.write(fd, b"new\n")
    os.close(fd)
    assert name == str(tmp_path / (outfile.TEMPORARY_PREFIX + "01" * 8))
    assert taken.is_symlink() and (tmp_path / "elsewhere").read_text() == "keep\n"


def test_a_folder_that_cannot_be_written_is_an_error(tmp_path: Path) -> None:
    from postproc.output.outfile import temporary_file
    with pytest.raises(FileNotFoundError):
        temporary_file(str(tmp_path / "missing"))


def test_without_a_folder_the_first_usable_temporary_folder_is_used(tmp_path: Path,
                                                                     monkeypatch: pytest.MonkeyPatch) -> None:
    """As ``tempfile.gettempdir``: $TMPDIR, $TEMP, $TMP in that order, skipping one that is not usable."""
    from postproc.output.outfile import temporary_file
    (tmp_path / "temp").mkdir()
    monkeypatch.setenv("TMPDIR", str(tmp_path / "missing"))
    monkeypatch.setenv("TEMP", str(tmp_path / "temp"))
    monkeypatch.setenv("TMP", str(tmp_path))
    fd, name = temporary_file(None)
    os.close(fd)
    assert os.path.dirname(name) == str(tmp_path / "temp")


def test_standard_output_gets_the_whole_output(tmp_path: Path) -> None:
    env = dict(os.environ, TMPDIR=str(tmp_path))
    done = subprocess.run([sys.executable, "-m", "postproc", *TRANSLATE[:1], str(PROGRAM), *TRANSLATE[1:]],
                          capture_output=True, env=env, cwd=ROOT, timeout=120)
    assert (done.returncode, done.stdout, done.stderr) == (0, PROGRAM.read_bytes(), b"")
    assert list(tmp_path.iterdir()) == []  # the temporary output is gone
