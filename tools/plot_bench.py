#!/usr/bin/python3
"""Plots the time per 1,000,000 points against the number of generators M, direct sum and tree,
from BoostedBench's JSON output (the Many/Direct and Many/Tree rows, bench/BenchManyGenerators.cpp).

    build/bin/BoostedBench --benchmark_filter=Many/ --benchmark_out=many.json \\
        --benchmark_out_format=json
    /usr/bin/python3 tools/plot_bench.py many.json many.png   (Debian's python3 has matplotlib)
"""
import argparse
import collections
import json
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after choosing the backend)


def series(benchmarks):
    """{label: [(M, seconds per million points)]} of the Many/ rows, best of any repetitions."""
    best = collections.defaultdict(dict)
    for row in benchmarks:
        if row.get("run_type") == "aggregate":
            continue
        match = re.match(r"Many/(Direct|Tree)/M:(\d+)(?:/digits:(\d+))?", row["name"])
        if not match or "points/s" not in row:
            continue
        kind, m, digits = match.groups()
        label = "direct sum" if kind == "Direct" else "tree, Tolerance 1e-%s" % digits
        seconds = 1e6 / row["points/s"]
        m = int(m)
        best[label][m] = min(seconds, best[label].get(m, float("inf")))
    return {label: sorted(values.items()) for label, values in best.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("json", help="BoostedBench --benchmark_out file (JSON)")
    parser.add_argument("png", help="the plot to write")
    arguments = parser.parse_args()
    with open(arguments.json) as stream:
        data = json.load(stream)
    lines = series(data["benchmarks"])
    if not lines:
        raise SystemExit("no Many/Direct or Many/Tree rows in %s" % arguments.json)
    figure, axes = plt.subplots(figsize=(6.4, 4.4))
    for label, points in sorted(lines.items()):
        axes.plot([m for m, _ in points], [s for _, s in points], marker="o", label=label)
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("generators M")
    axes.set_ylabel("seconds per 1,000,000 points (one thread)")
    context = data.get("context", {})
    axes.set_title("B(p) by direct sum and by tree, %s" % context.get("host_name", ""))
    axes.grid(True, which="both", alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(arguments.png, dpi=100)


if __name__ == "__main__":
    main()
