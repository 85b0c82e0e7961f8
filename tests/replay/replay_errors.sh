#!/usr/bin/env bash
# firtp replay and firtp record on damaged logs (tests/replay/edit_log.py): each problem gets its
# exit status and a message naming it.   replay_errors.sh FIRTP_BIN REPLAY_DIR EXAMPLES_DIR
set -euo pipefail
firtp=$1 dir=$2 examples=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
log=$dir/diamond.lcmlog
edit() { python3 "$dir/edit_log.py" "$log" "$work/$1.lcmlog" "${@:2}"; }

# expect NAME STATUS REGEX COMMAND...: COMMAND exits STATUS and its output matches REGEX.
expect() {
  local name=$1 want=$2 regex=$3 status=0
  shift 3
  "$@" > "$work/out.txt" 2>&1 || status=$?
  if [ "$status" != "$want" ] || ! grep -Eq "$regex" "$work/out.txt"; then
    echo "FAIL $name: exit $status (want $want), output:"; cat "$work/out.txt"; exit 1
  fi
  echo "ok   $name: exit $status, $(grep -Em1 "$regex" "$work/out.txt")"
}

expect "the golden log replays" 0 "result +equal" "$firtp" replay "$log"
expect "bit for bit" 0 "result +equal" "$firtp" replay "$log" --tolerance 0
# Another machine: the states differ, and the first difference is named.
expect "another machine differs" 4 "position X: recorded .*, replayed " \
  "$firtp" replay "$log" --ini "$examples/diamond_modes.ini"
expect "where it differs" 4 "first difference: FIRTP_AXIS_STATE seq [0-9]+ \\(log event [0-9]+, tick [0-9]+, t = " \
  "$firtp" replay "$log" --ini "$examples/diamond_modes.ini"
# An intact log that says something else: one axis state's position X changed by its lowest bit
# (crc recomputed) is a difference, named at that state.
edit nudged nudge FIRTP_AXIS_STATE 700
expect "an altered state, named" 4 "first difference: FIRTP_AXIS_STATE seq 700 \\(log event [0-9]+, tick 699, " \
  "$firtp" replay "$work/nudged.lcmlog"
expect "an altered state: position X" 4 "^  position X: recorded " "$firtp" replay "$work/nudged.lcmlog"
edit no_config strip FIRTP_CONFIG
expect "no machine in the log" 1 "no FIRTP_CONFIG in the log" "$firtp" replay "$work/no_config.lcmlog"
expect "no machine, --ini given" 0 "result +equal" "$firtp" replay "$work/no_config.lcmlog" --ini "$examples/diamond.ini"
edit dropped drop FIRTP_AXIS_STATE 100
expect "axis states missing" 1 "1 axis states missing before FIRTP_AXIS_STATE seq 101 \\(event [0-9]+\\)" "$firtp" replay "$work/dropped.lcmlog"
edit no_block drop FIRTP_BLOCK 2
expect "a block missing" 1 "misses 2 of its blocks 1..5 \\(first: seq 2\\)" "$firtp" replay "$work/no_block.lcmlog"
# Operator controls, each fed in the period its axis state names (record_controls.sh made this log:
# feed override, hold, resume and override again, sent at wall-clock times during the diamond).
controls=$dir/diamond_controls.lcmlog
expect "the log with controls replays" 0 "result +equal" "$firtp" replay "$controls"
expect "its controls placed by the states" 0 "^fed +5 blocks and 21 controls in the periods the axis states name" \
  "$firtp" replay "$controls"
# A control the component applied, missing from the log (every 5th dropped: seq 5, the override to
# 0.6, applied in the period of axis state 820): named, nothing replayed.
python3 "$dir/edit_log.py" "$controls" "$work/no_control.lcmlog" drop FIRTP_CONTROL 5
expect "an applied control missing" 1 \
  "FIRTP_AXIS_STATE seq 820 \\(log event [0-9]+\\) says control session [0-9]+ seq 5 was taken, but the log does not hold it" \
  "$firtp" replay "$work/no_control.lcmlog"
# A log from before axis_state_t named the control applied: refused, naming the fields it lacks.
edit old old FIRTP_AXIS_STATE
expect "axis states without the control fields" 1 \
  "event [0-9]+ on FIRTP_AXIS_STATE: an axis_state_t without control_session and control_seq" \
  "$firtp" replay "$work/old.lcmlog"
edit flipped flip FIRTP_BLOCK 3
expect "a corrupted block" 1 "event [0-9]+ on FIRTP_BLOCK: corrupted: CRC mismatch" "$firtp" replay "$work/flipped.lcmlog"
expect "no such log" 1 "no log file" "$firtp" replay "$work/none.lcmlog"
expect "no log given" 2 "missing LOG.lcmlog" "$firtp" replay

# Several runs of the component in one log (FIRTP_CONFIG's seq starts again: serve run twice, a
# restarted LinuxCNC): replayed run by run, each with its own machine; --run N replays one.
python3 "$dir/edit_log.py" "$log" "$work/two_runs.lcmlog" append "$controls"
expect "two runs: both equal" 0 "^all runs +2 equal" "$firtp" replay "$work/two_runs.lcmlog"
expect "two runs: the second's events" 0 "^run +2 \\(log events 1421-5410\\)" "$firtp" replay "$work/two_runs.lcmlog"
expect "--run 2: its controls" 0 "^fed +5 blocks and 21 controls in the periods" "$firtp" replay "$work/two_runs.lcmlog" --run 2
expect "--run 3: no such run" 1 "holds 2 runs of the component, not a run 3" "$firtp" replay "$work/two_runs.lcmlog" --run 3
python3 "$dir/edit_log.py" "$log" "$work/two_nudged.lcmlog" append "$work/nudged.lcmlog"
expect "two runs: the second differs" 4 "^all runs +1 of 2 DIFFERENT" "$firtp" replay "$work/two_nudged.lcmlog"
# A run that starts with a running component (firtp-lcm-bridge restarted under firtp.so, or the
# recorder started late): refused, naming the run and its first tick; the run before replays alone.
python3 "$dir/edit_log.py" "$log" "$work/late.lcmlog" from FIRTP_AXIS_STATE 300
python3 "$dir/edit_log.py" "$log" "$work/restarted.lcmlog" append "$work/late.lcmlog"
expect "a run from tick 299: refused" 1 \
  "run 2 of 2 \\(log events [0-9]+-[0-9]+\\): its first axis state \\(FIRTP_AXIS_STATE seq 300, event [0-9]+\\) is tick 299 of a component that had taken blocks or controls before" \
  "$firtp" replay "$work/restarted.lcmlog"
expect "the run before it, alone" 0 "result +equal" "$firtp" replay "$work/restarted.lcmlog" --run 1
# A recorder started a few periods after the component, before it took anything (as
# record_controls.sh's often is): replayed from tick 0, those periods unchecked, equal.
python3 "$dir/edit_log.py" "$controls" "$work/late_fresh.lcmlog" from FIRTP_AXIS_STATE 18
expect "started 17 periods late, nothing taken yet" 0 "^compared +3422 states, largest difference 0 " \
  "$firtp" replay "$work/late_fresh.lcmlog"
# firtp-lcm-bridge started again under a running firtp.so (its FIRTP_CONFIG and the states' seq
# from 1, the ticks going on, the old bridge's control named 0, 0): one run, equal.
python3 "$dir/edit_log.py" "$controls" "$work/bridge_restart.lcmlog" restart FIRTP_AXIS_STATE 1500
expect "a bridge restart: one run" 0 "^restart +of the bridge at FIRTP_AXIS_STATE log event [0-9]+ \\(tick 1499\\): the component ran on, one run$" \
  "$firtp" replay "$work/bridge_restart.lcmlog"
expect "a bridge restart: equal" 0 "^compared +3439 states, largest difference 0 " "$firtp" replay "$work/bridge_restart.lcmlog"
# Restarted without a FIRTP_CONFIG of its own: the axis states start again at seq 1, named.
python3 "$dir/edit_log.py" "$work/no_config.lcmlog" "$work/no_config_twice.lcmlog" append "$work/no_config.lcmlog"
expect "a restart without FIRTP_CONFIG" 1 "the axis states start again at FIRTP_AXIS_STATE seq 1 \\(event [0-9]+\\) without a new FIRTP_CONFIG" \
  "$firtp" replay "$work/no_config_twice.lcmlog" --ini "$examples/diamond.ini"

# The recorder's accounting, fed by LCM's file:// provider (the same receive path as udpm://).
expect "record: nothing lost" 0 "nothing lost" \
  "$firtp" record "$work/copy.lcmlog" --lcm-url "file://$log?speed=0" --idle 1 --duration 30
expect "record: the copy replays" 0 "result +equal" "$firtp" replay "$work/copy.lcmlog"
expect "record: missing named" 4 "FIRTP_AXIS_STATE: [0-9]+ messages, missing 12, .*LOST" \
  "$firtp" record "$work/lost.lcmlog" --lcm-url "file://$work/dropped.lcmlog?speed=0" --idle 1 --duration 30
edit twice dup FIRTP_STATUS 10
expect "record: repeats named" 4 "FIRTP_STATUS: [0-9]+ messages, missing 0, repeated [1-9][0-9]*, .*LOST" \
  "$firtp" record "$work/twice_copy.lcmlog" --lcm-url "file://$work/twice.lcmlog?speed=0" --idle 1 --duration 30
expect "record: corrupted named" 4 "FIRTP_BLOCK: 4 messages, .*corrupted 1  LOST" \
  "$firtp" record "$work/flipped_copy.lcmlog" --lcm-url "file://$work/flipped.lcmlog?speed=0" --idle 1 --duration 30
# Two runs of the component (FIRTP_CONFIG's seq starts again): counted per run, nothing lost
# (before, the second run's seqs counted as repeats); the controls per host session.
expect "record: two runs, nothing lost" 0 "^the component started again 1 time .*\n?" \
  "$firtp" record "$work/two_copy.lcmlog" --lcm-url "file://$work/two_runs.lcmlog?speed=0" --idle 1 --duration 30
expect "record: two runs, states counted per run" 0 "FIRTP_AXIS_STATE: 4665 messages, missing 0, repeated 0, reordered 0, corrupted 0$" \
  "$firtp" record "$work/two_copy.lcmlog" --lcm-url "file://$work/two_runs.lcmlog?speed=0" --idle 1 --duration 30
expect "dump --count: the second run" 0 "^FIRTP_AXIS_STATE run=2 events=3439 seq=1-3439 missing=0 repeated=0 reordered=0$" \
  "$(dirname "$firtp")/firtp-lcm-dump" --count "$work/two_runs.lcmlog"
expect "dump --count: controls per session" 0 "^FIRTP_CONTROL session=[0-9]+ events=21 seq=1-21 missing=0 repeated=0" \
  "$(dirname "$firtp")/firtp-lcm-dump" --count "$work/two_runs.lcmlog"
expect "record --ini: the machine first" 0 "^0 .*FIRTP_CONFIG config_t seq=1 command=serve ini=.*diamond.ini" \
  bash -c '"$0" record "$1/ini.lcmlog" --ini "$2/diamond.ini" --lcm-url "file://$1/no_config.lcmlog?speed=0" --idle 1 --duration 30 >/dev/null && "$(dirname "$0")/firtp-lcm-dump" "$1/ini.lcmlog" | head -1 | sed "s/^[0-9]* /0 /"' \
  "$firtp" "$work" "$examples"
# On a terminal (script(1) gives it one) the replay shows its progress on stderr.
if command -v script > /dev/null; then
  expect "progress on a terminal" 0 "replay: [0-9]+ of 1226 axis states \\([0-9]+ %\\)" \
    script -qec "'$firtp' replay '$log'" /dev/null
fi
