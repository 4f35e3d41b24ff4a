#!/usr/bin/env bash
# Instructions per block of one translation, deterministic (no wall-clock noise on a loaded machine):
# valgrind's callgrind counts the instructions of a 40k-block and a 20k-block run of the same
# CAM-style program (benchmarks/generate.py) and prints the difference per block, so start-up and
# imports cancel out.  Usage: benchmarks/callgrind.sh [--program cam|cycles] SRC TGT NORMALIZE(0|1) [LABEL]
# TGT toolpath: the toolpath command (--format jsonl, benchmarks/machine.xml); TGT verify:DIALECT: verify
# against the program's translation to DIALECT (prepared unmeasured), per block of the source.
# --program cycles measures per hole instead: a 20k-hole minus a 10k-hole run of the drilling rows
# (generate.py --kind cycles), divided by 10k holes.
# POSTPROC_PURE=1 measures the pure-Python fallback (postproc --version says which build runs).
# CALLGRIND_SMALL/CALLGRIND_LARGE (thousands of blocks, default 20 and 40) measure smaller CAM programs: a
# verify row on a busy machine takes most of an hour at 20k/40k under valgrind.
set -euo pipefail
cd "$(dirname "$0")/.."
program=cam
if [ "${1:-}" = "--program" ]; then program=$2; shift 2; fi
src=$1 tgt=$2 norm=$3 label=${4:-$1-$2-$3}
case $program in
  cam) small=${CALLGRIND_SMALL:-20} large=${CALLGRIND_LARGE:-40} unit=block ;;
  cycles) small=10 large=20 unit=hole label=cycles-$label ;;
  *) echo "unknown program $program (cam or cycles)" >&2; exit 2 ;;
esac
work=${TMPDIR:-/tmp}/postproc-callgrind
mkdir -p "$work"
prefix=b; [ "$program" = cam ] || prefix=$program
for n in $small $large; do
  [ -f "$work/$prefix$n.nc" ] || .venv/bin/python benchmarks/generate.py ${n}000 "$work/$prefix$n.nc" --kind "$program"
done
env -u PYTHONDONTWRITEBYTECODE .venv/bin/python -m compileall -q postproc dialects plugins
# One run first, unmeasured: after an install the first run discovers the entry points (and caches them,
# postproc.entry_points) and writes byte code; measured, that lands in one of the two runs only and was
# most of the +-4-7k noise of the per-block figure.
if [[ $tgt == verify:* ]]; then
  for n in $small $large; do
    PREPARE=1 .venv/bin/python benchmarks/callgrind_once.py "$src" "$tgt" "$norm" "$work/$prefix$n.nc" 2>/dev/null
  done
fi
sleep 2.5  # the entry-point cache trusts an installation at least postproc.entry_points.SETTLE seconds old
.venv/bin/python benchmarks/callgrind_once.py "$src" "$tgt" "$norm" "$work/${prefix}$small.nc" 2>/dev/null
for n in $small $large; do
  PYTHONHASHSEED=0 valgrind --tool=callgrind --callgrind-out-file="$work/$label.$n.out" \
    .venv/bin/python benchmarks/callgrind_once.py "$src" "$tgt" "$norm" "$work/$prefix$n.nc" 2>&1 \
    | grep Collected | awk '{print $4}' > "$work/$label.$n.txt"
done
a=$(cat "$work/$label.$small.txt"); b=$(cat "$work/$label.$large.txt")
echo "$label $(( (b - a) / ((large - small) * 1000) )) instr/$unit ($(.venv/bin/postproc --version))"
