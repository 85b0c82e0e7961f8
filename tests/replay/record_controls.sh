#!/usr/bin/env bash
# Records the golden log with operator controls, tests/replay/diamond_controls.lcmlog: `firtp host`
# streams the diamond to `firtp serve` over UDP multicast (loopback, a private network namespace)
# while an operator's commands arrive on its stdin at wall-clock times, so each control reaches the
# component in whatever servo period it happens to, as on a machine: the feed override down to 0.6
# mid-program, a hold on the path, a resume, the feed override back to 1. `firtp record` writes the
# log; it must hold every message (nothing lost) and replay equal bit for bit. The test
# replay.record_serve_host_controls records a new one in every run (the controls land in other
# periods each time).
#   record_controls.sh FIRTP_BIN OUT.lcmlog        (from the repository's root; needs unshare -n)
set -euo pipefail
firtp=$(realpath "$1") out=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
unshare -n true 2>/dev/null || { echo "no network namespace here (needs root or user namespaces)"; exit 77; }

unshare -n bash -s "$firtp" "$work" <<'INNER'
set -euo pipefail
firtp=$1 work=$2
ip link set lo up
ip route add 224.0.0.0/4 dev lo
# listening LOG TEXT: wait (up to 30 s) until the process logging to LOG says TEXT, which each
# says once subscribed.
listening() {
  for _ in $(seq 300); do grep -q "$2" "$1" && return 0; sleep 0.1; done
  echo "not listening after 30 s:"; cat "$1"; return 1
}
"$firtp" record "$work/controls.lcmlog" --idle 2 --duration 60 > "$work/record.log" 2>&1 &
record=$!
listening "$work/record.log" '^firtp record: recording'  # serve publishes FIRTP_CONFIG at start
"$firtp" serve --ini examples/diamond.ini --exit-when-done --duration 30 > "$work/serve.log" 2>&1 &
serve=$!
listening "$work/serve.log" '^firtp serve: servo thread'
{ sleep 0.35; echo "feed 0.6"; sleep 0.35; echo hold; sleep 0.6; echo resume; sleep 0.4; echo "feed 1"; sleep 5; } |
  "$firtp" host examples/diamond.ngc --ini examples/diamond.ini > "$work/host.log" 2>&1 ||
  { echo "host failed"; cat "$work/host.log" "$work/serve.log"; kill $record $serve; exit 1; }
wait "$serve" || { echo "serve failed"; cat "$work/serve.log"; kill $record; exit 1; }
wait "$record" || { cat "$work/record.log"; exit 1; }
cat "$work/host.log" "$work/record.log"
INNER
cp "$work/controls.lcmlog" "$out"
# Equal bit for bit, every control placed by the states (the host republishes every 100 ms: more
# than the operator's four).
"$firtp" replay "$out" | tee "$work/replay.txt"
grep -Eq "^fed +[0-9]+ blocks and ([5-9]|[1-9][0-9]+) controls in the periods" "$work/replay.txt" ||
  { echo "the axis states did not place the controls"; exit 1; }
