#!/usr/bin/env python3
"""Run a G-code program headless in LinuxCNC 2.9 and check what the planner commanded.

    examples/linuxcnc/run.py PROGRAM.ngc [--tp firtp_tp|tpmod] [--tp-params "t1=0.148 t2=0.089"]
        [--module build/linuxcnc/firtp_tp.so] [--check-tool build/bin/firtp-tp-check]
        [--out DIR] [--scenario ACTIONS] [--set SECTION:KEY=VALUE ...] [--lcnc TREE]
        [-- CHECK OPTIONS...]

It copies this configuration (firtp_tp.ini, machine.hal, record.hal, bin/firtp-headless) into a
scratch directory, sets [TRAJ]TPMOD, runs `linuxcnc -r` there (as `nobody` when run as root:
rtapi_app refuses root), which homes, runs the program and records every servo period, then runs
firtp-tp-check on the recording (CHECK OPTIONS, e.g. --tolerance 0.5 --limits --jerk 100000, are
passed on). --module places that firtp_tp.so in LinuxCNC's module directory for the run (rtapi_app
loads modules from there only) and puts back what was there. Only one HAL session can run on a
machine: it waits up to 60 s for another to end, and cleans up with `halrun -U`.

--set SECTION:KEY=VALUE (repeatable) sets a key of the scratch copy's INI, e.g.
--set DISPLAY:MAX_FEED_OVERRIDE=1.0. --lcnc TREE runs another LinuxCNC, built run-in-place in TREE
(its scripts/rip-environment; e.g. a build of LinuxCNC master, whose [TRAJ]PLANNER_TYPE = 1 is a
jerk-limited S-curve planner), instead of the installed one; --tp then names a planner module of
that tree (tpmod).

Exit status: 0 program completed and every check passed, 1 otherwise, 77 LinuxCNC (or the module)
is not available (a skipped test).
"""
import argparse
import json
import os
import pwd
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
CONFIG_FILES = ("firtp_tp.ini", "machine.hal", "record.hal", "tool.tbl", "bin")
MODULE_DIR = "/usr/lib/linuxcnc/modules"
REALTIME = "/usr/lib/linuxcnc/realtime"
SKIP = 77


class Skip(Exception):
    pass


class LinuxCNC:
    """Which LinuxCNC runs: the installed one (tree None) or a run-in-place build in tree."""

    def __init__(self, tree=None):
        self.tree = os.path.abspath(tree) if tree else None
        if self.tree is None:
            self.env = dict(os.environ)
            self.realtime = REALTIME
            return
        rip = os.path.join(self.tree, "scripts", "rip-environment")
        self.realtime = os.path.join(self.tree, "scripts", "realtime")
        missing = [f for f in (rip, self.realtime, os.path.join(self.tree, "scripts", "linuxcnc"),
                               os.path.join(self.tree, "bin", "rtapi_app"), os.path.join(self.tree, "bin", "milltask"),
                               os.path.join(self.tree, "rtlib", "motmod.so")) if not os.path.exists(f)]
        if missing:
            raise Skip("%s is not a built run-in-place LinuxCNC tree (no %s)" % (self.tree, ", ".join(missing)))
        # Its environment (PATH, PYTHONPATH, ...), from a system PATH: Debian's python3, not a pyenv shim.
        base = dict(os.environ, PATH="/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin")
        for name in ("PYTHONPATH", "PYTHONHOME", "VIRTUAL_ENV", "PYENV_VERSION"):
            base.pop(name, None)
        out = subprocess.run(["bash", "-c", '. "$1" >/dev/null && env -0', "bash", rip], env=base, capture_output=True,
                             check=True).stdout
        self.env = dict(item.split("=", 1) for item in out.decode().split("\0") if "=" in item)

    def available(self):
        return (shutil.which("linuxcnc", path=self.env.get("PATH")) is not None and os.path.exists(self.realtime))

    def name(self):
        return "LinuxCNC in " + self.tree if self.tree else "LinuxCNC"


def hal_running(lcnc=None):
    """Any HAL session (rtapi_app) on this machine: an installed and a run-in-place one share the SysV keys."""
    realtime = lcnc.realtime if lcnc is not None else REALTIME
    if not os.path.exists(realtime):
        realtime = REALTIME
    return subprocess.run([realtime, "status"], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode == 0


def set_ini(text, section, key, value):
    """Sets KEY = VALUE in [SECTION] of an INI text: replaces the key's lines there, or adds it."""
    lines = text.split("\n")
    start = next((i for i, l in enumerate(lines) if l.strip() == "[%s]" % section), None)
    if start is None:
        return text.rstrip("\n") + "\n\n[%s]\n%s = %s\n" % (section, key, value)
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("[")), len(lines))
    found = [i for i in range(start + 1, end) if re.match(r"\s*%s\s*=" % re.escape(key), lines[i])]
    if found:
        lines[found[0]] = "%s = %s" % (key, value)
        for i in reversed(found[1:]):
            del lines[i]
    else:
        lines.insert(start + 1, "%s = %s" % (key, value))
    return "\n".join(lines)


def as_user_prefix(work):
    """The command prefix that runs LinuxCNC unprivileged, and that user's uid/gid."""
    if os.geteuid() != 0:
        return [], os.getuid(), os.getgid()
    user = pwd.getpwnam("nobody")
    return (["setpriv", "--reuid=%d" % user.pw_uid, "--regid=%d" % user.pw_gid, "--clear-groups"],
            user.pw_uid, user.pw_gid)


class PlacedModule:
    """This build's module in LinuxCNC's module directory for the run; what was there comes back."""

    def __init__(self, module, backup_dir):
        self.module = module
        self.installed = None
        self.backup = None
        if module is None:
            return
        if module == "none" or not os.path.exists(module):
            raise Skip("%s was not built (FIRTP_LINUXCNC)" % module)
        name = os.path.basename(module)
        target = os.path.join(MODULE_DIR, name)
        if os.path.exists(target) and open(target, "rb").read() == open(module, "rb").read():
            return
        if not os.access(MODULE_DIR, os.W_OK):
            raise Skip("%s is not this build's and %s is not writable: install it (cmake --build BUILD "
                       "--target install-linuxcnc, as root) or run as root" % (target, MODULE_DIR))
        if os.path.exists(target):
            self.backup = os.path.join(backup_dir, name + ".before")
            shutil.copy2(target, self.backup)
        shutil.copy(module, target + ".new")
        os.rename(target + ".new", target)
        self.installed = target

    def restore(self):
        if self.installed is None:
            return
        if self.backup is not None:
            shutil.copy2(self.backup, self.installed + ".new")
            os.rename(self.installed + ".new", self.installed)
        else:
            os.remove(self.installed)
        self.installed = None


def prepare(work, program, tpmod, ini_set=()):
    for name in CONFIG_FILES:
        source = os.path.join(HERE, name)
        if os.path.isdir(source):
            shutil.copytree(source, os.path.join(work, name))
        else:
            shutil.copy(source, work)
    shutil.copy(program, os.path.join(work, "program.ngc"))
    ini = os.path.join(work, "firtp_tp.ini")
    text = open(ini).read()
    text, n = re.subn(r"(?m)^TPMOD = .*$", "TPMOD = " + tpmod, text)
    if n != 1:
        raise RuntimeError("firtp_tp.ini has no single TPMOD line")
    text = re.sub(r"(?m)^OPEN_FILE = .*$", "OPEN_FILE = program.ngc", text)
    for section, key, value in ini_set:
        text = set_ini(text, section, key, value)
    open(ini, "w").write(text)
    return ini


def run_linuxcnc(work, prefix, timeout, scenario="", lcnc=None):
    lcnc = lcnc or LinuxCNC()
    env = dict(lcnc.env, HOME=work, FIRTP_SCENARIO=scenario)
    log = open(os.path.join(work, "linuxcnc.log"), "w")
    command = prefix + ["env", "HOME=" + work, "FIRTP_SCENARIO=" + scenario, "linuxcnc", "-r", "firtp_tp.ini"]
    try:
        status = subprocess.run(command, cwd=work, env=env, stdout=log, stderr=subprocess.STDOUT,
                                timeout=timeout).returncode
    except subprocess.TimeoutExpired:
        status = -1
    finally:
        log.close()
        if hal_running(lcnc):
            subprocess.run(prefix + ["env", "HOME=" + work, "halrun", "-U"], cwd=work, env=env,
                           stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, timeout=30)
    return status


def find_tool(given):
    if given:
        return given
    for build in ("build", "build-tp"):
        candidate = os.path.join(HERE, "..", "..", build, "bin", "firtp-tp-check")
        if os.path.exists(candidate):
            return os.path.normpath(candidate)
    raise Skip("firtp-tp-check not found: give --check-tool")


def run(program, tp="firtp_tp", tp_params="", module=None, check_tool=None, out=None, check_args=(),
        timeout=180, quiet=False, scenario="", ini_set=(), lcnc=None):
    """Runs one program; returns (status, report dict or None). ini_set: (section, key, value) set in the
    scratch INI; lcnc: a LinuxCNC (a run-in-place tree) instead of the installed one."""
    lcnc = lcnc or LinuxCNC()
    if not lcnc.available():
        raise Skip("LinuxCNC is not installed (linuxcnc-uspace)" if lcnc.tree is None
                   else "%s has no linuxcnc script or realtime" % lcnc.tree)
    tool = find_tool(check_tool)
    work = tempfile.mkdtemp(prefix="firtp-lcnc-tp.")
    placed = None
    try:
        placed = PlacedModule(module if tp == "firtp_tp" else None, work)
        for _ in range(60):  # one HAL session per machine: wait for someone else's
            if not hal_running(lcnc):
                break
            time.sleep(1)
        else:
            raise RuntimeError("another HAL session (rtapi_app) is still running after 60 s")
        prepare(work, program, (tp + " " + tp_params).strip(), ini_set)
        prefix, uid, gid = as_user_prefix(work)
        for root, dirs, files in os.walk(work):
            for name in dirs + files + [""]:
                os.chown(os.path.join(root, name), uid, gid)
        began = time.time()
        status = run_linuxcnc(work, prefix, timeout, scenario, lcnc)
        wall = time.time() - began
        result_path = os.path.join(work, "result.json")
        result = json.load(open(result_path)) if os.path.exists(result_path) else {"completed": False,
                                                                                     "errors": ["no result"]}
        report = None
        check = [tool, os.path.join(work, "samples.txt"), "--ini", os.path.join(work, "firtp_tp.ini"),
                 "--program", os.path.join(work, "program.ngc"), "--json", os.path.join(work, "check.json")]
        if os.path.exists(os.path.join(work, "samples_tp.txt")):
            check += ["--tp-samples", os.path.join(work, "samples_tp.txt")]
        checked = subprocess.run(check + list(check_args), capture_output=True, text=True) \
            if os.path.exists(os.path.join(work, "samples.txt")) else None
        if os.path.exists(os.path.join(work, "check.json")):
            report = json.load(open(os.path.join(work, "check.json")))
            report["completed"] = result.get("completed", False)
            report["errors"] = result.get("errors", [])
        if not quiet:
            print("%s with %s%s: linuxcnc exit %d in %.1f s, program %s" % (
                os.path.basename(program), tp, " (%s)" % lcnc.name() if lcnc.tree else "", status, wall,
                "completed" if result.get("completed") else "NOT completed"))
            for e in result.get("errors", []):
                print("  LinuxCNC error: " + e)
            if checked is not None:
                sys.stdout.write(checked.stdout)
                sys.stderr.write(checked.stderr)
        ok = status == 0 and result.get("completed") and checked is not None and checked.returncode == 0
        if not ok and not quiet:
            log = os.path.join(work, "linuxcnc.log")
            if os.path.exists(log):
                print("---- linuxcnc.log (last lines)")
                print("".join(open(log).readlines()[-30:]))
        if out:
            os.makedirs(out, exist_ok=True)
            for name in ("samples.txt", "samples_tp.txt", "result.json", "check.json", "linuxcnc.log", "firtp_tp.ini"):
                if os.path.exists(os.path.join(work, name)):
                    shutil.copy(os.path.join(work, name), out)
        return (0 if ok else 1), report
    finally:
        if placed is not None:
            placed.restore()
        shutil.rmtree(work, ignore_errors=True)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("program")
    parser.add_argument("--tp", default="firtp_tp", help="planner module: firtp_tp (default) or tpmod")
    parser.add_argument("--tp-params", default="jerk=100000 tolerance=0.05",
                        help="module parameters for firtp_tp")
    parser.add_argument("--module", help="this build's firtp_tp.so, placed in LinuxCNC's module directory for the run")
    parser.add_argument("--check-tool", help="firtp-tp-check (default: build/bin or build-tp/bin)")
    parser.add_argument("--out", help="keep the recording, result and report here")
    parser.add_argument("--timeout", type=float, default=180)
    parser.add_argument("--set", action="append", default=[], metavar="SECTION:KEY=VALUE",
                        help="set a key of the run's INI, e.g. DISPLAY:MAX_FEED_OVERRIDE=1.0 (repeatable)")
    parser.add_argument("--lcnc", metavar="TREE",
                        help="run a run-in-place LinuxCNC build in TREE (scripts/rip-environment) instead of the "
                             "installed one")
    parser.add_argument("--scenario", default="",
                        help="operator actions while it runs, e.g. 'feed=0.5@0.1,pause@0.4,resume@1.2' or 'abort@0.5'")
    argv = sys.argv[1:]
    check = argv[argv.index("--") + 1:] if "--" in argv else []
    a = parser.parse_args(argv[:argv.index("--")] if "--" in argv else argv)
    ini_set = []
    for item in a.set:
        m = re.match(r"^([^:=]+):([^=]+)=(.*)$", item)
        if not m:
            parser.error("--set %s: SECTION:KEY=VALUE" % item)
        ini_set.append(tuple(x.strip() for x in m.groups()))
    try:
        status, _ = run(os.path.abspath(a.program), a.tp, a.tp_params if a.tp == "firtp_tp" else "", a.module,
                        a.check_tool, a.out, check, a.timeout, scenario=a.scenario, ini_set=ini_set,
                        lcnc=LinuxCNC(a.lcnc) if a.lcnc else None)
    except Skip as e:
        print("SKIPPED: %s" % e)
        return SKIP
    return status


if __name__ == "__main__":
    sys.exit(main())
