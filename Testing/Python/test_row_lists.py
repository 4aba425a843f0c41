"""The one list API of the classes with a list (vtkBoostedRowList in C++), through the
Python wrapping: AddX returns the index, SetX(i, ...), SetNumberOfX(n), GetX(i, values),
RemoveAllX(), GetNumberOfX(), and the 10^6-row cap: one error, then an empty output until the list
is cleared or resized.

    PYTHONPATH=<build>/lib/python3.11/site-packages python3 test_row_lists.py -v
"""
import unittest

from boostedsurfaces import (vtkConformalOrbitSource, vtkCurvaturePatchSource,
                             vtkDipoleFieldSource, vtkHopfFibrationSource,
                             vtkPointPairDeformationFilter)
from vtkmodules.vtkFiltersSources import vtkSphereSource

import python_test_common as common

MAXIMUM_ROWS = 1000000  # vtkBoostedRowList::MaximumRows


def deformation_filter():
    sphere = vtkSphereSource()
    deformation = vtkPointPairDeformationFilter()
    deformation.SetInputConnection(sphere.GetOutputPort())
    return deformation


def hopf_source():
    source = vtkHopfFibrationSource()
    source.SetSamplingModeToBasePoints()
    return source


def orbit_generators():
    source = vtkConformalOrbitSource()
    source.SetGeneratorTypeToGeneratorList()
    return source


def orbit_seeds():
    source = vtkConformalOrbitSource()
    source.SetSeedModeToSeedList()
    return source


def patch_source():
    source = vtkCurvaturePatchSource()
    source.SetMethodToControlPoints()
    return source


# (make the object, row name, a valid row, the row SetNumberOfX gives new rows, rows it starts with)
LISTS = [
    (deformation_filter, "Generator", [0.0, 0.0, 0.5, 0.0, 0.0, 1.0, 0.5, 1.0, 0.25], [0.0] * 9, 0),
    (vtkDipoleFieldSource, "Generator", [0.0, 0.5, 0.0, 1.0, 0.0, 0.0, 0.5, 3.0, 0.0], [0.0] * 9, 1),
    (hopf_source, "BasePoint", [0.5, 0.25], [0.0, 0.0], 0),
    (orbit_generators, "Generator", [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.5, 1.0, 0.0], [0.0] * 9, 0),
    (orbit_seeds, "Seed", [0.15, 0.0, 0.0], [0.0, 0.0, 0.0], 0),
    (patch_source, "ControlPoint", [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 0.0, 0.0, 0.5, 0.5],
     [0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0], 0),
]


def api(obj, row):
    return {name: getattr(obj, name % row) for name in
            ("Add%s", "Set%s", "SetNumberOf%ss", "Get%s", "RemoveAll%ss", "GetNumberOf%ss")}


class RowListTest(unittest.TestCase):
    def test_generator_rows_without_kind_and_pitch_are_point_pairs(self):
        # The 7-value AddGenerator/SetGenerator of older scripts: kind POINT_PAIR (0), pitch 0.
        for make in (deformation_filter, vtkDipoleFieldSource, orbit_generators):
            with self.subTest(cls=make.__name__):
                obj = make()
                obj.RemoveAllGenerators()
                index = obj.AddGenerator(1, 2, 3, 0, 0, 1, 0.5)
                got = [9.0] * 9
                self.assertTrue(obj.GetGenerator(index, got))
                self.assertEqual(got, [1, 2, 3, 0, 0, 1, 0.5, obj.POINT_PAIR, 0])
                obj.SetGenerator(index, 1, 2, 3, 0, 0, 1, 0.5, obj.TWIST, 0.2)
                obj.SetGenerator(index, 4, 5, 6, 1, 0, 0, 0.25)
                self.assertTrue(obj.GetGenerator(index, got))
                self.assertEqual(got, [4, 5, 6, 1, 0, 0, 0.25, obj.POINT_PAIR, 0])

    def test_one_api_on_every_class(self):
        for make, row, values, blank, initial in LISTS:
            with self.subTest(row=row, cls=make.__name__):
                obj = make()
                f = api(obj, row)
                self.assertEqual(f["GetNumberOf%ss"](), initial)
                f["RemoveAll%ss"]()
                self.assertEqual(f["GetNumberOf%ss"](), 0)
                self.assertEqual(f["Add%s"](*values), 0)
                self.assertEqual(f["Add%s"](*values), 1)
                f["SetNumberOf%ss"](3)
                got = [9.0] * len(values)
                self.assertTrue(f["Get%s"](2, got))
                self.assertEqual(got, blank)
                changed = [v + 1.0 for v in values]
                before = obj.GetMTime()
                f["Set%s"](2, *changed)
                self.assertGreater(obj.GetMTime(), before)
                before = obj.GetMTime()
                f["Set%s"](2, *changed)  # the same values: not modified
                self.assertEqual(obj.GetMTime(), before)
                self.assertTrue(f["Get%s"](2, got))
                self.assertEqual(got, changed)
                self.assertFalse(f["Get%s"](3, got))
                self.assertFalse(f["Get%s"](-1, got))
                errors = common.ErrorRecorder(obj)
                f["Set%s"](3, *values)  # outside the list: an error, nothing changes
                self.assertEqual(len(errors.messages), 1)
                self.assertIn("outside the list of 3 rows", errors.messages[0])
                f["SetNumberOf%ss"](1)
                self.assertEqual(f["GetNumberOf%ss"](), 1)
                obj.Update()
                self.assertEqual(len(errors.messages), 1)
                self.assertGreater(obj.GetOutputDataObject(0).GetNumberOfPoints(), 0)

    def test_more_rows_than_the_cap_give_one_error_and_an_empty_output(self):
        for make, row, values, _, _ in LISTS:
            for how in ("SetNumberOf", "SetNumberOf on an empty list", "Add"):
                with self.subTest(row=row, cls=make.__name__, how=how):
                    obj = make()
                    f = api(obj, row)
                    f["RemoveAll%ss"]()
                    if how != "SetNumberOf on an empty list":
                        f["Add%s"](*values)
                        obj.Update()
                        self.assertGreater(obj.GetOutputDataObject(0).GetNumberOfPoints(), 0)
                    errors = common.ErrorRecorder(obj)
                    if how.startswith("SetNumberOf"):
                        # As ParaView pushes a table: the count, then every row by index.
                        f["SetNumberOf%ss"](MAXIMUM_ROWS + 1)
                        for i in (0, 1, MAXIMUM_ROWS - 1, MAXIMUM_ROWS):
                            f["Set%s"](i, *values)
                    else:
                        f["SetNumberOf%ss"](MAXIMUM_ROWS)
                        self.assertEqual(f["Add%s"](*values), -1)
                        self.assertEqual(f["Add%s"](*values), -1)
                    self.assertEqual(len(errors.messages), 1, errors.messages)
                    self.assertIn("at most %d rows" % MAXIMUM_ROWS, errors.messages[0])
                    obj.Update()
                    self.assertEqual(len(errors.messages), 2, errors.messages)
                    self.assertIn("more than the %d it may hold" % MAXIMUM_ROWS,
                                  errors.messages[1])
                    self.assertEqual(obj.GetOutputDataObject(0).GetNumberOfPoints(), 0)
                    f["SetNumberOf%ss"](1)  # within the cap again: usable
                    f["Set%s"](0, *values)
                    obj.Update()
                    self.assertEqual(len(errors.messages), 2, errors.messages)
                    self.assertGreater(obj.GetOutputDataObject(0).GetNumberOfPoints(), 0)

    def test_selected_row_handle(self):
        for make, row in ((deformation_filter, "Generator"), (patch_source, "ControlPoint")):
            with self.subTest(row=row):
                obj = make()
                self.assertEqual(getattr(obj, "GetSelected%s" % row)(), -1)
                getattr(obj, "SetSelected%s" % row)(-5)  # clamped to -1: none
                self.assertEqual(getattr(obj, "GetSelected%s" % row)(), -1)
                getattr(obj, "SetSelected%sLocation" % row)(0.1, 0.2, 0.3)
                self.assertEqual(getattr(obj, "GetSelected%sLocation" % row)(), (0.1, 0.2, 0.3))


if __name__ == "__main__":
    unittest.main()
