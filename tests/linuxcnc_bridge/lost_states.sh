#!/bin/bash
# A bridge that falls behind loses periods only as counted ones: firtp-lcm-bridge on a 1 ms thread
# with a 50-record stream is stopped (SIGSTOP) for 0.5 s; the stream overflows, and what reaches
# LCM must show it: a gap in the ticks (the seq stays consecutive), a status with error 7 naming as
# many lost periods as the gap, and the writer's count equal (mode motion: the sampler's stream,
# pin firtp-lcm-bridge.lost; with FIRTP_SO, mode firtp: firtp.so's axis-state stream, pin
# firtp.state-overruns). Then SIGTERM ends it cleanly (hal_exit: halrun unloads without complaint).
#   lost_states.sh BRIDGE STATES-TOOL [FIRTP_SO]     (skips, 77, without LinuxCNC, root or unshare -n)
set -u
bridge=$1 states=$2 firtp_so=${3:-}
moddir=/usr/lib/linuxcnc/modules
skip() { echo "SKIPPED: $*"; exit 77; }
[ "$bridge" != none ] && [ -x "$bridge" ] || skip "firtp-lcm-bridge was not built (FIRTP_LINUXCNC)"
command -v halrun > /dev/null || skip "halrun not found (linuxcnc-uspace)"
[ "$(id -u)" -eq 0 ] && unshare -n true 2> /dev/null || skip "needs root and unshare -n (LCM multicast in a private namespace)"
[ "$firtp_so" != none ] || skip "the LinuxCNC firtp.so was not built (FIRTP_LINUXCNC)"

work=$(mktemp -d /tmp/firtp-lcm-lost.XXXXXX)
uid=$(id -u nobody) gid=$(id -g nobody)
as_user() { setpriv --reuid="$uid" --regid="$gid" --clear-groups env HOME="$work" PATH="$work:$PATH" "$@"; }
cleanup() {
  local status=$?
  if /usr/lib/linuxcnc/realtime status > /dev/null 2>&1; then as_user timeout 20 halrun -U > /dev/null 2>&1; fi
  if [ -n "$firtp_so" ]; then  # put back the module directory's firtp.so
    if [ -e "$work/firtp.so.before" ]; then mv -f "$work/firtp.so.before" "$moddir/firtp.so"; else rm -f "$moddir/firtp.so"; fi
  fi
  rm -rf "$work"
  exit $status
}
trap cleanup EXIT
trap 'exit 1' INT TERM
cp "$bridge" "$work/firtp-lcm-bridge"
cat > "$work/pause" <<'PAUSE'
#!/bin/sh
# stop the bridge for 0.5 s while the servo thread keeps sampling
sleep 0.5; pid=$(pgrep -f '^firtp-lcm-bridge --mode'); kill -STOP $pid; sleep 0.5; kill -CONT $pid; sleep 0.5
halcmd getp firtp-lcm-bridge.lost > lost.txt
PAUSE
chmod +x "$work/pause"
if [ -z "$firtp_so" ]; then
  counter=firtp-lcm-bridge.lost
  writer='loadrt sampler depth=50 cfg=fffs
addf sampler.0 servo-thread'
  mode=motion
else
  counter=firtp.state-overruns
  writer='loadrt firtp axes=3 t1=0.1 t2=0.05 stream_depth=50
addf firtp.update servo-thread'
  mode=firtp
  [ -e "$moddir/firtp.so" ] && cp -p "$moddir/firtp.so" "$work/firtp.so.before"
  cp "$firtp_so" "$moddir/.firtp.so.test" && mv -f "$moddir/.firtp.so.test" "$moddir/firtp.so"
fi
sed -i "s/^halcmd getp .*/halcmd getp $counter > lost.txt/" "$work/pause"
cat > "$work/lost.hal" <<HAL
loadrt threads name1=servo-thread period1=1000000
$writer
loadusr -W firtp-lcm-bridge --mode $mode --axes 3 --period-ns 1000000
start
loadusr -w ./pause
unloadusr firtp-lcm-bridge
HAL
chown -R "$uid:$gid" "$work"
for _ in $(seq 60); do /usr/lib/linuxcnc/realtime status > /dev/null 2>&1 || break; sleep 1; done

export work states uid gid
unshare -n bash -c '
  ip link set lo up && ip route add 224.0.0.0/4 dev lo || exit 3
  "$states" record "$work/states.lcmlog" > "$work/record.log" 2>&1 & recorder=$!
  sleep 0.3
  (cd "$work" && setpriv --reuid="$uid" --regid="$gid" --clear-groups env HOME="$work" PATH="$work:$PATH" \
     timeout 60 halrun -f lost.hal) > "$work/halrun.log" 2>&1
  status=$?
  sleep 0.2; kill -INT $recorder; wait $recorder
  exit $status' || { echo "FAIL: halrun"; cat "$work/halrun.log"; exit 1; }
cat "$work/halrun.log"

out=$("$states" samples "$work/states.lcmlog" "$work/samples.txt")
echo "$out"
missing=$(sed -n 's/.*(\([0-9]*\) periods missing).*/\1/p' <<< "$out")
seq_gaps=$(sed -n 's/^gaps *\([0-9]*\) in seq.*/\1/p' <<< "$out")
reported=$(sed -n 's/^last report *\([0-9]*\) axis states lost.*/\1/p' <<< "$out")
pin=$(tr -d '[:space:]' < "$work/lost.txt")
echo "missing periods $missing, last status reports $reported, $counter = $pin, seq gaps $seq_gaps"
fail=0
[ "${missing:-0}" -gt 0 ] || { echo "FAIL: no period was lost: the test did not overflow the stream"; fail=1; }
[ "${seq_gaps:-1}" -eq 0 ] || { echo "FAIL: the axis-state seq has gaps (LCM lost messages)"; fail=1; }
[ "${reported:-x}" = "${missing:-y}" ] || { echo "FAIL: the status reports ${reported:-nothing}, the ticks miss $missing"; fail=1; }
[ "$pin" = "${missing:-y}" ] || { echo "FAIL: $counter is $pin, the ticks miss $missing"; fail=1; }
grep -q "axis states published" "$work/halrun.log" || { echo "FAIL: the bridge did not exit cleanly on unload"; fail=1; }
[ $fail -eq 0 ] && echo PASS
exit $fail
