#!/usr/bin/env python3
"""What a user sees: a sample configuration in LinuxCNC's AXIS GUI and lcm-spy beside it, both on
a virtual X display (Xvfb), while a program runs; a screenshot of the screen.

    screenshot.py CONFIG_DIR --program NGC --bridge firtp-lcm-bridge --module SO --out PNG
        [--jar firtp_lcm_types.jar] [--at S]

Like run_config.py (a scratch copy, modules placed for the run, LinuxCNC as `nobody`, a private
network namespace for LCM) but with the configuration's own display, AXIS. lcm-spy
(lcm-types/lcm-spy.sh) subscribes; `bin/firtp-headless -ini INI`, started beside AXIS as a plain
client of LinuxCNC, resets E-stop, homes and runs the program; S seconds after the program line
first changes, the screen is captured (xwd, convert). Closing AXIS (SIGTERM) ends the session.
The check (exit 1 otherwise): the AXIS and LCM Spy windows exist, the program completed, and
firtp-lcm-bridge published states. Exit 77 where Xvfb, xwd, lcm-spy, LinuxCNC or root are missing.
"""
import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "examples", "linuxcnc"))
import run as lcnc_run  # noqa: E402
import run_config  # noqa: E402

SKIP = 77
SESSION = r"""set -u
ip link set lo up && ip route add 224.0.0.0/4 dev lo || exit 3
FIRTP_LCM_TYPES_JAR="$JAR" setsid "$ROOT/lcm-types/lcm-spy.sh" > "$WORK/lcm-spy.log" 2>&1 & spy=$!
(cd "$CONFIG" && $AS_USER env HOME="$WORK" DISPLAY="$DISPLAY" PATH="$PATH" timeout 180 linuxcnc "$INI") > "$WORK/linuxcnc.log" 2>&1 & lcnc=$!
echo "start at $(date +%T)" > "$WORK/times.log"
# AXIS up: its main window ("FILE - AXIS VERSION on MACHINE") is on the screen; then it loads OPEN_FILE.
# (axis-remote cannot be used: Tk's `send` refuses an X server without access control, Xvfb -ac.)
for _ in $(seq 900); do
  xwininfo -root -tree -display "$DISPLAY" 2> /dev/null | grep -q ' - AXIS ' && break
  sleep 0.1
done
sleep 3
echo "AXIS up at $(date +%T)" >> "$WORK/times.log"
if ! kill -0 $spy 2> /dev/null; then  # lcm-spy could not open the display at its start: once more, logged
  echo "lcm-spy had exited; started again at $(date +%T)" >> "$WORK/times.log"
  mv "$WORK/lcm-spy.log" "$WORK/lcm-spy-first.log"
  FIRTP_LCM_TYPES_JAR="$JAR" setsid "$ROOT/lcm-types/lcm-spy.sh" > "$WORK/lcm-spy.log" 2>&1 & spy=$!
  for _ in $(seq 300); do
    xwininfo -root -tree -display "$DISPLAY" 2> /dev/null | grep -q 'LCM Spy' && break
    sleep 0.1
  done
fi
(cd "$CONFIG" && $AS_USER env HOME="$WORK" PATH="$CONFIG/bin:$PATH" timeout 120 /usr/bin/python3 bin/firtp-headless -ini "$INI") > "$WORK/driver.log" 2>&1 & driver=$!
for _ in $(seq 600); do
  line=$($AS_USER env HOME="$WORK" halcmd -s getp motion.program-line 2> /dev/null || echo 0)
  [ "${line:-0}" -gt 0 ] && break
  sleep 0.1
done
sleep "$AT"
echo "program running at $(date +%T)" >> "$WORK/times.log"
xwininfo -root -tree -display "$DISPLAY" > "$WORK/windows.txt"
xwd -root -silent -display "$DISPLAY" > "$WORK/screen.xwd"
echo "screenshot at $(date +%T)" >> "$WORK/times.log"
wait $driver; echo "driver exit $?" >> "$WORK/driver.log"
echo "driver done at $(date +%T)" >> "$WORK/times.log"
axis=$(pgrep -u "$(id -u nobody)" -fx "/usr/bin/python3 /usr/bin/axis -ini $INI")  # this run's AXIS
[ -n "$axis" ] && kill -TERM $axis  # the launcher then shuts LinuxCNC down
for _ in $(seq 300); do kill -0 $lcnc 2> /dev/null || break; sleep 0.1; done
kill -TERM $lcnc 2> /dev/null; wait $lcnc
echo "linuxcnc done at $(date +%T)" >> "$WORK/times.log"
kill -TERM -- -$spy 2> /dev/null; wait $spy 2> /dev/null
exit 0
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("config")
    parser.add_argument("--program", required=True)
    parser.add_argument("--bridge", required=True)
    parser.add_argument("--module", required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("--jar", default=os.path.join(ROOT, "build", "lcm-types", "firtp_lcm_types.jar"))
    parser.add_argument("--at", default="3", help="seconds into the program")
    parser.add_argument("--keep", help="copy the scratch directory (logs) here")
    a = parser.parse_args()
    for tool in ("Xvfb", "xwd", "xwininfo", "convert", "lcm-spy", "linuxcnc", "pgrep"):
        if shutil.which(tool) is None:
            print("SKIPPED: %s not found (xvfb, x11-apps, imagemagick, liblcm-java, linuxcnc-uspace)" % tool)
            return SKIP
    if os.geteuid() != 0 or not os.path.exists(a.jar) or a.bridge == "none":
        print("SKIPPED: needs root, the types jar (firtp_lcm_types_jar) and firtp-lcm-bridge")
        return SKIP
    a.program, a.bridge, a.module, a.jar, a.out = map(os.path.abspath, (a.program, a.bridge, a.module, a.jar, a.out))
    work = tempfile.mkdtemp(prefix="firtp-lcm-screen.")
    prefix, uid, gid = lcnc_run.as_user_prefix(work)
    display = ":%d" % (70 + os.getpid() % 20)
    xvfb = placed = None
    problems = []
    try:
        placed = lcnc_run.PlacedModule(a.module, work)
        args = argparse.Namespace(config=os.path.abspath(a.config), program=a.program, bridge=a.bridge, host=None)
        config, ini = run_config.prepare(work, args)
        text = open(ini).read()
        text = lcnc_run.set_ini(text, "DISPLAY", "DISPLAY", "axis")  # the user's display; firtp-headless drives
        open(ini, "w").write(text)
        with open(os.path.join(work, ".axisrc"), "w") as f:  # AXIS right of lcm-spy
            f.write("root_window.tk.call('wm', 'geometry', '.', '1100x1040+810+0')\n")
        for root, dirs, files in os.walk(work):
            for name in dirs + files + [""]:
                os.chown(os.path.join(root, name), uid, gid)
        # -noreset: by default Xvfb resets when its last client leaves, so the probe below closing its
        # connection reset the server just as lcm-spy connected ("Can't connect to X11 window server").
        xvfb = subprocess.Popen(["Xvfb", display, "-screen", "0", "1920x1080x24", "-ac", "-nolisten", "tcp", "-noreset"],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        # Until the display answers (a fixed second was not always enough on a loaded machine:
        # lcm-spy, started at once, could not open it).
        for _ in range(300):
            if subprocess.run(["xwininfo", "-root", "-display", display], stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL).returncode == 0:
                break
            time.sleep(0.1)
        env = dict(os.environ, WORK=work, CONFIG=config, INI=ini, AS_USER=" ".join(prefix), DISPLAY=display,
                   JAR=a.jar, ROOT=ROOT, AT=a.at)
        subprocess.run(["unshare", "-n", "bash", "-c", SESSION], env=env, timeout=400)
        windows = open(os.path.join(work, "windows.txt")).read() if os.path.exists(os.path.join(work, "windows.txt")) else ""
        for title in ("AXIS", "LCM Spy"):  # window titles
            if title not in windows:
                problems.append("no %s window on the screen" % title)
        for name in ("times.log", "driver.log"):
            if os.path.exists(os.path.join(work, name)):
                print(open(os.path.join(work, name)).read().strip())
        driver = ""
        result = os.path.join(config, "result.json")
        if not os.path.exists(result) or '"completed": true' not in open(result).read():
            problems.append("the program did not complete")
        if os.path.exists(os.path.join(work, "screen.xwd")):
            convert = shutil.which("convert-im6.q16") or "convert"  # Debian's ImageMagick, not a stand-in first on PATH
            subprocess.run([convert, "xwd:" + os.path.join(work, "screen.xwd"), a.out], check=True)
            print("wrote " + a.out)
        else:
            problems.append("no screenshot")
        if problems:
            for name in ("linuxcnc.log", "lcm-spy-first.log", "lcm-spy.log"):
                path = os.path.join(work, name)
                if os.path.exists(path):
                    print("---- " + name)
                    lines = open(path).readlines()
                    print("".join(lines if len(lines) <= 40 else lines[:10] + ["...\n"] + lines[-25:]))
    finally:
        if lcnc_run.hal_running():
            subprocess.run(prefix + ["env", "HOME=" + work, "halrun", "-U"], cwd=work, timeout=30,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        if xvfb is not None:
            xvfb.terminate()
            xvfb.wait(10)
        if placed is not None:
            placed.restore()
        if a.keep:
            shutil.copytree(work, a.keep, dirs_exist_ok=True)
        shutil.rmtree(work, ignore_errors=True)
    if problems:
        print("FAIL: " + "; ".join(problems))
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
