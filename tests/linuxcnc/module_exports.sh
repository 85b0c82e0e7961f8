#!/usr/bin/env bash
# The LinuxCNC firtp.so exports only what rtapi_app looks up (rtapi_app_main, rtapi_app_exit,
# rtapi_info_*): rtapi_app opens every module RTLD_GLOBAL, so the C++ core inside must stay local
# or it would clash with another module holding the same core (firtp_tp). Exit 77 without LinuxCNC.
set -euo pipefail
module=$1
[ "$module" != none ] || { echo "SKIPPED: LinuxCNC's headers are not installed, the LinuxCNC firtp.so was not built"; exit 77; }
defined=$(nm -D --defined-only "$module" | awk '{print $3}')
echo "$(wc -l <<< "$defined") defined dynamic symbols in $module"
for symbol in rtapi_app_main rtapi_app_exit rtapi_info_address_t1 rtapi_info_type_t1 rtapi_info_license; do
  grep -qx "$symbol" <<< "$defined" || { echo "FAIL: $symbol is not exported"; exit 1; }
done
others=$(grep -Ev '^(rtapi_app_main|rtapi_app_exit|rtapi_info_[A-Za-z0-9_]+)$' <<< "$defined" || true)
[ -z "$others" ] || { echo "FAIL: exported beyond rtapi_app_main, rtapi_app_exit, rtapi_info_*:"; echo "$others"; exit 1; }
echo "only rtapi_app_main, rtapi_app_exit and rtapi_info_* are global"
