#!/usr/bin/python3
"""Plots the time per 1,000,000 points against the number of generators M, direct sum and tree,
from BoostedBench's JSON output (the Many/Direct and Many/Tree rows, bench/BenchManyGenerators.cpp).

    build/bin/BoostedBench --benchmark_filter=Many/ --benchmark_out=many.json \\
        --benchmark_out_format=json
    /usr/bin/python3 tools/plot_bench.py many.json many.png   (Debian's python3 has matplotlib)

Several runs in one plot (e.g. before and after a change): `--run before=old.json`, each run's
lines labelled with its name; the positional file is then optional.
"""
import argparse
import collections
import json
import re

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402 (after choosing the backend)


UNIT_SECONDS = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}


def series(benchmarks, prefix="", cpu=False):
    """{label: [(M, seconds per million points)]} of the Many/ rows, best of any repetitions:
    wall time, or with cpu the process's CPU time."""
    best = collections.defaultdict(dict)
    for row in benchmarks:
        if row.get("run_type") == "aggregate":
            continue
        match = re.match(r"Many/(Direct|Tree)/M:(\d+)(?:/digits:(\d+))?", row["name"])
        if not match or "points/s" not in row:
            continue
        kind, m, digits = match.groups()
        label = prefix + ("direct sum" if kind == "Direct" else "tree, Tolerance 1e-%s" % digits)
        if cpu:
            seconds = 1e6 * row["cpu_time"] * UNIT_SECONDS[row["time_unit"]] / row["points timed"]
        else:
            seconds = 1e6 / row["points/s"]
        m = int(m)
        best[label][m] = min(seconds, best[label].get(m, float("inf")))
    return {label: sorted(values.items()) for label, values in best.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("files", nargs="+", metavar="[json] png",
                        help="a BoostedBench --benchmark_out file (JSON), then the plot to write")
    parser.add_argument("--run", action="append", default=[], metavar="NAME=JSON",
                        help="another run's JSON, its lines labelled NAME")
    parser.add_argument("--cpu", action="store_true",
                        help="the process's CPU time instead of wall time (under load)")
    arguments = parser.parse_args()
    if len(arguments.files) > 2 or (len(arguments.files) == 1 and not arguments.run):
        parser.error("expected [json] png, or png with --run")
    png = arguments.files[-1]
    runs = [("", path) for path in arguments.files[:-1]]
    for run in arguments.run:
        name, separator, path = run.partition("=")
        if not separator:
            parser.error("--run takes NAME=JSON, not %r" % run)
        runs.append((name + ": ", path))
    lines = {}
    for prefix, path in runs:
        with open(path) as stream:
            data = json.load(stream)
        found = series(data["benchmarks"], prefix, arguments.cpu)
        if not found:
            raise SystemExit("no Many/Direct or Many/Tree rows in %s" % path)
        lines.update(found)
    figure, axes = plt.subplots(figsize=(6.4, 4.4))
    for label, points in sorted(lines.items()):
        axes.plot([m for m, _ in points], [s for _, s in points], marker="o", label=label)
    axes.set_xscale("log")
    axes.set_yscale("log")
    axes.set_xlabel("generators M")
    axes.set_ylabel("%s seconds per 1,000,000 points (one thread)" % ("CPU" if arguments.cpu else "wall"))
    context = data.get("context", {})
    # The run's date, kernels and CPU count (a host name says nothing on a cloud machine).
    axes.set_title("B(p) by direct sum and by tree: %s, %s kernels, %s CPUs" % (
        context.get("date", "?")[:10], context.get("kernel_isa", "?"), context.get("num_cpus", "?")))
    axes.grid(True, which="both", alpha=0.3)
    axes.legend()
    figure.tight_layout()
    figure.savefig(png, dpi=100)


if __name__ == "__main__":
    main()
