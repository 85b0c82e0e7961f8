#!/bin/bash
# compare_outputs.sh OLD_FIRTP NEW_FIRTP [PROGRAM...]
# Plans every example (with the settings the README and tests use) and any further programs with
# two firtp binaries, and compares what they write byte for byte: CSV, JSON, the summary (stdout),
# stderr and the exit status. Exit 1 on any difference. Used to check that streaming `firtp plan`
# (issue 14) changed none of its outputs: build the old commit's firtp, then run this.
# COMMAND=run compares `firtp run` the same way (the chain over LCM and the component).
set -u
old=$(realpath "$1"); new=$(realpath "$2"); shift 2
here=$(cd "$(dirname "$0")/../.." && pwd)
ex=$here/examples
work=$(mktemp -d); [ -z "${KEEP:-}" ] && trap 'rm -rf "$work"' EXIT; echo "work: $work"
cases=(
  "diamond|$ex/diamond.ngc --ini $ex/diamond.ini"
  "diamond_modes|$ex/diamond.ngc --ini $ex/diamond_modes.ini"
  "arcs|$ex/arcs.ngc"
  "cam_contour|$ex/cam_contour.ngc"
  "cam_contour_contour|$ex/cam_contour.ngc --tolerance-meaning contour"
  "corner90|$ex/corner90.ngc"
  "five_axis|$ex/five_axis.ngc --ini $ex/five_axis.ini"
  "polygon360|$ex/polygon360.ngc"
  "steps|$ex/steps.ngc"
  "steps_chain|$ex/steps.ngc --t1 0.05 --t2 0.02"
)
for p in "$@"; do cases+=("$(basename "$p")|$p"); done
status=0
for c in "${cases[@]}"; do
  name=${c%%|*}; args=${c#*|}
  for side in old new; do
    bin=$old; [ $side = new ] && bin=$new
    d=$work/$side; mkdir -p "$d"
    # shellcheck disable=SC2086
    (cd "$d" && "$bin" "${COMMAND:-plan}" $args --csv "$name.csv" --json "$name.json" > "$name.out" 2> "$name.err"; echo $? > "$name.rc")
  done
  for f in csv json out err rc; do
    if ! cmp -s "$work/old/$name.$f" "$work/new/$name.$f"; then echo "DIFFERENT $name.$f"; status=1; fi
  done
  echo "compared $name"
done
[ $status = 0 ] && echo "all outputs identical"
exit $status
