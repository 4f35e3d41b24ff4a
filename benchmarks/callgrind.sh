#!/usr/bin/env bash
# Instructions per block of one translation, deterministic (no wall-clock noise on a loaded machine):
# valgrind's callgrind counts the instructions of a 40k-block and a 20k-block run of the same
# CAM-style program (benchmarks/generate.py) and prints the difference per block, so start-up and
# imports cancel out.  Usage: benchmarks/callgrind.sh SRC TGT NORMALIZE(0|1) [LABEL]
# POSTPROC_PURE=1 measures the pure-Python fallback (postproc --version says which build runs).
set -euo pipefail
cd "$(dirname "$0")/.."
src=$1 tgt=$2 norm=$3 label=${4:-$1-$2-$3}
work=${TMPDIR:-/tmp}/postproc-callgrind
mkdir -p "$work"
for n in 20 40; do
  [ -f "$work/b$n.nc" ] || .venv/bin/python benchmarks/generate.py ${n}000 "$work/b$n.nc"
done
env -u PYTHONDONTWRITEBYTECODE .venv/bin/python -m compileall -q postproc dialects plugins
for n in 20 40; do
  PYTHONHASHSEED=0 valgrind --tool=callgrind --callgrind-out-file="$work/$label.$n.out" \
    .venv/bin/python benchmarks/callgrind_once.py "$src" "$tgt" "$norm" "$work/b$n.nc" 2>&1 \
    | grep Collected | awk '{print $4}' > "$work/$label.$n.txt"
done
a=$(cat "$work/$label.20.txt"); b=$(cat "$work/$label.40.txt")
echo "$label $(( (b - a) / 20000 )) instr/block ($(.venv/bin/postproc --version))"
