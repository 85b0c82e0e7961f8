#!/usr/bin/env bash
# firtp.so in real LinuxCNC 2.9 (halrun, POSIX non-realtime, 1 ms servo thread) against hal-shim:
# the diamond's blocks go in through the block pins (LinuxCNC's streamer, one row a period), the
# axis pins are recorded every period (sampler + halsampler), and every period must equal
# firtp-hal running the same firtp part of the script, within 1e-9 (firtp-lcnc-hal-run compare).
#
# rtapi_app refuses to run as root: as root this runs halrun as `nobody` (setpriv, no account to
# create; rtapi_app is setuid root and drops to the real uid itself). rtapi_app loads modules from
# its fixed directory only (`loadrt /path/firtp` is refused), so this build's firtp.so is placed
# there for the run and whatever was there before is put back afterwards. Only one HAL session can
# exist per machine: ctest runs this under RESOURCE_LOCK linuxcnc. Exit 77 (skipped) where
# LinuxCNC is not installed.
set -euo pipefail
tool=$1 module=$2 firtp_hal=$3 shim_modules=$4 moddir=$5 examples=$6
skip() { echo "SKIPPED: $*"; exit 77; }
[ "$module" != none ] || skip "LinuxCNC's headers are not installed (linuxcnc-uspace-dev), so the LinuxCNC firtp.so was not built (FIRTP_LINUXCNC)"
command -v halrun > /dev/null || skip "halrun not found (linuxcnc-uspace)"
[ -d "$moddir" ] || skip "no LinuxCNC module directory $moddir"
realtime=/usr/lib/linuxcnc/realtime

begin=$(date +%s%N)
work=$(mktemp -d /tmp/firtp-lcnc-hal.XXXXXX)
installed=$moddir/firtp.so
placed=0 session=0 halrun_pid=
if [ "$(id -u)" -eq 0 ]; then
  uid=$(id -u nobody 2> /dev/null || echo 65534) gid=$(id -g nobody 2> /dev/null || echo 65534)
  chown "$uid:$gid" "$work"
  as_user() { setpriv --reuid="$uid" --regid="$gid" --clear-groups env HOME="$work" "$@"; }
  echo "halrun runs as uid $uid (setpriv): rtapi_app refuses root"
else
  as_user() { env HOME="$work" "$@"; }
fi
running() { "$realtime" status > /dev/null 2>&1; }
cleanup() {
  local status=$?
  if [ -n "$halrun_pid" ]; then kill "$halrun_pid" 2> /dev/null || true; fi
  if ((session)) && running; then as_user timeout 20 halrun -U > /dev/null 2>&1 || echo "halrun -U failed" >&2; fi
  if ((placed)); then
    if [ -e "$work/firtp.so.before" ]; then mv -f "$work/firtp.so.before" "$installed"; else rm -f "$installed"; fi
  fi
  rm -rf "$work"
  exit $status
}
trap cleanup EXIT
trap 'exit 1' INT TERM

# This build's module where rtapi_app looks for it.
if [ -e "$installed" ] && cmp -s "$module" "$installed"; then
  echo "$installed is this build's already"
elif [ -w "$moddir" ]; then
  if [ -e "$installed" ]; then cp -p "$installed" "$work/firtp.so.before"; fi
  placed=1
  cp "$module" "$moddir/.firtp.so.test" && mv -f "$moddir/.firtp.so.test" "$installed"
else
  skip "$installed is not this build's and $moddir is not writable: cmake --build BUILD --target install-linuxcnc (as root), or run as root"
fi

# One HAL session per machine: wait for someone else's to end rather than break it.
for _ in $(seq 60); do running || break; sleep 1; done
running && { echo "FAIL: another HAL session (rtapi_app) is still running after 60 s"; exit 1; }

"$tool" prepare "$examples/diamond.ngc" "$examples/diamond.ini" "$work"
chmod a+r "$work"/*

# LinuxCNC
session=1
lcnc_begin=$(date +%s%N)
(cd "$work" && as_user timeout 60 halrun -f linuxcnc.hal) > "$work/halrun.log" 2>&1 &
halrun_pid=$!  # waited for in the background, so a signal reaches the cleanup at once
if ! wait "$halrun_pid"; then
  halrun_pid=
  echo "FAIL: halrun -f linuxcnc.hal"; cat "$work/halrun.log"; exit 1
fi
halrun_pid=
lcnc_ms=$((($(date +%s%N) - lcnc_begin) / 1000000))
overruns=$(awk '$NF == "sampler.0.overruns" {print $(NF - 1)}' "$work/halrun.log")
[ "$overruns" = 0 ] \
  || { echo "FAIL: the sampler lost samples"; cat "$work/halrun.log"; exit 1; }
tmax=$(awk '$NF == "firtp.update.tmax" {print $(NF - 1)}' "$work/halrun.log")
echo "halrun: $lcnc_ms ms (POSIX non-realtime), no sampler overruns, longest firtp.update $tmax CPU clocks (firtp.update.tmax)"

# hal-shim, virtual time
"$firtp_hal" --no-realtime -L "$shim_modules" -f "$work/shim.hal" > "$work/shim.out" 2> "$work/shim.err" \
  || { echo "FAIL: firtp-hal -f shim.hal"; cat "$work/shim.err"; exit 1; }

"$tool" compare "$work" "$work/shim.out"
echo "total $((($(date +%s%N) - begin) / 1000000)) ms"
