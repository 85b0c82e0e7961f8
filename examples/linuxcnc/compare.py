#!/usr/bin/env python3
"""Stock tpmod against firtp_tp on the same programs, in LinuxCNC 2.9, side by side.

    examples/linuxcnc/compare.py [--module build/linuxcnc/firtp_tp.so] [--check-tool build/bin/firtp-tp-check]
        [--readme examples/linuxcnc/README.md]

Each program runs headless through run.py twice, once with LinuxCNC's stock planner and once
with firtp_tp, on this directory's machine (X Y Z, 300 mm/s, 5000 mm/s^2, 1 ms). The recording is
measured by firtp-tp-check: cycle time, largest distance from the programmed path, largest axis
acceleration and jerk from 1 ms differences, and the CPU time per servo period of
motion-controller (tpRunCycle inside) and motion-command-handler (tpAdd* inside), from their
HAL .time pins. With --readme the table replaces the one between the markers in that file.
Takes about a minute and a half; one HAL session at a time.
"""
import argparse
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run  # noqa: E402

EXAMPLES = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

# program, what it is, firtp_tp's parameters
PROGRAMS = [
    ("diamond.ngc", "diamond, F15000 G64 P0.5 (the paper's T1 148 ms, T2 89 ms)",
     "t1=0.148 t2=0.089 jerk=100000 tolerance=0.05"),
    ("diamond.ngc", "diamond, F15000 G64 P0.5 (T1 60, T2 50 ms from the limits)", "jerk=100000 tolerance=0.05"),
    ("cam_contour.ngc", "cam_contour: 2,603 segments, G64 P0.02 Q0", "jerk=100000 tolerance=0.05"),
    ("arcs.ngc", "arcs: G2/G3 in 3 planes, helix, G64 P0.02", "jerk=100000 tolerance=0.05"),
]

BEGIN = "<!-- compare.py: begin -->"
END = "<!-- compare.py: end -->"


def row(label, tp, report):
    if report is None:
        return "| %s | %s | failed | | | | | |" % (label, tp)
    ctl, cmd = report["motion_controller"], report["motion_command_handler"]
    completed = "" if report.get("completed") else " (not completed)"
    return "| %s | %s | %.3f s%s | %.4f mm | %.0f | %.3g | %.1f / %.1f / %.0f µs | %.1f / %.0f µs |" % (
        label, tp, report["cycle_time_s"], completed, report["max_contour_error_mm"],
        max(report["max_axis_acceleration"]), max(report["max_axis_jerk"]),
        ctl["median_us"], ctl["p99_us"], ctl["max_us"], cmd["p99_us"], cmd["max_us"])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--module", help="this build's firtp_tp.so (placed in LinuxCNC's module directory for the runs)")
    parser.add_argument("--check-tool", help="firtp-tp-check")
    parser.add_argument("--readme", help="write the table between the markers in this file")
    a = parser.parse_args()

    lines = ["| program | planner | cycle time | max contour error | max axis acc (mm/s²) | max axis jerk (mm/s³) "
             "| motion-controller median / p99 / max | motion-command-handler p99 / max |",
             "|---|---|---|---|---|---|---|---|"]
    extra = []
    try:
        for program, label, params in PROGRAMS:
            path = os.path.join(EXAMPLES, program)
            for tp in ("tpmod", "firtp_tp"):
                status, report = run.run(path, tp, params if tp == "firtp_tp" else "", a.module, a.check_tool,
                                         None, [], quiet=True)
                lines.append(row(label, tp, report))
                print(lines[-1], flush=True)
                if tp == "firtp_tp" and report is not None and "firtp_tp" in report:
                    t = report["firtp_tp"]
                    extra.append("| %s | %.1f / %.1f µs (%d) | %.1f / %.1f / %.0f µs | %.1f / %.0f µs | %d |" % (
                        label, t["add"]["median_us"], t["add"]["max_us"], t["add"]["cycles"],
                        t["run_cycle"]["median_us"], t["run_cycle"]["p99_us"], t["run_cycle"]["max_us"],
                        t["planning"]["p99_us"], t["planning"]["max_us"], t["most_blocks_planned_in_a_period"]))
    except run.Skip as e:
        print("SKIPPED: %s" % e)
        return run.SKIP
    lines += ["", "firtp_tp's own pins (rtapi_get_time, ns) on the same runs:", "",
              "| program | tpAdd* median / max (adds) | tpRunCycle median / p99 / max | planning p99 / max "
              "| most blocks planned in a period |", "|---|---|---|---|---|"] + extra
    table = "\n".join(lines)
    print()
    print(table)
    if a.readme:
        text = open(a.readme).read()
        new, n = re.subn(re.escape(BEGIN) + ".*?" + re.escape(END), BEGIN + "\n" + table + "\n" + END, text,
                         flags=re.S)
        if n != 1:
            print("%s has no %s ... %s markers" % (a.readme, BEGIN, END))
            return 1
        open(a.readme, "w").write(new)
    return 0


if __name__ == "__main__":
    sys.exit(main())
