#!/usr/bin/env bash
# firtp run (host -> LCM -> bridge -> firtp.so on a hal-shim servo thread -> LCM) must give the
# samples of firtp plan, within 1e-9 mm, for every example program.
set -euo pipefail
firtp=$1 examples=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
check() {
  local program=$1; shift
  [[ $program == /* ]] || program=$examples/$program
  "$firtp" plan "$program" "$@" --csv "$work/plan.csv" > /dev/null
  "$firtp" run "$program" "$@" --csv "$work/run.csv" > "$work/run.log"
  python3 - "$work/plan.csv" "$work/run.csv" "$program" <<'PY'
import csv, sys
plan, run = (list(csv.reader(open(f))) for f in sys.argv[1:3])
assert len(plan) == len(run), f"{sys.argv[3]}: {len(run)} rows from run, {len(plan)} planned"
worst = max(abs(float(a[i]) - float(b[i])) for a, b in zip(plan[1:], run[1:]) for i in (1, 2, 3))
print(f"{sys.argv[3]}: {len(run) - 1} samples, largest difference {worst:g} mm")
assert worst <= 1e-9, worst
PY
}
check diamond.ngc --ini "$examples/diamond.ini"
check corner90.ngc
check steps.ngc
check steps.ngc --tolerance-meaning contour --t1 0.03 --t2 0.011
check corner90.ngc --ini "$(dirname "$0")/override.ini"
# A program without motion (a subroutine file, as LinuxCNC's g881.ngc): its one sample at rest.
printf '(defines a subroutine, moves nothing)\no<touch> sub\nG1 X1 F100\no<touch> endsub\nM2\n' > "$work/still.ngc"
check "$work/still.ngc"
# The same samples draw the same picture, the corner zooms (paired with the reference plan's
# corner reports) included.
if command -v gnuplot > /dev/null; then
  "$firtp" plan "$examples/diamond.ngc" --ini "$examples/diamond.ini" --plot "$work/plan.png" > /dev/null
  "$firtp" run "$examples/diamond.ngc" --ini "$examples/diamond.ini" --plot "$work/run.png" > /dev/null
  cmp "$work/plan.png" "$work/run.png" || { echo "diamond: run's plot differs from plan's"; exit 1; }
  echo "diamond: run's plot is plan's"
fi
