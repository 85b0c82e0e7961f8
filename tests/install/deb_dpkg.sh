#!/usr/bin/env bash
# The package really installed and removed: dpkg -i, then the installed firtp runs, man finds the
# pages, and halrun (as nobody) loads firtp.so by name from where dpkg put it; dpkg -r then leaves
# none of its files behind (nothing left to purge either). Changes the system, so it runs only as
# root with FIRTP_TEST_DPKG=1 (`FIRTP_TEST_DPKG=1 flock /tmp/firtp-hal.lock ctest -L package`), and
# never where a firtp package is installed already. Module files that were in LinuxCNC's module directory before (install-linuxcnc,
# a HAL test) are put back afterwards.
set -euo pipefail
build=$(cd "$1" && pwd) moddir=$2
skip() { echo "SKIPPED: $*"; exit 77; }
[ "$(id -u)" -eq 0 ] || skip "needs root (dpkg -i)"
[ "${FIRTP_TEST_DPKG:-0}" = 1 ] || skip "changes the system: run with FIRTP_TEST_DPKG=1 (ctest -L package)"
command -v dpkg > /dev/null || skip "no dpkg"
if [[ "$(dpkg-query -W -f='${Status}' firtp 2> /dev/null || true)" == *installed* ]]; then skip "a firtp package is installed already"; fi
work=$(mktemp -d /tmp/firtp-dpkg.XXXXXX)
chmod 755 "$work"
installed=0
modules=(firtp.so firtp_tp.so)
cleanup() {
  local status=$?
  if ((installed)); then dpkg -P firtp > /dev/null 2>&1 || echo "dpkg -P firtp failed" >&2; fi
  for m in "${modules[@]}"; do
    if [ -e "$work/$m.before" ]; then cp -p "$work/$m.before" "$moddir/.$m.new" && mv -f "$moddir/.$m.new" "$moddir/$m"; fi
  done
  rm -rf "$work"
  exit $status
}
trap cleanup EXIT
trap 'exit 1' INT TERM
fail() { echo "FAIL: $*"; exit 1; }
for m in "${modules[@]}"; do
  if [ -e "$moddir/$m" ]; then cp -p "$moddir/$m" "$work/$m.before"; fi
done

here=$(cd "$(dirname "$0")" && pwd)
source "$here/make_deb.sh"
dpkg-deb -c "$deb" | awk '{print $6}' | sed 's|^\./|/|' | grep -v '/$' > "$work/files.txt"

installed=1
dpkg -i "$deb" > "$work/dpkg.log" 2>&1 || { cat "$work/dpkg.log"; fail "dpkg -i"; }
echo "dpkg -i: $(dpkg-query -W -f='${Package} ${Version} ${Status}' firtp)"
listed=$(dpkg -L firtp)
grep -qx "$moddir/firtp_tp.so" <<< "$listed" || fail "dpkg -L firtp does not list $moddir/firtp_tp.so"
while read -r f; do [ -e "$f" ] || fail "$f missing after dpkg -i"; done < "$work/files.txt"

(cd "$work" && /usr/bin/firtp plan /usr/share/doc/firtp/examples/diamond.ngc --ini /usr/share/doc/firtp/examples/diamond.ini > plan.txt) ||
  fail "/usr/bin/firtp plan"
grep -q 'all within tolerance' "$work/plan.txt" || fail "installed firtp plan"
[ "$(man -w 9 firtp_tp)" = /usr/share/man/man9/firtp_tp.9.gz ] || fail "man -w 9 firtp_tp: $(man -w 9 firtp_tp 2>&1)"
echo "installed: firtp plans the installed diamond; man 9 firtp_tp is /usr/share/man/man9/firtp_tp.9.gz"

if command -v halrun > /dev/null; then
  if /usr/lib/linuxcnc/realtime status > /dev/null 2>&1; then fail "another HAL session is running"; fi
  uid=$(id -u nobody) gid=$(id -g nobody)
  mkdir "$work/hal" && chown "$uid:$gid" "$work/hal"  # halrun's HOME and directory: rtapi_app binds a socket there
  printf 'loadrt firtp tolerance=0.03 max_acceleration=5000,5000,5000\nshow param firtp.tolerance\n' > "$work/hal/load.hal"
  chmod a+r "$work/hal/load.hal"
  as_nobody() { (cd "$work/hal" && setpriv --reuid="$uid" --regid="$gid" --clear-groups env HOME="$work/hal" "$@"); }
  as_nobody timeout 60 halrun -f load.hal > "$work/halrun.log" 2>&1 ||
    { as_nobody halrun -U > /dev/null 2>&1 || true; cat "$work/halrun.log"; fail "halrun: loadrt firtp from the package"; }
  as_nobody halrun -U > /dev/null 2>&1 || true
  grep -qE 'RO +0\.03 +firtp\.tolerance' "$work/halrun.log" || { cat "$work/halrun.log"; fail "halrun: no firtp.tolerance 0.03"; }
  echo "halrun (as nobody): loadrt firtp found the packaged module; firtp.tolerance 0.03"
fi

if [ -e "$moddir/firtp_tp.so" ]; then  # install-linuxcnc's way back leaves the package's modules alone
  cmake --build "$build" --target uninstall-linuxcnc > "$work/uninstall.log" 2>&1 || { cat "$work/uninstall.log"; fail "uninstall-linuxcnc"; }
  [ -e "$moddir/firtp_tp.so" ] && [ -e "$moddir/firtp.so" ] || fail "uninstall-linuxcnc removed a module the package owns"
  grep -q 'belongs to the package firtp' "$work/uninstall.log" || { cat "$work/uninstall.log"; fail "uninstall-linuxcnc did not say why it left them"; }
  echo "uninstall-linuxcnc: leaves the package's modules to dpkg"
fi

dpkg -r firtp > "$work/dpkg.log" 2>&1 || { cat "$work/dpkg.log"; fail "dpkg -r firtp"; }
left=$(while read -r f; do [ ! -e "$f" ] || echo "$f"; done < "$work/files.txt")
[ -z "$left" ] || fail "left behind after dpkg -r: $left"
[ ! -e /usr/share/doc/firtp ] && [ ! -e /usr/lib/firtp ] && [ ! -e /usr/share/firtp ] || fail "directories left behind"
status=$(dpkg-query -W -f='${Status}' firtp 2> /dev/null || true)
[ -z "$status" ] || [ "$status" = "unknown ok not-installed" ] || fail "after dpkg -r firtp is '$status' (no conffiles: nothing should remain)"
installed=0
echo "dpkg -r: all $(wc -l < "$work/files.txt") files and the package's directories gone, nothing left for dpkg -P"
echo "PASS"
