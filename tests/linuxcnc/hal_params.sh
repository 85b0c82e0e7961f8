#!/usr/bin/env bash
# firtp.so's load-time settings under real LinuxCNC 2.9 halrun: `halcmd show param firtp` lists each
# as a read-only param with the value in effect, for given module parameters and for the defaults.
# Set-up: hal_session.sh.
set -euo pipefail
module=$1 moddir=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/hal_session.sh"

# Two sessions, one per load: a reload within one session is rtapi_app's business, not this test's
# (under load, CI saw that second loadrt fail with no message from firtp).
cat > "$work/given.hal" << 'HAL'
loadrt firtp axes=2 stages=3 t1=0.1 t2=0.05 t3=0.02 tolerance=0.02 meaning=contour period_ns=500000 max_velocity=100,200 max_acceleration=1000,2000 max_jerk=50000,60000 queue=64 max_blocks=8 plan_budget_us=100 block_key=0 state_key=0 stream_depth=16 max_feed_override=1.5 rate_reserve=0.3 brake_speed=2
show param firtp
HAL
cat > "$work/defaults.hal" << 'HAL'
loadrt firtp max_acceleration=5000,5000,5000
show param firtp
HAL
chmod a+r "$work/given.hal" "$work/defaults.hal"
run_halrun given.hal
mv "$work/halrun.log" "$work/given.log"
run_halrun defaults.hal
mv "$work/halrun.log" "$work/defaults.log"

# LinuxCNC prints "Owner Type Dir Value Name" per show.
# (LinuxCNC adds firtp.update.tmax and tmax-increased, the function's own, not counted)
params() { awk '($3 == "RO" || $3 == "RW") && $5 !~ /^firtp\.update\./ {print $3, $4, $5}' "$1"; }
params "$work/given.log" > "$work/given.txt"
params "$work/defaults.log" > "$work/defaults.txt"

check() {  # FILE NAME VALUE: NAME is a read-only param of that value
  local line
  line=$(awk -v n="$2" '$3 == n' "$1")
  [ -n "$line" ] || { echo "FAIL: no param $2 ($1)"; cat "$1"; exit 1; }
  [ "$line" = "RO $3 $2" ] || { echo "FAIL: $2: got '$line', expected 'RO $3 $2'"; exit 1; }
}
given=(firtp.axes 2  firtp.fixed-chain TRUE  firtp.stages 3  firtp.t1 0.1  firtp.t2 0.05  firtp.t3 0.02  firtp.t4 0
  firtp.tolerance 0.02  firtp.contour TRUE  firtp.period-ns 500000  firtp.queue 64  firtp.max-blocks 8
  firtp.plan-budget-us 100  firtp.block-key 0  firtp.state-key 0  firtp.stream-depth 16  firtp.max-feed-override 1.5
  firtp.rate-reserve 0.3  firtp.brake-speed 2  firtp.axis.0.max-velocity 100  firtp.axis.1.max-velocity 200
  firtp.axis.0.max-acceleration 1000  firtp.axis.1.max-acceleration 2000  firtp.axis.0.max-jerk 50000
  firtp.axis.1.max-jerk 60000)
for ((i = 0; i < ${#given[@]}; i += 2)); do check "$work/given.txt" "${given[i]}" "${given[i + 1]}"; done
[ "$(wc -l < "$work/given.txt")" -eq 25 ] || { echo "FAIL: expected 25 params for 2 axes"; cat "$work/given.txt"; exit 1; }
defaults=(firtp.axes 3  firtp.fixed-chain FALSE  firtp.stages 0  firtp.t1 0  firtp.tolerance 0.05  firtp.contour FALSE
  firtp.period-ns 1000000  firtp.queue 1024  firtp.max-blocks 32  firtp.plan-budget-us 250
  firtp.block-key 1179210306  firtp.state-key 1179210323  firtp.stream-depth 4096  firtp.max-feed-override 1
  firtp.rate-reserve 0.2  firtp.brake-speed 1  firtp.axis.2.max-acceleration 5000  firtp.axis.2.max-jerk 0
  firtp.axis.2.max-velocity 0)
for ((i = 0; i < ${#defaults[@]}; i += 2)); do check "$work/defaults.txt" "${defaults[i]}" "${defaults[i + 1]}"; done
[ "$(wc -l < "$work/defaults.txt")" -eq 28 ] || { echo "FAIL: expected 28 params for 3 axes"; cat "$work/defaults.txt"; exit 1; }
echo "show param firtp: $(wc -l < "$work/given.txt") read-only params with the given settings, $(wc -l < "$work/defaults.txt") with the defaults, each as in effect"
