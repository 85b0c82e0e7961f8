#!/usr/bin/env bash
# Runs firtp_stream_bench over UDP multicast on loopback in a private network namespace (root).
#   tests/bench/stream_bench.sh [build dir] [bench args...]
set -euo pipefail
build=${1:-build}; shift || true
exec unshare -n bash -c 'ip link set lo up; ip route add 224.0.0.0/4 dev lo; FIRTP_MODULE="$0/lib/firtp.so" "$0/bin/firtp_stream_bench" "$@"' "$build" "$@"
