#!/usr/bin/env python3
"""Cycle time of five programs under LinuxCNC's planners and firtp_tp, in one run series, side by side.

    examples/linuxcnc/compare.py [--master TREE] [--module build/linuxcnc/firtp_tp.so]
        [--check-tool build/bin/firtp-tp-check] [--readme README.md [--details docs/BENCHMARKS.md]] [--cam DIR]

The programs (issue 13): examples/diamond.ngc (F15000 G64 P0.5), corner90.ngc (F3000 G64 P0.1),
polygon360.ngc (a closed 360-gon, R20, 0.35 mm chords, F15000 G64 P0.5 Q0), cam_contour.ngc and
arcs.ngc. Each runs headless through run.py on this directory's machine (X Y Z, 300 mm/s,
5000 mm/s^2 every axis, 1 ms servo = trajectory period), with [DISPLAY]MAX_FEED_OVERRIDE = 1.0, under

  stock       LinuxCNC 2.9's planner (tpmod), as installed; no jerk limit
  firtp 5e6   firtp_tp jerk=5000000 (module parameter; [AXIS_*]MAX_JERK set to match for firtp-tp-check)
  firtp 1e5   firtp_tp jerk=100000
  S-curve     with --master TREE: LinuxCNC master built run-in-place in TREE (scripts/rip-environment),
              its stock tpmod with [TRAJ]PLANNER_TYPE = 1 (the jerk-limited S-curve planner),
              [TRAJ]MAX_LINEAR_JERK and [AXIS_*]/[JOINT_*]MAX_JERK = 1e5, then 5e6

and one more firtp_tp run, the diamond with the paper's filters (t1=0.148 t2=0.089 jerk=100000), in the
detail table only. firtp-tp-check measures each recording: cycle time (first moving sample to rest at
the end), the largest corner error (closest approach to a programmed corner point) and contour error
(distance from the programmed path), per-axis acceleration and jerk from 1 ms differences, and CPU
time per servo period of motion-controller (tpRunCycle) and motion-command-handler (tpAdd*).

Printed: the cycle-time table with ratios to the stock planner and firtp_tp's errors and peaks, the
targets of issue 13 per program (jerk 5e6: firtp <= 1.00 x stock; jerk 1e5: firtp <= max(0.8 x
S-curve 1e5, stock); on the diamond and the 90° corner the share of P and of the acceleration limit
firtp_tp uses), notes (runs that failed, rest off the end, go beyond G64 P or above their jerk
limit), then the detail table of every run and firtp_tp's own pins. Without --master
(or when TREE is not built) the S-curve columns say "-" and the second target is not judged. With
--readme the tables replace those between the markers in that file (with --details FILE, the
detail tables go between the markers of FILE instead). One HAL session at a time; about
5 minutes with --master, 2 without.

--cam DIR adds real CAM programs (CAM_PROGRAMS from DIR, prepared as issue 13 ran them, and a
laser-style program written here), about 7 minutes more; their table goes between the
'compare.py cam' markers of --readme. --cam-only runs and rewrites only those (the five programs'
table keeps its S-curve columns from a --master run).
"""
import argparse
import os
import re
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run  # noqa: E402

EXAMPLES = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))

# program, what it is
PROGRAMS = [
    ("diamond.ngc", "diamond, F15000 G64 P0.5"),
    ("corner90.ngc", "90° corner, F3000 G64 P0.1"),
    ("polygon360.ngc", "360-gon R20 (0.35 mm chords), F15000 G64 P0.5 Q0"),
    ("cam_contour.ngc", "cam_contour: 2,603 segments, F3000 G64 P0.02 Q0"),
    ("arcs.ngc", "arcs: G2/G3 in 3 planes, helix, F2400 G64 P0.02"),
]

# --cam DIR: real CAM programs (pcb2gcode's testing/gerbv_example outputs, GPL-3.0, and LinuxCNC's
# nc_files/3D_Chips.ngc, GPL-2.0: not in this repository), prepared as issue 13 measured them:
# pauses, tool changes and dwells removed, and (the pcb2gcode ones) G64 P0.02 after the first G90;
# 3D_Chips keeps its own G64 P0.1. And a laser-style program written here (LASER).
CAM_PROGRAMS = [
    ("pcb2gcode__milldrill.ngc", "pcb2gcode drill file (multivibrator milldrill.ngc)", True),
    ("pcb2gcode__back.ngc", "pcb2gcode isolation milling, 21,624 moves (D1MiniGSR back.ngc)", True),
    ("lcnc__3D_Chips.ngc", "LinuxCNC's 3D_Chips.ngc: ball-nose surfacing, 1,215 moves, its own G64 P0.1", False),
]
LASER = "laser-style: M3/M5 around each of 20 squares, F1200 G64 P0.05"
CAM_BEGIN, CAM_END = "<!-- compare.py cam: begin -->", "<!-- compare.py cam: end -->"


def prepare_cam(src, dst, tolerance=True):
    """src as issue 13 ran it: no M0, M1, M6, T, G04 (line numbers aside); with `tolerance`, G64 P0.02
    after its first G90."""
    out, placed = [], not tolerance
    for line in open(src):
        word = line.lstrip().upper()
        if re.match(r"(N\d+\s*)?(M0?0|M0?1|M0?6|T[\d#]|G0?4)(\D|$)", word):
            continue
        out.append(line)
        if not placed and re.match(r"G90(\D|$)", word):
            out.append("G64 P0.02\n")
            placed = True
    open(dst, "w").write("".join(out))


def write_laser(dst):
    """20 squares of 8 mm, the spindle (a laser) on around each: LinuxCNC waits for motion at M3 and M5."""
    lines = ["G21 G90 G64 P0.05", "F1200"]
    for i in range(20):
        x, y = (i % 5) * 12.0, (i // 5) * 12.0
        lines += ["G0 X%.3f Y%.3f" % (x, y), "M3 S1000"]
        lines += ["G1 X%.3f Y%.3f" % p for p in ((x + 8, y), (x + 8, y + 8), (x, y + 8), (x, y))]
        lines.append("M5")
    lines += ["G0 X0 Y0", "M2"]
    open(dst, "w").write("\n".join(lines) + "\n")


# The paper's filters on the diamond (firtp_tp only; detail table).
PAPER = ("diamond.ngc", "diamond, the paper's filters t1=0.148 t2=0.089", "t1=0.148 t2=0.089 jerk=100000 tolerance=0.05")

COMMON = [("DISPLAY", "MAX_FEED_OVERRIDE", "1.0")]
ACC_LIMIT = 5000.0  # every axis' MAX_ACCELERATION in firtp_tp.ini, mm/s²
AXES, JOINTS = ("X", "Y", "Z"), (0, 1, 2)


def firtp_planner(jerk):
    settings = COMMON + [("AXIS_" + a, "MAX_JERK", "%g" % jerk) for a in AXES]
    return {"tp": "firtp_tp", "params": "jerk=%d tolerance=0.05" % jerk, "set": settings, "jerk": jerk,
            "master": False}


def scurve_planner(jerk):
    settings = COMMON + [("TRAJ", "PLANNER_TYPE", "1"), ("TRAJ", "MAX_LINEAR_JERK", "%g" % jerk)]
    settings += [("AXIS_" + a, "MAX_JERK", "%g" % jerk) for a in AXES]
    settings += [("JOINT_%d" % j, "MAX_JERK", "%g" % jerk) for j in JOINTS]
    return {"tp": "tpmod", "params": "", "set": settings, "jerk": jerk, "master": True}


# key, label in the detail table, how it runs
PLANNERS = [
    ("stock", "stock 2.9 (tpmod)", {"tp": "tpmod", "params": "", "set": COMMON, "jerk": None, "master": False}),
    ("firtp_5e6", "firtp_tp jerk=5e6", firtp_planner(5000000)),
    ("firtp_1e5", "firtp_tp jerk=1e5", firtp_planner(100000)),
    ("scurve_1e5", "master S-curve jerk=1e5", scurve_planner(100000)),
    ("scurve_5e6", "master S-curve jerk=5e6", scurve_planner(5000000)),
]

BEGIN = "<!-- compare.py: begin -->"
END = "<!-- compare.py: end -->"


def g64_p(path):
    """The program's first G64 P (its tolerance), in mm (G20 before it: inches)."""
    text = open(path).read()
    m = re.search(r"G64\s*P\s*([0-9.]+)", text, re.I)
    if not m:
        return None
    inches = re.search(r"\bG20(\D|$)", text[:m.start()], re.I | re.M) is not None
    return float(m.group(1)) * (25.4 if inches else 1.0)


def first_lines(errors):
    """Each different error's first line (LinuxCNC's own messages run over several, and repeat)."""
    seen = []
    for e in errors:
        line = e.strip().splitlines()[0] if e.strip() else ""
        if line and line not in seen:
            seen.append(line)
    return "; ".join(seen)


def good(report):
    return report is not None and report.get("completed")


def seconds(report):
    if report is None:
        return "failed"
    if not report.get("completed"):
        return "%.3f s (not completed)" % report["cycle_time_s"]
    return "%.3f s" % report["cycle_time_s"]


def ratio(report, stock):
    if not good(report) or not good(stock):
        return "-"
    return "%.2f" % (report["cycle_time_s"] / stock["cycle_time_s"])


def errors_and_peaks(report, p):
    if report is None:
        return "-"
    return "%.3f / %.3f mm (P %g); %.0f; %.3g" % (
        report["max_corner_error_mm"], report["max_contour_error_mm"], p, max(report["max_axis_acceleration"]),
        max(report["max_axis_jerk"]))


def detail_row(label, planner, report):
    if report is None:
        return "| %s | %s | failed | | | | | | |" % (label, planner)
    ctl, cmd = report["motion_controller"], report["motion_command_handler"]
    return "| %s | %s | %s | %.4f mm | %.4f mm | %.0f | %.3g | %.1f / %.1f / %.0f µs | %.1f / %.0f µs |" % (
        label, planner, seconds(report), report["max_corner_error_mm"], report["max_contour_error_mm"],
        max(report["max_axis_acceleration"]), max(report["max_axis_jerk"]),
        ctl["median_us"], ctl["p99_us"], ctl["max_us"], cmd["p99_us"], cmd["max_us"])


def cycle_table(rows, scurve):
    """The cycle-time table of (label, G64 P, {planner: report}) rows: ratios to the stock planner."""
    table = ["| program | stock 2.9 | firtp_tp jerk=5e6 | ratio | firtp_tp jerk=1e5 | ratio "
             "| master S-curve jerk=1e5 | jerk=5e6 | firtp_tp 5e6: corner / contour error; acc; jerk "
             "| firtp_tp 1e5: corner / contour error; acc; jerk |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for label, p, r in rows:
        stock = r.get("stock")
        table.append("| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |" % (
            label, seconds(stock), seconds(r.get("firtp_5e6")), ratio(r.get("firtp_5e6"), stock),
            seconds(r.get("firtp_1e5")), ratio(r.get("firtp_1e5"), stock),
            seconds(r.get("scurve_1e5")) if scurve else "-", seconds(r.get("scurve_5e6")) if scurve else "-",
            errors_and_peaks(r.get("firtp_5e6"), p), errors_and_peaks(r.get("firtp_1e5"), p)))
    return table


def targets(label, p, r, scurve, corners):
    """Issue 13's targets for one program, as lines of text."""
    stock, f5, f1, s1 = r.get("stock"), r.get("firtp_5e6"), r.get("firtp_1e5"), r.get("scurve_1e5")
    out = ["- %s:" % label]
    tol = p * (1 + 1e-9) + 0.001  # arcs run as chords of 0.001 mm sagitta

    def within(report):
        if not good(report):
            return ""
        ok = report["max_corner_error_mm"] <= tol and report["max_contour_error_mm"] <= tol
        return "; within P %g: %s" % (p, "yes" if ok else "NO (corner %.4f, contour %.4f mm)" % (
            report["max_corner_error_mm"], report["max_contour_error_mm"]))

    if good(f5) and good(stock):
        x = f5["cycle_time_s"] / stock["cycle_time_s"]
        out.append("  jerk 5e6: firtp %.3f s <= 1.00 x stock %.3f s: %s (%.2fx)%s" % (
            f5["cycle_time_s"], stock["cycle_time_s"], "met" if x <= 1.0 else "NOT met", x, within(f5)))
    else:
        out.append("  jerk 5e6: not judged (a run failed)")
    if not scurve:
        out.append("  jerk 1e5: not judged (no S-curve runs: --master)")
    elif good(f1) and good(stock) and good(s1):
        bound = max(0.8 * s1["cycle_time_s"], stock["cycle_time_s"])
        out.append("  jerk 1e5: firtp %.3f s <= max(0.8 x S-curve %.3f s, stock %.3f s) = %.3f s: %s (%.2fx the bound)%s" % (
            f1["cycle_time_s"], s1["cycle_time_s"], stock["cycle_time_s"], bound,
            "met" if f1["cycle_time_s"] <= bound else "NOT met", f1["cycle_time_s"] / bound, within(f1)))
    else:
        out.append("  jerk 1e5: not judged (a run failed)")
    if corners:  # a few corners: how much of the tolerance and the acceleration firtp_tp uses
        for name, report in (("5e6", f5), ("1e5", f1)):
            if good(report):
                out.append("  jerk %s: corner error %.2f of P (target >= 0.9 where no limit binds), peak axis "
                           "acceleration %.2f of the limit (target >= 0.95)" % (
                               name, report["max_corner_error_mm"] / p, max(report["max_axis_acceleration"]) / ACC_LIMIT))
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--master", metavar="TREE",
                        help="LinuxCNC master built run-in-place in TREE: adds its S-curve planner (PLANNER_TYPE 1)")
    parser.add_argument("--module", help="this build's firtp_tp.so (placed in LinuxCNC's module directory for the runs)")
    parser.add_argument("--check-tool", help="firtp-tp-check")
    parser.add_argument("--readme", help="write the tables between the markers in this file")
    parser.add_argument("--details", metavar="FILE",
                        help="with --readme: the detail tables (every run, firtp_tp's pins) go between the markers "
                             "in FILE instead (docs/BENCHMARKS.md), the README keeps the summary")
    parser.add_argument("--no-detail", action="store_true", help="skip the paper's-filters run and the detail tables")
    parser.add_argument("--cam", metavar="DIR",
                        help="also real CAM programs: pcb2gcode__milldrill.ngc and pcb2gcode__back.ngc from DIR (as "
                             "../shared/corpus names them), and a laser-style program; their table goes between the "
                             "'compare.py cam' markers of --readme")
    parser.add_argument("--cam-only", action="store_true",
                        help="with --cam: only the CAM programs (--readme then rewrites only their table)")
    a = parser.parse_args()

    began = time.time()
    master = None
    if a.master:
        try:
            master = run.LinuxCNC(a.master)
            if not master.available():
                raise run.Skip("%s has no linuxcnc script or realtime" % a.master)
        except Exception as e:  # any reason (not built, no rip-environment): skip the columns, say why
            print("S-curve columns skipped: %s" % e, flush=True)
            master = None
    planners = [p for p in PLANNERS if master is not None or not p[2]["master"]]

    detail = ["| program | planner | cycle time | max corner error | max contour error | max axis acc (mm/s²) "
              "| max axis jerk (mm/s³) | motion-controller median / p99 / max | motion-command-handler p99 / max |",
              "|---|---|---|---|---|---|---|---|---|"]
    extra = []
    notes = []
    results = []
    cam_results = []

    def one(path, label, name, how, params=None):
        p = g64_p(path)
        status, report = run.run(path, how["tp"], how["params"] if params is None else params,
                                 a.module if how["tp"] == "firtp_tp" else None, a.check_tool, None, [], quiet=True,
                                 ini_set=how["set"], lcnc=master if how["master"] else None)
        detail.append(detail_row(label, name, report))
        print(detail[-1], flush=True)
        if report is None or not report.get("completed"):
            notes.append("%s, %s: %s" % (label, name, first_lines(report.get("errors", [])) if report else "no recording"))
        elif report.get("end_error_mm", 0.0) > 1e-6:
            notes.append("%s, %s: the tool rests %.3g mm from the program's end" % (label, name, report["end_error_mm"]))
        if p is not None and report is not None and max(report["max_corner_error_mm"],
                                                        report["max_contour_error_mm"]) > p + 0.001 + 1e-9:
            notes.append("%s, %s: corner error %.4f mm, contour error %.4f mm: beyond G64 P%g (+ 0.001 mm chords)" % (
                label, name, report["max_corner_error_mm"], report["max_contour_error_mm"], p))
        if how["jerk"] and report is not None and max(report["max_axis_jerk"]) > 1.2 * how["jerk"]:
            notes.append("%s, %s: axis jerk %.3g mm/s³ above the limit %.3g (1 ms differences)" % (
                label, name, max(report["max_axis_jerk"]), how["jerk"]))
        if how["tp"] == "firtp_tp" and report is not None and "firtp_tp" in report:
            t = report["firtp_tp"]
            extra.append("| %s | %s | %.1f / %.1f µs (%d) | %.1f / %.1f / %.0f µs | %.1f / %.0f µs | %d |" % (
                label, name, t["add"]["median_us"], t["add"]["max_us"], t["add"]["cycles"],
                t["run_cycle"]["median_us"], t["run_cycle"]["p99_us"], t["run_cycle"]["max_us"],
                t["planning"]["p99_us"], t["planning"]["max_us"], t["most_blocks_planned_in_a_period"]))
        return report

    if a.cam_only and not a.cam:
        parser.error("--cam-only needs --cam DIR")
    try:
        for program, label in ([] if a.cam_only else PROGRAMS):
            path = os.path.join(EXAMPLES, program)
            r = {name: one(path, label, title, how) for name, title, how in planners}
            results.append((label, g64_p(path), r, program in ("diamond.ngc", "corner90.ngc")))
        if not a.no_detail and not a.cam_only:
            program, label, params = PAPER
            one(os.path.join(EXAMPLES, program), label, "firtp_tp " + params.split(" tolerance")[0], PLANNERS[2][2],
                params)
        if a.cam:
            scratch = tempfile.mkdtemp(prefix="firtp-compare-cam.")
            os.chmod(scratch, 0o755)
            cams = []
            for program, label, tolerance in CAM_PROGRAMS:
                src = os.path.join(a.cam, program)
                if not os.path.exists(src):
                    print("--cam: %s not found" % src)
                    return 1
                cams.append((os.path.join(scratch, program), label))
                prepare_cam(src, cams[-1][0], tolerance)
            cams.append((os.path.join(scratch, "laser.ngc"), LASER))
            write_laser(cams[-1][0])
            for path, label in cams:
                os.chmod(path, 0o644)
                r = {name: one(path, label, title, how) for name, title, how in planners}
                cam_results.append((label, g64_p(path), r))
    except run.Skip as e:
        print("SKIPPED: %s" % e)
        return run.SKIP

    scurve = master is not None
    main_table = cycle_table([(label, p, r) for label, p, r, _ in results], scurve)
    checks = []
    for label, p, r, corners in results:
        checks += targets(label, p, r, scurve, corners)

    cam_table = []
    if cam_results:
        cam_table = ["Real CAM programs through LinuxCNC's interpreter, the same machine and run series (%s; "
                     "`--cam`: M0, M1, M6, T and G04 removed, G64 P0.02 after the first G90 of the pcb2gcode programs; the "
                     "drill file is in inches, its P0.02 is 0.508 mm; the isolation milling sets its own G64 P0.01 in mm "
                     "after it; 3D_Chips keeps its G64 P0.1):"
                     % time.strftime("%Y-%m-%d"), ""] + cycle_table(cam_results, scurve)

    elapsed = time.time() - began
    text = ["Cycle times, one run series (%s; %.0f s); ratios to the stock planner; firtp_tp's largest corner "
            "and contour errors against the program's G64 P, peak axis acceleration (mm/s²) and jerk (mm/s³) "
            "from 1 ms differences:" % (time.strftime("%Y-%m-%d"), elapsed), ""]
    text += main_table + ["", "Targets of issue 13:", ""] + checks
    if notes:
        text += ["", "Notes:", ""] + ["- " + n for n in notes]
    details = []
    if not a.no_detail:
        details += ["Every run (%s):" % time.strftime("%Y-%m-%d"), ""] + detail
        details += ["", "firtp_tp's own pins (rtapi_get_time, ns) on the same runs:", "",
                    "| program | planner | tpAdd* median / max (adds) | tpRunCycle median / p99 / max | planning p99 / max "
                    "| most blocks planned in a period |", "|---|---|---|---|---|---|"] + extra
    if details and not a.details:
        text += [""] + details
    table = "\n".join(text)
    print()
    print(table)
    if cam_table:
        print()
        print("\n".join(cam_table))
    if a.details:
        print()
        print("\n".join(details))
    for path, body, begin, end in ((None if a.cam_only else a.readme, table, BEGIN, END),
                                   (None if a.cam_only else a.details, "\n".join(details), BEGIN, END),
                                   (a.readme if cam_table else None, "\n".join(cam_table), CAM_BEGIN, CAM_END)):
        if not path or (path == a.details and not details):
            continue
        old = open(path).read()
        new, n = re.subn(re.escape(begin) + ".*?" + re.escape(end), lambda m: begin + "\n" + body + "\n" + end, old,
                         flags=re.S)
        if n != 1:
            print("%s has no %s ... %s markers" % (path, begin, end))
            return 1
        open(path, "w").write(new)
    return 0


if __name__ == "__main__":
    sys.exit(main())
