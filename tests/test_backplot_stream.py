"""The streamed backplot draws the same picture, byte for byte, as the in-memory one it replaced.

The goldens under ``tests/golden/backplot/`` were written by the in-memory backplot (commit 19a283a, before
streaming; see the README there), whose pictures the other backplot tests check property by property. Each
case is drawn again with the default spill chunk and with a tiny one, so runs, tool changes and
``PATH_POINTS`` splits fall across chunk boundaries of the spill file.
"""

from __future__ import annotations

import gzip
import importlib.util
import sys
from pathlib import Path
from typing import Any, Callable

import pytest

import postproc.drawing.backplot as backplot
import postproc.drawing.pointstore as pointstore

ROOT = Path(__file__).resolve().parent.parent
GOLDEN = ROOT / "tests" / "golden" / "backplot"
SETUPS = ROOT / "examples" / "setups"

ZERO_TOOLS = str(ROOT / "tests" / "support" / "zero_tools.xml")
"""Tools measured as zero: the simulation needs the lengths G43 reads (the pictures are of the programmed path)."""

EXAMPLES: list[tuple[str, list[str]]] = (
    [(f"examples/fanuc/{n}.nc", ["--dialect", "fanuc", "--machine", ZERO_TOOLS]) for n in (
        "o1001_plate_drill_tap", "o1002_bracket_inch", "o1003_pocket_and_edge", "o1004_flange_least_increment",
        "o1005_bolt_circle_macro")]
    + [(f"examples/fanuc-lathe/{n}.nc", ["--dialect", "fanuc", "--machine", str(SETUPS / "fanuc_0i_tf.xml")])
       for n in ("o2001_stepped_shaft", "o2002_grooves", "o2003_thread")]
    + [(f"examples/gsk/{n}.nc", ["--dialect", "gsk", "--machine", str(SETUPS / "gsk_980tdc.xml")])
       for n in ("o0101_stepped_shaft", "o0102_grooves", "o0103_thread")]
    + [(f"examples/isg/{n}.nc", ["--dialect", "isg"]) for n in ("prof_contour_xy", "steps_subroutine")]
    + [("examples/fagor/drill_plate.nc", ["--dialect", "fagor"])]
    + [(f"examples/linuxcnc/{n}.ngc", ["--dialect", "linuxcnc", "--machine", ZERO_TOOLS])
       for n in ("cover_profile", "plate_drill_peck", "slot_pattern_owords")]
)
"""Every bundled example the toolpath simulates (``isg/prof_open_close.nc`` is refused: #CYL, axis U)."""

TOOLS_PROGRAM = "".join(
    ["G21 G90 G17\nG00 X0. Y0. Z5.\n"]
    + [f"T{1 + k % 3} M06\nG00 X{k}. Y0. Z2.\nG01 Z-1. F300.\nG02 X{k + 4}. Y0. I2. J0.\nG01 X{k + 4}. Y{k % 5}.\n"
       f"G03 X{k}. Y0. R3.\nG00 Z5.\n" for k in range(12)]
    + ["T7 M06\nT8 M06\nG00 X-5. Y-5.\nM30\n"])
"""Tools change every few moves (and twice with no move between): 14 tool stretches over 4 tools."""


def generate(n: int) -> str:
    """A deterministic CAM-style program of ``n`` blocks from ``benchmarks/generate.py``."""
    spec = importlib.util.spec_from_file_location("bench_generate", ROOT / "benchmarks" / "generate.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault("bench_generate", module)
    spec.loader.exec_module(module)
    return "".join(module.blocks(n))


def toolpath_case(program: str | None, args: list[str]) -> Callable[[Any, Path], list[object]]:
    def argv(cli: Any, tmp: Path) -> list[object]:
        src = ROOT / args[0] if program is None else tmp / "in.nc"
        if program is not None:
            src.write_text(program)
        return ["toolpath", src, *args[1:], "--format", "svg"]
    return argv


def verify_case(source: str, target: str) -> Callable[[Any, Path], list[object]]:
    def argv(cli: Any, tmp: Path) -> list[object]:
        (tmp / "in.nc").write_text(source)
        (tmp / "out.nc").write_text(target)
        return ["verify", "in.nc", "out.nc", "--from", "fanuc", "--to", "fanuc",  # names in the legend
                "--machine", ZERO_TOOLS]
    return argv


def o1003(shift: bool) -> str:
    text = (ROOT / "examples" / "fanuc" / "o1003_pocket_and_edge.nc").read_text()
    return text.replace("N220 Y16.", "N220 Y16.3") if shift else text


CASES: dict[str, tuple[Callable[[Any, Path], list[object]], int]] = {
    **{Path(path).stem: (toolpath_case(None, [path, *args]), 20000) for path, args in EXAMPLES},
    "generated_3000": (toolpath_case(generate(3000), ["in.nc", "--dialect", "fanuc", "--machine", ZERO_TOOLS]), 50),
    "tools": (toolpath_case(TOOLS_PROGRAM, ["in.nc", "--dialect", "fanuc"]), 10),
    "verify_o1003_shifted": (verify_case(o1003(False), o1003(True)), 20000),
    "verify_generated_800": (verify_case(generate(800), generate(800).replace("X4.907", "X4.95")), 40),
}
"""Case name -> (command line without the picture's file, ``PATH_POINTS`` when it was drawn)."""


def draw(cli: Any, tmp: Path, name: str) -> bytes:
    argv, path_points = CASES[name]
    picture = tmp / f"{name}.svg"
    args = argv(cli, tmp)
    args += ["--plot", picture] if args[0] == "verify" else ["-o", picture]
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(backplot, "PATH_POINTS", path_points)
        patch.chdir(tmp)
        result = cli(*args)
    assert result.status in (0, 1) and picture.exists(), result.err
    return picture.read_bytes()


def golden(name: str) -> bytes:
    plain, packed = GOLDEN / f"{name}.svg", GOLDEN / f"{name}.svg.gz"
    return plain.read_bytes() if plain.exists() else gzip.decompress(packed.read_bytes())


@pytest.mark.parametrize("chunk", [pointstore.CHUNK, 7])
@pytest.mark.parametrize("name", sorted(CASES))
def test_the_streamed_picture_is_the_in_memory_one(cli: Any, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
                                                  name: str, chunk: int) -> None:
    monkeypatch.setattr(pointstore, "CHUNK", chunk)
    assert draw(cli, tmp_path, name) == golden(name)
