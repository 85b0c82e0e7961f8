#!/bin/bash
# A wrong HAL setup stops firtp-lcm-bridge at once with what is wrong, and `loadusr -W` fails
# instead of waiting: a sampler channel of another layout, no sampler at all, mode firtp without
# firtp.so; a bad option exits 2 with the usage.
#   setup_errors.sh BRIDGE      (skips, 77, without LinuxCNC, root or unshare -n)
set -u
bridge=$1
skip() { echo "SKIPPED: $*"; exit 77; }
[ "$bridge" != none ] && [ -x "$bridge" ] || skip "firtp-lcm-bridge was not built (FIRTP_LINUXCNC)"
command -v halrun > /dev/null || skip "halrun not found (linuxcnc-uspace)"
[ "$(id -u)" -eq 0 ] && unshare -n true 2> /dev/null || skip "needs root and unshare -n (LCM multicast in a private namespace)"

work=$(mktemp -d /tmp/firtp-lcm-setup.XXXXXX)
uid=$(id -u nobody) gid=$(id -g nobody)
cleanup() {
  local status=$?
  if /usr/lib/linuxcnc/realtime status > /dev/null 2>&1; then
    setpriv --reuid="$uid" --regid="$gid" --clear-groups env HOME="$work" timeout 20 halrun -U > /dev/null 2>&1
  fi
  rm -rf "$work"
  exit $status
}
trap cleanup EXIT
trap 'exit 1' INT TERM
cp "$bridge" "$work/firtp-lcm-bridge"
cat > "$work/cfg.hal" <<'HAL'
loadrt sampler depth=10 cfg=ffb
loadusr -W firtp-lcm-bridge --mode motion --axes 3
HAL
cat > "$work/none.hal" <<'HAL'
loadusr -W firtp-lcm-bridge --mode motion --axes 3 --sampler-channel 2
HAL
cat > "$work/firtp.hal" <<'HAL'
loadusr -W firtp-lcm-bridge --mode firtp --axes 3
HAL
chown -R "$uid:$gid" "$work"
for _ in $(seq 60); do /usr/lib/linuxcnc/realtime status > /dev/null 2>&1 || break; sleep 1; done

fail=0
expect() {  # HAL file, text the output must contain
  local out
  out=$(unshare -n bash -c 'ip link set lo up && ip route add 224.0.0.0/4 dev lo &&
    cd "$0" && setpriv --reuid="$1" --regid="$2" --clear-groups env HOME="$0" PATH="$0:$PATH" timeout 30 halrun -f "$3"' \
    "$work" "$uid" "$gid" "$1" 2>&1)
  local status=$?
  if [ $status -ne 0 ] && grep -qF -- "$2" <<< "$out"; then
    echo "ok: $1 fails (halrun exit $status) saying: $(grep -F -- "$2" <<< "$out" | head -1)"
  else
    echo "FAIL: $1: halrun exit $status, expected an error containing '$2':"; echo "$out"; fail=1
  fi
}
expect cfg.hal "sampler channel 0 has cfg=ffb, expected fffs"
expect none.hal "no sampler channel 2"
expect firtp.hal "cannot create pins or attach to the component's streams (is firtp loaded"
out=$("$bridge" --mode nonsense 2>&1); status=$?
if [ $status -eq 2 ] && grep -q "mode must be firtp or motion" <<< "$out"; then echo "ok: --mode nonsense exits 2"
else echo "FAIL: --mode nonsense: exit $status: $out"; fail=1; fi
[ $fail -eq 0 ] && echo PASS
exit $fail
