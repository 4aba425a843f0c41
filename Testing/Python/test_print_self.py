"""PrintSelf (str() in Python) of every class of the package: it names every property and prints
its current value. The properties are the property fuzz's (fuzz_recipe.discover: every scalar
Set<Name> of the class and its package bases, every row list), so a new property that PrintSelf
forgets fails here.

For each setter with a getter: the line "<Name>: ..." is printed, and it changes when the property
is set to another value (a bool flipped, a clamped number set to the end of its range it is not at,
another number moved by 1, a string set to a new text). For each list: after one row is added, the
line "<Row> 0: (...)" shows that row's values. For each array selection: an enabled array's name.

    PYTHONPATH=<build>/lib/python3.11/site-packages python3 test_print_self.py -v
"""
import re
import unittest

import fuzz_recipe

MODELS = fuzz_recipe.discover()


def printed_value(text, name):
    """The text after "<name>: " on its line of a PrintSelf output, or None."""
    match = re.search(r"^\s*%s: (.*)$" % re.escape(name), text, re.M)
    return match.group(1) if match else None


def another_value(types, bounds, current):
    """Arguments for Set<Name> that differ from the current value in every component."""
    values = list(current) if isinstance(current, tuple) else [current]
    if types == ["str"]:
        return ["PrintSelfCheck"]
    if types == ["bool"] or isinstance(values[0], bool):
        return [not values[0]]
    if bounds is not None:
        low, high = bounds
        values = [high if value != high else low for value in values]
    else:
        values = [value + 1 for value in values]
    return [int(v) if t == "int" else float(v) for v, t in zip(values, types)]


class PrintSelfTest(unittest.TestCase):
    def test_the_classes_are_found(self):
        names = {model.name for model in MODELS}
        for expected in ("vtkBoostedSurfaceSource", "vtkConformalOrbitSource",
                         "vtkCurvaturePatchSource", "vtkDipoleFieldSource",
                         "vtkHopfFibrationSource", "vtkPointPairDeformationFilter",
                         "vtkPointPairFitFilter"):
            self.assertIn(expected, names)
        for model in MODELS:
            self.assertGreater(len(model.setters), 10, model.name)

    def test_every_property_is_printed_with_its_value(self):
        for model in MODELS:
            for name, (types, bounds) in sorted(model.setters.items()):
                instance = model.cls()
                getter = getattr(instance, "Get" + name, None)
                if getter is None:
                    continue  # a setter without a getter (none so far) prints nothing to compare
                with self.subTest(cls=model.name, property=name):
                    before = printed_value(str(instance), name)
                    self.assertIsNotNone(before, "%s is not printed" % name)
                    old = getter()
                    arguments = another_value(types, bounds, old)
                    getattr(instance, "Set" + name)(*arguments)
                    self.assertNotEqual(getter(), old)  # the property did change
                    after = printed_value(str(instance), name)
                    self.assertIsNotNone(after)
                    self.assertNotEqual(after, before,
                                        "Set%s%s left its printed value %r" % (
                                            name, tuple(arguments), before))
                    if types == ["str"]:
                        self.assertIn(arguments[0], after)

    def test_every_array_selection_prints_its_enabled_arrays(self):
        found = 0
        for model in MODELS:
            for getter in model.selections:
                with self.subTest(cls=model.name, selection=getter):
                    instance = model.cls()
                    getattr(instance, getter)().EnableArray("PrintSelfArray")
                    self.assertIn("'PrintSelfArray'", str(instance))
                    found += 1
        self.assertGreater(found, 0)  # the deformation filter has its array selections

    def test_every_list_prints_its_rows(self):
        for model in MODELS:
            for row, width in sorted(model.lists.items()):
                with self.subTest(cls=model.name, row=row):
                    instance = model.cls()
                    values = [0.5 * (i + 1) for i in range(width)]
                    getattr(instance, "Add" + row)(*values)
                    printed = printed_value(str(instance), "%s 0" % row)
                    self.assertIsNotNone(printed, "no line %s 0" % row)
                    numbers = [float(x) for x in re.findall(r"-?\d+(?:\.\d+)?(?:e[-+]?\d+)?",
                                                            printed)]
                    stored = [0.0] * width
                    getattr(instance, "Get" + row)(0, stored)
                    self.assertEqual(numbers, stored, printed)


if __name__ == "__main__":
    unittest.main()
