#!/usr/bin/env python3
"""Start a sample configuration of examples/linuxcnc/configs with the `linuxcnc` launcher,
headless, and check what firtp-lcm-bridge published over LCM.

    run_config.py CONFIG_DIR --program NGC --bridge firtp-lcm-bridge --module SO --states TOOL
        --check-tool firtp-tp-check [--host firtp] [--dump firtp-lcm-dump] [--plan firtp]
        [--within MM] [--replay firtp] [--restart-bridge-at S] [-- CHECK OPTIONS]

CONFIG_DIR's INI is copied into a scratch directory with [DISPLAY]DISPLAY = firtp-headless (no
screen: E-stop reset, machine on, home, run OPEN_FILE, exit) and the bridge in its bin/. With
--host (firtp.so fed by the LCM bridge), OPEN_FILE stays the configuration's (send_diamond.ngc:
its M101, a user M-code that task waits for, runs `firtp host $FIRTP_HOST_PROGRAM --ini INI`, here
NGC, with `firtp` from bin/), as a user runs it; otherwise OPEN_FILE is NGC itself.

Everything runs in a private network namespace (`unshare -n`, loopback with a multicast route):
the LCM subscriber `firtp-bridge-states record` and `lcm-logger` start first, then `linuxcnc -r`
as `nobody` (rtapi_app refuses root); `halrun -U` cleans up even on failure. Then:
`firtp-bridge-states samples` checks every FIRTP_AXIS_STATE arrived intact, seq 1, 2, ... and
ticks consecutive, no status reporting lost states, and turns them into samples that
`firtp-tp-check` measures against NGC (end point exact, CHECK OPTIONS: tolerance, limits, lines;
with --plan every moving period equal to `firtp plan NGC --ini INI` within --within mm).
lcm-logger's log is counted by firtp-lcm-dump and reported. With --replay, `firtp record` records
beside them (it must lose nothing) and `firtp replay` runs on its log with nothing else: the log
carries the machine as firtp-lcm-bridge published it (FIRTP_CONFIG, firtp.so's settings in effect),
and the replay must be equal bit for bit, every block placed by the axis states; with
--replay-refused TEXT it must instead exit 1 saying TEXT (a log it cannot replay, e.g. LinuxCNC's
own motion with no FIRTP_BLOCK in it). --restart-bridge-at S: S seconds into the host's run,
firtp-lcm-bridge is unloaded and lcm.hal loaded again while firtp.so runs on; the host must still
finish, the states show one restart with consecutive ticks, and the replay takes both bridges' logs
as one run of firtp.so. Exit 0 passed, 1 failed, 77 skipped.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLES = os.path.normpath(os.path.join(HERE, "..", "..", "examples", "linuxcnc"))
sys.path.insert(0, EXAMPLES)
import run as lcnc_run  # noqa: E402  (examples/linuxcnc/run.py: placing modules, INI edits, running as nobody)

SKIP = 77


def ini_of(config):
    names = [n for n in os.listdir(config) if n.endswith(".ini")]
    if len(names) != 1:
        raise RuntimeError("%s: expected one .ini, found %s" % (config, names))
    return names[0]


def prepare(work, a):
    config = os.path.join(work, "config")
    shutil.copytree(a.config, config)
    os.makedirs(os.path.join(config, "bin"), exist_ok=True)
    shutil.copy(os.path.join(EXAMPLES, "bin", "firtp-headless"), os.path.join(config, "bin"))
    shutil.copy(a.bridge, os.path.join(config, "bin", "firtp-lcm-bridge"))
    ini = os.path.join(config, ini_of(config))
    shutil.copy(a.program, os.path.join(config, "program.ngc"))
    text = open(ini).read()
    text = lcnc_run.set_ini(text, "DISPLAY", "DISPLAY", "firtp-headless")
    text = lcnc_run.set_ini(text, "FIRTP_RUN", "RECORD", "no")
    text = lcnc_run.set_ini(text, "FIRTP_RUN", "RESULT", "result.json")
    text = lcnc_run.set_ini(text, "FIRTP_RUN", "TIMEOUT", "60")
    if a.host:
        # As a user runs it: OPEN_FILE (send_diamond.ngc) calls the configuration's M101, which
        # runs `firtp host $FIRTP_HOST_PROGRAM` from the PATH (bin/ here); task waits for it.
        shutil.copy(a.host, os.path.join(config, "bin", "firtp"))
    else:
        text = lcnc_run.set_ini(text, "DISPLAY", "OPEN_FILE", "program.ngc")
    open(ini, "w").write(text)
    return config, ini


SESSION = r"""set -u
ip link set lo up && ip route add 224.0.0.0/4 dev lo || { echo "no multicast route"; exit 3; }
"$STATES" record "$WORK/states.lcmlog" > "$WORK/states.log" 2>&1 &
recorder=$!
logger=
if command -v lcm-logger > /dev/null; then lcm-logger --quiet -f "$WORK/lcm-logger.lcmlog" > "$WORK/lcm-logger.out" 2>&1 & logger=$!; fi
record=
if [ -n "$FIRTP_RECORD" ]; then "$FIRTP_RECORD" record "$WORK/record.lcmlog" > "$WORK/record.out" 2>&1 & record=$!; fi
sleep 0.5
[ -n "$OPERATOR" ] && { (timeout 60 sh -c "$OPERATOR") > "$FIRTP_HOST_INPUT" & }
(cd "$CONFIG" && $AS_USER env HOME="$CONFIG" PATH="$PATH" FIRTP_HOST_PROGRAM="$FIRTP_HOST_PROGRAM" \
   FIRTP_HOST_INPUT="$FIRTP_HOST_INPUT" timeout 120 linuxcnc -r "$INI") > "$WORK/linuxcnc.log" 2>&1
status=$?
sleep 0.3
kill -INT $recorder; wait $recorder
[ -n "$logger" ] && { kill -INT $logger; wait $logger; }
[ -n "$record" ] && { kill -INT $record; wait $record; echo $? > "$WORK/record.rc"; }
exit $status
"""


def record_and_replay(work, a):
    """`firtp record`'s log: nothing lost, and `firtp replay LOG` equal (or refused as expected)."""
    failed = []
    rc_file = os.path.join(work, "record.rc")
    rc = int(open(rc_file).read()) if os.path.exists(rc_file) else -1
    print("firtp record (exit %d):\n%s" % (rc, open(os.path.join(work, "record.out")).read().strip()))
    if rc != 0:
        failed.append("firtp record exit %d (0: nothing lost)" % rc)
    log = os.path.join(work, "record.lcmlog")
    replay = subprocess.run([a.replay, "replay", log], capture_output=True, text=True)
    print("firtp replay (exit %d):\n%s%s" % (replay.returncode, replay.stdout, replay.stderr))
    if a.replay_refused:
        if replay.returncode != 1 or a.replay_refused not in replay.stderr:
            failed.append("firtp replay: expected exit 1 saying '%s'" % a.replay_refused)
        return failed
    if replay.returncode != 0 or not re.search(r"^result +equal$", replay.stdout, re.M):
        failed.append("firtp replay: not equal (exit %d)" % replay.returncode)
    if a.restart_bridge_at is not None and not re.search(r"^restart +of the bridge at .*: the component ran on, one run$",
                                                          replay.stdout, re.M):
        failed.append("firtp replay: the bridge's restart not taken as one run of firtp.so")
    # the machine from the log: firtp.so's settings as firtp-lcm-bridge read them in LinuxCNC
    if not re.search(r"^machine +firtp-lcm-bridge .*: firtp\.so in LinuxCNC \(.*\.ini\), loadrt firtp axes=",
                     replay.stdout, re.M):
        failed.append("firtp replay: the log's machine is not firtp-lcm-bridge's FIRTP_CONFIG")
    counts = re.search(r"^log +(\d+) blocks, (\d+) program events, (\d+) controls.*\n"
                       r"fed +(\d+) blocks and (\d+) controls in the periods", replay.stdout, re.M)
    if not counts or int(counts[4]) != int(counts[1]) + int(counts[2]) or int(counts[5]) != int(counts[3]):
        failed.append("firtp replay: not every block, event and control placed by the axis states")
    return failed


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("config")
    parser.add_argument("--program", required=True)
    parser.add_argument("--bridge", required=True)
    parser.add_argument("--module", required=True, help="the LinuxCNC module the configuration loads (firtp_tp.so, firtp.so)")
    parser.add_argument("--states", required=True, help="firtp-bridge-states")
    parser.add_argument("--check-tool", required=True, help="firtp-tp-check")
    parser.add_argument("--host", help="firtp: send the program with `firtp host` (M101)")
    parser.add_argument("--plan", help="firtp: compare every period with `firtp plan`")
    parser.add_argument("--within", default="1e-9")
    parser.add_argument("--dump", help="firtp-lcm-dump, to count lcm-logger's log")
    parser.add_argument("--operator", default="",
                        help="with --host: shell commands whose output is the host's operator input "
                             "(FIRTP_HOST_INPUT, a named pipe), e.g. 'sleep 0.3; echo hold; sleep 0.5; echo resume'")
    parser.add_argument("--restart-bridge-at", type=float,
                        help="with --host: S seconds after the host starts, unload firtp-lcm-bridge and load "
                             "lcm.hal again (halcmd), while firtp.so runs on")
    parser.add_argument("--replay", help="firtp: record with `firtp record`, then `firtp replay` the log")
    parser.add_argument("--replay-refused", help="with --replay: replay must exit 1 saying this")
    parser.add_argument("--keep", help="copy the logs and recordings here")
    argv = sys.argv[1:]
    checks = argv[argv.index("--") + 1:] if "--" in argv else []
    a = parser.parse_args(argv[:argv.index("--")] if "--" in argv else argv)
    if a.restart_bridge_at is not None:  # as a user would, from a shell beside the running LinuxCNC
        a.operator = ("sleep %g; (cd \"$CONFIG\" && $AS_USER env HOME=\"$CONFIG\" PATH=\"$CONFIG/bin:$PATH\" halcmd unload "
                      "firtp-lcm-bridge && $AS_USER env HOME=\"$CONFIG\" PATH=\"$CONFIG/bin:$PATH\" halcmd waitusr "
                      "firtp-lcm-bridge && $AS_USER env HOME=\"$CONFIG\" PATH=\"$CONFIG/bin:$PATH\" halcmd -i \"$INI\" "
                      "-f lcm.hal) > \"$WORK/restart.log\" 2>&1; sleep 10; %s" % (a.restart_bridge_at, a.operator))
    for name in ("program", "bridge", "module", "states", "check_tool", "host", "plan", "dump", "replay"):
        if getattr(a, name) not in (None, "none"):
            setattr(a, name, os.path.abspath(getattr(a, name)))

    lcnc = lcnc_run.LinuxCNC()
    if not lcnc.available():
        print("SKIPPED: LinuxCNC is not installed (linuxcnc-uspace)")
        return SKIP
    if a.bridge == "none" or not os.path.exists(a.bridge):
        print("SKIPPED: firtp-lcm-bridge was not built (FIRTP_LINUXCNC)")
        return SKIP
    if os.geteuid() != 0 or subprocess.run(["unshare", "-n", "true"], capture_output=True).returncode != 0:
        print("SKIPPED: needs root and a private network namespace (unshare -n) for LCM's multicast")
        return SKIP
    work = tempfile.mkdtemp(prefix="firtp-lcm-bridge.")
    placed = None
    prefix, uid, gid = lcnc_run.as_user_prefix(work)
    failed = []
    try:
        placed = lcnc_run.PlacedModule(a.module, work)
        for _ in range(60):  # one HAL session per machine
            if not lcnc_run.hal_running():
                break
            subprocess.run(["sleep", "1"])
        else:
            raise RuntimeError("another HAL session (rtapi_app) is still running after 60 s")
        config, ini = prepare(work, a)
        for root, dirs, files in os.walk(work):
            for name in dirs + files + [""]:
                os.chown(os.path.join(root, name), uid, gid)
        host_input = "/dev/null"
        if a.operator:  # a named pipe: the commands' timing starts when the host opens it
            host_input = os.path.join(work, "operator.fifo")
            os.mkfifo(host_input)
            os.chown(host_input, uid, gid)
        env = dict(os.environ, STATES=a.states, WORK=work, CONFIG=config, INI=ini, AS_USER=" ".join(prefix),
                   FIRTP_HOST_PROGRAM=os.path.join(config, "program.ngc"), FIRTP_HOST_INPUT=host_input,
                   OPERATOR=a.operator, FIRTP_RECORD=a.replay or "")
        session = subprocess.run(["unshare", "-n", "bash", "-c", SESSION], env=env)
        result = os.path.join(config, "result.json")
        print("linuxcnc -r %s: exit %d, %s" % (os.path.basename(ini), session.returncode,
                                               open(result).read().replace("\n", " ") if os.path.exists(result)
                                               else "no result.json"))
        if session.returncode != 0:
            failed.append("linuxcnc exit %d" % session.returncode)
        if a.host:  # firtp host printed into LinuxCNC's output: its progress and "PROGRAM: done in T s"
            log = open(os.path.join(work, "linuxcnc.log")).read() if os.path.exists(os.path.join(work, "linuxcnc.log")) else ""
            host = [l for l in log.splitlines() if l.startswith("firtp host") or l.startswith("  ")]
            print("\n".join(host))
            if "program.ngc: done in" not in log:
                failed.append("firtp host (M101) did not report the program done")
        print(open(os.path.join(work, "states.log")).read().strip())
        samples = os.path.join(work, "samples.txt")
        got = subprocess.run([a.states, "samples", os.path.join(work, "states.lcmlog"), samples],
                             capture_output=True, text=True)
        sys.stdout.write(got.stdout)
        if got.returncode != 0:
            failed.append("LCM states")
        # The operator's controls reach firtp.so as generations (lcm.hal nets firtp.control-gen): the
        # axis states name the ones applied, as `firtp replay` needs them.
        if a.operator and re.search(r"^controls +0 named", got.stdout, re.M):
            failed.append("no axis state names an operator control (is firtp.control-gen netted?)")
        if a.restart_bridge_at is not None:
            restart_log = os.path.join(work, "restart.log")
            print("bridge restart:\n" + (open(restart_log).read().strip() if os.path.exists(restart_log) else "(no log)"))
            if not re.search(r"^restarts +1 of the bridge", got.stdout, re.M):
                failed.append("the bridge was not restarted once under the running firtp.so")
        check = [a.check_tool, samples, "--ini", ini, "--program", a.program] + checks
        if a.plan:
            plan_csv = os.path.join(work, "plan.csv")
            subprocess.run([a.plan, "plan", a.program, "--ini", ini, "--csv", plan_csv], check=True,
                           stdout=subprocess.DEVNULL)
            check += ["--reference", plan_csv, "--within", a.within]
        checked = subprocess.run(check, capture_output=True, text=True)
        sys.stdout.write(checked.stdout)
        sys.stderr.write(checked.stderr)
        if checked.returncode != 0:
            failed.append("firtp-tp-check on the LCM states")
        logger = os.path.join(work, "lcm-logger.lcmlog")
        if a.dump and os.path.exists(logger):
            counted = subprocess.run([a.dump, "--count", logger], capture_output=True, text=True)
            print("lcm-logger beside it:\n" + counted.stdout.strip())
        if a.replay:
            failed += record_and_replay(work, a)
        if failed:
            log = os.path.join(work, "linuxcnc.log")
            print("---- linuxcnc.log (last lines)")
            print("".join(open(log).readlines()[-40:]) if os.path.exists(log) else "(none)")
    finally:
        if lcnc_run.hal_running():
            subprocess.run(prefix + ["env", "HOME=" + work, "halrun", "-U"], cwd=work, timeout=30,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if placed is not None:
            placed.restore()
        if a.keep:
            shutil.copytree(work, a.keep, dirs_exist_ok=True,  # not the operator's named pipe
                            ignore=lambda d, names: [n for n in names if n.endswith(".fifo")])
        shutil.rmtree(work, ignore_errors=True)
    if failed:
        print("FAIL: " + "; ".join(failed))
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
