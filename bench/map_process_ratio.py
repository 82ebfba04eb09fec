#!/usr/bin/env python3
"""The MOMA det J map as a user meets it: the whole `pkm map moma-3a --grid N --json` process
(start-up, bounds, the map, its summary, the JSON) against the plain NumPy computation of the
same map alone (moma_map_numpy.py: same bounds, same cells, one thread), in one run.

For each grid of --ratio (GRID:GOAL[:MIN], default 3000:20:12 and 500:8:0) the two are timed
in turn, pkm then NumPy, RUNS times; the ratio NumPy/pkm is taken pair by pair, so that a
machine whose speed drifts during the run still gives a fair figure. Its median is reported
against GOAL (met or missed) and fails the benchmark below MIN. The reachable cells of the two
must agree but for the outline (0.1 %). Beside it, the floor no process can go under: the
median time of starting and reaping /bin/true, and the ratio that floor would give.

Then the cost curve over --curve grids (default 250 … 4000): the process time and the map time
the process reports, per million cells, to show that the cost grows with the cells and not
faster.

    map_process_ratio.py PKM BENCH_MAP [--runs 5] [--ratio 3000:20:12 --ratio 500:8:0]
                         [--curve 250,500,1000,2000,3000,4000]

BENCH_MAP (bench/bench_map) supplies the design's parameters in the NumPy script's form.
Exit status: 0 when every ratio reaches its MIN and the maps agree, 1 otherwise, 2 on bad
arguments, 3 without NumPy.
"""

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

from benchmachine import machine

try:
    import numpy as np
except ImportError:
    print("error: NumPy is missing; install it with: apt-get install python3-numpy "
          "(or run scripts/install-deps.sh)", file=sys.stderr)
    sys.exit(3)

import moma_map_numpy


def run_pkm(pkm, grid):
    """One whole `pkm map` process: its wall time (ms) and its JSON."""
    start = time.perf_counter()
    done = subprocess.run([pkm, "map", "moma-3a", "--grid", str(grid), "--json"], capture_output=True, timeout=120)
    wall = (time.perf_counter() - start) * 1e3
    if done.returncode != 0:
        raise RuntimeError(f"pkm map --grid {grid} failed ({done.returncode}): "
                           f"{done.stderr.decode('utf-8', 'replace')[:500]}")
    return wall, json.loads(done.stdout)


def numpy_spec(design, result):
    """The NumPy script's input for the grid pkm used: pkm's grid, bench_map's design."""
    grid = result["grid"]
    return {"design": design, "columns": grid["columns"], "rows": grid["rows"],
            "bounds": [grid["x_min"], grid["y_min"], grid["x_max"], grid["y_max"]]}


def process_floor(runs):
    """The median wall time (ms) of starting and reaping /bin/true."""
    walls = []
    for _ in range(runs + 1):
        start = time.perf_counter()
        subprocess.run(["/bin/true"], check=False)
        walls.append((time.perf_counter() - start) * 1e3)
    return statistics.median(walls[1:])


def ratio_at(pkm, design, grid, goal, minimum, floor, runs):
    """Times pkm and NumPy in turn at `grid`; prints the figures, returns (above MIN, agree)."""
    _, result = run_pkm(pkm, grid)  # warm-up: the page cache, the CPU's clock
    spec = numpy_spec(design, result)
    values = moma_map_numpy.det_map(spec)
    processes, numpies, ratios = [], [], []
    for _ in range(runs):
        wall, result = run_pkm(pkm, grid)
        start = time.perf_counter()
        values = moma_map_numpy.det_map(spec)
        numpy_ms = (time.perf_counter() - start) * 1e3
        processes.append(wall)
        numpies.append(numpy_ms)
        ratios.append(numpy_ms / wall)
    cells = spec["columns"] * spec["rows"]
    reachable = int(np.count_nonzero(~np.isnan(values)))
    ours = result["reachable_cells"]
    agree = abs(ours - reachable) <= max(10, reachable // 1000)
    ratio = statistics.median(ratios)
    print(f"grid {grid} ({spec['columns']}x{spec['rows']} = {cells} cells): whole pkm process median "
          f"{statistics.median(processes):.1f} ms (min {min(processes):.1f}, max {max(processes):.1f}; "
          f"its map {result['seconds'] * 1e3:.1f} ms), NumPy median {statistics.median(numpies):.1f} ms "
          f"(min {min(numpies):.1f})")
    print(f"  NumPy/pkm ratio, pair by pair: median {ratio:.1f}x (min {min(ratios):.1f}, max {max(ratios):.1f}); "
          f"goal >= {goal:g}x: {'met' if ratio >= goal else 'MISSED'}; fails below {minimum:g}x")
    print(f"  a process that only starts (/bin/true, {floor:.2f} ms) would be "
          f"{statistics.median(numpies) / floor:.1f}x")
    print(f"  reachable cells: pkm {ours}, NumPy {reachable}: {'agree' if agree else 'DISAGREE'}")
    return ratio >= minimum, agree


def curve(pkm, grids, runs):
    """The process and map times over `grids`, per million cells."""
    print("cost curve (median of %d runs): grid, cells, process ms, map ms, process ms per Mcell, map ms per Mcell"
          % runs)
    for grid in grids:
        run_pkm(pkm, grid)
        walls, maps = [], []
        for _ in range(runs):
            wall, result = run_pkm(pkm, grid)
            walls.append(wall)
            maps.append(result["seconds"] * 1e3)
        cells = result["grid"]["columns"] * result["grid"]["rows"]
        wall, mapped = statistics.median(walls), statistics.median(maps)
        print(f"  {grid:5d} {cells:9d} {wall:8.1f} {mapped:8.1f} {wall / cells * 1e6:8.2f} {mapped / cells * 1e6:8.2f}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("pkm")
    parser.add_argument("bench_map")
    parser.add_argument("--runs", type=int, default=5)
    parser.add_argument("--ratio", action="append", default=[], help="GRID:GOAL[:MIN]")
    parser.add_argument("--curve", default="250,500,1000,2000,3000,4000")
    args = parser.parse_args()
    try:
        goals = []
        for item in args.ratio or ["3000:20:12", "500:8:0"]:
            parts = item.split(":")
            if len(parts) not in (2, 3):
                raise ValueError(item)
            goals.append((int(parts[0]), float(parts[1]), float(parts[2]) if len(parts) == 3 else float(parts[1])))
        grids = [int(g) for g in args.curve.split(",") if g]
    except ValueError:
        parser.error("--ratio takes GRID:GOAL[:MIN] and --curve a comma-separated list of grids")
    if args.runs < 1 or any(g < 2 or g > 4000 for g, _, _ in goals) or any(g < 2 or g > 4000 for g in grids):
        parser.error("--runs must be at least 1 and every grid between 2 and 4000")

    with tempfile.TemporaryDirectory() as work:
        side = os.path.join(work, "design.json")
        subprocess.run([args.bench_map, "1000000", "--size", "2", "--runs", "1", "--json", side], check=True,
                       capture_output=True, timeout=60)
        with open(side, encoding="utf-8") as f:
            design = json.load(f)["design"]
    print(f"pkm map moma-3a --json against NumPy {np.__version__}, {args.runs} runs, on {machine()}")
    floor = process_floor(args.runs)
    status = 0
    for grid, goal, minimum in goals:
        enough, agree = ratio_at(args.pkm, design, grid, goal, minimum, floor, args.runs)
        if not agree or not enough:
            status = 1
    if grids:
        curve(args.pkm, grids, args.runs)
    return status


if __name__ == "__main__":
    sys.exit(main())
