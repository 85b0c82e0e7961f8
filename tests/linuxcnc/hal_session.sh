# Sourced by the real-LinuxCNC HAL tests, with $module (this build's LinuxCNC firtp.so or firtp_tp.so, or none)
# and $moddir (rtapi_app's module directory) set: skips (exit 77) where LinuxCNC is missing, makes
# $work, defines as_user (halrun as `nobody` when root: rtapi_app refuses root; setpriv, no account
# to create; rtapi_app is setuid root and drops to the real uid itself), places this build's
# module where rtapi_app looks (`loadrt /path/firtp` is refused) and puts back what was there on
# exit, and waits for another HAL session to end: only one can exist per machine (ctest runs these
# under RESOURCE_LOCK linuxcnc). run_halrun FILE (at the end) runs halrun -f FILE: it sets session=1,
# so the exit trap runs `halrun -U`, and runs halrun in the background so a signal reaches the trap.
skip() { echo "SKIPPED: $*"; exit 77; }
[ "$module" != none ] || skip "LinuxCNC's headers are not installed (linuxcnc-uspace-dev), so the LinuxCNC firtp.so was not built (FIRTP_LINUXCNC)"
command -v halrun > /dev/null || skip "halrun not found (linuxcnc-uspace)"
[ -d "$moddir" ] || skip "no LinuxCNC module directory $moddir"
realtime=/usr/lib/linuxcnc/realtime

work=$(mktemp -d /tmp/firtp-lcnc-hal.XXXXXX)
module_name=$(basename "$module")
installed=$moddir/$module_name
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
    if [ -e "$work/$module_name.before" ]; then mv -f "$work/$module_name.before" "$installed"; else rm -f "$installed"; fi
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
  if [ -e "$installed" ]; then cp -p "$installed" "$work/$module_name.before"; fi
  placed=1
  cp "$module" "$moddir/.$module_name.test" && mv -f "$moddir/.$module_name.test" "$installed"
else
  skip "$installed is not this build's and $moddir is not writable: cmake --build BUILD --target install-linuxcnc (as root), or run as root"
fi

# One HAL session per machine: wait for someone else's (or this test's previous one) to end rather
# than break it.
wait_no_session() {
  for _ in $(seq 60); do running || return 0; sleep 1; done
  echo "FAIL: another HAL session (rtapi_app) is still running after 60 s"; exit 1
}
wait_no_session

# Runs $work/$1 (readable by the session's user) under halrun as that user, output in
# $work/halrun.log; fails the test with the log (and the shared memory present) if halrun fails.
# In the background, so a signal reaches the cleanup at once.
run_halrun() {
  wait_no_session
  session=1
  (cd "$work" && as_user timeout 60 halrun -f "$1") > "$work/halrun.log" 2>&1 &
  halrun_pid=$!
  if ! wait "$halrun_pid"; then
    halrun_pid=
    echo "FAIL: halrun -f $1"; cat "$work/halrun.log"; ipcs -m -c; exit 1
  fi
  halrun_pid=
}
