#!/usr/bin/env python3
"""The Python module against the C++ it wraps, as a user meets both (issue: Python module).

  sweep: design.sweep('theta', numpy.linspace(-60, 60, STEPS)) against the whole process
         `pkm sweep pjoint-prototype --var theta --from -60 --to 60 --steps STEPS --csv > /dev/null`
         (goal: at most 1.5 times its time);
  map:   design.map('det', grid=3000) for MOMA 3a, the whole call, against the computation of
         the same map inside it, as the C++ times it (Map.seconds; goal: at most 1.2 times).

Best of RUNS runs each. Prints the machine (CPU model and vector extensions) with the figures
and fails if a ratio exceeds its goal.

  python3 bench/python_module.py PKM [--steps 1000000] [--grid 3000] [--runs 5]
"""

import argparse
import os
import subprocess
import sys
import time

import numpy as np

import pkmstudio
from benchmachine import machine


def best(runs, work):
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        work()
        times.append(time.perf_counter() - start)
    return min(times), sorted(times)[len(times) // 2]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("pkm")
    parser.add_argument("--steps", type=int, default=1_000_000)
    parser.add_argument("--grid", type=int, default=3000)
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--sweep-goal", type=float, default=1.5)
    parser.add_argument("--map-goal", type=float, default=1.2)
    options = parser.parse_args()
    print(f"machine: {machine()}")

    prototype = pkmstudio.load("pjoint-prototype")
    values = np.linspace(-60, 60, options.steps)
    command = [options.pkm, "sweep", "pjoint-prototype", "--var", "theta", "--from", "-60", "--to", "60",
               "--steps", str(options.steps), "--csv"]

    def cli_sweep():
        with open(os.devnull, "w") as null:
            subprocess.run(command, stdout=null, check=True)

    cli_best, cli_median = best(options.runs, cli_sweep)
    python_best, python_median = best(options.runs, lambda: prototype.sweep("theta", values))
    sweep_ratio = python_best / cli_best
    print(f"sweep of {options.steps} steps: Python {python_best * 1e3:.0f} ms (median {python_median * 1e3:.0f}), "
          f"pkm sweep --csv process {cli_best * 1e3:.0f} ms (median {cli_median * 1e3:.0f}): "
          f"{sweep_ratio:.2f}× (goal ≤ {options.sweep_goal}×)")

    moma = pkmstudio.load("moma-3a")
    calls, inside = [], []
    for _ in range(options.runs):
        start = time.perf_counter()
        mapped = moma.map("det", grid=options.grid)
        calls.append(time.perf_counter() - start)
        inside.append(mapped.seconds)
        del mapped
    map_ratio = min(calls) / min(inside)
    cells = options.grid * options.grid
    print(f"det J map of moma-3a at grid {options.grid}: the Python call {min(calls) * 1e3:.1f} ms, the C++ map in it "
          f"{min(inside) * 1e3:.1f} ms ({cells / min(inside) / 1e6:.0f} M cells/s of the bounding square): "
          f"{map_ratio:.2f}× (goal ≤ {options.map_goal}×)")

    failed = [name for name, ratio, goal in (("sweep", sweep_ratio, options.sweep_goal),
                                              ("map", map_ratio, options.map_goal)) if ratio > goal]
    if failed:
        print("missed: " + ", ".join(failed))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
