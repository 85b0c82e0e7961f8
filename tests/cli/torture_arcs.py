#!/usr/bin/env python3
"""Torture programs in the style of LinuxCNC's tort.ngc: random helical G2/G3 arcs (1-10 mm, any
sweep) between G0/G1 moves, feeds F100-F890, G64 P0.05, each `firtp plan`ned on the built-in
machine within 120 s: exit 0 (3 would be a measured tolerance, limit or end-point violation).
Seeds 2, 4 and 7 once found a block added while the one under way could not take the new plan:
the plan fell back on one that left the newest block at speed 0 (seeds 4, 7: the tool rested for
good, plan never finished; seed 2: a jump of 92,000 mm/s^2); seed 2 also went over limits before
the limit sweep's fixes of 5c02b7e.
    torture_arcs.py FIRTP [SEED...]"""
import math
import os
import random
import subprocess
import sys
import tempfile


def program(seed, moves=300):
    r = random.Random(seed)
    lines = ["G21 G90 G64 P0.05", "G0 X0 Y0 Z20", "F100"]
    x = y = 0.0
    z = 20.0
    for _ in range(moves):
        line = r.random()
        feed = r.choice([100, 160, 170, 290, 300, 310, 480, 690, 730, 890])
        if line < 0.25:
            x += r.uniform(-5, 5)
            y += r.uniform(-5, 5)
            z = min(25, max(-10, z + r.uniform(-4, 4)))
            lines.append("G%d F%d X%.6f Y%.6f Z%.6f" % (r.choice([0, 1]), feed, x, y, z))
            continue
        radius, a0, sweep = r.uniform(1, 10), r.uniform(0, 2 * math.pi), r.uniform(0.2, 2 * math.pi)
        cw = r.random() < 0.5
        cx, cy = x - radius * math.cos(a0), y - radius * math.sin(a0)
        a1 = a0 - sweep if cw else a0 + sweep
        x, y = cx + radius * math.cos(a1), cy + radius * math.sin(a1)
        z = min(25, max(-10, z + r.uniform(-4, 4)))
        lines.append("G17 G%d F%d I%.6f J%.6f X%.6f Y%.6f Z%.6f" % (
            2 if cw else 3, feed, -radius * math.cos(a0), -radius * math.sin(a0), x, y, z))
    return "\n".join(lines + ["M2", ""])


def main():
    firtp, seeds = sys.argv[1], [int(s) for s in sys.argv[2:]] or [2, 4, 7]
    failed = []
    with tempfile.TemporaryDirectory() as work:
        for seed in seeds:
            path = os.path.join(work, "tort%d.ngc" % seed)
            open(path, "w").write(program(seed))
            try:
                run = subprocess.run([firtp, "plan", path], capture_output=True, text=True, timeout=120)
            except subprocess.TimeoutExpired:
                print("seed %d: did not finish within 120 s" % seed)
                failed.append(seed)
                continue
            summary = [l for l in run.stdout.splitlines() if l.split(" ")[0] in ("blocks", "cycle", "corners", "axes")]
            print("seed %d: exit %d; %s" % (seed, run.returncode, "; ".join(" ".join(l.split()) for l in summary)))
            sys.stdout.write(run.stderr)
            if run.returncode != 0 or "all within tolerance" not in run.stdout:
                failed.append(seed)
    if failed:
        print("FAIL: seeds %s" % failed)
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())
