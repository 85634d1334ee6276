#!/usr/bin/env python3
"""Plots time per vertex of one RK4 step against mesh size (docs/performance.md "Scaling").

Usage:
  build/release/tests/bench/rift_bench_scaling --benchmark_format=json > scaling.json
  scripts/plot-scaling.py scaling.json docs/images/performance-scaling.png

Needs python3-matplotlib (Debian), only for this picture: CI does not run it.
"""
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

# Benchmark name prefix -> (label, colour, line style, marker).
SERIES = [
    ("BM_ScalingClothRift/quads/", "quads, rift", "tab:blue", "-", "o"),
    ("BM_ScalingClothReference/quads_atomic/", "quads, reference (atomic)", "tab:blue", "--", "s"),
    ("BM_ScalingClothReference/quads_cumulated/", "quads, reference (cumulated)", "tab:blue", ":", "^"),
    ("BM_ScalingClothRift/triangles/", "triangles, rift", "tab:orange", "-", "o"),
    ("BM_ScalingClothReference/triangles_atomic/", "triangles, reference (atomic)", "tab:orange", "--", "s"),
    ("BM_ScalingClothReference/triangles_cumulated/", "triangles, reference (cumulated)", "tab:orange", ":", "^"),
    ("BM_ScalingSolid/hexahedra/", "hexahedra, rift (3D mass-spring)", "tab:green", "-", "o"),
    ("BM_ScalingSolid/tetrahedra/", "tetrahedra, rift (co-rotational FEM)", "tab:red", "-", "o"),
]


def main(argv):
    if len(argv) != 3:
        sys.exit(__doc__)
    with open(argv[1]) as f:
        report = json.load(f)
    runs = [b for b in report["benchmarks"] if b.get("run_type", "iteration") == "iteration"]
    fig, ax = plt.subplots(figsize=(8, 5), dpi=110)
    for prefix, label, colour, style, marker in SERIES:
        points = sorted(
            (b["vertices"], b["s_per_vertex"] * 1e9) for b in runs if b["name"].startswith(prefix)
        )
        if not points:
            continue
        xs, ys = zip(*points)
        ax.plot(xs, ys, style, color=colour, marker=marker, label=label)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("vertices")
    ax.set_ylabel("ns per vertex per RK4 step (one thread)")
    context = report.get("context", {})
    ax.set_title("Time per vertex against mesh size ({} CPUs, {})".format(
        context.get("num_cpus", "?"), context.get("date", "")[:10]))
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(argv[2])


if __name__ == "__main__":
    main(sys.argv)
