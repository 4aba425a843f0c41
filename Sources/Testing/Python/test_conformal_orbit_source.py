"""Tests of the Python-wrapped vtkConformalOrbitSource: it imports from the package, errors and
warnings reach Python, generators and seeds can be given from Python and seeds from an input, and
the torus knot's orbit closes after its period with the linking numbers the README states. Plain
Python, no numpy.

    PYTHONPATH=<build>/lib/python3.11/site-packages python3 test_conformal_orbit_source.py -v
"""
import math
import unittest

from vtkmodules.vtkFiltersSources import vtkPointSource

from boostedsurfaces import vtkConformalOrbitSource

import python_test_common as common


def polylines(output):
    """The points of each polyline (closed ones without the repeated point) and whether all are
    closed."""
    lines, closed = [], True
    cells = output.GetLines()
    cells.InitTraversal()
    from vtkmodules.vtkCommonCore import vtkIdList
    ids = vtkIdList()
    while cells.GetNextCell(ids):
        n = ids.GetNumberOfIds()
        is_closed = n > 2 and ids.GetId(0) == ids.GetId(n - 1)
        closed = closed and is_closed
        lines.append([output.GetPoint(ids.GetId(k)) for k in range(n - 1 if is_closed else n)])
    return lines, closed and bool(lines)


def gauss_linking(a, b):
    """(1/4pi) sum of (a - b).(da x db)/|a - b|^3 over segment midpoints of two closed polygons."""
    total = 0.0
    for i in range(len(a)):
        p, q = a[i], a[(i + 1) % len(a)]
        da = [q[k] - p[k] for k in range(3)]
        ma = [p[k] + 0.5 * da[k] for k in range(3)]
        for j in range(len(b)):
            r, s = b[j], b[(j + 1) % len(b)]
            db = [s[k] - r[k] for k in range(3)]
            d = [ma[k] - r[k] - 0.5 * db[k] for k in range(3)]
            cross = (da[1] * db[2] - da[2] * db[1], da[2] * db[0] - da[0] * db[2],
                     da[0] * db[1] - da[1] * db[0])
            total += sum(d[k] * cross[k] for k in range(3)) / math.sqrt(sum(x * x for x in d)) ** 3
    return total / (4 * math.pi)


class ConformalOrbitSourceTest(unittest.TestCase):
    def test_trefoil_closes_and_links_its_cores_three_and_two_times(self):
        source = vtkConformalOrbitSource()
        source.SetTResolution(300)
        source.SetCoreResolution(120)
        source.Update()
        output = source.GetOutput()
        self.assertAlmostEqual(output.GetFieldData().GetArray("Period").GetValue(0), 6.0, places=12)
        (knot,), closed = polylines(output)
        self.assertTrue(closed)
        self.assertEqual(len(knot), 300)
        cores, cores_closed = polylines(source.GetOutputDataObject(1))
        self.assertTrue(cores_closed)
        self.assertEqual(len(cores), 2)
        self.assertAlmostEqual(gauss_linking(knot, cores[0]), 3.0, delta=0.05)  # Q with A
        self.assertAlmostEqual(gauss_linking(knot, cores[1]), 2.0, delta=0.05)  # P with C

    def test_bad_input_is_an_error_in_python_and_empty_outputs(self):
        source = vtkConformalOrbitSource()
        errors = common.ErrorRecorder(source).messages
        source.SetKnotP(0)
        source.Update()
        self.assertEqual(len(errors), 1)
        self.assertIn("KnotP", errors[0])
        self.assertEqual(source.GetOutput().GetNumberOfPoints(), 0)
        self.assertEqual(source.GetOutputDataObject(1).GetNumberOfPoints(), 0)
        source.SetKnotP(3)
        source.SetTRange(2, 1)
        source.ClosePeriodicOrbitsOff()
        source.Update()
        self.assertEqual(len(errors), 2)
        self.assertIn("TRange", errors[1])

    def test_generators_and_seeds_from_python(self):
        source = vtkConformalOrbitSource()
        source.SetGeneratorTypeToGeneratorList()
        self.assertEqual(source.AddGenerator(1, 0, 0, 0, 1, 0, 1), 0)
        self.assertEqual(source.AddGenerator(-1, 0, 0, 0, -1, 0, 1), 1)
        source.SetSeedModeToSeedList()
        for k in range(4):
            source.AddSeed(0.1 * k, 0.2, 0.3)
        source.SetTRange(-1, 1)
        source.SetTResolution(20)
        recorder = common.ErrorRecorder(source)
        source.Update()
        self.assertEqual(recorder.messages, [])
        lines, _ = polylines(source.GetOutput())
        self.assertEqual(len(lines), 4)
        ids = source.GetOutput().GetPointData().GetArray("OrbitId")
        self.assertEqual(sorted({int(ids.GetValue(i)) for i in range(ids.GetNumberOfTuples())}),
                         [0, 1, 2, 3])
        row = [0.0] * 9
        self.assertTrue(source.GetGenerator(1, row))
        self.assertEqual(row, [-1, 0, 0, 0, -1, 0, 1, 0, 0])

    def test_zero_bivector_warns_and_keeps_the_seeds(self):
        source = vtkConformalOrbitSource()
        source.SetGeneratorTypeToGeneratorList()
        recorder = common.ErrorRecorder(source)
        source.Update()
        self.assertEqual(recorder.messages, [])
        self.assertEqual(len(recorder.warnings), 1)
        self.assertIn("identity", recorder.warnings[0])
        self.assertEqual(source.GetOutput().GetNumberOfVerts(), 1)

    def test_input_points_are_seeds(self):
        points = vtkPointSource()
        points.SetNumberOfPoints(7)
        points.SetCenter(0.15, 0, 0)  # on tori about A, off the middle torus through the origin
        points.SetRadius(0.05)
        source = vtkConformalOrbitSource()
        source.SetInputConnection(points.GetOutputPort())
        source.SetSeedModeToInputPoints()
        source.SetKnotP(3)
        source.SetKnotQ(5)
        source.Update()
        self.assertAlmostEqual(
            source.GetOutput().GetFieldData().GetArray("Period").GetValue(0), 15.0, places=12)
        lines, closed = polylines(source.GetOutput())
        self.assertEqual(len(lines), 7)
        self.assertTrue(closed)


if __name__ == "__main__":
    unittest.main()
