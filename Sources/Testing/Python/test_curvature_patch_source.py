"""Tests of the Python-wrapped vtkCurvaturePatchSource: the bent line of eq 15 against its closed
form, the control point API, presets, and errors Python can see. Plain Python, no numpy.

    PYTHONPATH=<build>/lib/python3.11/site-packages python3 test_curvature_patch_source.py -v
"""
import math
import unittest

from boostedsurfaces import vtkCurvaturePatchSource

import python_test_common as common


class CurvaturePatchSourceTest(unittest.TestCase):
    def test_bent_line_is_a_circle_of_radius_one_over_kappa(self):
        for kappa in (0.5, -0.25, 2.0):
            source = vtkCurvaturePatchSource()
            source.SetMethodToBentLine()
            source.SetOrigin(1.0, -1.0, 0.5)
            source.SetSize(10.0, 0.0)
            source.SetUResolution(50)
            source.SetKappaU(kappa)
            source.Update()
            output = source.GetOutput()
            self.assertEqual(output.GetNumberOfPoints(), 51)
            center = (1.0, -1.0, 0.5 - 1.0 / kappa)  # p - n/kappa with n = +z
            for i in range(output.GetNumberOfPoints()):
                self.assertAlmostEqual(math.dist(output.GetPoint(i), center), 1.0 / abs(kappa),
                                       delta=1e-9)
            weights = output.GetPointData().GetArray("GeneratorWeight")
            self.assertAlmostEqual(weights.GetValue(0), kappa / 2, delta=1e-15)

    def test_control_point_api(self):
        source = vtkCurvaturePatchSource()
        source.SetMethodToControlPoints()
        source.AddControlPoint(0, 0, 0, 0, 0, 1, 1, 0, 0, 0.5, -0.5)
        errors = common.ErrorRecorder(source)
        source.SetControlPoint(2, 1, 1, 0, 0, 0, 1, 0, 1, 0, 0.25, 0.25)  # no row 2 yet
        self.assertEqual(len(errors.messages), 1)
        self.assertIn("outside the list of 1 rows", errors.messages[0])
        source.SetNumberOfControlPoints(3)  # new rows: at the origin, normal z, u along x, flat
        values = [0.0] * 11
        self.assertTrue(source.GetControlPoint(1, values))
        self.assertEqual(values, [0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0])
        source.SetControlPoint(2, 1, 1, 0, 0, 0, 1, 0, 1, 0, 0.25, 0.25)
        self.assertEqual(source.GetNumberOfControlPoints(), 3)
        self.assertTrue(source.GetControlPoint(2, values))
        self.assertEqual(values, [1, 1, 0, 0, 0, 1, 0, 1, 0, 0.25, 0.25])
        self.assertFalse(source.GetControlPoint(3, values))
        self.assertEqual(source.AddControlPoint(0, 1, 0, 0, 0, 1, 1, 0, 0, 0.5, 0.5), 3)
        source.SetNumberOfControlPoints(3)
        source.Update()
        self.assertGreater(source.GetOutput().GetNumberOfCells(), 0)
        source.RemoveAllControlPoints()
        errors = common.ErrorRecorder(source)
        source.Update()
        self.assertEqual(len(errors.messages), 1)
        self.assertIn("control point", errors.messages[0])
        self.assertEqual(source.GetOutput().GetNumberOfPoints(), 0)

    def test_bad_size_and_nan_give_an_error(self):
        for setup in (lambda s: s.SetSize(0.0, 1.0), lambda s: s.SetOrigin(float("nan"), 0, 0)):
            source = vtkCurvaturePatchSource()
            setup(source)
            errors = common.ErrorRecorder(source)
            source.Update()
            self.assertEqual(len(errors.messages), 1)
            self.assertEqual(source.GetOutput().GetNumberOfPoints(), 0)

    def test_presets_give_the_fig7_signs(self):
        # the height of the point (a, b) = (1, 0) and (0, 1): below the plane for kappa > 0
        expected = {1: (-1, 0), 2: (-1, -1), 3: (-1, -1), 4: (1, -1)}
        for preset, (sign_u, sign_v) in expected.items():
            source = vtkCurvaturePatchSource()
            source.SetCurvaturePreset(preset)
            source.SetSize(2.0, 2.0)
            source.SetUResolution(2)
            source.SetVResolution(2)
            source.Update()
            output = source.GetOutput()
            heights = {}
            u, v = (output.GetPointData().GetArray(n) for n in ("u", "v"))
            for i in range(output.GetNumberOfPoints()):
                heights[(u.GetValue(i), v.GetValue(i))] = output.GetPoint(i)[2]

            def sign(x):
                return 0 if abs(x) < 1e-12 else (1 if x > 0 else -1)

            self.assertEqual(sign(heights[(1.0, 0.0)]), sign_u, preset)
            self.assertEqual(sign(heights[(0.0, 1.0)]), sign_v, preset)


if __name__ == "__main__":
    unittest.main()
