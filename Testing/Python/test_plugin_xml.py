"""The ParaView XML of the plugin (Plugin/*.xml) against the wrapped classes it drives, without
ParaView: every scalar property's default is the class's, its range domain is the setter's clamp
(a bound the setter does not clamp to must be one that an update rejects with an error), every
label is the property name in words (paraview.simple names properties after labels), an
enumeration lists exactly the clamped values, and each entry text is the class constant in words
("Control Points" is CONTROL_POINTS; the precision entries name vtkAlgorithm's *_PRECISION) and
the name of its shortcut (SetMethodToControlPoints(); not for the precision). A
table's Kind column (ParaView's tables hold numbers only) lists its values in the documentation,
"1 Rotation (ROTATION ...", with the same rule: the value is the constant, the text its words.

    PYTHONPATH=<build>/lib/python3.11/site-packages python3 test_plugin_xml.py <Plugin dir> -v
"""
import glob
import math
import os
import re
import sys
import unittest
import xml.etree.ElementTree as ET

import boostedsurfaces
from vtkmodules.vtkFiltersSources import vtkSphereSource

import python_test_common as common

PLUGIN_DIR = sys.argv.pop(1) if len(sys.argv) > 1 and os.path.isdir(sys.argv[1]) else os.path.join(
    os.path.dirname(os.path.abspath(__file__)), "..", "..", "Plugin")
INT_LIMITS = (-2**31, 2**31 - 1)
DOUBLE_LIMITS = (-1e300, 1e300)
UNBOUNDED = 1e299  # VTK_DOUBLE_MAX: a clamp there bounds nothing


def scalar_properties():
    """(class name, property element) of every one-number Int/DoubleVectorProperty with a
    command."""
    for path in sorted(glob.glob(os.path.join(PLUGIN_DIR, "*.xml"))):
        for proxy in ET.parse(path).getroot().iter("SourceProxy"):
            for prop in proxy:
                if (prop.tag in ("IntVectorProperty", "DoubleVectorProperty")
                        and prop.get("command") and prop.get("number_of_elements") == "1"
                        and not prop.get("repeat_command")):
                    yield proxy.get("class"), prop


def new_object(class_name):
    obj = getattr(boostedsurfaces, class_name)()
    if obj.GetNumberOfInputPorts() > 0 and class_name == "vtkPointPairDeformationFilter":
        sphere = vtkSphereSource()
        obj.SetInputConnection(sphere.GetOutputPort())
        obj.AddGenerator(0, 0, 0.5, 0, 0, 1, 0.5)
        obj._keep = sphere
    return obj


def clamp(class_name, prop):
    """The (low, high) the setter clamps to; None where it does not clamp."""
    limits = INT_LIMITS if prop.tag == "IntVectorProperty" else DOUBLE_LIMITS
    obj = new_object(class_name)
    setter, getter = getattr(obj, prop.get("command")), getattr(obj, "G" + prop.get("command")[1:])
    bounds = []
    for limit in limits:
        setter(limit)
        value = getter()
        bounds.append(None if value == limit or abs(value) >= UNBOUNDED else value)
    return tuple(bounds)


def update_rejects(class_name, prop, value):
    """True when an update with the property at `value` gives an error and an empty output."""
    obj = new_object(class_name)
    getattr(obj, prop.get("command"))(value)
    errors = common.ErrorRecorder(obj)
    obj.Update()
    output = obj.GetOutputDataObject(0)
    return len(errors.messages) > 0 and output.GetNumberOfPoints() == 0


def number(text, prop):
    return int(text) if prop.tag == "IntVectorProperty" else float(text)


def fixed_size_properties():
    """(class name, property element) of every Int/DoubleVectorProperty of 2 to 4 numbers set by
    one command (origins, ranges, directions)."""
    for path in sorted(glob.glob(os.path.join(PLUGIN_DIR, "*.xml"))):
        for proxy in ET.parse(path).getroot().iter("SourceProxy"):
            for prop in proxy:
                if (prop.tag in ("IntVectorProperty", "DoubleVectorProperty")
                        and prop.get("command") and prop.get("number_of_elements") in "234"
                        and not prop.get("repeat_command") and prop.get("default_values")):
                    yield proxy.get("class"), prop


class PluginXmlTest(unittest.TestCase):
    def test_vector_defaults_are_the_classes(self):
        for class_name, prop in fixed_size_properties():
            with self.subTest(cls=class_name, property=prop.get("name")):
                obj = getattr(boostedsurfaces, class_name)()
                expected = [number(v, prop) for v in prop.get("default_values").split()]
                self.assertEqual(list(getattr(obj, "G" + prop.get("command")[1:])()), expected)

    def test_python_names_are_the_property_names(self):
        # paraview.simple names a property after its label without spaces: that must be the
        # XML name, so that pvpython, the C++ setter and the README say the same.
        for path in sorted(glob.glob(os.path.join(PLUGIN_DIR, "*.xml"))):
            for proxy in ET.parse(path).getroot().iter("SourceProxy"):
                for prop in proxy:
                    label = prop.get("label")
                    if prop.get("name") and label is not None:
                        self.assertEqual(label.replace(" ", ""), prop.get("name"),
                                         "%s: label %r" % (os.path.basename(path), label))

    def test_defaults_are_the_classes(self):
        for class_name, prop in scalar_properties():
            with self.subTest(cls=class_name, property=prop.get("name")):
                obj = getattr(boostedsurfaces, class_name)()
                self.assertEqual(getattr(obj, "G" + prop.get("command")[1:])(),
                                 number(prop.get("default_values"), prop))

    def test_range_domains_are_the_clamps(self):
        for class_name, prop in scalar_properties():
            domain = prop.find("IntRangeDomain")
            if domain is None:
                domain = prop.find("DoubleRangeDomain")
            if domain is None or prop.find("EnumerationDomain") is not None:
                continue
            for side, attribute in enumerate(("min", "max")):
                with self.subTest(cls=class_name, property=prop.get("name"), bound=attribute):
                    clamped = clamp(class_name, prop)[side]
                    stated = domain.get(attribute)
                    stated = None if stated is None else number(stated, prop)
                    if clamped is None and stated is None:
                        continue
                    if clamped is not None and stated is not None and clamped == stated:
                        continue
                    # A stricter XML bound than the clamp: the values between are errors.
                    self.assertIsNotNone(stated, "the setter clamps %s to %r; the XML says "
                                         "nothing" % (attribute, clamped))
                    beyond = clamped if clamped is not None else (
                        stated + (-1 if side == 0 else 1) * max(1, abs(stated)))
                    self.assertTrue((beyond < stated) if side == 0 else (beyond > stated),
                                    "the XML %s %r lies beyond the clamp %r"
                                    % (attribute, stated, clamped))
                    self.assertTrue(update_rejects(class_name, prop, beyond),
                                    "the XML %s is %r but %r is accepted"
                                    % (attribute, stated, beyond))

    def test_enumerations_are_the_class_constants(self):
        for class_name, prop in scalar_properties():
            domain = prop.find("EnumerationDomain")
            if domain is None:
                continue
            with self.subTest(cls=class_name, property=prop.get("name")):
                cls = getattr(boostedsurfaces, class_name)
                entries = {int(e.get("value")): e.get("text") for e in domain.findall("Entry")}
                low, high = clamp(class_name, prop)
                self.assertEqual(sorted(entries), list(range(low, high + 1)))
                for value, text in entries.items():
                    constant = text.upper().replace(" ", "_")
                    if not hasattr(cls, constant):
                        constant += "_PRECISION"
                    self.assertEqual(getattr(cls, constant, None), value,
                                     "entry %r is not %s.%s" % (text, class_name, constant))
                    if constant.endswith("_PRECISION"):
                        continue  # VTK's OutputPointsPrecision has its constants only
                    # The project's own enumerations have a Set...To...() shortcut per value.
                    shortcut = "%sTo%s" % (prop.get("command"), text.replace(" ", ""))
                    obj = new_object(class_name)
                    self.assertTrue(hasattr(obj, shortcut), "%s has no %s()" % (class_name, shortcut))
                    getattr(obj, prop.get("command"))(high if value == low else low)
                    getattr(obj, shortcut)()
                    self.assertEqual(getattr(obj, "G" + prop.get("command")[1:])(), value, shortcut)

    def test_decorators_name_properties_and_values_of_their_proxy(self):
        """Every visibility decorator of a panel names a property of its own proxy and, where that
        property is an enumeration, one of its values (a typo would hide a property for good)."""
        decorators = 0
        for path in sorted(glob.glob(os.path.join(PLUGIN_DIR, "*.xml"))):
            for proxy in ET.parse(path).getroot().iter("SourceProxy"):
                properties = {p.get("name"): p for p in proxy if p.get("name")}
                for decorator in proxy.iter("PropertyWidgetDecorator"):
                    if decorator.get("type") != "GenericDecorator":
                        continue
                    decorators += 1
                    name, value = decorator.get("property"), decorator.get("value")
                    with self.subTest(proxy=proxy.get("name"), property=name, value=value):
                        self.assertIn(name, properties)
                        domain = properties[name].find("EnumerationDomain")
                        if domain is not None:
                            self.assertIn(value, [e.get("value") for e in domain.findall("Entry")])
        self.assertGreater(decorators, 20)

    def test_kind_columns_are_the_class_constants(self):
        tables = 0
        for path in sorted(glob.glob(os.path.join(PLUGIN_DIR, "*.xml"))):
            for proxy in ET.parse(path).getroot().iter("SourceProxy"):
                for prop in proxy:
                    labels = [c.get("label") for c in prop.iter("ComponentLabel")]
                    if not prop.get("repeat_command") or "Kind" not in labels:
                        continue
                    tables += 1
                    with self.subTest(cls=proxy.get("class"), property=prop.get("name")):
                        cls = getattr(boostedsurfaces, proxy.get("class"))
                        text = " ".join(prop.find("Documentation").text.split())
                        entries = re.findall(r"(\d+) ([A-Z][a-z]+(?: [A-Z][a-z]+)*) \(([A-Z_]+)",
                                             text.split("Kind:", 1)[1])
                        constants = sorted(getattr(cls, k, None) for k in (
                            "POINT_PAIR", "ROTATION", "TWIST", "DILATION", "TRANSLATION"))
                        self.assertEqual(sorted(int(e[0]) for e in entries), constants)
                        self.assertEqual(constants, list(range(5)))
                        for value, words, constant in entries:
                            self.assertEqual(words.upper().replace(" ", "_"), constant)
                            self.assertEqual(getattr(cls, constant), int(value))
        # The deformation filter's, the dipole source's, the orbits', the fit filter's.
        self.assertEqual(tables, 4)


if __name__ == "__main__":
    unittest.main()
