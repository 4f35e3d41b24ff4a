#!/usr/bin/env bash
# `make run`: translate every bundled example, check each translation's toolpath against its source
# with `postproc verify`, and show one result. Outputs go to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
P=${POSTPROC:-.venv/bin/postproc}
mkdir -p out

run() { echo "\$ postproc $*"; "$P" "$@"; }

for f in examples/fanuc/*.nc; do
  n=$(basename "$f" .nc)
  run translate "$f" --from fanuc --to fanuc --normalize -o "out/$n.fanuc.nc"
  # Every example uses G43 H (a tool table), which grbl lacks: warn, keep the motion, say so; verify
  # lists the tool length offset it could not compare, and --allow-ignored accepts that difference.
  run translate "$f" --from fanuc --to grbl --on-unsupported warn -o "out/$n.grbl.nc"
  run verify "$f" "out/$n.grbl.nc" --from fanuc --to grbl --allow-ignored
  # LinuxCNC keeps a program's loops and variables where it can spell them; otherwise it is flattened.
  run translate "$f" --from fanuc --to linuxcnc -o "out/$n.ngc"
  run verify "$f" "out/$n.ngc" --from fanuc --to linuxcnc
done
for f in examples/linuxcnc/*.ngc; do
  n=$(basename "$f" .ngc)
  if run translate "$f" --from linuxcnc --to fanuc -o "out/$n.fanuc.nc"; then
    run verify "$f" "out/$n.fanuc.nc" --from linuxcnc --to fanuc
  else
    echo "  (refused with the located error above: nothing was written)"
  fi
done
for f in examples/isg/*.nc; do
  n=$(basename "$f" .nc)
  # ISG to ISG is byte for byte.
  run translate "$f" --from isg --to isg -o "out/$n.isg.nc"
  cmp "$f" "out/$n.isg.nc"
  # Fanuc keeps P parameters and $FOR as Custom Macro B where it can spell them (else the program is
  # flattened); a machine transformation (#CYL) is refused on its line, naming it.
  if run translate "$f" --from isg --to fanuc -o "out/$n.fanuc.nc"; then
    run verify "$f" "out/$n.fanuc.nc" --from isg --to fanuc
    run translate "$f" --from isg --to grbl -o "out/$n.grbl.nc"
    run verify "$f" "out/$n.grbl.nc" --from isg --to grbl
    run translate "$f" --from isg --to linuxcnc -o "out/$n.ngc"
    run verify "$f" "out/$n.ngc" --from isg --to linuxcnc
  else
    echo "  (refused with the located errors above: nothing was written)"
  fi
done
echo
echo "== out/prof_contour_xy.fanuc.nc: an ISG \$FOR contour kept as Custom Macro B"
cat out/prof_contour_xy.fanuc.nc
echo
echo "== out/o1001_plate_drill_tap.grbl.nc (first 30 lines)"
head -n 30 out/o1001_plate_drill_tap.grbl.nc
echo "..."
echo "== out/o1005_bolt_circle_macro.grbl.nc: a Custom Macro B program flattened for grbl (first 20 lines)"
head -n 20 out/o1005_bolt_circle_macro.grbl.nc
echo "..."
echo "translated programs are in out/"
echo "the postproc command is .venv/bin/postproc: '. .venv/bin/activate' puts it on your PATH"
