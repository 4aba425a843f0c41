"""The property fuzz's model of the classes and its seeded trials (test_property_fuzz.py runs them).

Every class of the boostedsurfaces package that is a vtkAlgorithm is fuzzed, and what is fuzzed is
found by introspection of the wrapped class, so that a new class, property or list is fuzzed
without touching this file:

* setters: every Set<Name> declared by the class or by a base class of the package (the shared
  vtkPointPairFieldAlgorithm) whose Python signature takes only int, float or bool values (or one
  str), with its clamp range from Get<Name>MinValue/MaxValue when it has one;
* shortcuts: every argument-less Set<Name>To<Value>;
* lists: every Add<Row> with numeric arguments that has a SetNumberOf<Row>s (the one list API);
  a row's kind column (ROW_KINDS) is mostly one of the kinds, so that most rows are usable and
  the classes do real work (a random double is almost never a kind), and sometimes any value;
* array selections: every Get<Name>ArraySelection returning a vtkDataArraySelection (names of
  input arrays to act on), whose arrays are enabled, disabled or cleared;
* inputs: every input port, its required data type and whether it is optional; the Generators
  input of a class with a `Tolerance` sometimes holds enough generators for its tree
  (MANY_GENERATORS).

A trial is a recipe: plain data made by random.Random("<seed>/<trial>") alone (the same on every
machine and Python), so that `--seed S --trial T` replays it exactly. make_recipe makes it,
describe prints it.
"""
import math
import random
import re
import sys

import boostedsurfaces
from vtkmodules.vtkCommonCore import vtkDataArraySelection
from vtkmodules.vtkCommonDataModel import (vtkImageData, vtkPolyData, vtkRectilinearGrid,
                                           vtkStructuredGrid, vtkUnstructuredGrid)
from vtkmodules.vtkCommonExecutionModel import vtkAlgorithm

INT_MIN, INT_MAX = -2 ** 31, 2 ** 31 - 1
DBL_MAX = sys.float_info.max
FLT_MAX = 3.4028234663852886e38
MAXIMUM_ROWS = 1000000  # vtkBoostedRowList::MaximumRows

EXTREME_DOUBLES = [0.0, -0.0, 5e-324, -5e-324, 2.2250738585072014e-308, 1e-300, -1e-300, 1e-12,
                   -1e-12, 1e8, -1e8, 2.0 ** 53, FLT_MAX, 1e39, -1e39, 1e150, 1e300, -1e300,
                   DBL_MAX, -DBL_MAX]
NON_FINITE = [math.nan, math.inf, -math.inf]
EXTREME_INTS = [0, 1, -1, 2, 3, 1000, 65536, 100000, 100001, MAXIMUM_ROWS, MAXIMUM_ROWS + 1,
                10 ** 8, INT_MAX - 1, INT_MAX, INT_MIN, INT_MIN + 1]
NAMES = ["Direction", "Weight", "Normals", "", "missing", "x" * 300, "\u00dcn\u00efcode"]

# The column of a list row that holds a kind, and the kinds (vtkBoostedGeneratorRows: a generator
# row is x, y, z, direction x, y, z, weight, kind, pitch; the kinds are the classes' POINT_PAIR ...
# TRANSLATION, 0 to 4). Other values of that column are bad input, chosen with BAD_KIND_RATE.
ROW_KINDS = {"Generator": (7, [0, 1, 2, 3, 4])}
BAD_KIND_RATE = 0.04

# Setters the fuzz holds at or below a value: set to it first in every trial of a class that has
# one, and a larger drawn value is lowered to it (NaN stays: a refusal). The fit filter's FitKinds
# search may do up to MaximumKindSearchWork units of work (README, "Kinds": up to about 14 us
# each); its default, minutes, is beyond the driver's --timeout, 1e6 is seconds.
HELD_AT_MOST = {"MaximumKindSearchWork": 1e6}

# A class with a Tolerance builds a generator tree only from 10,000 kept generators (the measured
# crossover, cga::PointPairField::treeMinimumGenerators), far more than a few rows. So a share of
# its Generators inputs hold size^2 points (a polydata or unstructured grid), enough left after a
# non-finite regime spoils a few, and then TOLERANCE_RATE of them come with a Tolerance the tree
# is built for (above treeMinimumTolerance: 1e-4 (10,000/M)^3), so that the tree's build, its
# sharing across a trial's updates and its bad input are fuzzed too.
MANY_GENERATORS = {"rate": 0.25, "size": 110, "tolerance_rate": 0.8, "tolerances": (1e-4, 1.0)}

# The value regimes of a trial: most trials stay where the classes do real work, so that valid
# outputs are checked as often as refusals.
REGIMES = [("typical", 0.55), ("extreme", 0.33), ("non-finite", 0.12)]

SIGNATURE = re.compile(r"^(\w+)\(self(?:, ([^)]*))?\)", re.M)
SCALAR_TYPES = {"int", "float", "bool", "str"}


def signatures(cls, name):
    """The argument types of every Python signature of cls.name, e.g. [["float", "float"]]."""
    found = []
    for match in SIGNATURE.finditer(getattr(cls, name).__doc__ or ""):
        if match.group(1) != name:
            continue
        text = match.group(2) or ""
        if "(" in text:  # a tuple argument such as _arg:(float, float, float)
            continue
        found.append([argument.split(":")[1].strip() for argument in text.split(",")
                      if argument.strip()])
    return found


def scalar_signature(cls, name):
    """The first signature of only int/float/bool arguments (or one str), or None."""
    for types in signatures(cls, name):
        if types and all(t in SCALAR_TYPES for t in types) and (
                "str" not in types or types == ["str"]):
            return types
    return None


class ClassModel:
    """What the fuzz knows of one class: found by introspection of the wrapped class."""

    def __init__(self, cls):
        self.cls = cls
        self.name = cls.__name__
        own = sorted(set().union(*(vars(base) for base in package_classes(cls))))
        self.lists = {}
        for method in own:
            if method.startswith("Add"):
                row = method[3:]
                # The full row: the longest signature (AddGenerator also takes the 7 values of a
                # point pair; GetGenerator fills the 9 of a row of any kind).
                widths = [len(types) for types in signatures(cls, method)
                          if types and all(t in SCALAR_TYPES for t in types)]
                if widths and "SetNumberOf%ss" % row in own and "Set%s" % row in own:
                    self.lists[row] = max(widths)
        list_methods = {f % row for row in self.lists for f in ("Set%s", "SetNumberOf%ss")}
        instance = cls()
        self.selections = [method for method in own
                           if re.match(r"Get\w+ArraySelection$", method)
                           and isinstance(getattr(instance, method)(), vtkDataArraySelection)]
        self.setters = {}
        self.shortcuts = []
        for method in own:
            if not method.startswith("Set") or method in list_methods:
                continue
            if re.match(r"Set\w+To\w+$", method) and signatures(cls, method) == [[]]:
                self.shortcuts.append(method)
                continue
            types = scalar_signature(cls, method)
            if types is None:
                continue
            name = method[3:]
            bounds = None
            if hasattr(instance, "Get%sMinValue" % name):
                bounds = (getattr(instance, "Get%sMinValue" % name)(),
                          getattr(instance, "Get%sMaxValue" % name)())
            self.setters[name] = (types, bounds)
        self.ports = []
        for port in range(instance.GetNumberOfInputPorts()):
            info = instance.GetInputPortInformation(port)
            key = vtkAlgorithm.INPUT_REQUIRED_DATA_TYPE()
            required = [info.Get(key, i) for i in range(info.Length(key))]
            optional = bool(info.Get(vtkAlgorithm.INPUT_IS_OPTIONAL()))
            self.ports.append((required, optional))


def package_classes(cls):
    """cls and its base classes that the boostedsurfaces package defines (their methods are the
    class's own API; VTK's bases are not fuzzed)."""
    return [base for base in cls.__mro__ if getattr(boostedsurfaces, base.__name__, None) is base]


def instantiable(cls):
    """False for an abstract class (a shared base such as vtkPointPairFieldAlgorithm)."""
    try:
        cls()
    except TypeError:
        return False
    return True


def discover():
    """A ClassModel for every concrete vtkAlgorithm of the boostedsurfaces package, sorted by
    name."""
    models = []
    for name in sorted(dir(boostedsurfaces)):
        cls = getattr(boostedsurfaces, name)
        if isinstance(cls, type) and issubclass(cls, vtkAlgorithm) and instantiable(cls):
            models.append(ClassModel(cls))
    return models


def log_uniform(rng, low, high):
    return math.exp(rng.uniform(math.log(low), math.log(high)))


class Values:
    """The random values of one trial, in its regime."""

    def __init__(self, rng, regime):
        self.rng = rng
        self.regime = regime

    def odd(self):
        """True when this value should leave the typical range: never in the typical regime."""
        return self.regime != "typical" and self.rng.random() < 0.5

    def double(self, bounds=None):
        rng = self.rng
        if self.regime == "non-finite" and rng.random() < 0.3:
            return rng.choice(NON_FINITE)
        if self.odd():
            return rng.choice(EXTREME_DOUBLES)
        if bounds is not None:
            low, high = bounds
            if high - low <= 1e3:
                return rng.uniform(low, high)
            low, high = max(low, 1e-3), min(high, 1e3)
            return log_uniform(rng, low, high) if low < high else low
        kind = rng.random()
        if kind < 0.4:
            return rng.uniform(-3.0, 3.0)
        if kind < 0.8:
            return rng.choice([-1, 1]) * log_uniform(rng, 1e-3, 1e3)
        return float(rng.randint(-2, 2))

    def integer(self, bounds=None):
        rng = self.rng
        if self.odd():
            return rng.choice(EXTREME_INTS)
        if bounds is None:
            return int(log_uniform(rng, 1, 40)) if rng.random() < 0.9 else rng.randint(-2, 0)
        low, high = int(bounds[0]), int(bounds[1])
        if high - low <= 10:  # an enumeration or a small range
            return rng.randint(low, high)
        if rng.random() < 0.9:  # a moderate size: most outputs within the fuzz's memory budget
            top = min(high, 200)
            return int(log_uniform(rng, max(low, 1), top)) if max(low, 1) < top else low
        return int(log_uniform(rng, max(low, 1), high)) if max(low, 1) < high else high

    def value(self, kind, bounds=None):
        if kind == "float":
            return self.double(bounds)
        if kind == "int":
            return self.integer(bounds)
        if kind == "bool":
            return self.rng.random() < 0.5
        return self.rng.choice(NAMES + [None])

    def index(self, count):
        """A row index: mostly a valid one, else just outside or far outside the list."""
        if count > 0 and (not self.odd()) and self.rng.random() < 0.85:
            return self.rng.randrange(count)
        return self.rng.choice([-1, min(count, INT_MAX), min(count + 1, INT_MAX), INT_MAX,
                                INT_MIN])

    def count(self):
        if self.odd():
            return self.rng.choice([-1, INT_MIN, MAXIMUM_ROWS + 1, INT_MAX, 0])
        return self.rng.randint(0, 4)

    def row(self, name, width):
        """The values of a list row: random, but its kind column (ROW_KINDS) mostly a kind."""
        values = [self.double() for _ in range(width)]
        column, kinds = ROW_KINDS.get(name, (None, None))
        if column is not None and column < width and self.rng.random() >= BAD_KIND_RATE:
            values[column] = float(self.rng.choice(kinds))
        return values


# The data-set kinds of fuzz_inputs and their VTK classes.
KIND_CLASSES = {"polydata": vtkPolyData, "unstructured": vtkUnstructuredGrid,
                "structured": vtkStructuredGrid, "image": vtkImageData,
                "rectilinear": vtkRectilinearGrid}


def data_spec(rng, values, required, optional, rows_hint, tree=False):
    """The input of one port: a data-set kind and how to fill it (built by fuzz_inputs.build).
    Mostly a kind the port accepts (so that the class runs), sometimes any (the pipeline's type
    check refuses it). With `tree` (a Generators input of a class with a Tolerance), sometimes
    MANY_GENERATORS's many points."""
    kinds = sorted(KIND_CLASSES)
    accepted = [k for k in kinds if any(KIND_CLASSES[k].IsTypeOf(t) for t in required)] or kinds
    spec = {"seed": rng.getrandbits(32), "regime": values.regime}
    roll = rng.random()
    if roll < (0.25 if optional else 0.02):  # no input: on a required port the pipeline refuses
        return None
    if roll < 0.04:
        spec["kind"] = "table"  # not a data set: the pipeline's type check refuses it
    elif roll < 0.08:
        spec["kind"] = "empty-" + rng.choice(kinds)
    else:
        spec["kind"] = rng.choice(accepted if rng.random() < 0.85 else kinds)
    spec["points"] = rng.choice(["double", "double", "float", "soa-double", "soa-float", "int"])
    spec["size"] = rng.choice([1, 2, 3, 4, 6, 8]) if rows_hint else rng.choice([2, 3, 5, 8, 12])
    # Arrays: the names this class reads are among NAMES; on an optional port (the Generators
    # input) an array may have the wrong number of tuples or components.
    spec["arrays"] = [(rng.choice(NAMES[:4]), rng.choice([1, 1, 3, 3, 2, 4]),
                       rng.choice(["double", "float", "int", "soa-double", "uchar"]),
                       rng.choice([0, 0, 0, 0, -1, 1, 5]) if optional else 0)
                      for _ in range(rng.randint(0, 3))]
    if rows_hint and rng.random() < 0.75:
        # Generators as data: mostly with the directions a class reads by default (NAMES[0]),
        # so that the port's generators are used; the random arrays above may still spoil them.
        spec["arrays"].insert(0, (NAMES[0], 3, "double", 0))
    spec["cell_arrays"] = rng.randint(0, 2)
    if tree and rows_hint and spec["kind"] in ("polydata", "unstructured") and \
            rng.random() < MANY_GENERATORS["rate"]:
        spec["size"] = MANY_GENERATORS["size"]
        if spec["arrays"][:1] != [(NAMES[0], 3, "double", 0)]:
            spec["arrays"].insert(0, (NAMES[0], 3, "double", 0))  # usable, unless spoiled
    return spec


def reaches_tree(model):
    """Whether a class has a generator tree for the fuzz to reach: a Tolerance and an optional
    Generators input (the deformation filter; the dipole field source has rows only)."""
    return "Tolerance" in model.setters and any(optional for _, optional in model.ports[1:])


def many_generators(spec):
    """Whether an input of data_spec holds MANY_GENERATORS's many points."""
    return spec is not None and spec.get("size") == MANY_GENERATORS["size"]


def request(rng, values, model):
    """How an update is asked for: plainly, a piece, an extent or a time."""
    roll = rng.random()
    if roll < 0.45:
        return ("Update", [])
    if roll < 0.75:
        if values.odd():
            pieces = rng.choice([0, -1, 1, 2, INT_MAX])
            piece = rng.choice([-1, 0, pieces, pieces + 1 if pieces < INT_MAX else INT_MIN,
                                INT_MAX, INT_MIN])
            ghosts = rng.choice([0, 1, -1, 1000, INT_MAX])
        else:
            pieces = rng.randint(1, 4)
            piece = rng.randrange(pieces)
            ghosts = rng.choice([0, 0, 1])
        return ("UpdatePiece", [piece, pieces, ghosts])
    if roll < 0.9:
        if values.odd():
            extent = [rng.choice([INT_MIN, -1, 0, 5, 10 ** 6, INT_MAX]) for _ in range(6)]
        else:
            extent = []
            for _ in range(3):
                low = rng.randint(-2, 20)
                extent += [low, low + rng.randint(-1, 20)]
        return ("UpdateExtent", [extent])
    return ("UpdateTimeStep", [rng.choice([0.0, 0.25, 1.0, -1.0, 1e300] +
                                          (NON_FINITE if values.regime == "non-finite" else []))])


def mutation(rng, values, model, rows):
    """One call that changes the object: a setter, a shortcut, a list operation or an input."""
    roll = rng.random()
    if model.lists and roll < 0.3:
        row = rng.choice(sorted(model.lists))
        width = model.lists[row]
        operation = rng.choices(["Add", "Set", "SetNumberOf", "Get", "RemoveAll"],
                                [5, 3, 1.5, 1, 0.3])[0]
        if operation == "Add":
            rows[row] += 1
            return ("Add%s" % row, values.row(row, width))
        if operation == "Set":
            return ("Set%s" % row, [values.index(rows[row])] + values.row(row, width))
        if operation == "SetNumberOf":
            rows[row] = values.count()
            return ("SetNumberOf%ss" % row, [rows[row]])
        if operation == "Get":
            return ("Get%s" % row, [values.index(rows[row]), [0.0] * width])
        rows[row] = 0
        return ("RemoveAll%ss" % row, [])
    if model.shortcuts and roll < 0.4:
        return (rng.choice(model.shortcuts), [])
    if model.ports and roll < 0.47:
        port = rng.randrange(len(model.ports))
        required, optional = model.ports[port]
        return ("SetInputDataObject", [port, data_spec(rng, values, required, optional,
                                                        port > 0 and optional,
                                                        reaches_tree(model))])
    if model.selections and roll < 0.57:
        # "Get<Name>ArraySelection.<Method>": the runner calls the getter, then the method. The
        # names are the ones fuzz_inputs gives arrays (of 1 to 4 components), and others.
        selection = rng.choice(model.selections)
        operation = rng.choices(["EnableArray", "DisableArray", "RemoveAllArrays"], [6, 2, 1])[0]
        return ("%s.%s" % (selection, operation),
                [] if operation == "RemoveAllArrays" else [rng.choice(NAMES)])
    name = rng.choice(sorted(model.setters))
    types, bounds = model.setters[name]
    if all(t == "float" for t in types) and len(types) > 1 and rng.random() < 0.1:
        return ("Set" + name, [0.0] * len(types))  # a zero vector
    arguments = [values.value(t, bounds) for t in types]
    if name in HELD_AT_MOST:
        arguments = [a if not a > HELD_AT_MOST[name] else HELD_AT_MOST[name] for a in arguments]
    if name.endswith("Range") and len(types) == 2 and rng.random() < 0.85:
        arguments.sort(key=lambda x: (math.isnan(x), x))  # mostly [min, max] (a NaN stays)
    return ("Set" + name, arguments)


def make_recipe(models, seed, trial):
    """The calls of one trial: which class, its inputs, changes and updates."""
    rng = random.Random("%d/%d" % (seed, trial))
    model = models[trial % len(models)]
    regime = rng.choices([r for r, _ in REGIMES], [w for _, w in REGIMES])[0]
    values = Values(rng, regime)
    rows = {row: None for row in model.lists}  # None: the class's own initial count
    calls = [("Set" + name, [value]) for name, value in sorted(HELD_AT_MOST.items())
             if name in model.setters]
    first = None
    for port, (required, optional) in enumerate(model.ports):
        if not optional or rng.random() < 0.5:
            # A later optional port holds a few rows (generators); a later required one (the fit
            # filter's target) is sized like the first: 45 % of the time it is the first's data
            # (the same points: a fit to where the mesh already is), 45 % the first's data with
            # its points moved (fuzz_inputs: the same count and order elsewhere, a real fit),
            # else any.
            spec = data_spec(rng, values, required, optional, port > 0 and optional,
                             reaches_tree(model))
            roll = rng.random()
            if port > 0 and not optional and first is not None and spec is not None and roll < 0.9:
                spec = dict(first, moved=spec["seed"]) if roll < 0.45 else dict(first)
            first = spec if port == 0 else first
            calls.append(("SetInputDataObject", [port, spec]))
            if port > 0 and many_generators(spec) and \
                    rng.random() < MANY_GENERATORS["tolerance_rate"]:
                calls.append(("SetTolerance", [log_uniform(rng, *MANY_GENERATORS["tolerances"])]))
    instance = model.cls()
    for row in rows:
        rows[row] = getattr(instance, "GetNumberOf%ss" % row)()
    for row in sorted(rows):
        # Most trials start with a few rows (a class without default rows, the fit filter, then
        # has generators to work on).
        if rng.random() < 0.75:
            for _ in range(rng.randint(1, 3)):
                rows[row] += 1
                calls.append(("Add%s" % row, values.row(row, model.lists[row])))
    for _ in range(rng.choice([1, 1, 1, 2, 3])):
        for _ in range(rng.randint(0, 8)):
            calls.append(mutation(rng, values, model, rows))
        calls.append(request(rng, values, model))
    return {"seed": seed, "trial": trial, "class": model.name, "regime": regime, "calls": calls}


def call(algorithm, method, arguments):
    """Calls `method` of a recipe on `algorithm` ("Get<Name>ArraySelection.<Method>" through the
    getter)."""
    target = algorithm
    *getters, name = method.split(".")
    for getter in getters:
        target = getattr(target, getter)()
    return getattr(target, name)(*arguments)


def describe(recipe):
    """The recipe as Python-like lines, one call each."""
    lines = ["# seed %d trial %d: %s, %s values" % (recipe["seed"], recipe["trial"],
                                                  recipe["class"], recipe["regime"])]
    for method, arguments in recipe["calls"]:
        lines.append("algorithm.%s(%s)" % (method.replace(".", "()."),
                                            ", ".join(repr(a) for a in arguments)))
    return "\n".join(lines)
