#!/usr/bin/env bash
# examples/hal/pins.hal under real LinuxCNC 2.9 halrun (1 ms servo thread): the block pins' strobe /
# ack handshake as a plain HAL user drives them. The waits are real time here, so the half-way
# values vary; checked: the ack, and at rest 2.5 mm, velocity 0, done. Set-up: hal_session.sh.
set -euo pipefail
module=$1 moddir=$2 hal=$3
here=$(cd "$(dirname "$0")" && pwd)
source "$here/hal_session.sh"

cp "$hal" "$work/pins.hal" && chmod a+r "$work/pins.hal"
run_halrun pins.hal
mapfile -t got < <(grep -v '^Note:' "$work/halrun.log")
echo "getp printed: ${got[*]}"
[ "${#got[@]}" -eq 6 ] || { echo "FAIL: expected 6 values"; exit 1; }
[ "${got[0]}" = TRUE ] || { echo "FAIL: no ack after the strobe"; exit 1; }
[ "${got[3]} ${got[4]} ${got[5]}" = "2.5 0 TRUE" ] || { echo "FAIL: expected at rest 2.5 0 TRUE"; exit 1; }
echo "acked, then at rest exactly on 2.5 mm, done"
