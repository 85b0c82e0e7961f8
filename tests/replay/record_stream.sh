#!/usr/bin/env bash
# A 50,000-block program streamed by `firtp host` to `firtp serve` over UDP multicast (loopback, a
# private network namespace), recorded by `firtp record`: nothing may be lost (its exit status and
# per-channel summary), every block must be in the log, and `firtp replay` must reproduce the
# component's axis states from the log alone. Exit 77 (skipped) where no namespace can be made.
#   record_stream.sh FIRTP_BIN FIRTP_LCM_DUMP_BIN INI|- BLOCKS FEED [QUEUE [PATH [SECONDS [REPLAY]]]]
# PATH: spiral (1 mm chords of a 2 m circle) or zigzag (0.5 mm steps across 0.3 mm, the stream
# benchmark's). SECONDS: stop host and component after that long (the log then ends in the middle
# of the motion; the replay compares what was recorded). REPLAY: equal (the replay must equal the
# recording bit for bit: the default) or report (print its result only, for measurements).
# $FIRTP_KEEP=DIR keeps the files there.
set -euo pipefail
firtp=$1 dump=$2 ini=$3 blocks=$4 feed=$5 queue=${6:-1024} path=${7:-spiral} seconds=${8:-0} replay=${9:-equal}
work=${FIRTP_KEEP:-$(mktemp -d)}
mkdir -p "$work"
[ -n "${FIRTP_KEEP:-}" ] || trap 'rm -rf "$work"' EXIT
unshare -n true 2>/dev/null || { echo "no network namespace here (needs root or user namespaces)"; exit 77; }

# BLOCKS blocks at FEED mm/min (tests/replay/stream.ini); the host sends them as fast as the
# component's queue (QUEUE, and its 4096-record stream) takes them.
python3 - "$blocks" "$feed" "$path" > "$work/stream.ngc" <<'PY'
import math, sys
n, feed, path = int(sys.argv[1]), sys.argv[2], sys.argv[3]
r = 2000.0
print(f"G21 G90 G64 P0.01 Q0\nG0 X{r if path == 'spiral' else 0} Y0 Z0\nF{feed}")
for i in range(1, n):
    if path == "spiral":
        print(f"G1 X{r * math.cos(i / r):.4f} Y{r * math.sin(i / r):.4f} Z{i * 0.0001:.4f}")
    else:
        print(f"G1 X{0.5 * i:.1f} Y{0.3 if i % 2 else 0}")
print("M2")
PY

unshare -n bash -s "$firtp" "$ini" "$work" "$queue" "$seconds" <<'INNER'
set -euo pipefail
firtp=$1 ini=$2 work=$3 queue=$4 seconds=$5
limit=(); [ "$seconds" = 0 ] || limit=(timeout -s INT "$seconds")
machine=(--ini "$ini"); [ "$ini" != - ] || machine=()  # -: the built-in machine
ip link set lo up
ip route add 224.0.0.0/4 dev lo
"$firtp" record "$work/stream.lcmlog" --idle 3 --duration 300 > "$work/record.log" 2>&1 &
record=$!
"$firtp" serve "${machine[@]}" --queue "$queue" --exit-when-done --duration $((seconds > 0 ? seconds + 1 : 240)) > "$work/serve.log" 2>&1 &
serve=$!
# The host starts once both listen (each says so when subscribed): a recorder that subscribes
# after the first blocks went out would miss them (a fixed 0.5 s was short on a loaded machine).
for _ in $(seq 300); do
  grep -q '^firtp record: recording' "$work/record.log" && grep -q '^firtp serve: servo thread' "$work/serve.log" && break
  sleep 0.1
done
grep -q '^firtp record: recording' "$work/record.log" && grep -q '^firtp serve: servo thread' "$work/serve.log" \
  || { echo "recorder or component not listening after 30 s"; cat "$work/record.log" "$work/serve.log"; kill $record $serve 2>/dev/null; exit 1; }
start=$(date +%s.%N)
host=0; "${limit[@]}" "$firtp" host "$work/stream.ngc" "${machine[@]}" < /dev/null > "$work/host.log" 2>&1 || host=$?
if [ $host != 0 ] && ! [ $host = 124 -a "$seconds" != 0 ]; then
  echo "host failed ($host)"; cat "$work/host.log" "$work/serve.log"; kill $record $serve 2>/dev/null; exit 1
fi
wait "$serve" || { echo "serve failed"; cat "$work/serve.log"; kill $record; exit 1; }
status=0; wait "$record" || status=$?
end=$(date +%s.%N)
tail -3 "$work/host.log"
cat "$work/serve.log" "$work/record.log"
echo "host to recorder done in $(python3 -c "print(round($end - $start, 1))") s"
exit $status
INNER

# Every block of the program is in the log (the dump tool counts on its own).
"$dump" --count "$work/stream.lcmlog" | tee "$work/count.txt"
grep -Eq "^FIRTP_BLOCK program=[0-9]+ events=[0-9]+ seq=1-$blocks missing=0 " "$work/count.txt" \
  || { echo "the log does not hold blocks 1-$blocks without a gap"; exit 1; }
grep -Eq "^FIRTP_AXIS_STATE .* missing=0 " "$work/count.txt" || { echo "axis states missing"; exit 1; }
# The block rate the recorder kept up with: on average, and in the busiest 100 ms.
"$dump" -c FIRTP_BLOCK "$work/stream.lcmlog" | python3 -c '
import collections, sys
t = [int(line.split()[0]) for line in sys.stdin]
busiest = max(collections.Counter(x // 100000 for x in t).values())
print(f"blocks recorded: {len(t)} in {(t[-1] - t[0]) / 1e6:.2f} s, {len(t) / max(t[-1] - t[0], 1) * 1e6:.0f} blocks/s; busiest 100 ms: {busiest * 10} blocks/s")'
status=0; "$firtp" replay "$work/stream.lcmlog" || status=$?
[ "$replay" = report ] && [ $status = 4 ] && { echo "(replay differs: reported, not checked)"; exit 0; }
exit $status
