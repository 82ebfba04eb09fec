#!/usr/bin/env python3
"""The MOMA det J map in plain NumPy, the baseline bench_map is measured against.

Reads the grid and the design from the JSON side file bench_map writes (--json): Moma's
workspace bounds come from sampling, so they are handed over rather than recomputed. Computes
the same map as core/momamaps.cpp (the MOMA document: inverse kinematics (7–9) of both legs per
cell, det J = β₁β₂·(L₁×L₂)/(√D₁·√D₂), NaN where the design cannot reach), vectorised over the
whole grid, times --runs runs, and prints the speed ratio C++/NumPy (best to best). With
--compare it checks that its map agrees with bench_map's (--write): the same reachable cells
but for rounding at the outline, and the same values to --rtol.

    moma_map_numpy.py --json map.json [--compare map.f32] [--runs 5] [--min-ratio 0] [--goal-ratio 20]
                      [--rtol 1e-4]

Exit status: 0 on success, 1 when the maps disagree or the ratio is below --min-ratio, 2 on
bad arguments, 3 when NumPy is missing.
"""

import argparse
import json
import sys
import time

try:
    import numpy as np
except ImportError:
    print("error: NumPy is missing; install it with: apt-get install python3-numpy "
          "(or run scripts/install-deps.sh)", file=sys.stderr)
    sys.exit(3)


def det_map(spec):
    """The det J map as float32, shape (rows, columns), row 0 at the bottom, NaN unreachable.

    The operations follow core/momamaps.cpp in the same order, so that the two maps agree to
    rounding and a cell on the outline is classified alike but for the last bit.
    """
    d = spec["design"]
    x_min, y_min, x_max, y_max = spec["bounds"]
    columns, rows = spec["columns"], spec["rows"]
    dx = (x_max - x_min) / columns
    dy = (y_max - y_min) / rows
    # cell centres exactly as MapGrid computes them: x = x(0) + i·dx, y = y_min + (r + ½)·dy
    x = (x_min + 0.5 * dx) + np.arange(columns) * dx
    y = y_min + (np.arange(rows) + 0.5) * dy
    p_min, p_max = d["stroke"]
    legs = []
    for reference, alpha, length, branch, inner in zip((d["R1"], d["R2"]), d["alpha"], d["length"], d["branch"],
                                                       d["inner_side"]):
        ax, ay = np.cos(alpha), np.sin(alpha)
        ex = x - reference[0]  # one row of x − x_R and one column of y − y_R: the grid by broadcasting
        ey = (y - reference[1])[:, None]
        B = ax * ex + ay * ey                                   # (8)
        D = B * B - ((ex * ex + ey * ey) - length * length)     # (9)
        s = np.sqrt(np.maximum(D, 0.0))
        p = B + branch * s                                      # (7)
        lx = ex - p * ax                                        # link L_i = P − Z_i
        ly = ey - p * ay
        slack = np.minimum(D, np.minimum(p - p_min, p_max - p))
        if d["one_side"] and inner:
            slack = np.minimum(slack, inner * (ax * ly - ay * lx) + 1e-9 * max(d["length"]))
        legs.append((s, lx, ly, slack))
    (sa, lax, lay, slack_a), (sb, lbx, lby, slack_b) = legs
    cross = lax * lby - lay * lbx
    l1, l2 = d["length"]
    side = d["assembly"] * cross + 1e-9 * l1 * l2
    ok = np.minimum(np.minimum(slack_a, slack_b), side) >= 0.0
    branches = d["branch"][0] * d["branch"][1]
    with np.errstate(divide="ignore", invalid="ignore"):
        value = (branches * cross) / (sa * sb)
    return np.where(ok, value, np.nan).astype(np.float32)


def compare(ours, theirs, rtol):
    """Differences between two maps; returns a list of problems (empty: they agree)."""
    problems = []
    if ours.shape != theirs.shape:
        return ["shapes differ: %s vs %s" % (ours.shape, theirs.shape)]
    reach_ours, reach_theirs = ~np.isnan(ours), ~np.isnan(theirs)
    mismatch = reach_ours != reach_theirs
    reachable = int(reach_theirs.sum())
    if reachable == 0:
        problems.append("the C++ map has no reachable cell")
    # A cell classified differently must lie on the outline (rounding in the last bit of a slack
    # that is 0 at the boundary): in each map, one of its 8 neighbours is of the kind the other
    # map gives the cell. (A cell flipped inside the workspace fails this in one of the maps.)
    def neighbours(reach):
        """Whether any of the 8 neighbours is reachable, and whether any is not (off-grid: not)."""
        padded = np.pad(reach, 1, mode="constant", constant_values=False)
        rows, columns = reach.shape
        any_reachable = np.zeros_like(reach)
        any_unreachable = np.zeros_like(reach)
        for dr in (-1, 0, 1):
            for dc in (-1, 0, 1):
                if dr or dc:
                    window = padded[1 + dr:1 + dr + rows, 1 + dc:1 + dc + columns]
                    any_reachable |= window
                    any_unreachable |= ~window
        return any_reachable, any_unreachable

    theirs_reachable, theirs_unreachable = neighbours(reach_theirs)
    ours_reachable, ours_unreachable = neighbours(reach_ours)
    on_outline = np.where(reach_theirs, theirs_unreachable & ours_reachable, theirs_reachable & ours_unreachable)
    off_edge = mismatch & ~on_outline
    if off_edge.any():
        r, c = np.argwhere(off_edge)[0]
        problems.append("%d cells differ in reachability away from the outline (first: row %d, column %d)"
                        % (int(off_edge.sum()), r, c))
    if mismatch.sum() > max(10, reachable // 1000):
        problems.append("%d cells differ in reachability (more than 0.1 %% of %d)" % (int(mismatch.sum()), reachable))
    both = reach_ours & reach_theirs
    a, b = ours[both].astype(np.float64), theirs[both].astype(np.float64)
    relative = np.abs(a - b) / np.maximum(np.abs(b), np.finfo(np.float32).tiny)
    worst = float(relative.max()) if relative.size else 0.0
    if worst > rtol:
        problems.append("values differ by up to %.3g (relative), more than %.1g" % (worst, rtol))
    print("agreement: %d reachable cells in C++, %d in NumPy, %d classified otherwise; values agree to %.2g"
          % (reachable, int(reach_ours.sum()), int(mismatch.sum()), worst))
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--json", required=True, help="side file written by bench_map --json")
    parser.add_argument("--compare", help="raw float32 map written by bench_map --write")
    parser.add_argument("--runs", type=int, default=5, help="timed runs; the best counts")
    parser.add_argument("--min-ratio", type=float, default=0.0, help="fail if C++ is not this many times faster")
    parser.add_argument("--goal-ratio", type=float, default=20.0, help="report whether C++ is this many times faster")
    parser.add_argument("--rtol", type=float, default=1e-4, help="relative tolerance on the values")
    args = parser.parse_args()
    if args.runs < 1:
        parser.error("--runs must be at least 1")
    with open(args.json, encoding="utf-8") as f:
        spec = json.load(f)

    det_map(spec)  # warm-up: allocator, page faults
    times = []
    for _ in range(args.runs):
        start = time.perf_counter()
        ours = det_map(spec)
        times.append((time.perf_counter() - start) * 1e3)
    best = min(times)
    cells = spec["columns"] * spec["rows"]
    print("NumPy %s: %dx%d cells, best of %d runs %.1f ms (runs: %s ms); %.1f Mcells/s"
          % (np.__version__, spec["columns"], spec["rows"], args.runs, best,
             ", ".join("%.1f" % t for t in times), cells / best * 1e-3))

    status = 0
    if spec.get("min_ms") and spec.get("median_ms"):
        # Best against best is the fairest figure on a shared machine (both least disturbed);
        # median against median is printed too.
        median = sorted(times)[len(times) // 2]
        ratio = best / spec["min_ms"]
        print("C++ (%d threads) best %.3f ms, median %.3f ms; NumPy (1 thread) best %.1f ms, median %.1f ms"
              % (spec.get("threads", 0), spec["min_ms"], spec["median_ms"], best, median))
        print("C++/NumPy speed ratio: %.1fx best to best, %.1fx median to median (goal >= %gx: %s)"
              % (ratio, median / spec["median_ms"], args.goal_ratio, "met" if ratio >= args.goal_ratio else "MISSED"))
        if spec.get("single_thread_min_ms"):
            print("per core: C++ on one thread best %.3f ms, %.1fx faster than NumPy"
                  % (spec["single_thread_min_ms"], best / spec["single_thread_min_ms"]))
        if ratio < args.min_ratio:
            print("FAIL: the ratio is below %.1fx" % args.min_ratio)
            status = 1
    if args.compare:
        theirs = np.fromfile(args.compare, dtype="<f4")
        if theirs.size != cells:
            print("FAIL: %s holds %d values, not %d" % (args.compare, theirs.size, cells))
            return 1
        problems = compare(ours, theirs.reshape(spec["rows"], spec["columns"]), args.rtol)
        for problem in problems:
            print("FAIL: " + problem)
        if problems:
            status = 1
    return status


if __name__ == "__main__":
    sys.exit(main())
