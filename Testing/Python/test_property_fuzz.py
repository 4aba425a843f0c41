"""Seeded property fuzz of every class: random, extreme, NaN and infinite values for every setter
(found by introspection, fuzz_recipe.py), list rows, invalid pieces, extents and times, and inputs
of every data-set type and array layout (fuzz_inputs.py). Every update must report an error and
leave its output empty, or give a valid output (fuzz_checks.py): cells within the points, arrays
as long as the points and cells, and no NaN or infinity anywhere when the inputs were finite. No
trial may crash or hang: trials run in a worker process, and a trial that kills it, takes more
than --timeout seconds, or during which the worker writes a line that cannot be read or ends, is a
failure; no trial ends without a result or a failure, even after an error of the driver. Every
failure prints a one-line reproducer. The summary counts each class's updates, refusals, valid
outputs and (the deformation filter) updates that built a generator tree; a run of many trials
fails a class that seldom gives a valid output, or never builds the tree it can.

    PYTHONPATH=<build>/lib/python3.11/site-packages:Testing/Support \\
        /usr/bin/python3 Testing/Python/test_property_fuzz.py [--seed S] [--trials N]
    ... test_property_fuzz.py --seed S --trial T     # replays one trial here, printing its calls

    ... test_property_fuzz.py --found                # the kept recipes of fuzz_found.json

Every failure the fuzz once found is kept in fuzz_found.json as its recipe (the calls, which no
later change of the recipe generator alters) and replayed by --found (ctest Python.PropertyFuzzFound),
each in a process of its own, so that a fixed defect stays fixed whatever the seeds reach.

The seed is fixed in CI (DEFAULT_SEED); BOOSTEDSURFACES_FUZZ_SEED or --seed gives another, and
BOOSTEDSURFACES_FUZZ_TRIALS or --trials another number of trials. The process sets its own
environment before VTK starts: a small memory budget (--memory-budget, so that nothing big is
allocated) and vtkSMPTools' STDThread backend on 2 threads (so that the threaded paths run).
"""
import argparse
import json
import os
import queue
import signal
import subprocess
import sys
import tempfile
import threading
import time
import traceback

DEFAULT_SEED = 20261202
DEFAULT_TRIALS = 8000
# The least share of a class's updates that must give a valid non-empty output (its real work):
# below it the fuzz mostly checks refusals (the fit filter once reached 2 fits in 1,880 updates,
# its generator rows' random kinds being almost never kinds). Measured with the default seed:
# 16 % for the fit filter, 40 % or more for the others.
LEAST_OUTPUT_SHARE = 0.05
# From this many trials a class that can build a generator tree (fuzz_recipe.reaches_tree) must
# have built one: 50 updates build one in the default seed's 8,000 trials.
LEAST_TREE_TRIALS = 4000

# Failures excused (counted, printed, not failed) while a fix is under way; --strict fails them
# too. Each entry names the category of fuzz_checks' problem (or "crash") it excuses. None now.
KNOWN_ISSUES = {}


def arguments():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--seed", type=int,
                        default=int(os.environ.get("BOOSTEDSURFACES_FUZZ_SEED") or DEFAULT_SEED))
    parser.add_argument("--trials", type=int,
                        default=int(os.environ.get("BOOSTEDSURFACES_FUZZ_TRIALS") or
                                    DEFAULT_TRIALS))
    parser.add_argument("--first", type=int, default=0, help="the first trial's number")
    parser.add_argument("--trial", type=int, help="replay this one trial in this process")
    parser.add_argument("--found", action="store_true",
                        help="replay every recipe of fuzz_found.json, each in a process")
    parser.add_argument("--found-case", type=int, help=argparse.SUPPRESS)  # one, in this process
    parser.add_argument("--timeout", type=float, default=60.0, help="seconds a trial may take")
    parser.add_argument("--jobs", type=int, default=1, help="worker processes at once")
    parser.add_argument("--memory-budget", default="32M",
                        help="BOOSTEDSURFACES_MEMORY_BUDGET of the trials")
    parser.add_argument("--strict", action="store_true", help="do not excuse KNOWN_ISSUES")
    parser.add_argument("--worker", help=argparse.SUPPRESS)  # "first:end", the driver's child
    return parser.parse_args()


ARGS = arguments()
os.environ["BOOSTEDSURFACES_MEMORY_BUDGET"] = ARGS.memory_budget
os.environ["VTK_SMP_BACKEND_IN_USE"] = "STDThread"
os.environ["VTK_SMP_MAX_THREADS"] = "2"

from vtkmodules.vtkCommonCore import (vtkCommand, vtkLogger,  # noqa: E402 (after the environment)
                                      vtkOutputWindow)

import fuzz_checks  # noqa: E402
import fuzz_inputs  # noqa: E402
import fuzz_recipe  # noqa: E402
import python_test_common as common  # noqa: E402


def environment():
    """The variables a reproducer sets: PYTHONPATH, and in the sanitizer build the preloaded
    runtime and its options (CMake/BoostedSurfacesTesting.cmake)."""
    names = ["LD_PRELOAD", "ASAN_OPTIONS"] if "LD_PRELOAD" in os.environ else []
    return " ".join("%s=%s" % (name, os.environ.get(name, ""))
                    for name in names + ["PYTHONPATH"])


def reproducer(seed, trial):
    """The one line that replays a trial."""
    command = [sys.executable, os.path.abspath(__file__), "--seed", str(seed), "--trial",
               str(trial)]
    if ARGS.memory_budget != "32M":
        command += ["--memory-budget", ARGS.memory_budget]
    return "%s %s" % (environment(), " ".join(command))


class MessageLog:
    """Every error and warning of VTK: the algorithm's own (its ErrorRecorder) and the rest (the
    executive's, the data's) through the output window, which prints nothing."""

    def __init__(self):
        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
        window = vtkOutputWindow.GetInstance()
        window.SetDisplayModeToNever()
        self.window = common.ErrorRecorder(window)

    def take(self, recorder):
        """(the algorithm's errors, the other objects' errors, all warnings) since the last take."""
        own, others = list(recorder.messages), list(self.window.messages)
        warnings = self.window.warnings + recorder.warnings
        for source in (recorder, self.window):
            source.messages.clear()
            source.warnings.clear()
        return own, others, warnings


def run_trial(models, log, seed, trial, verbose=False):
    """Runs one trial; returns (problems, statistics)."""
    return run_recipe(models, log, fuzz_recipe.make_recipe(models, seed, trial), verbose)


def run_recipe(models, log, recipe, verbose=False):
    """Runs one recipe (fuzz_recipe.make_recipe's, or a kept one); returns (problems, statistics)."""
    if verbose:
        print(fuzz_recipe.describe(recipe).replace("algorithm.SetInputDataObject", "# input"))
    model = next(m for m in models if m.name == recipe["class"])
    algorithm = model.cls()
    recorder = common.ErrorRecorder(algorithm)
    log.take(recorder)
    finite_ports = {}
    problems = []
    statistics = {"updates": 0, "errors": 0, "outputs": 0, "trees": 0}
    progress_texts = set()
    algorithm.AddObserver(vtkCommand.ProgressEvent,
                          lambda caller, event: progress_texts.add(caller.GetProgressText()))
    for method, call_arguments in recipe["calls"]:
        if method == "SetInputDataObject":
            port, spec = call_arguments
            data, finite = fuzz_inputs.build(spec) if spec is not None else (None, True)
            finite_ports[port] = finite or model.ports[port][1]  # optional ports never excuse
            if verbose:
                print("input %d: %s, finite: %s" % (port, fuzz_inputs.summary(spec), finite))
            algorithm.SetInputDataObject(port, data)
            log.take(recorder)
            continue
        # Every output port is checked (the Generators ports too): one update runs them all.
        ports = range(algorithm.GetNumberOfOutputPorts())
        befores = [algorithm.GetOutputDataObject(port) for port in ports]
        stamps = [b.GetMTime() if b is not None else None for b in befores]
        progress_texts.clear()
        fuzz_recipe.call(algorithm, method, call_arguments)
        if not method.startswith("Update"):
            log.take(recorder)  # a setter's own error (a row outside the list) is not the update's
            continue
        own_errors, pipeline_errors, warnings = log.take(recorder)
        errors = own_errors + pipeline_errors
        statistics["updates"] += 1
        statistics["errors"] += bool(errors)
        output = algorithm.GetOutputDataObject(0)
        statistics["outputs"] += bool(not errors and output and output.GetNumberOfPoints())
        statistics["trees"] += common.BUILDING_TREE in progress_texts
        found = []
        for port in ports:
            port_output = algorithm.GetOutputDataObject(port)
            unchanged = (port_output is befores[port] and port_output is not None
                         and port_output.GetMTime() == stamps[port])
            if port == 0:
                refused = bool(errors) and not own_errors and unchanged
            found += [(category, ("output %d: " % port if port else "") + text)
                      for category, text in fuzz_checks.output_problems(
                          port_output, own_errors, pipeline_errors, unchanged,
                          all(finite_ports.values()))]
        if verbose:
            print("%s: %d errors%s, %d warnings, %s%s" % (
                method, len(errors), " (the pipeline's, output unchanged)" if refused else "",
                len(warnings), "%d points, %d cells" % (
                    output.GetNumberOfPoints(), output.GetNumberOfCells()) if output else
                "no output", "".join("\n  " + m.strip().splitlines()[-1]
                                     for m in errors + warnings)))
        problems += [(category, "%s: %s" % (method, text)) for category, text in found]
    return problems, statistics


def excused(category):
    return not ARGS.strict and category in KNOWN_ISSUES


def simulated_failures():
    """{trial: kind} from BOOSTEDSURFACES_FUZZ_SIMULATE ("crash:2,hang:4"): the harness's own test
    (test_property_fuzz_harness.py) makes those trials go wrong. In the worker: "crash" aborts,
    "hang" sleeps, "cut" writes half a result line and dies (a line that cannot be read), "exit"
    ends the worker quietly before the trial begins, "sanitizer" ends it as AddressSanitizer
    does (a report on stderr, then exit code 1). In the driver: "driver-error" raises at
    the trial's result (a bug of the driver itself). With --found, "found-crash" and
    "found-hang" make the kept case of that number abort or hang. The item "late-eof" (no
    trial) is simulated_load's."""
    items = os.environ.get("BOOSTEDSURFACES_FUZZ_SIMULATE", "").split(",")
    return {int(trial): kind for kind, trial in (item.split(":") for item in items
                                                 if ":" in item)}


def simulated_load():
    """(seconds each worker waits before its first trial, seconds each worker's reader waits
    after the output ended before it says so): (2, 1) with the item "late-eof" of
    BOOSTEDSURFACES_FUZZ_SIMULATE, else none. As on a loaded machine, the end of a killed
    worker's output then comes after the next worker started and before its first line
    (read_lines)."""
    items = os.environ.get("BOOSTEDSURFACES_FUZZ_SIMULATE", "").split(",")
    return (2.0, 1.0) if "late-eof" in items else (0.0, 0.0)


def worker(span):
    """The driver's child: runs trials first..end-1, one line before and after each."""
    first, end = (int(x) for x in span.split(":"))
    models = fuzz_recipe.discover()
    log = MessageLog()
    simulated = simulated_failures()
    time.sleep(simulated_load()[0])
    for trial in range(first, end):
        if simulated.get(trial) == "exit":
            sys.exit(0)
        print("BEGIN %d" % trial, flush=True)
        if simulated.get(trial) == "crash":
            os.abort()
        if simulated.get(trial) == "hang":
            time.sleep(3600)
        if simulated.get(trial) == "sanitizer":
            sys.stderr.write("==1==ERROR: AddressSanitizer: heap-buffer-overflow on address 0x1\n"
                             "    #0 0x1 in simulated() simulated.cxx:1\n"
                             "SUMMARY: AddressSanitizer: heap-buffer-overflow simulated.cxx:1 in "
                             "simulated()\n" + "".join("  legend %d\n" % i for i in range(20)))
            sys.stderr.flush()
            os._exit(1)
        if simulated.get(trial) == "cut":
            sys.stdout.write('END %d [[["bad-' % trial)
            sys.stdout.flush()
            os._exit(0)
        try:
            problems, statistics = run_trial(models, log, ARGS.seed, trial)
        except Exception:
            problems = [("exception", traceback.format_exc().strip().replace("\n", " | "))]
            statistics = {}
        print("END %d %s" % (trial, json.dumps([problems, statistics])), flush=True)


class Failures:
    """The driver's results, shared by its threads: the failed and excused trials, every trial
    that has a result (its worker's END line, or a failure), and each class's statistics."""

    # The trials printed in full when a whole span fails at once (the rest are counted).
    PRINTED_OF_A_SPAN = 10

    def __init__(self):
        self.lock = threading.Lock()
        self.failed = []
        self.known = []
        self.answered = set()
        self.statistics = {}

    def add(self, trial, category, text, class_name):
        with self.lock:
            known = excused(category)
            (self.known if known else self.failed).append(trial)
            self.answered.add(trial)
            print("%s trial %d (%s): [%s] %s\n  reproduce: %s" % (
                "KNOWN ISSUE" if known else "FAIL", trial, class_name, category, text,
                reproducer(ARGS.seed, trial)), flush=True)

    def add_all(self, trials, category, text, class_names):
        """Fails every one of `trials` for one cause: its text is printed with the first trial."""
        for k, trial in enumerate(trials):
            class_name = class_names[trial % len(class_names)]
            if k < self.PRINTED_OF_A_SPAN:
                self.add(trial, category, text if k == 0 else "(as trial %d)" % trials[0],
                         class_name)
            else:
                with self.lock:
                    self.failed.append(trial)
                    self.answered.add(trial)
        if len(trials) > self.PRINTED_OF_A_SPAN:
            print("FAIL trials %d..%d: [%s] (as trial %d, not printed)" % (
                trials[self.PRINTED_OF_A_SPAN], trials[-1], category, trials[0]), flush=True)

    def has_result(self, trial):
        with self.lock:
            return trial in self.answered

    def count(self, trial, class_name, statistics):
        with self.lock:
            self.answered.add(trial)
            totals = self.statistics.setdefault(class_name, {})
            for key, value in statistics.items():
                totals[key] = totals.get(key, 0) + value


def read_lines(stream, lines, late):
    """A worker's reader thread: every line of its stdout onto the queue `lines`, then None
    (after `late` seconds, simulated_load). The stream and the queue are its arguments, not
    names of the driver's loop: a reader that looked `lines` up when its killed worker's output
    ended could put that None into the next worker's queue, which then ended that worker's span
    with its trials unrun and unreported."""
    for line in stream:
        lines.put(line)
    time.sleep(late)
    lines.put(None)


def parse_line(line, current, expected):
    """One line of a worker: ("BEGIN", trial, None) when `expected` begins while no trial runs,
    ("END", trial, (problems, statistics)) when the `current` trial ends, else None (a stray
    line, a line cut short by the worker's death, a trial out of order)."""
    if not line.endswith("\n"):
        return None  # the last, unfinished line of a worker that died writing it
    word, _, rest = line[:-1].partition(" ")
    number, _, result = rest.partition(" ")
    if not (number.isascii() and number.isdigit()):
        return None
    trial = int(number)
    if word == "BEGIN" and not result and current is None and trial == expected:
        return word, trial, None
    if word != "END" or trial != current:
        return None
    try:
        problems, statistics = json.loads(result)
    except (ValueError, TypeError):  # not JSON, or not a pair
        return None
    if not (isinstance(problems, list) and isinstance(statistics, dict) and
            all(isinstance(p, list) and len(p) == 2 and all(isinstance(x, str) for x in p)
                for p in problems) and
            all(isinstance(value, int) for value in statistics.values())):
        return None
    return word, trial, (problems, statistics)


def run_worker(first, end, class_names, failures, simulated):
    """Runs trials from `first` (of first..end-1) in one worker process until it ends, dies,
    hangs or writes a line that cannot be read; each of those is a failure of the trial it
    happened in (or the next). Returns the trial the next worker begins with."""
    def fail(trial, category, text):
        failures.add(trial, category, text, class_names[trial % len(class_names)])

    with tempfile.TemporaryFile() as stderr:
        child = subprocess.Popen(
            [sys.executable, os.path.abspath(__file__), "--seed", str(ARGS.seed),
             "--memory-budget", ARGS.memory_budget, "--worker", "%d:%d" % (first, end)],
            stdout=subprocess.PIPE, stderr=stderr, text=True, errors="replace")
        try:
            lines = queue.Queue()
            threading.Thread(target=read_lines, args=(child.stdout, lines, simulated_load()[1]),
                             daemon=True).start()
            current, expected = None, first  # the trial running, the next one to begin
            while True:
                try:
                    line = lines.get(timeout=ARGS.timeout)
                except queue.Empty:  # current None: the worker does not even start that trial
                    trial = expected if current is None else current
                    fail(trial, "hang", "no result after %g s" % ARGS.timeout)
                    return trial + 1
                if line is None:  # the worker ended
                    child.wait()
                    if current is None and expected == end:
                        return end
                    how = ended_how(child.returncode, stderr)
                    if current is not None:
                        fail(current, "crash", "the process died (%s): %s" % how)
                        return current + 1
                    if expected == first:  # before any trial: a new worker would do the same
                        failures.add_all(list(range(first, end)), "crash",
                                         "the worker ended before its first trial (%s): %s"
                                         % how, class_names)
                        return end
                    fail(expected, "crash",
                         "the worker ended before the trial began (%s): %s" % how)
                    return expected + 1
                parsed = parse_line(line, current, expected)
                if parsed is None:  # the worker is not doing what it should: a new one goes on
                    trial = expected if current is None else current
                    fail(trial, "bad-output", "unreadable line from the worker: %r" % line[:300])
                    return trial + 1
                word, trial, result = parsed
                if word == "BEGIN":
                    current = trial
                    continue
                if simulated.get(trial) == "driver-error":
                    raise RuntimeError("simulated error of the driver at trial %d" % trial)
                problems, statistics = result
                class_name = class_names[trial % len(class_names)]
                failures.count(trial, class_name, statistics)
                for category, text in problems[:3]:
                    failures.add(trial, category, text, class_name)
                current, expected = None, trial + 1
        finally:
            if child.poll() is None:
                child.kill()
            child.wait()


def exit_description(code):
    """A process's return code in words: its signal, or its exit code."""
    if code < 0:
        try:
            return "signal %s" % signal.Signals(-code).name
        except ValueError:  # a signal without a name (a real-time one)
            return "signal %d" % -code
    return "exit code %d" % code


def telling_lines(text, count):
    """A dead process's output in brief: the sanitizers' lines that say what and where if it has
    them (their reports end in a legend), else its last `count` lines."""
    lines = text.strip().splitlines()
    report = [line for line in lines if line.startswith("SUMMARY: ") or "runtime error:" in line]
    return report or lines[-count:]


def ended_how(code, stderr):
    """How a worker ended: (its signal or exit code, telling_lines of its stderr)."""
    stderr.seek(0)
    lines = telling_lines(stderr.read().decode(errors="replace"), 12)
    return exit_description(code), " | ".join(lines) or "nothing on stderr"


def drive_span(first, end, class_names, failures):
    """Runs trials first..end-1 in worker processes: a worker that dies, hangs or writes what
    cannot be read is reported with its trial and replaced by a new one that goes on with the
    next trial. An exception here (a bug of the driver) fails every trial of the span that has
    no result yet, with its traceback, rather than ending this thread and losing them unseen."""
    simulated = simulated_failures()
    start = first
    try:
        while first < end:
            first = run_worker(first, end, class_names, failures, simulated)
    except Exception:
        failures.add_all([t for t in range(start, end) if not failures.has_result(t)],
                         "driver-error", "the driver failed: " +
                         traceback.format_exc().strip().replace("\n", " | "), class_names)


def check_discovery(models):
    """The introspection finds what the classes are known to have (so that it cannot silently
    find nothing); a new class or property only adds to it."""
    found = {m.name: m for m in models}
    expected = {"vtkBoostedSurfaceSource": {}, "vtkCurvaturePatchSource": {"ControlPoint": 11},
                "vtkDipoleFieldSource": {"Generator": 9}, "vtkHopfFibrationSource":
                {"BasePoint": 2}, "vtkPointPairDeformationFilter": {"Generator": 9},
                "vtkConformalOrbitSource": {"Generator": 9, "Seed": 3},
                "vtkPointPairFitFilter": {"Generator": 9}}
    problems = []
    for name, lists in expected.items():
        if name not in found:
            problems.append("%s not discovered" % name)
            continue
        for row, width in lists.items():
            if found[name].lists.get(row) != width:
                problems.append("%s: list %s of %s values, found %s" % (
                    name, row, width, found[name].lists.get(row)))
    surface = found.get("vtkBoostedSurfaceSource")
    if surface and (surface.setters.get("LambdaResolution") != (["int"], (1, 100000)) or
                    surface.setters.get("CircleCenter") != (["float"] * 3, None) or
                    "SetOutputTypeToCircles" not in surface.shortcuts):
        problems.append("vtkBoostedSurfaceSource's setters: %s" % surface.setters)
    deformation = found.get("vtkPointPairDeformationFilter")
    if deformation and [optional for _, optional in deformation.ports] != [False, True]:
        problems.append("the deformation filter's ports: %s" % deformation.ports)
    fit = found.get("vtkPointPairFitFilter")
    if fit and [optional for _, optional in fit.ports] != [False, False, True]:
        problems.append("the fit filter's ports: %s" % fit.ports)
    # A setter the fuzz holds down that no class has any more (renamed) would let trials run for
    # hours again.
    for name in fuzz_recipe.HELD_AT_MOST:
        if not any(name in model.setters for model in models):
            problems.append("no class has the setter %s that the fuzz holds down" % name)
    return problems


def drive():
    models = fuzz_recipe.discover()
    problems = check_discovery(models)
    for problem in problems:
        print("FAIL discovery: " + problem)
    for model in models:
        print("%s: %d setters, %d shortcuts, lists %s, %d input ports" % (
            model.name, len(model.setters), len(model.shortcuts), model.lists or "none",
            len(model.ports)))
    class_names = [m.name for m in models]
    failures = Failures()
    start = time.time()
    first, end = ARGS.first, ARGS.first + ARGS.trials
    bounds = [first + (end - first) * k // ARGS.jobs for k in range(ARGS.jobs + 1)]
    threads = [threading.Thread(target=drive_span, args=(bounds[k], bounds[k + 1], class_names,
                                                         failures))
               for k in range(ARGS.jobs)]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    # Every trial has a result or a failure: one that has neither was lost by the driver.
    lost = [t for t in range(first, end) if not failures.has_result(t)]
    failures.add_all(lost, "lost", "no result: the driver lost this trial", class_names)
    seconds = time.time() - start
    print("seed %d, trials %d..%d, %.0f s:" % (ARGS.seed, first, end - 1, seconds))
    lifeless, treeless = [], []
    for model in models:
        name = model.name
        totals = failures.statistics.get(name, {})
        print("  %s: %d updates, %d refused with an error, %d valid non-empty outputs%s" % (
            name, totals.get("updates", 0), totals.get("errors", 0), totals.get("outputs", 0),
            ", %d built a generator tree" % totals.get("trees", 0)
            if fuzz_recipe.reaches_tree(model) else ""))
        # The tree's trials are rare (fuzz_recipe.MANY_GENERATORS).
        if ARGS.trials >= LEAST_TREE_TRIALS and fuzz_recipe.reaches_tree(model) and \
                totals.get("trees", 0) == 0:
            treeless.append(name)
        # A fuzz that seldom reaches a class's real work (or never its refusals) checks little.
        if ARGS.trials >= 20 * len(class_names) and not (
                totals.get("outputs", 0) >= LEAST_OUTPUT_SHARE * totals.get("updates", 0) > 0
                and totals.get("errors", 0) > 0):
            lifeless.append(name)
    for name in lifeless:
        print("FAIL %s: valid non-empty outputs in fewer than %g %% of its updates, or no refusal,"
              " in %d trials" % (name, 100 * LEAST_OUTPUT_SHARE, ARGS.trials))
    for name in treeless:
        print("FAIL %s: no update built a generator tree in %d trials" % (name, ARGS.trials))
    print("%d failed trials, %d excused as known issues (%s)" % (
        len(set(failures.failed)), len(set(failures.known)), ", ".join(sorted(KNOWN_ISSUES))
        or "none"))
    return 1 if failures.failed or problems or lifeless or treeless else 0


def replay(trial):
    return replay_recipe(fuzz_recipe.make_recipe(fuzz_recipe.discover(), ARGS.seed, trial),
                         "trial %d" % trial)


def replay_recipe(recipe, name):
    problems, _ = run_recipe(fuzz_recipe.discover(), MessageLog(), recipe, verbose=True)
    for category, text in problems:
        print("%s [%s] %s" % ("KNOWN ISSUE" if excused(category) else "FAIL", category, text))
    print("%s: %s" % (name, "passed" if not problems else "%d problems" % len(problems)))
    return 1 if any(not excused(category) for category, _ in problems) else 0


FOUND_FILE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fuzz_found.json")


def found_cases():
    """The kept recipes: [{"found": where, "defect": what it showed, "recipe": calls}]."""
    with open(FOUND_FILE) as stream:
        return json.load(stream)


def replay_found():
    """Each kept recipe in a process of its own (a crash or hang is that case's failure)."""
    cases = found_cases()
    failed = 0
    for k, case in enumerate(cases):
        command = [sys.executable, os.path.abspath(__file__), "--memory-budget",
                   ARGS.memory_budget, "--found-case", str(k)]
        try:
            done = subprocess.run(command, capture_output=True, text=True, errors="replace",
                                  timeout=ARGS.timeout)
            code, output = done.returncode, done.stdout + done.stderr
        except subprocess.TimeoutExpired as expired:
            code, output = None, (expired.stdout or b"").decode(errors="replace")
        verdict = ("passed" if code == 0 else "hung (more than %g s)" % ARGS.timeout
                   if code is None else "failed (%s)" % exit_description(code))
        print("%s case %d (%s, %s; %s): %s" % ("ok" if code == 0 else "FAIL", k,
                                               case["recipe"]["class"], case["found"],
                                               case["defect"], verdict), flush=True)
        if code != 0:
            failed += 1
            print("  " + "\n  ".join(telling_lines(output, 15)))
            print("  reproduce: %s %s" % (environment(), " ".join(command)))
    print("%d of %d kept recipes failed" % (failed, len(cases)))
    return 1 if failed or not cases else 0


if __name__ == "__main__":
    if ARGS.worker:
        worker(ARGS.worker)
    elif ARGS.trial is not None:
        sys.exit(replay(ARGS.trial))
    elif ARGS.found_case is not None:
        simulated_found = simulated_failures().get(ARGS.found_case)
        if simulated_found == "found-crash":
            os.abort()
        if simulated_found == "found-hang":
            time.sleep(3600)
        sys.exit(replay_recipe(found_cases()[ARGS.found_case]["recipe"],
                               "kept case %d" % ARGS.found_case))
    elif ARGS.found:
        sys.exit(replay_found())
    else:
        sys.exit(drive())
