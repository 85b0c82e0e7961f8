#!/usr/bin/env bash
# Reproduces every figure README.md quotes, on this machine (docs/BENCHMARKS.md):
#   tests/bench/reproduce.sh BUILD_DIR [--quick] [--out FILE.md] [--json FILE.json]
#       [--skip-stream] [--skip-linuxcnc] [--skip-ctest] [--plan-timeout S] [--wait-linuxcnc S]
# BUILD_DIR: a Release build (cmake -S . -B BUILD_DIR && cmake --build BUILD_DIR -j2).
set -euo pipefail
exec python3 "$(dirname "$0")/reproduce.py" "$@"
