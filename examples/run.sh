#!/usr/bin/env bash
# `make run`: translate every bundled example, check each translation's toolpath against its source
# with `postproc verify`, and show one result. Outputs go to out/.
set -euo pipefail
cd "$(dirname "$0")/.."
P=${POSTPROC:-.venv/bin/postproc}
mkdir -p out
TOUCHED_OFF=examples/setups/router_tools_touched_off.xml

run() { echo "\$ postproc $*"; "$P" "$@"; }

for f in examples/fanuc/*.nc; do
  n=$(basename "$f" .nc)
  run translate "$f" --from fanuc --to fanuc --normalize -o "out/$n.fanuc.nc"
  # Every example uses G43 H (a tool table), which grbl lacks: on a router whose tools are touched off at
  # each change (<Machine toolLengths="touched_off">) each offset is dropped with a comment and verify
  # says why; on a machine with lengths, grbl gets G43.1 Z<length>. --on-unsupported warn drops what grbl
  # cannot run (a block delete), and --allow-ignored accepts a setting it cannot compare.
  run translate "$f" --from fanuc --to grbl --on-unsupported warn --machine "$TOUCHED_OFF" -o "out/$n.grbl.nc"
  run verify "$f" "out/$n.grbl.nc" --from fanuc --to grbl --allow-ignored --machine "$TOUCHED_OFF"
  # LinuxCNC keeps a program's loops and variables where it can spell them; otherwise it is flattened.
  run translate "$f" --from fanuc --to linuxcnc -o "out/$n.ngc"
  run verify "$f" "out/$n.ngc" --from fanuc --to linuxcnc --machine "$TOUCHED_OFF"
done
for f in examples/linuxcnc/*.ngc; do
  n=$(basename "$f" .ngc)
  if run translate "$f" --from linuxcnc --to fanuc -o "out/$n.fanuc.nc"; then
    run verify "$f" "out/$n.fanuc.nc" --from linuxcnc --to fanuc --machine "$TOUCHED_OFF"
  else
    echo "  (refused with the located error above: nothing was written)"
  fi
done
for f in examples/isg/*.nc; do
  n=$(basename "$f" .nc)
  # ISG to ISG is byte for byte (on a machine with the U axis prof_open_close.nc programs).
  run translate "$f" --from isg --to isg --machine examples/setups/isg_twincat_cylinder.xml -o "out/$n.isg.nc"
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
for f in examples/fagor/*.nc; do
  n=$(basename "$f" .nc)
  # Fagor to Fagor is byte for byte; Fagor's G81/G89 with Z (reference plane), I (depth), K (dwell)
  # become Fanuc's G82/G89 with R, Z, P and back; grbl and LinuxCNC get the moves.
  run translate "$f" --from fagor --to fagor -o "out/$n.fagor.nc"
  cmp "$f" "out/$n.fagor.nc"
  for t in fanuc linuxcnc grbl; do
    run translate "$f" --from fagor --to "$t" -o "out/$n.$t.nc"
    run verify "$f" "out/$n.$t.nc" --from fagor --to "$t"
  done
  run translate "out/$n.fanuc.nc" --from fanuc --to fagor -o "out/$n.back.fagor.nc"
  run verify "out/$n.fanuc.nc" "out/$n.back.fagor.nc" --from fanuc --to fagor
done
# Multiple machining: the Fagor G81 + G163 bolt circle and the same holes written one by one for Fanuc
# make the same toolpath, checked both ways.
run verify examples/fagor/bolt_circle.nc examples/fagor/fanuc/o1401_bolt_circle_points.nc --from fagor --to fanuc
run verify examples/fagor/fanuc/o1401_bolt_circle_points.nc examples/fagor/bolt_circle.nc --from fanuc --to fagor
echo
echo "== out/prof_contour_xy.fanuc.nc: an ISG \$FOR contour kept as Custom Macro B"
cat out/prof_contour_xy.fanuc.nc
# Lathes: GSK 980TDc and Fanuc T keep their cycles native between them (every word written for GSK);
# LinuxCNC gets the roughing, grooving and threading passes (threads as G33 moves, G96 with its clamp as
# G96 D.. S.., G99 as G95; issue 29); grbl has no spindle-synchronised motion.
GSK=examples/setups/gsk_980tdc.xml
FT=examples/setups/fanuc_0i_tf.xml
for f in examples/gsk/*.nc; do
  n=$(basename "$f" .nc)
  run translate "$f" --from gsk --to fanuc --machine "$GSK" -o "out/$n.fanuc.nc"
  run verify "$f" "out/$n.fanuc.nc" --from gsk --to fanuc --machine "$GSK"
  # LinuxCNC takes the turret index's offset as G43 H; grbl has no lathe tool offsets (translate warns,
  # verify reports the lost offset), so it is not shown here
  run translate "$f" --from gsk --to linuxcnc --machine "$GSK" -o "out/$n.linuxcnc.nc"
  run verify "$f" "out/$n.linuxcnc.nc" --from gsk --to linuxcnc --machine "$GSK"
done
for f in examples/fanuc-lathe/*.nc; do
  n=$(basename "$f" .nc)
  run translate "$f" --from fanuc --to gsk --machine "$FT" -o "out/$n.gsk.nc"
  run verify "$f" "out/$n.gsk.nc" --from fanuc --to gsk --machine "$FT"
  run translate "$f" --from fanuc --to linuxcnc --machine "$FT" -o "out/$n.ngc"
  run verify "$f" "out/$n.ngc" --from fanuc --to linuxcnc --machine "$FT"
done
echo
echo "== out/o1001_plate_drill_tap.grbl.nc (first 30 lines)"
head -n 30 out/o1001_plate_drill_tap.grbl.nc
echo "..."
echo "== out/o1005_bolt_circle_macro.grbl.nc: a Custom Macro B program flattened for grbl (first 20 lines)"
head -n 20 out/o1005_bolt_circle_macro.grbl.nc
echo "..."
echo "== out/o0101_stepped_shaft.linuxcnc.nc: GSK G71/G70 expanded for LinuxCNC (G18 G7, T0101 as G43 H01 T1 M6; first 25 lines)"
head -n 25 out/o0101_stepped_shaft.linuxcnc.nc
echo "..."
echo "translated programs are in out/"
echo "the postproc command is .venv/bin/postproc: '. .venv/bin/activate' puts it on your PATH"
