#!/usr/bin/env bash
# firtp serve and firtp host as two processes over UDP multicast in a private network namespace
# (loopback with a multicast route): the host's recorded trajectory must equal firtp plan's.
# Exit 77 (skipped) where no network namespace can be made.
set -euo pipefail
firtp=$1 examples=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unshare -n true 2>/dev/null || { echo "no network namespace here (needs root or user namespaces)"; exit 77; }

"$firtp" plan "$examples/diamond.ngc" --ini "$examples/diamond.ini" --csv "$work/plan.csv" > /dev/null
unshare -n bash -s "$firtp" "$examples" "$work" <<'INNER'
set -euo pipefail
firtp=$1 examples=$2 work=$3
ip link set lo up
ip route add 224.0.0.0/4 dev lo
"$firtp" serve --ini "$examples/diamond.ini" --exit-when-done --duration 60 > "$work/serve.log" 2>&1 &
serve=$!
sleep 0.5
"$firtp" host "$examples/diamond.ngc" --ini "$examples/diamond.ini" --csv "$work/host.csv" < /dev/null > "$work/host.log" 2>&1 \
  || { cat "$work/host.log" "$work/serve.log"; exit 1; }
wait "$serve" || { cat "$work/serve.log"; exit 1; }
INNER
python3 - "$work/plan.csv" "$work/host.csv" <<'PY'
import csv, sys
plan = list(csv.reader(open(sys.argv[1])))
host = list(csv.reader(open(sys.argv[2])))
assert plan[0][:4] == ["t", "x", "y", "z"] and host[0][:4] == ["t", "x", "y", "z"]
assert len(plan) == len(host), f"{len(host)} rows over UDP, {len(plan)} planned"
worst = max(abs(float(a[i]) - float(b[i])) for a, b in zip(plan[1:], host[1:]) for i in (1, 2, 3))
print(f"{len(host) - 1} samples over UDP multicast, largest difference from the plan {worst:g} mm")
assert worst <= 1e-9, worst
PY
