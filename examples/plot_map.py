#!/usr/bin/env python3
"""Plots a design's det J map with its singular curves, using the pkmstudio module.

    python3 examples/plot_map.py moma-3a --quantity det --grid 600 -o moma-det.png

Without -o the figure opens in a window. Run it from a build (PYTHONPATH=build/python) or
with PKM Studio installed.
"""

import argparse

import matplotlib.pyplot as plt
import numpy as np

import pkmstudio


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("design", nargs="?", default="moma-3a", help="a preset id or a .pkm.json file")
    parser.add_argument("--quantity", default="det", help="det, cond, range, force_worst, …")
    parser.add_argument("--grid", type=int, default=600, help="cells along the longer side")
    parser.add_argument("-o", "--output", help="the picture to write (PNG, SVG, PDF)")
    options = parser.parse_args()

    design = pkmstudio.load(options.design)
    mapped = design.map(options.quantity, grid=options.grid)
    values = mapped.values
    figure, axes = plt.subplots(figsize=(7, 6), layout="constrained")
    if mapped.quantity == "det":
        # a symmetric scale clipped at the 95th percentile, so that the spikes beside the
        # inverse singularities do not wash out the rest
        limit = float(np.nanpercentile(np.abs(values[np.isfinite(values)]), 95))
        image = axes.imshow(values, origin="lower", extent=mapped.extent, cmap="RdBu_r", vmin=-limit, vmax=limit)
    elif mapped.quantity == "cond":
        image = axes.imshow(np.log10(values), origin="lower", extent=mapped.extent, cmap="viridis_r")
    else:
        image = axes.imshow(values, origin="lower", extent=mapped.extent, cmap="viridis")
    for curve in mapped.singular_curves:
        points = curve["points"]
        axes.plot(points[:, 0], points[:, 1], "k-" if curve["type"] == "inverse" else "k--", linewidth=0.8)
    label = mapped.title if mapped.quantity != "cond" else "log₁₀ " + mapped.title
    figure.colorbar(image, ax=axes, label=label)
    axes.set_xlim(mapped.extent[0], mapped.extent[1])
    axes.set_ylim(mapped.extent[2], mapped.extent[3])
    axes.set_aspect("equal")
    axes.set_xlabel("x (mm)")
    axes.set_ylabel("y (mm)")
    axes.set_title(f"{mapped.title} of {design.origin}: {mapped.area:.0f} mm² reachable")
    if options.output:
        figure.savefig(options.output, dpi=120)
    else:
        plt.show()


if __name__ == "__main__":
    main()
