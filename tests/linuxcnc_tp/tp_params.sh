#!/usr/bin/env bash
# firtp_tp's jerk limit and load-time settings under real LinuxCNC 2.9 halrun (no motmod: the module
# alone), with INI_FILE_NAME set as the linuxcnc launcher sets it: `show param firtp_tp` gives the jerk
# and where it came from (0 default, 1 jerk=, 2 the INI), for
#   no INI_FILE_NAME                                      100000, 0
#   [TRAJ]MAX_LINEAR_JERK 20000, [AXIS_X]MAX_JERK 30000,    8000, 2 (the smallest); per axis (firtp_tp.jerk-L)
#   [AXIS_Y]MAX_JERK 8000                                  X 20000 (at most the linear one), Y 8000, the
#                                                          others 8000 ([AXIS_Z]'s 10 not read: not in COORDINATES)
#   the same with jerk=5000                                5000, 1 (the override), 5000 on every axis
#   [AXIS_Y]MAX_JERK = fast                                the load is refused, naming file, line and key
# and without settings the defaults of firtp/defaults.hpp; meaning=contour sets firtp_tp.contour,
# meaning=max is refused; [TASK]CYCLE_TIME 0.004 shows as firtp_tp.task-cycle.
# Set-up: tests/linuxcnc/hal_session.sh.
set -euo pipefail
module=$1 moddir=$2
source "$(cd "$(dirname "$0")/../linuxcnc" && pwd)/hal_session.sh"

cat > "$work/machine.ini" << 'INI'
[TASK]
CYCLE_TIME = 0.004
[TRAJ]
COORDINATES = X Y
MAX_LINEAR_JERK = 20000
[AXIS_X]
MAX_JERK = 30000
[AXIS_Y]
MAX_JERK = 8000
[AXIS_Z]
MAX_JERK = 10
INI
sed '9s/.*/MAX_JERK = fast/' "$work/machine.ini" > "$work/bad.ini"  # [AXIS_Y]
chmod a+r "$work"/*.ini

# One halrun session: loadrt firtp_tp ARGS, show its params; env INI_FILE_NAME=$1 (empty: unset).
session_with() {
  local ini=$1; shift
  printf 'loadrt firtp_tp %s\nshow param firtp_tp\n' "$*" > "$work/tp.hal"
  chmod a+r "$work/tp.hal"
  if [ -n "$ini" ]; then export INI_FILE_NAME=$ini; else unset INI_FILE_NAME; fi
  session=1
  local status=0
  (cd "$work" && as_user timeout 60 halrun -f tp.hal) > "$work/halrun.log" 2>&1 || status=$?
  as_user timeout 20 halrun -U > /dev/null 2>&1 || true
  unset INI_FILE_NAME
  return $status
}
param() { awk -v n="$1" '$5 == n && $3 == "RO" {print $4}' "$work/halrun.log"; }
expect() {  # CASE JERK SOURCE
  local jerk source
  jerk=$(param firtp_tp.jerk) source=$(param firtp_tp.jerk-source)
  [ "$jerk $source" = "$2 $3" ] || { cat "$work/halrun.log"; echo "FAIL: $1: jerk $jerk source $source, expected $2 $3"; exit 1; }
  echo "$1: firtp_tp.jerk $jerk, jerk-source $source"
}

session_with "" "tolerance=0.02 t1=0.1" || { cat "$work/halrun.log"; echo "FAIL: loadrt firtp_tp without an INI"; exit 1; }
expect "no INI" 100000 0
[ "$(param firtp_tp.tolerance) $(param firtp_tp.t1) $(param firtp_tp.stages) $(param firtp_tp.queue)" = "0.02 0.1 2 1024" ] ||
  { cat "$work/halrun.log"; echo "FAIL: tolerance, t1, stages, queue"; exit 1; }

defaults_h="$(cd "$(dirname "$0")/../.." && pwd)/component/core/include/firtp/defaults.hpp"
default_text() { sed -nE "s/^#define FIRTP_DEFAULT_$1_TEXT \"(.*)\"$/\1/p" "$defaults_h"; }
session_with "" "" || { cat "$work/halrun.log"; echo "FAIL: loadrt firtp_tp without settings"; exit 1; }
shown="$(param firtp_tp.tolerance) $(param firtp_tp.chord-tol) $(param firtp_tp.rate-reserve) $(param firtp_tp.contour)"
wanted="$(default_text TOLERANCE) $(default_text ARC_CHORD_TOLERANCE) $(default_text RATE_RESERVE) FALSE"
[ "$shown" = "$wanted" ] || { cat "$work/halrun.log"; echo "FAIL: defaults $shown, expected $wanted (defaults.hpp)"; exit 1; }
echo "defaults: tolerance, chord-tol, rate-reserve, contour $shown"
session_with "" "meaning=contour" || { cat "$work/halrun.log"; echo "FAIL: loadrt firtp_tp meaning=contour"; exit 1; }
[ "$(param firtp_tp.contour)" = TRUE ] || { cat "$work/halrun.log"; echo "FAIL: meaning=contour: contour not TRUE"; exit 1; }
if session_with "" "meaning=max"; then cat "$work/halrun.log"; echo "FAIL: meaning=max was accepted"; exit 1; fi
grep -qF "meaning must be corner or contour" "$work/halrun.log" ||
  { cat "$work/halrun.log"; echo "FAIL: meaning=max: the refusal does not say why"; exit 1; }
echo "meaning=contour: firtp_tp.contour TRUE; meaning=max: refused"

session_with "$work/machine.ini" "" || { cat "$work/halrun.log"; echo "FAIL: loadrt firtp_tp with the INI"; exit 1; }
expect "INI" 8000 2
[ "$(param firtp_tp.task-cycle)" = 0.004 ] || { cat "$work/halrun.log"; echo "FAIL: [TASK]CYCLE_TIME 0.004 not read"; exit 1; }
echo "INI: firtp_tp.task-cycle 0.004"
axes() { echo "$(param firtp_tp.jerk-x) $(param firtp_tp.jerk-y) $(param firtp_tp.jerk-z) $(param firtp_tp.jerk-a)"; }
[ "$(axes)" = "20000 8000 8000 8000" ] ||
  { cat "$work/halrun.log"; echo "FAIL: jerk per axis X Y Z A $(axes), expected 20000 8000 8000 8000"; exit 1; }
echo "INI: firtp_tp.jerk-x/y/z/a $(axes)"

session_with "$work/machine.ini" "jerk=5000" || { cat "$work/halrun.log"; echo "FAIL: loadrt firtp_tp jerk=5000"; exit 1; }
expect "INI and jerk=5000" 5000 1
[ "$(axes)" = "5000 5000 5000 5000" ] || { cat "$work/halrun.log"; echo "FAIL: jerk=5000 per axis $(axes)"; exit 1; }

if session_with "$work/bad.ini" ""; then cat "$work/halrun.log"; echo "FAIL: a jerk of 'fast' was accepted"; exit 1; fi
grep -qF "$work/bad.ini:9: [AXIS_Y]MAX_JERK = 'fast': not a number" "$work/halrun.log" ||
  { cat "$work/halrun.log"; echo "FAIL: the refusal does not name file, line and key"; exit 1; }
echo "bad INI: load refused: $(grep -oF "$work/bad.ini:9: [AXIS_Y]MAX_JERK = 'fast'" "$work/halrun.log" | head -1)"
