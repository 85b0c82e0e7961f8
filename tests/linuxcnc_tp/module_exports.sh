#!/usr/bin/env bash
# firtp_tp.so defines every tp* and tcqFull symbol motmod.so leaves undefined (motmod fails to load
# otherwise), and exports nothing else but rtapi_app_main, rtapi_app_exit and rtapi_info_*: rtapi_app
# opens modules RTLD_GLOBAL, so the C++ core inside (also in firtp.so) must stay local. Exit 77
# without LinuxCNC.
set -euo pipefail
module=$1 motmod=$2
[ "$module" != none ] || { echo "SKIPPED: LinuxCNC's headers are not installed, firtp_tp.so was not built"; exit 77; }
[ -e "$motmod" ] || { echo "SKIPPED: no $motmod (linuxcnc-uspace)"; exit 77; }
defined=$(nm -D --defined-only "$module" | awk '{print $3}')
needed=$(nm -D "$motmod" | awk '$1 == "U" && $2 ~ /^(tp|tcq)/ {print $2}')
echo "motmod.so needs $(wc -l <<< "$needed") planner symbols"
[ "$(wc -l <<< "$needed")" -eq 30 ] || { echo "FAIL: expected 30 (29 tp* and tcqFull)"; exit 1; }
for symbol in $needed rtapi_app_main rtapi_app_exit; do
  grep -qx "$symbol" <<< "$defined" || { echo "FAIL: $symbol is not exported by $module"; exit 1; }
done
others=$(grep -Ev '^(rtapi_app_main|rtapi_app_exit|rtapi_info_[A-Za-z0-9_]+)$' <<< "$defined" | grep -vxF "$needed" || true)
[ -z "$others" ] || { echo "FAIL: exported beyond motmod's needs and rtapi_*:"; echo "$others"; exit 1; }
echo "all 30 defined; nothing else global ($(wc -l <<< "$defined") symbols with rtapi_*)"
