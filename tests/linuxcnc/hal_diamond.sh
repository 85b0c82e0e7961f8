#!/usr/bin/env bash
# firtp.so in real LinuxCNC 2.9 (halrun, POSIX non-realtime, 1 ms servo thread) against hal-shim:
# the diamond's blocks go in through the block pins (LinuxCNC's streamer, one row a period), the
# axis pins are recorded every period (sampler + halsampler), and every period must equal
# firtp-hal running the same firtp part of the script, within 1e-9 (firtp-lcnc-hal-run compare).
# Session set-up (as `nobody`, this build's module in place, one session a machine, skip where
# LinuxCNC is missing): hal_session.sh.
set -euo pipefail
tool=$1 module=$2 firtp_hal=$3 shim_modules=$4 moddir=$5 examples=$6
begin=$(date +%s%N)
source "$(dirname "$0")/hal_session.sh"

"$tool" prepare "$examples/diamond.ngc" "$examples/diamond.ini" "$work"
chmod a+r "$work"/*

# LinuxCNC
lcnc_begin=$(date +%s%N)
run_halrun linuxcnc.hal
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
