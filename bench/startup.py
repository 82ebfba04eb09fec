#!/usr/bin/env python3
"""Benchmark: pkm-studio from exec to its first painted window, the whole process as a user
meets it (dynamic linking, fonts, the window, the first paint of the linkage), on Qt's
offscreen platform so that no display server is timed. The program is run RUNS times with
--quit-after-first-paint, which quits right after the linkage view has painted and prints
how long that took from main(); the wall time of each whole process is measured here.

    startup.py PKM_STUDIO [--limit-ms 500] [--runs 10] [--preset ID]

Prints min, median and max of both, the machine, and whether the median meets the limit
(exit 1 if not)."""
import argparse
import os
import re
import statistics
import subprocess
import sys
import time

from benchmachine import machine


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("program")
    parser.add_argument("--limit-ms", type=float, default=500.0)
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--preset", default="pjoint-prototype")
    args = parser.parse_args()
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen", QT_LOGGING_RULES="qt.qpa.*=false")
    walls, paints = [], []
    for run in range(args.runs + 1):
        start = time.perf_counter()
        done = subprocess.run([args.program, "--quit-after-first-paint", args.preset], env=env,
                              capture_output=True, text=True, timeout=60)
        wall = (time.perf_counter() - start) * 1e3
        found = re.search(r"first paint after ([0-9.]+) ms", done.stdout)
        if done.returncode != 0 or not found:
            print(f"FAIL: pkm-studio exited {done.returncode} without painting:\n{done.stdout}{done.stderr}")
            return 1
        if run == 0:
            continue  # the first run pages the libraries in
        walls.append(wall)
        paints.append(float(found.group(1)))
    median = statistics.median(walls)
    print(f"pkm-studio {args.preset}, offscreen, {args.runs} runs, on {machine()}")
    print(f"whole process to the first painted window: min {min(walls):.0f} ms, median {median:.0f} ms, "
          f"max {max(walls):.0f} ms (main() to first paint: median {statistics.median(paints):.0f} ms)")
    print(f"target: median <= {args.limit_ms:.0f} ms ({'met' if median <= args.limit_ms else 'MISSED'})")
    return 0 if median <= args.limit_ms else 1


if __name__ == "__main__":
    sys.exit(main())
