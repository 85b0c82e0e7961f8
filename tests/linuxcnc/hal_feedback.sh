#!/usr/bin/env bash
# firtp.so's pos-fb / vel-fb in real LinuxCNC 2.9 (halrun, 1 ms servo thread): feedback.hal, whose
# getp lines must print exactly the expected values. Session set-up: hal_session.sh.
set -euo pipefail
module=$1 moddir=$2
here=$(cd "$(dirname "$0")" && pwd)
source "$here/hal_session.sh"

cp "$here/feedback.hal" "$work/" && chmod a+r "$work/feedback.hal"
run_halrun feedback.hal
got=$(grep -v '^Note:' "$work/halrun.log" | tr '\n' ' ')
want="12.5 5 12.5 -4.25 0 19 -5.55 0 4 8 "
echo "getp printed: $got"
[ "$got" = "$want" ] || { echo "FAIL: expected $want"; exit 1; }
echo "disabled: pos-cmd followed pos-fb (12.5, state 5); enabled at rest: no motion; enabled while moving at (100, -20) mm/s: braked to (19, -5.55), error 8"
