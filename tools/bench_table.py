"""The tables of one BoostedBench run: printed, and written as Markdown for the README.

    bench_table.py bench.json [more.json ...] [--markdown bench.md] [--machine NAME] [--load-before L]
                   [--load-after L] [--date D] [--commit C] [--repetitions N] [--seconds S]

tools/bench calls it after its run. Every figure is the best of the run's repetitions (the
shortest time): "wall" is the points per second over wall-clock time, what the issue's targets
count; "CPU" over the process's CPU time (all threads), which other jobs on a shared machine
disturb less. Million points per second unless a column says otherwise. The targets are those of
the issue "Fast and exact at every scale" (README, Performance); a mark tells whether the wall
figure meets its target in this run.
"""
import argparse
import json
import re
import sys

GENERATORS = (1, 4, 16, 64)
# The one-thread kernel targets, million points per second, at M = 1, 4, 16, 64.
KERNEL_TARGETS = {"Paper": (61, 46, 33, 20), "Exact": (41, 31, 22, 13.4)}
TWO_THREADS_TARGET = 1.9  # kernel and filter: two threads at least this many times one
FILTER_OVER_KERNEL_TARGET = 1.1  # filter time at most this many times the kernel's
SOURCE_TWO_THREADS_TARGET = 1.8  # each source on two threads ÷ itself on one
TREE_SPEEDUP_TARGET = 20  # M = 100,000: the tree at least this many times the direct sum ...
TREE_ERROR_TARGET = 1e-6  # ... with the largest image error at most this over the largest move


def load_runs(paths):
    """name -> best run: wall and CPU rates, time (ms) and counters, over the repetitions."""
    best = {}
    for run in (run for path in paths for run in json.load(open(path))["benchmarks"]):
        if run.get("run_type") != "iteration" or run.get("error_occurred"):
            continue
        name = run.get("run_name", run["name"])
        name = re.sub(r"/(process_time|real_time|manual_time|iterations:\d+)", "", name)
        scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[run.get("time_unit", "ns")]
        wall_ms, cpu_ms = run["real_time"] * scale, run["cpu_time"] * scale
        entry = {"wall_ms": wall_ms, "cpu_ms": cpu_ms, "counters": run}
        if "points/s" in run:
            entry["wall"] = run["points/s"] / 1e6
            entry["cpu"] = entry["wall"] * wall_ms / cpu_ms if cpu_ms > 0 else 0.0
        old = best.get(name)
        if old is None or wall_ms < old["wall_ms"]:
            entry["best_cpu_ms"] = min(cpu_ms, old["best_cpu_ms"]) if old else cpu_ms
            best[name] = entry
        else:
            old["best_cpu_ms"] = min(old["best_cpu_ms"], cpu_ms)
    # The CPU rate: the best over the repetitions too (not necessarily the wall's best one).
    for entry in best.values():
        if "wall" in entry and entry["best_cpu_ms"] > 0:
            entry["cpu"] = entry["wall"] * entry["wall_ms"] / entry["best_cpu_ms"]
    return best


def number(x):
    if x is None:
        return "–"
    if x >= 100:
        return f"{x:.0f}"
    if x >= 10:
        return f"{x:.1f}"
    return f"{x:.2f}"


def mark(ok):
    return " ✓" if ok else " ✗"


def natural(name):
    """Sort key: names in order, their numbers by value (M:4 before M:16)."""
    return [int(t) if t.isdigit() else t for t in re.split(r"(\d+)", name)]


class Tables:
    def __init__(self, runs):
        self.runs = runs
        self.used = set()

    def get(self, name):
        run = self.runs.get(name)
        if run is not None:
            self.used.add(name)
        return run

    def rate(self, name, key="wall"):
        run = self.get(name)
        return run.get(key) if run else None

    def cell(self, name):
        run = self.get(name)
        if not run or "wall" not in run:
            return "–"
        return f"{number(run['wall'])} ({number(run['cpu'])})"

    @staticmethod
    def table(header, rows):
        if not rows:
            return ""
        lines = ["| " + " | ".join(header) + " |", "| " + " | ".join("---" for _ in header) + " |"]
        lines += ["| " + " | ".join(row) + " |" for row in rows]
        return "\n".join(lines)

    def kernel_and_filter(self):
        rows = []
        per_m = lambda f: [f(m) for m in GENERATORS]
        for rule in ("Paper", "Exact"):
            kernel = lambda m, t=1: f"Kernel/{rule}/M:{m}/threads:{t}"
            rows.append([f"kernel `{rule}`, 1 thread"] + per_m(lambda m: self.cell(kernel(m))))
            targets = KERNEL_TARGETS[rule]
            rows.append([f"target, kernel `{rule}` (wall)"] + [
                f"≥ {t:g}" + ("" if self.rate(kernel(m)) is None else mark(self.rate(kernel(m)) >= t))
                for m, t in zip(GENERATORS, targets)])
        rows += self.two_threads("Kernel", "kernel", per_m)
        for rule in ("Paper", "Exact"):
            rows.append([f"filter `{rule}`, 1 thread"] +
                        per_m(lambda m: self.cell(f"Filter/{rule}/M:{m}/threads:1")))
            rows.append([f"filter `{rule}` time ÷ kernel's, 1 thread (target ≤ "
                         f"{FILTER_OVER_KERNEL_TARGET})"] +
                        per_m(lambda m: self.ratio(f"Kernel/{rule}/M:{m}/threads:1",
                                                   f"Filter/{rule}/M:{m}/threads:1",
                                                   lambda r: r <= FILTER_OVER_KERNEL_TARGET)))
        rows += self.two_threads("Filter", "filter", per_m)
        rows.append(["full-multivector reference `Paper`, 1 thread"] +
                    per_m(lambda m: self.cell(f"Reference/Paper/M:{m}")))
        return self.table(["M generators"] + [str(m) for m in GENERATORS], rows)

    def two_threads(self, row, label, per_m):
        """Each rule's two-thread rates of `row` and their ratio to one thread."""
        rows = []
        for rule in ("Paper", "Exact"):
            name = lambda m, t: f"{row}/{rule}/M:{m}/threads:{t}"
            rows.append([f"{label} `{rule}`, 2 threads"] + per_m(lambda m: self.cell(name(m, 2))))
            rows.append([f"{label} `{rule}`, 2 threads ÷ 1 (target ≥ {TWO_THREADS_TARGET})"] +
                        per_m(lambda m: self.ratio(name(m, 2), name(m, 1),
                                                   lambda r: r >= TWO_THREADS_TARGET)))
        return rows

    def ratio(self, faster, slower, meets):
        """Rate of `faster` ÷ rate of `slower`, wall (CPU), marked by meets(wall ratio)."""
        a, b = self.get(faster), self.get(slower)
        if not a or not b or "wall" not in a or "wall" not in b or not b["wall"] or not b["cpu"]:
            return "–"
        wall, cpu = a["wall"] / b["wall"], a["cpu"] / b["cpu"]
        return f"{wall:.2f} ({cpu:.2f}){mark(meets(wall))}"

    def threaded_rows(self, prefixes):
        """Rows with a 1- and a 2-thread variant: wall (CPU) each and the wall ratio."""
        rows = []
        names = sorted({re.sub(r"/threads:\d+$", "", n) for n in self.runs
                        if re.search(r"/threads:\d+$", n) and n.split("/")[0] in prefixes},
                       key=natural)
        for base in names:
            one, two = f"{base}/threads:1", f"{base}/threads:2"
            ratio = "–"
            if self.rate(one) and self.rate(two):
                ratio = f"{self.rate(two) / self.rate(one):.2f}"
            rows.append([f"`{base}`", self.cell(one), self.cell(two), ratio])
        return rows

    def derivatives(self):
        rows = self.threaded_rows({"WarpVector", "KernelJacobian", "KernelDirectional",
                                   "FilterNormals", "FilterDerivatives"})
        return self.table(["row", "1 thread", "2 threads", "2 ÷ 1, wall"], rows)

    def sizes(self):
        counts = sorted({int(m.group(1)) for n in self.runs
                         for m in [re.search(r"Size/.*/N:(\d+)/", n)] if m})
        rows = []
        for row in ("KernelSize", "FilterSize"):
            for threads in (1, 2):
                rows.append([f"`{row}` `Exact` M = 16, {threads} thread{'s' if threads > 1 else ''}"]
                            + [self.cell(f"{row}/Exact/M:16/N:{n}/threads:{threads}")
                               for n in counts])
        peak = []
        for n in counts:
            run = self.get(f"FilterSize/Exact/M:16/N:{n}/threads:1")
            value = run["counters"].get("peak B/point") if run else None
            peak.append("–" if value is None else f"{value:.1f}")
        rows.append(["filter's peak bytes per point, 1 thread"] + peak)
        return self.table(["N points"] + [f"{n:,}" for n in counts], rows) if counts else ""

    def many(self):
        ms = sorted({int(m.group(1)) for n in self.runs
                     for m in [re.search(r"^Many/Direct/M:(\d+)$", n)] if m})
        digits = sorted({int(m.group(1)) for n in self.runs
                         for m in [re.search(r"^Many/Tree/M:\d+/digits:(\d+)$", n)] if m})
        if not ms:
            return ""
        rows = []
        for m in ms:
            direct = self.get(f"Many/Direct/M:{m}")
            row = [f"{m:,}", self.cell(f"Many/Direct/M:{m}")]
            for d in digits:
                tree = self.get(f"Many/Tree/M:{m}/digits:{d}")
                if not tree or not direct or "wall" not in tree:
                    row.append("–")
                    continue
                speedup = tree["wall"] / direct["wall"]
                error = tree["counters"].get("error/displacement")
                text = f"{number(tree['wall'])}, {speedup:.1f}×"
                if error is not None:
                    text += f", error {error:.1e}"
                if m >= 100000:
                    text += mark(speedup >= TREE_SPEEDUP_TARGET and error is not None and
                                 error <= TREE_ERROR_TARGET)
                row.append(text)
            rows.append(row)
        header = ["M generators", "direct sum"] + [f"tree, Tolerance 1e-{d}" for d in digits]
        return self.table(header, rows)

    def sources(self):
        torus = self.rate("Torus/threads:1")
        # The torus with vtkCurvatures (Gaussian, then mean): context for the rows with
        # curvatures, not a target.
        torusCurvatures = self.rate("TorusCurvatures/threads:1")
        rows = []
        # The yardsticks first, then the sources by name.
        yardsticks = ["Torus/threads:1", "TorusCurvatures/threads:1"]
        names = [n for n in yardsticks if n in self.runs] + sorted(
            (n for n in self.runs if n.endswith("/threads:1") and n.split("/")[0] in
             {"BoostedSurface", "HopfFibration", "CurvaturePatch", "ConformalOrbit",
              "DipoleField"}), key=lambda n: natural(n[: -len("/threads:1")]))
        for one in names:
            base = one[: -len("/threads:1")]
            yardstick = one in yardsticks
            two = f"{base}/threads:2"
            rate = self.rate(one)
            versus = "–"
            if rate and torus:
                versus = f"{rate / torus:.2f}" + ("" if yardstick else mark(rate >= torus))
            if rate and torusCurvatures and base.endswith("/Curvatures"):
                versus += f" ({rate / torusCurvatures:.1f} × the torus with `vtkCurvatures`)"
            ratio = "–"
            if rate and self.rate(two):
                r = self.rate(two) / rate
                ratio = f"{r:.2f}" + ("" if yardstick else mark(r >= SOURCE_TWO_THREADS_TARGET))
            rows.append([f"`{base}`", self.cell(one), versus, self.cell(two), ratio])
        header = ["source, 1,000,000 points", "1 thread", "÷ torus, wall (target ≥ 1)",
                  "2 threads", f"2 ÷ 1, wall (target ≥ {SOURCE_TWO_THREADS_TARGET})"]
        return self.table(header, rows)

    def others(self):
        rows = []
        for name, run in sorted(self.runs.items(), key=lambda item: natural(item[0])):
            if name in self.used:
                continue
            counter = run["counters"].get("time/point/unknown")
            extra = "" if counter is None else f"{counter * 1e9:.0f} ns per point and unknown"
            rates = self.cell(name) if "wall" in run else "–"
            rows.append([f"`{name}`", f"{run['wall_ms']:.1f}", f"{run['cpu_ms']:.1f}", rates, extra])
        return self.table(["row", "wall ms", "CPU ms", "rate", "note"], rows)


def markdown(runs, options):
    tables = Tables(runs)
    parts = [
        f"Measured {options.date} at commit {options.commit} with `./tools/bench` "
        f"(repetitions: {options.repetitions}; the best of them"
        + (f", {options.seconds / 60:.0f} min" if options.seconds else "") + f") on "
        f"*{options.machine}* (lscpu model name), load average {options.load_before} before "
        f"and {options.load_after} after the run. Million points per second, wall clock and, in "
        "brackets, over the process's CPU time (all threads); ✓/✗: the wall figure meets the "
        "issue's target or not.",
        "**Kernel and filter** (10⁶ points):",
        tables.kernel_and_filter(),
    ]
    for title, table in (
        ("**Derivatives and `vtkWarpVector`** (10⁶ points):", tables.derivatives()),
        ("**Point counts** (`Exact`, M = 16):", tables.sizes()),
        ("**Many generators** (`Exact`, one thread; rate, speed-up over the direct sum, largest "
         "image error ÷ largest displacement; target at M = 100,000: ≥ "
         f"{TREE_SPEEDUP_TARGET}× at ≤ {TREE_ERROR_TARGET:g}):", tables.many()),
        ("**Sources**:", tables.sources()),
        ("**Other rows**:", tables.others()),
    ):
        if table:
            parts += [title, table]
    return "\n\n".join(parts) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("json", nargs="+")
    parser.add_argument("--markdown")
    for option in ("machine", "load-before", "load-after", "date", "commit", "repetitions"):
        parser.add_argument(f"--{option}", default="?")
    parser.add_argument("--seconds", type=float, default=0.0)
    options = parser.parse_args()
    runs = load_runs(options.json)
    print(f"{'benchmark':48s} {'wall':>9s} {'cpu':>9s} {'peak B/point':>12s}")
    for name, run in runs.items():
        if "wall" not in run:
            continue
        peak = run["counters"].get("peak B/point")
        memory = f"{peak:12.1f}" if peak is not None else ""
        print(f"{name:48s} {run['wall']:9.2f} {run['cpu']:9.2f} {memory}")
    if options.markdown:
        with open(options.markdown, "w") as out:
            out.write(markdown(runs, options))
        print(f"Markdown tables for the README: {options.markdown}")


if __name__ == "__main__":
    sys.exit(main())
