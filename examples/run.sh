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
  # Every example uses G43 H (a tool table), which grbl lacks: warn, keep the motion, say so.
  run translate "$f" --from fanuc --to grbl --on-unsupported warn -o "out/$n.grbl.nc"
  run verify "$f" "out/$n.grbl.nc" --from fanuc --to grbl
done
for f in examples/linuxcnc/*.ngc; do
  n=$(basename "$f" .ngc)
  if run translate "$f" --from linuxcnc --to fanuc -o "out/$n.fanuc.nc"; then
    run verify "$f" "out/$n.fanuc.nc" --from linuxcnc --to fanuc
  else
    echo "  (refused with the located error above: nothing was written)"
  fi
done
echo
echo "== out/o1001_plate_drill_tap.grbl.nc (first 30 lines)"
head -n 30 out/o1001_plate_drill_tap.grbl.nc
echo "..."
echo "translated programs are in out/"
