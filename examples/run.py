"""`make run`: translate every bundled example, check each translation's toolpath against its source with
`postproc verify`, and show one result. Outputs go to out/.

Every `$ postproc ...` line printed is a command you can run as it stands. Here they run one after the
other in this process (`postproc.commands.cli.main`, as the test suite runs its commands): the same outputs,
messages and exit statuses as 115 processes (checked byte for byte), without the start of an interpreter and
its imports and the loading of the dialects each time, which were nearly all of the examples' CPU time (16.9
CPU s as separate processes, 0.9 s here, pure build).
"""

from __future__ import annotations

import filecmp
import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
OUT = Path("out")
TOUCHED_OFF = "examples/setups/router_tools_touched_off.xml"
GSK = "examples/setups/gsk_980tdc.xml"
FANUC_T = "examples/setups/fanuc_0i_tf.xml"


def postproc(*args: str) -> bool:
    """``postproc ARGS``; True where it exits 0."""
    from postproc.commands.cli import main

    print("$ postproc " + " ".join(args), flush=True)
    try:
        status = main(list(args))
    except SystemExit as exc:  # argparse refuses a wrong usage by exiting
        status = exc.code if isinstance(exc.code, int) else 2
    sys.stdout.flush()
    sys.stderr.flush()
    return status == 0


def must(ok: bool) -> None:
    """Stop as `set -e` would: a command meant to work did not."""
    if not ok:
        sys.exit(1)


def same(a: str, b: str) -> None:
    """A copy is byte for byte its source (`cmp`)."""
    if not filecmp.cmp(a, b, shallow=False):
        print(f"{a} {b} differ", file=sys.stderr)
        sys.exit(1)


def show(title: str, path: str, lines: int | None = None) -> None:
    print(f"== {path}{title}")
    text = Path(path).read_text(encoding="utf-8", errors="replace").splitlines(keepends=True)
    sys.stdout.write("".join(text[:lines]))
    if lines is not None:
        print("...")


def examples(folder: str, suffix: str) -> list[tuple[str, str]]:
    return [(str(p), p.name.removesuffix(suffix)) for p in sorted(Path(folder).glob("*" + suffix))]


def main() -> None:
    os.chdir(ROOT)
    OUT.mkdir(exist_ok=True)
    for f, n in examples("examples/fanuc", ".nc"):
        must(postproc("translate", f, "--from", "fanuc", "--to", "fanuc", "--normalize", "-o", f"out/{n}.fanuc.nc"))
        # Every example uses G43 H (a tool table), which grbl lacks: on a router whose tools are touched off at
        # each change (<Machine toolLengths="touched_off">) each offset is dropped with a comment and verify
        # says why; on a machine with lengths, grbl gets G43.1 Z<length>. --on-unsupported warn drops what grbl
        # cannot run (a block delete), and --allow-ignored accepts a setting it cannot compare.
        must(postproc("translate", f, "--from", "fanuc", "--to", "grbl", "--on-unsupported", "warn", "--machine",
                      TOUCHED_OFF, "-o", f"out/{n}.grbl.nc"))
        must(postproc("verify", f, f"out/{n}.grbl.nc", "--from", "fanuc", "--to", "grbl", "--allow-ignored",
                      "--machine", TOUCHED_OFF))
        # LinuxCNC keeps a program's loops and variables where it can spell them; otherwise it is flattened.
        must(postproc("translate", f, "--from", "fanuc", "--to", "linuxcnc", "-o", f"out/{n}.ngc"))
        must(postproc("verify", f, f"out/{n}.ngc", "--from", "fanuc", "--to", "linuxcnc", "--machine", TOUCHED_OFF))
    for f, n in examples("examples/linuxcnc", ".ngc"):
        if postproc("translate", f, "--from", "linuxcnc", "--to", "fanuc", "-o", f"out/{n}.fanuc.nc"):
            must(postproc("verify", f, f"out/{n}.fanuc.nc", "--from", "linuxcnc", "--to", "fanuc", "--machine",
                          TOUCHED_OFF))
        else:
            print("  (refused with the located error above: nothing was written)")
    for f, n in examples("examples/isg", ".nc"):
        # ISG to ISG is byte for byte (on a machine with the U axis prof_open_close.nc programs).
        must(postproc("translate", f, "--from", "isg", "--to", "isg", "--machine",
                      "examples/setups/isg_twincat_cylinder.xml", "-o", f"out/{n}.isg.nc"))
        same(f, f"out/{n}.isg.nc")
        # Fanuc keeps P parameters and $FOR as Custom Macro B where it can spell them (else the program is
        # flattened); a machine transformation (#CYL) is refused on its line, naming it.
        if postproc("translate", f, "--from", "isg", "--to", "fanuc", "-o", f"out/{n}.fanuc.nc"):
            must(postproc("verify", f, f"out/{n}.fanuc.nc", "--from", "isg", "--to", "fanuc"))
            must(postproc("translate", f, "--from", "isg", "--to", "grbl", "-o", f"out/{n}.grbl.nc"))
            must(postproc("verify", f, f"out/{n}.grbl.nc", "--from", "isg", "--to", "grbl"))
            must(postproc("translate", f, "--from", "isg", "--to", "linuxcnc", "-o", f"out/{n}.ngc"))
            must(postproc("verify", f, f"out/{n}.ngc", "--from", "isg", "--to", "linuxcnc"))
        else:
            print("  (refused with the located errors above: nothing was written)")
    for f, n in examples("examples/fagor", ".nc"):
        # Fagor to Fagor is byte for byte; Fagor's G81/G89 with Z (reference plane), I (depth), K (dwell)
        # become Fanuc's G82/G89 with R, Z, P and back; grbl and LinuxCNC get the moves.
        must(postproc("translate", f, "--from", "fagor", "--to", "fagor", "-o", f"out/{n}.fagor.nc"))
        same(f, f"out/{n}.fagor.nc")
        for t in ("fanuc", "linuxcnc", "grbl"):
            must(postproc("translate", f, "--from", "fagor", "--to", t, "-o", f"out/{n}.{t}.nc"))
            must(postproc("verify", f, f"out/{n}.{t}.nc", "--from", "fagor", "--to", t))
        must(postproc("translate", f"out/{n}.fanuc.nc", "--from", "fanuc", "--to", "fagor", "-o",
                      f"out/{n}.back.fagor.nc"))
        must(postproc("verify", f"out/{n}.fanuc.nc", f"out/{n}.back.fagor.nc", "--from", "fanuc", "--to", "fagor"))
    # Multiple machining: the Fagor G81 + G163 bolt circle and the same holes written one by one for Fanuc
    # make the same toolpath, checked both ways.
    points = "examples/fagor/fanuc/o1401_bolt_circle_points.nc"
    must(postproc("verify", "examples/fagor/bolt_circle.nc", points, "--from", "fagor", "--to", "fanuc"))
    must(postproc("verify", points, "examples/fagor/bolt_circle.nc", "--from", "fanuc", "--to", "fagor"))
    print()
    show(": an ISG $FOR contour kept as Custom Macro B", "out/prof_contour_xy.fanuc.nc")
    # Lathes: GSK 980TDc and Fanuc T keep their cycles native between them (every word written for GSK);
    # LinuxCNC gets the roughing, grooving and threading passes (threads as G33 moves, G96 with its clamp as
    # G96 D.. S.., G99 as G95; issue 29); grbl has no spindle-synchronised motion.
    for f, n in examples("examples/gsk", ".nc"):
        must(postproc("translate", f, "--from", "gsk", "--to", "fanuc", "--machine", GSK, "-o", f"out/{n}.fanuc.nc"))
        must(postproc("verify", f, f"out/{n}.fanuc.nc", "--from", "gsk", "--to", "fanuc", "--machine", GSK))
        # LinuxCNC takes the turret index's offset as G43 H; grbl has no lathe tool offsets (translate warns,
        # verify reports the lost offset), so it is not shown here
        must(postproc("translate", f, "--from", "gsk", "--to", "linuxcnc", "--machine", GSK, "-o",
                      f"out/{n}.linuxcnc.nc"))
        must(postproc("verify", f, f"out/{n}.linuxcnc.nc", "--from", "gsk", "--to", "linuxcnc", "--machine", GSK))
    for f, n in examples("examples/fanuc-lathe", ".nc"):
        must(postproc("translate", f, "--from", "fanuc", "--to", "gsk", "--machine", FANUC_T, "-o", f"out/{n}.gsk.nc"))
        must(postproc("verify", f, f"out/{n}.gsk.nc", "--from", "fanuc", "--to", "gsk", "--machine", FANUC_T))
        must(postproc("translate", f, "--from", "fanuc", "--to", "linuxcnc", "--machine", FANUC_T, "-o", f"out/{n}.ngc"))
        must(postproc("verify", f, f"out/{n}.ngc", "--from", "fanuc", "--to", "linuxcnc", "--machine", FANUC_T))
    print()
    show(" (first 30 lines)", "out/o1001_plate_drill_tap.grbl.nc", 30)
    show(": a Custom Macro B program flattened for grbl (first 20 lines)", "out/o1005_bolt_circle_macro.grbl.nc", 20)
    show(": GSK G71/G70 expanded for LinuxCNC (G18 G7, T0101 as G43 H01 T1 M6; first 25 lines)",
         "out/o0101_stepped_shaft.linuxcnc.nc", 25)
    print("translated programs are in out/")
    print("the postproc command is .venv/bin/postproc: '. .venv/bin/activate' puts it on your PATH")


if __name__ == "__main__":
    main()
