#!/usr/bin/env bash
# Instructions per unit of one `make bench` row, deterministic (no wall-clock noise on a loaded machine):
# valgrind's callgrind counts the instructions of a large and a small run of the same generated program
# (benchmarks/generate.py) and prints the difference per unit, so start-up and imports cancel out.
#
#   benchmarks/callgrind.sh [--program cam|cycles|macro|startup] SRC TGT NORMALIZE(0|1) [LABEL]
#
# --program cam (default): the CAM program of CALLGRIND_SMALL and CALLGRIND_LARGE thousand blocks (default 20
#   and 40), per block. TGT: a dialect (translate, with the options of its make bench row,
#   benchmarks/translations.py); toolpath; verify:DIALECT (against the program's translation to DIALECT,
#   prepared unmeasured, per block of the source); the peers, run as make bench runs them: peer:TOOL
#   (benchmarks/peers.py TOOL: gcode-lib, gcode-lib-state, gcodeparser, pygcode), peer:TOOL+DIALECT (over the
#   program and its translation: verify's baseline), plainloop (benchmarks/plainloop.py).
# --program cycles: per hole, the drilling rows (generate.py --kind cycles) of CALLGRIND_SMALL and
#   CALLGRIND_LARGE hundred holes (default 100 and 200; a hole costs about four CAM blocks); TGT a dialect
#   (expanded), or plainloop:DIALECT (the plain loop over that translation, prepared unmeasured: the row's
#   baseline in make bench).
# --program macro: per interpreted block (generate.bolt_circle_executed), the nested-WHILE bolt circles of
#   CALLGRIND_SMALL and CALLGRIND_LARGE hundred holes (about 700 interpreted blocks a hundred; default 10 and
#   20); TGT a dialect (flattened) or plainloop:DIALECT.
# --program startup: instructions of one start (no difference): TGT a dialect: the installed `postproc`
#   command translating a one-line program from SRC (as make bench's start-up row: `G00 X1.` to grbl);
#   dialects: `postproc dialects`; bare: `python -c pass` (the baseline). The start is made once unmeasured
#   first (entry-point cache, byte code).
# POSTPROC_PURE=1 measures the pure-Python fallback (postproc --version says which build runs). A verify row
# on a busy machine takes most of an hour at 20k/40k under valgrind: CALLGRIND_SMALL=5 CALLGRIND_LARGE=10.
# The last line printed is `LABEL N instr/UNIT (version)`; benchmarks/callgrind_summary.py runs every row.
set -euo pipefail
cd "$(dirname "$0")/.."
program=cam
if [ "${1:-}" = "--program" ]; then program=$2; shift 2; fi
src=$1 tgt=$2 norm=$3 label=${4:-$1-$2-$3} files=()
case $program in
  cam) small=${CALLGRIND_SMALL:-20} large=${CALLGRIND_LARGE:-40} unit=block ;;
  cycles) small=${CALLGRIND_SMALL:-100} large=${CALLGRIND_LARGE:-200} unit=hole label=cycles-$label ;;
  macro) small=${CALLGRIND_SMALL:-10} large=${CALLGRIND_LARGE:-20} unit=block label=macro-$label ;;
  startup) unit=start label=startup-$label ;;
  *) echo "unknown program $program (cam, cycles, macro or startup)" >&2; exit 2 ;;
esac
export CALLGRIND_PROGRAM=$program
work=${TMPDIR:-/tmp}/postproc-callgrind
mkdir -p "$work"
version=$(.venv/bin/postproc --version)
env -u PYTHONDONTWRITEBYTECODE .venv/bin/python -m compileall -q postproc dialects plugins

# measure OUT CMD...: run CMD under callgrind (its output in OUT.log), print its instruction count; a run
# that fails stops the script with the end of its log.
measure() {
  local out=$1; shift
  if ! PYTHONHASHSEED=0 valgrind --tool=callgrind --callgrind-out-file="$out.out" "$@" >"$out.log" 2>&1; then
    echo "callgrind.sh: failed: $*" >&2; tail -n 20 "$out.log" >&2; exit 1
  fi
  grep -o 'Collected : [0-9]*' "$out.log" | awk '{print $3}'
}

if [ "$program" = startup ]; then
  one="$work/one-line.nc"
  printf 'G00 X1.\n' > "$one"
  case $tgt in
    bare) cmd=(.venv/bin/python -c pass) ;;
    dialects) cmd=(.venv/bin/postproc dialects) ;;
    *) cmd=(.venv/bin/postproc translate "$one" -o "$work/one-line.out" --from "$src" --to "$tgt") ;;
  esac
  "${cmd[@]}" >/dev/null 2>&1 || { echo "callgrind.sh: failed: ${cmd[*]}" >&2; exit 1; }  # unmeasured: the entry-point cache and byte code
  sleep 2.5  # the entry-point cache trusts an installation at least postproc.entry_points.SETTLE seconds old
  n=$(measure "$work/$label" "${cmd[@]}")
  echo "$label $n instr/$unit ($version)"
  exit 0
fi

# The programs: b5.nc is 5,000 CAM blocks; cycles500.nc 500 holes, macro500.nc 500 holes.
scale=000; [ "$program" = cam ] || scale=00
for n in $small $large; do
  file=$work/b$n.nc; [ "$program" = cam ] || file=$work/$program$n$scale.nc
  [ -f "$file" ] || .venv/bin/python benchmarks/generate.py $n$scale "$file" --kind "$program"
  files+=("$file")
done
# Units of the difference: blocks, holes, or the interpreted blocks of the macro program.
units=$(( $large$scale - $small$scale ))
if [ "$program" = macro ]; then
  units=$(.venv/bin/python -c "
import sys; sys.path.insert(0, 'benchmarks'); import generate
def executed(holes): return generate.bolt_circle_executed(-(-holes // generate.MACRO_HOLES), generate.MACRO_HOLES)
print(executed($large$scale) - executed($small$scale))")
fi
# What the row reads besides the program (a translation, gcodeparser's copy), made unmeasured.
for file in "${files[@]}"; do
  PREPARE=1 .venv/bin/python benchmarks/callgrind_once.py "$src" "$tgt" "$norm" "$file" >/dev/null
done
# One run first, unmeasured: after an install the first run discovers the entry points (and caches them,
# postproc.entry_points) and writes byte code; measured, that lands in one of the two runs only and was
# most of the +-4-7k noise of the per-block figure.
sleep 2.5  # the entry-point cache trusts an installation at least postproc.entry_points.SETTLE seconds old
.venv/bin/python benchmarks/callgrind_once.py "$src" "$tgt" "$norm" "${files[0]}" >/dev/null 2>&1 \
  || { echo "callgrind.sh: the unmeasured run failed: callgrind_once.py $src $tgt $norm ${files[0]}" >&2; exit 1; }
a=$(measure "$work/$label.$small$scale" .venv/bin/python benchmarks/callgrind_once.py "$src" "$tgt" "$norm" "${files[0]}")
b=$(measure "$work/$label.$large$scale" .venv/bin/python benchmarks/callgrind_once.py "$src" "$tgt" "$norm" "${files[1]}")
# The fixed cost the two runs imply (start-up, imports, the file's header): a figure far from the row's
# usual start-up means something ran in one run only (an entry-point discovery, byte code written).
small_units=$(( units * small / (large - small) )); [ "$program" = macro ] && small_units=$(.venv/bin/python -c "
import sys; sys.path.insert(0, 'benchmarks'); import generate
print(generate.bolt_circle_executed(-(-$small$scale // generate.MACRO_HOLES), generate.MACRO_HOLES))")
per=$(( (b - a) / units ))
echo "$label $per instr/$unit ($version); runs $a $b, fixed $(( (a - per * small_units) / 1000000 )) M"
