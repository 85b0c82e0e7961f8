#!/usr/bin/env python3
"""Reproduce the figures README.md quotes, on this machine, in one run (docs/BENCHMARKS.md).

    tests/bench/reproduce.sh BUILD_DIR [--quick] [--out FILE.md] [--json FILE.json]
        [--skip-stream] [--skip-linuxcnc] [--skip-ctest] [--plan-timeout S] [--wait-linuxcnc S]

BUILD_DIR is a Release build with the benchmarks (cmake -S . -B BUILD_DIR; cmake --build BUILD_DIR).
Sections, each printed as it finishes:
  1. servo tick, mean (firtp_bench, Google Benchmark; median of repetitions)
  2. servo tick, worst case over a long run (firtp_worst_tick: 10^7 ticks of random moves a
     configuration; thread CPU clock and wall clock; end exact)
  3. planning one block: firtp_bench's random corners (median of repetitions) and every block of
     the example programs (firtp_plan_stream --program; median over runs of mean, p99 and max)
  4. offline planning of a 1,000,000-block program generated on the fly (firtp_plan_stream
     --generate): blocks/s and peak RSS, flat after the first tenth
  5. sustained LCM block rate with no loss (tests/bench/stream_bench.sh: root, unshare -n)
  6. cycle time against the closed form (firtp plan --json) and the README's example figures
  7. firtp_tp against LinuxCNC's stock planner (examples/linuxcnc/compare.py), where LinuxCNC is
     installed and no other HAL session runs (waits for rtapi_app to go away)
  8. the test-suite figures (paper figures, randomized suites, drift): ctest on those tests
--quick: fewer repetitions and ticks, 100,000 blocks instead of 10^6, one short stream run, no
LinuxCNC and no ctest; about 25 s. The full run takes about 8 minutes.
Results: a Markdown table on stdout and in --out (default BUILD_DIR/bench-results/results.md),
every raw figure in --json (default BUILD_DIR/bench-results/results.json).
"""
import argparse
import datetime
import json
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import time

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
SKIP = 77


def log(text=""):
    print(text, flush=True)


def run(cmd, timeout=None, check=True, env=None):
    log("  $ " + " ".join(cmd))
    p = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=timeout, env=env)
    if check and p.returncode != 0:
        raise RuntimeError("%s failed (%d):\n%s%s" % (cmd[0], p.returncode, p.stdout[-3000:], p.stderr[-3000:]))
    return p


def median(values):
    return statistics.median(values) if values else float("nan")


def spread(values, fmt="%.0f"):
    """'median (min-max)' of repeated runs."""
    if len(values) == 1:
        return fmt % values[0]
    return (fmt + " (" + fmt + "-" + fmt + ")") % (median(values), min(values), max(values))


class Results:
    def __init__(self):
        self.md = []
        self.raw = {}

    def section(self, title, note=None):
        self.md += ["", "### " + title, ""]
        if note:
            self.md += [note, ""]
        log("\n== " + title)

    def table(self, header, rows):
        lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
        lines += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
        self.md += lines
        log("\n".join(lines))

    def text(self, line):
        self.md.append(line)
        log(line)


def environment(build):
    cpu = ""
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    build_type = ""
    try:
        m = re.search(r"^CMAKE_BUILD_TYPE:\w+=(.*)$", open(os.path.join(build, "CMakeCache.txt")).read(), re.M)
        build_type = m.group(1) if m else ""
    except OSError:
        pass
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], cwd=ROOT, capture_output=True,
                            text=True).stdout.strip()
    return {"cpu": cpu, "cpus": os.cpu_count(), "kernel": platform.release(), "build_type": build_type,
            "commit": commit, "load_average": open("/proc/loadavg").read().split()[:3],
            "date": datetime.datetime.now().isoformat(timespec="seconds")}


# 1 and 3a: Google Benchmark ----------------------------------------------------------------------
def google_benchmark(r, build, quick):
    out = os.path.join(r.raw["out_dir"], "firtp_bench.json")
    reps = 1 if quick else 5
    cmd = [os.path.join(build, "bin", "firtp_bench"), "--benchmark_repetitions=%d" % reps,
           "--benchmark_out=" + out, "--benchmark_out_format=json", "--benchmark_format=console"]
    if quick:
        cmd.append("--benchmark_min_time=0.05")
    run(cmd)
    data = json.load(open(out))
    per = {}
    for b in data["benchmarks"]:
        if b.get("run_type") != "iteration":
            continue
        per.setdefault(b["run_name"], []).append(b)
    res = {}
    for name, runs in per.items():
        scale = {"ns": 1.0, "us": 1e3, "ms": 1e6}[runs[0]["time_unit"]]
        res[name] = {"real_ns": [x["real_time"] * scale for x in runs], "cpu_ns": [x["cpu_time"] * scale for x in runs],
                     "worst_ns": [x.get("worst_ns", 0.0) for x in runs]}
    r.raw["firtp_bench"] = res
    return res


def tick_means(r, gb, quick):
    r.section("Servo tick, mean (firtp_bench BM_Tick)",
              "Google Benchmark, mean over millions of calls; median of %d repetitions (min-max). README: 92, 100, 95, "
              "103, 108 ns." % (1 if quick else 5))
    configs = [(3, 2), (3, 3), (9, 2), (9, 3), (9, 4)]
    row, ratio = [], []
    base = median(gb.get("BM_Tick/axes:3/stages:2", {}).get("real_ns", [float("nan")]))
    for a, s in configs:
        v = gb.get("BM_Tick/axes:%d/stages:%d" % (a, s), {}).get("real_ns", [])
        row.append(spread(v) + " ns" if v else "-")
        ratio.append("%.2f" % (median(v) / base) if v else "-")
    r.table(["", "3 axes, 2 stages", "3 axes, 3 stages", "9 axes, 2 stages", "9 axes, 3 stages", "9 axes, 4 stages"],
            [["servo tick (interpolation)"] + row, ["ratio to 3 axes, 2 stages"] + ratio])


# 2: worst tick --------------------------------------------------------------------------------------
def worst_tick(r, build, quick):
    ticks = 1_000_000 if quick else 10_000_000
    r.section("Servo tick, worst case over a long run (firtp_worst_tick)",
              "%s ticks of random moves per configuration (0.05-40 mm, 50-300 mm/s, every 50th an exact stop), each "
              "tick timed alone. Thread CPU clock: leaves out the time the thread waits for a core, but on a VM it still "
              "counts interrupts and the hypervisor's steal, and includes its own system call (the \"floor\"). Wall "
              "clock: its maxima include preemption by other jobs on this shared VM. So the tick's own tail is the wall "
              "clock's p99.99; the maxima of both clocks are the machine's (docs/BENCHMARKS.md, \"Two clocks\"). "
              "End: the output at rest equals the last command bit for bit." % format(ticks, ","))
    configs = [(3, 2), (3, 3), (9, 2), (9, 3), (9, 4)]
    rows, raw = [], []
    for a, s in configs:
        p = run([os.path.join(build, "bin", "firtp_worst_tick"), "--axes", str(a), "--stages", str(s),
                 "--ticks", str(ticks), "--json"], check=False)
        d = json.loads(p.stdout.strip().splitlines()[-1])
        raw.append(d)
        c, w, f = d["cpu_ns"], d["wall_ns"], d["floor_cpu_ns"]
        rows.append(["%d axes, %d stages" % (a, s), "%.0f / %d / %d / %d ns" % (c["mean"], c["p99"], c["p9999"], c["max"]),
                     "%d ns" % f["p50"], "%.0f / %d / %d / %d ns" % (w["mean"], w["p99"], w["p9999"], w["max"]),
                     "exact" if d["end_exact"] else "NOT EXACT"])
    r.raw["worst_tick"] = raw
    r.table(["configuration", "CPU clock mean / p99 / p99.99 / max", "CPU timer floor (p50)",
             "wall clock mean / p99 / p99.99 / max", "end"], rows)
    r.text("")
    r.text("The CPU-clock figures include the clock's own cost (a system call on this VM: the floor), so the mean here "
           "is higher than firtp_bench's.")


# 3b: planning per block -------------------------------------------------------------------------
def plan_blocks(r, build, gb, quick):
    reps = 1 if quick else 5
    r.section("Planning one block",
              "firtp_bench BM_PlanBlock (random 2-40 mm corners, 100-300 mm/s, Td 237-268 ms): Google Benchmark "
              "mean, median of %d repetitions (min-max). README: 59, 67 µs equal feeds; 63, 70 µs feeds differ."
              % (1 if quick else 5))
    rows = []
    for feeds, v in (("equal feeds", 0), ("feeds differ between blocks", 1)):
        cells = []
        for s in (2, 3):
            x = gb.get("BM_PlanBlock/stages:%d/varying_feed:%d" % (s, v), {}).get("real_ns", [])
            cells.append(spread([t / 1e3 for t in x], "%.1f") + " µs" if x else "-")
        rows.append([feeds] + cells)
    r.table(["planning one block", "2 stages", "3 stages"], rows)
    r.text("")
    r.text("Every block of the example programs, built-in machine, planner.add timed alone (firtp_plan_stream "
           "--program): median over %d runs (min-max). README (examples/linuxcnc/README.md): max 129 µs CPU on "
           "cam_contour, 84 µs on arcs; median 14-15 µs, p99 40-44 µs." % reps)
    r.text("")
    rows, raw = [], {}
    for prog in ("cam_contour.ngc", "arcs.ngc", "diamond.ngc"):
        runs = []
        for _ in range(reps):
            p = run([os.path.join(build, "bin", "firtp_plan_stream"), "--program", os.path.join("examples", prog), "--json"])
            runs.append(json.loads(p.stdout.strip().splitlines()[-1]))
        raw[prog] = runs
        cpu = [x["add_cpu_ns"] for x in runs]
        wall = [x["add_wall_ns"] for x in runs]
        us = lambda xs, k: spread([x[k] / 1e3 for x in xs], "%.1f")  # noqa: E731
        rows.append([prog, runs[0]["blocks"], us(cpu, "mean"), us(cpu, "p50"), us(cpu, "p99"), us(cpu, "max"),
                     us(wall, "p99"), us(wall, "max")])
    r.raw["plan_examples"] = raw
    r.table(["program", "blocks", "CPU mean µs", "CPU p50 µs", "CPU p99 µs", "CPU max µs", "wall p99 µs",
             "wall max µs (preemption)"], rows)


# 4: a million blocks -------------------------------------------------------------------------------
def million(r, build, quick, timeout):
    blocks = 100_000 if quick else 1_000_000
    r.section("Offline planning of a %s-block program (firtp_plan_stream --generate)" % format(blocks, ","),
              "Generated on the fly, planned and sampled block by block (Planner + Interpolator, queue of 256 "
              "blocks), keeping running maxima only. Built-in machine (X Y Z, 300 mm/s, 5000 mm/s², 10^5 mm/s³, "
              "1 ms, T 60/50 ms). spiral: Archimedean from R 60 mm, 0.5 mm pitch, chords 0.3-0.7 mm, F6000, P0.05. random: "
              "chords 0.1-2 mm turning up to 90°, 100-300 mm/s, 0.01-0.05 mm. corners: firtp_bench's BM_PlanBlock "
              "blocks, corners 2-40 mm apart, 100-300 mm/s, 0.05 mm. Peak RSS is the process's high-water "
              "mark (VmHWM); \"if kept\" is what plan_trajectory / firtp plan would hold in samples alone.")
    rows, raw = [], {}
    for kind in ("spiral", "random", "corners"):
        cmd = [os.path.join(build, "bin", "firtp_plan_stream"), "--generate", kind, "--blocks", str(blocks),
               "--max-growth-kib", "1024", "--json"]
        try:
            p = run(cmd, timeout=timeout, check=False)
            d = json.loads(p.stdout.strip().splitlines()[-1])
        except subprocess.TimeoutExpired:
            raw[kind] = {"timeout_s": timeout}
            rows.append([kind, format(blocks, ","), "did not finish within %d s" % timeout] + [""] * 8)
            continue
        except (ValueError, IndexError):
            raw[kind] = {"failed": p.returncode}
            rows.append([kind, format(blocks, ","), "failed (exit %d): %s" % (p.returncode, p.stderr.strip()[-200:])]
                        + [""] * 8)
            continue
        raw[kind] = d
        c = d["add_cpu_ns"]
        rows.append([kind, format(d["blocks"], ","), format(d["ticks"], ","), "%.0f" % d["blocks_per_s"],
                     "%.1f s" % d["wall_s"],
                     "%.1f / %.1f / %.0f µs" % (c["mean"] / 1e3, c["p99"] / 1e3, c["max"] / 1e3),
                     "%.1f → %.1f MiB" % (d["peak_rss_kib_after_first_tenth"] / 1024, d["peak_rss_kib"] / 1024),
                     "%.0f MiB" % d["samples_mib_if_kept"],
                     "%.4f" % (d["cycle_time_s"] / d["closed_form_cycle_time_s"]),
                     "%.0f / %.0f" % (d["max_axis_acceleration"], d["max_axis_jerk"]),
                     ("exact" if d["end_exact"] else "NOT EXACT") + (", flat" if d["flat"] else ", GREW")])
    r.raw["million"] = raw
    r.table(["program", "blocks", "servo periods", "blocks/s", "wall time", "plan CPU mean / p99 / max",
             "peak RSS after 1/10 → end", "samples if kept", "cycle / closed form", "max axis a / j", "end, memory"],
            rows)


# 5: LCM stream -------------------------------------------------------------------------------------
STREAM_RE = {
    "rate": r"accepted in ([\d.]+) s = (\d+) blocks/s",
    "accepted": r"stream: (\d+) of (\d+) blocks",
    "resends": r"resends (\d+)\), refused (\d+)",
    "streaming": r"firtp.update while streaming.*?mean ([\d.]+) us, median ([\d.]+) us, p99 ([\d.]+) us, max ([\d.]+) us",
    "moving": r"firtp.update moving.*?mean ([\d.]+) us, median ([\d.]+) us, p99 ([\d.]+) us, max ([\d.]+) us",
}


def stream(r, build, quick):
    runs_n, blocks = (1, 10000) if quick else (3, 50000)
    r.section("Sustained LCM block rate, no loss (tests/bench/stream_bench.sh)",
              "Host and component on separate LCM endpoints over UDP multicast on loopback in a private network "
              "namespace, servo thread at 1 kHz, built-in machine, %s dense blocks of 0.5 mm at 250 mm/s, %d run(s). "
              "README: 20,500-21,300 blocks/s, 0 resends, 0 refused; firtp.update while planning mean 520-528 µs, "
              "p99 740-940 µs; moving median 0.5 µs." % (format(blocks, ","), runs_n))
    if os.geteuid() != 0 or not shutil.which("unshare"):
        r.text("Skipped: needs root and unshare.")
        return
    raw, rows = [], []
    for i in range(runs_n):
        p = run(["bash", os.path.join(ROOT, "tests", "bench", "stream_bench.sh"), build, "--blocks", str(blocks)],
                timeout=300, check=False)
        out = p.stdout
        m = {k: re.search(v, out) for k, v in STREAM_RE.items()}
        if not all(m.values()):
            r.text("Run %d failed (exit %d): %s" % (i + 1, p.returncode, (out + p.stderr)[-500:]))
            continue
        d = {"blocks_per_s": float(m["rate"].group(2)), "accepted": int(m["accepted"].group(1)),
             "blocks": int(m["accepted"].group(2)), "resends": int(m["resends"].group(1)),
             "refused": int(m["resends"].group(2)), "streaming_us": [float(x) for x in m["streaming"].groups()],
             "moving_us": [float(x) for x in m["moving"].groups()]}
        raw.append(d)
        rows.append([i + 1, "%.0f" % d["blocks_per_s"], "%d / %d" % (d["accepted"], d["blocks"]), d["resends"],
                     d["refused"], "%.0f / %.0f / %.0f / %.0f" % tuple(d["streaming_us"]),
                     "%.1f / %.1f / %.1f / %.0f" % tuple(d["moving_us"])])
    r.raw["stream"] = raw
    if raw:
        rows.append(["median", "%.0f" % median([d["blocks_per_s"] for d in raw]), "", "", "",
                     "%.0f / %.0f / %.0f / %.0f" % tuple(median([d["streaming_us"][k] for d in raw]) for k in range(4)),
                     "%.1f / %.1f / %.1f / %.0f" % tuple(median([d["moving_us"][k] for d in raw]) for k in range(4))])
    r.table(["run", "blocks/s", "accepted", "resends", "refused", "firtp.update streaming mean / p50 / p99 / max µs",
             "firtp.update moving mean / p50 / p99 / max µs"], rows)


# 6: cycle time and the README's program figures --------------------------------------------------------
PROGRAMS = [
    ("diamond.ngc", ["--ini", "examples/diamond.ini"], "1.2250 s (1.2247 s)"),
    ("cam_contour.ngc", [], "28.5 s (25.8 s)"),
    ("arcs.ngc", [], "9.87 s (9.73 s)"),
    ("five_axis.ngc", ["--ini", "examples/five_axis.ini"], "4.90 s (4.83 s)"),
]


def cycle_times(r, build):
    r.section("Cycle time against the closed form (firtp plan --json)",
              "Closed form: sum(Tv) + sum(Td - Tk) + Td, the time the filters alone need with the planner's overlaps. "
              "Built-in machine unless an INI is named. Deterministic (no timing involved).")
    rows, raw = [], {}
    for prog, args, readme in PROGRAMS:
        out = os.path.join(r.raw["out_dir"], prog.replace(".ngc", ".json"))
        run([os.path.join(build, "bin", "firtp"), "plan", os.path.join("examples", prog)] + args + ["--json", out])
        d = json.load(open(out))
        raw[prog] = d
        m = d["measured"]
        eps = max((c["epsilon_mm"] for c in d["corners"] if c["epsilon_mm"] is not None), default=float("nan"))
        rows.append([prog + (" " + " ".join(args) if args else ""), d["blocks"], "%.4f s" % d["cycle_time_s"],
                     "%.4f s" % d["closed_form_cycle_time_s"], "%.4f" % (d["cycle_time_s"] / d["closed_form_cycle_time_s"]),
                     readme, "%.5f / %.3g mm" % (m["max_corner_error_mm"], eps), "%.4f mm" % m["max_contour_error_mm"],
                     "%.1f mm/s" % m["max_path_speed_mm_s"],
                     "%.0f / %.0f" % (max(m["max_axis_acceleration"]), max(m["max_axis_jerk"])),
                     "%.1e mm" % m["end_error_mm"]])
    r.raw["plan"] = raw
    r.table(["program", "blocks", "cycle time", "closed form", "ratio", "README", "max corner error / tolerance",
             "max contour error", "max path speed", "max axis a / j", "end error"], rows)
    dm = raw["diamond.ngc"]
    r.text("")
    r.text("Diamond (Section 4): Tk per corner %s ms (paper 96.34 ms); corner errors %s mm (README 0.49974, 0.49978, "
           "0.49979)." % (", ".join("%.2f" % (c["tk_s"] * 1e3) for c in dm["corners"]),
                          ", ".join("%.5f" % c["measured_error_mm"] for c in dm["corners"])))


# 7: LinuxCNC -----------------------------------------------------------------------------------------
def hal_sessions():
    p = subprocess.run(["pgrep", "-a", "rtapi_app"], capture_output=True, text=True)
    return p.stdout.strip()


def linuxcnc(r, build, wait):
    r.section("firtp_tp against LinuxCNC's stock planner (examples/linuxcnc/compare.py)",
              "Same programs, X Y Z at 300 mm/s and 5000 mm/s², 1 ms; the stock planner has no jerk limit. "
              "Motion-controller times are HAL .time pins on a non-real-time kernel: maxima are preemption.")
    module = os.path.join(build, "linuxcnc", "firtp_tp.so")
    if not shutil.which("linuxcnc") or not os.path.exists(module):
        r.text("Skipped: LinuxCNC or %s not found." % module)
        return
    deadline = time.time() + wait
    while hal_sessions():
        if time.time() > deadline:
            r.text("Skipped: another HAL session (rtapi_app) ran for all of %d s: %s" % (wait, hal_sessions()))
            return
        log("  another HAL session runs (%s); waiting" % hal_sessions().replace("\n", "; "))
        time.sleep(10)
    p = run([sys.executable, os.path.join(ROOT, "examples", "linuxcnc", "compare.py"), "--module", module,
             "--check-tool", os.path.join(build, "bin", "firtp-tp-check")], timeout=900, check=False)
    if p.returncode == SKIP or "SKIPPED" in p.stdout:
        r.text("Skipped by compare.py: " + p.stdout.strip()[-300:])
        return
    table = [l for l in p.stdout.splitlines() if l.startswith("|")]
    rows = [[c.strip() for c in l.strip("|").split("|")] for l in table]
    main = []  # compare.py prints each row as it goes, then the whole table: keep the first of each
    for x in rows:
        if len(x) == 8 and x[1] in ("tpmod", "firtp_tp") and x not in main:
            main.append(x)
    r.raw["linuxcnc"] = {"stdout": p.stdout, "rows": main}
    full = p.stdout[p.stdout.find("| program | planner"):] if "| program | planner" in p.stdout else ""
    r.md += full.strip().splitlines()
    log(full)
    # Ratios on the same run: firtp_tp / tpmod cycle time per program.
    ratios = []
    for i in range(0, len(main) - 1, 2):
        a, b = main[i], main[i + 1]
        if a[1] == "tpmod" and b[1] == "firtp_tp" and a[0] == b[0]:
            ta, tb = float(a[2].split()[0]), float(b[2].split()[0])
            ratios.append([a[0], "%.3f s" % ta, "%.3f s" % tb, "%.2f" % (tb / ta)])
    r.text("")
    r.table(["program", "tpmod cycle", "firtp_tp cycle", "firtp_tp / tpmod"], ratios)
    if p.returncode != 0:
        r.text("compare.py exited with %d." % p.returncode)


# 8: the test-suite figures ---------------------------------------------------------------------------
def suite(r, build):
    r.section("Figures the test suite holds (ctest)",
              "Paper figures (Fig. 4, Eq. 13/14 against a simulated running-sum chain, the diamond), the randomized "
              "suites (3,800 programs; 150 G-code programs; 120 override programs), 10^7 ticks bit-exact, the "
              "chain and replay equalities, the example programs' tolerance, limits and closed form. Pass = the "
              "README's figure holds on this machine.")
    regex = (r"^(Overlap\.|Figure4\.|Diamond\.|RandomPaths\.|RandomPrograms\.|RateLimits\.|AxisLimits\.|"
             r"DensePaths\.|Drift\.|Examples/PlanExamples\.|Logs/Replay\.|chain\.run_equals_plan|"
             r"chain\.two_processes_over_udp_multicast)")
    p = run(["ctest", "--test-dir", build, "-R", regex, "-j2", "--output-on-failure"], timeout=1800, check=False)
    m = re.search(r"(\d+)% tests passed, (\d+) tests failed out of (\d+)", p.stdout)
    t = re.search(r"Total Test time \(real\) =\s+([\d.]+) sec", p.stdout)
    if m:
        r.text("ctest -R '%s': %s of %s passed, %s failed, %s s." % (regex, int(m.group(3)) - int(m.group(2)),
                                                                    m.group(3), m.group(2), t.group(1) if t else "?"))
        failed = re.findall(r"\d+ - (\S+) \(Failed\)", p.stdout)
        if failed:
            r.text("Failed: " + ", ".join(failed))
    else:
        r.text("ctest did not report (exit %d): %s" % (p.returncode, p.stdout[-500:]))
    r.raw["ctest"] = {"regex": regex, "returncode": p.returncode, "summary": m.group(0) if m else None}


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("build")
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--out")
    ap.add_argument("--json")
    ap.add_argument("--skip-stream", action="store_true")
    ap.add_argument("--skip-linuxcnc", action="store_true")
    ap.add_argument("--skip-ctest", action="store_true")
    ap.add_argument("--plan-timeout", type=int, default=120,
                    help="seconds each generated program may take (120); longer is reported, not fatal")
    ap.add_argument("--wait-linuxcnc", type=int, default=600, help="seconds to wait for other HAL sessions (600)")
    a = ap.parse_args()
    build = os.path.abspath(a.build)
    for exe in ("firtp", "firtp_bench", "firtp_worst_tick", "firtp_plan_stream"):
        if not os.path.exists(os.path.join(build, "bin", exe)):
            sys.exit("%s/bin/%s is missing: cmake --build %s -j2" % (build, exe, a.build))
    out_dir = os.path.join(build, "bench-results")
    os.makedirs(out_dir, exist_ok=True)
    r = Results()
    r.raw["out_dir"] = out_dir
    env = environment(build)
    r.raw["environment"] = env
    begin = time.time()
    r.md += ["## Results: %s" % env["date"], "",
             "`tests/bench/reproduce.sh %s`, commit %s, %s build; %s x %s, Linux %s; load average at start %s." % (
                 " ".join(sys.argv[1:]), env["commit"], env["build_type"] or "?", env["cpus"],
                 env["cpu"], env["kernel"], " ".join(env["load_average"]))]
    if env["build_type"] != "Release":
        r.text("WARNING: not a Release build: timings are not comparable with the README.")

    gb = google_benchmark(r, build, a.quick)
    tick_means(r, gb, a.quick)
    worst_tick(r, build, a.quick)
    plan_blocks(r, build, gb, a.quick)
    million(r, build, a.quick, a.plan_timeout)
    if a.skip_stream:
        r.section("Sustained LCM block rate, no loss (tests/bench/stream_bench.sh)", "Skipped (--skip-stream).")
    else:
        stream(r, build, a.quick)
    cycle_times(r, build)
    if a.quick or a.skip_linuxcnc:
        r.section("firtp_tp against LinuxCNC's stock planner (examples/linuxcnc/compare.py)",
                  "Skipped (%s)." % ("--quick" if a.quick else "--skip-linuxcnc"))
    else:
        linuxcnc(r, build, a.wait_linuxcnc)
    if not (a.quick or a.skip_ctest):
        suite(r, build)

    env_end = open("/proc/loadavg").read().split()[:3]
    r.md += ["", "Took %.0f s; load average at the end %s." % (time.time() - begin, " ".join(env_end))]
    r.raw["seconds"] = time.time() - begin
    md_path = a.out or os.path.join(out_dir, "results.md")
    json_path = a.json or os.path.join(out_dir, "results.json")
    with open(md_path, "w") as f:
        f.write("\n".join(r.md).lstrip("\n") + "\n")
    with open(json_path, "w") as f:
        json.dump(r.raw, f, indent=1)
    log("\nwrote %s and %s (%.0f s)" % (md_path, json_path, time.time() - begin))
    failed = any(not d["end_exact"] for d in r.raw.get("worst_tick", [])) or \
        any(not (d.get("end_exact", True) and d.get("flat", True)) for d in r.raw.get("million", {}).values())
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
