"""Tests of the Python-wrapped vtkBoostedSurfaceSource against the closed forms of docs/conventions.md section 3
items 1-3. Plain Python, no numpy: it must run wherever the wrapping does.

    PYTHONPATH=<build>/lib/python3.11/site-packages python3 test_boosted_surface_source.py -v
"""
import math
import os
import sys
import unittest

from boostedsurfaces import vtkBoostedSurfaceSource

import python_test_common as common

# The horn test uses the parameters of the example script.
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "Examples"))

TOLERANCE = 1e-9


def points_by_lambda(output):
    """{lambda: [(theta, (x, y, z)), ...]} from the "lambda" and "theta" point arrays."""
    lambdas = output.GetPointData().GetArray("lambda")
    thetas = output.GetPointData().GetArray("theta")
    groups = {}
    for i in range(output.GetNumberOfPoints()):
        groups.setdefault(lambdas.GetValue(i), []).append((thetas.GetValue(i), output.GetPoint(i)))
    return groups


def signed_area_xy(samples):
    """Shoelace area of the polygon through the samples in the order of theta (>0: counter-clockwise
    seen from +z)."""
    points = [p for _, p in sorted(samples)]
    area = 0.0
    for (x0, y0, _), (x1, y1, _) in zip(points, points[1:] + points[:1]):
        area += x0 * y1 - x1 * y0
    return 0.5 * area


class BoostedSurfaceSourceTest(unittest.TestCase):
    def test_fig1_in_plane_boost_gives_circles_and_a_line_at_lambda_one(self):
        # Unit circle in the xy plane, K = 1 + lambda no e1: center lambda/(lambda^2-1) e1, radius
        # 1/|lambda^2-1|; at lambda = +-1 the line x = 1/(2 lambda).
        source = vtkBoostedSurfaceSource()
        source.SetCircleNormal(0, 0, 1)
        source.SetBoostDirection(1, 0, 0)
        source.SetLambdaRange(-3.0, 3.0)
        source.SetLambdaResolution(24)  # steps of 0.25: +-1 are samples
        source.SetThetaResolution(48)
        source.SetClipRadius(100.0)
        source.SetOutputTypeToCircles()
        source.Update()
        groups = points_by_lambda(source.GetOutput())
        self.assertEqual(len(groups), 25)
        lines = circles = 0
        for lam, samples in groups.items():
            d = lam * lam - 1.0
            for _, (x, y, z) in samples:
                self.assertAlmostEqual(z, 0.0, delta=TOLERANCE)
            if abs(d) < 1e-12:
                for _, (x, y, z) in samples:
                    self.assertAlmostEqual(x, 0.5 / lam, delta=TOLERANCE, msg="lambda %g" % lam)
                lines += 1
                continue
            center, radius = lam / d, 1.0 / abs(d)
            for _, (x, y, z) in samples:
                self.assertAlmostEqual(math.hypot(x - center, y), radius,
                                       delta=TOLERANCE * max(1.0, radius), msg="lambda %g" % lam)
            # |lambda| > 1: the circle is turned inside out, its orientation reversed.
            area = signed_area_xy(samples)
            self.assertGreater(area if abs(lam) < 1 else -area, 0.0, "lambda %g" % lam)
            circles += 1
        self.assertEqual((lines, circles), (2, 23))

    def test_fig1_large_lambda_shrinks_onto_the_center(self):
        source = vtkBoostedSurfaceSource()
        source.SetCircleNormal(0, 0, 1)
        source.SetLambdaRange(1000.0, 1000.0)
        source.SetOutputTypeToCircles()
        source.Update()
        output = source.GetOutput()
        self.assertGreater(output.GetNumberOfPoints(), 0)
        for i in range(output.GetNumberOfPoints()):
            self.assertLess(math.sqrt(sum(c * c for c in output.GetPoint(i))), 2e-3)

    def test_fig2_normal_boost_gives_circles_in_parallel_planes(self):
        # Unit circle in the yz plane (the defaults), boosted along its normal x: the plane
        # x = lambda/(1+lambda^2), the radius 1/(1+lambda^2).
        source = vtkBoostedSurfaceSource()
        source.SetLambdaRange(0.0, 4.0)
        source.SetLambdaResolution(16)
        source.SetThetaResolution(32)
        source.Update()
        output = source.GetOutput()
        self.assertEqual(output.GetNumberOfPoints(), 17 * 33)
        self.assertEqual(output.GetNumberOfCells(), 16 * 32)
        for lam, samples in points_by_lambda(output).items():
            for _, (x, y, z) in samples:
                self.assertAlmostEqual(x, lam / (1.0 + lam * lam), delta=TOLERANCE)
                self.assertAlmostEqual(math.hypot(y, z), 1.0 / (1.0 + lam * lam), delta=TOLERANCE)

    def test_surface_output_has_its_arrays(self):
        source = vtkBoostedSurfaceSource()
        source.Update()
        data = source.GetOutput().GetPointData()
        self.assertIsNotNone(data.GetNormals())
        self.assertIsNotNone(data.GetTCoords())
        for name in ("lambda", "theta"):
            self.assertIsNotNone(data.GetArray(name), name)

    def test_zero_normal_gives_an_error_and_an_empty_output(self):
        source = vtkBoostedSurfaceSource()
        errors = common.ErrorRecorder(source)
        source.SetCircleNormal(0, 0, 0)
        source.Update()
        self.assertEqual(len(errors.messages), 1)
        self.assertIn("circle normal", errors.messages[0])
        self.assertEqual(source.GetOutput().GetNumberOfPoints(), 0)
        self.assertEqual(source.GetOutput().GetNumberOfCells(), 0)
        # Repaired, the same source works again.
        source.SetCircleNormal(1, 0, 0)
        source.Update()
        self.assertGreater(source.GetOutput().GetNumberOfPoints(), 0)
        self.assertEqual(len(errors.messages), 1)

    def test_print_self(self):
        source = vtkBoostedSurfaceSource()
        source.SetOutputTypeToCircles()
        text = str(source)
        self.assertIn("vtkBoostedSurfaceSource", text)
        for expected in ("CircleCenter: (0, 0, 0)", "CircleNormal: (1, 0, 0)", "CircleRadius: 1",
                         "BoostDirection: (1, 0, 0)", "BoostAtCircleCenter: 1",
                         "LambdaRange: [0, 2]", "ClipRadius: 20", "OutputType: CIRCLES"):
            self.assertIn(expected, text)

    def test_horn_example_is_finite_and_narrows_toward_the_fixed_point(self):
        import fig3_horn  # Examples/fig3_horn.py: only its pipeline is used, nothing is rendered

        source = fig3_horn.horn()
        source.Update()
        output = source.GetOutput()
        self.assertEqual(output.GetNumberOfPoints(),
                         (source.GetLambdaResolution() + 1) * (source.GetThetaResolution() + 1))
        tip = fig3_horn.LOCATION
        profile = []  # (x, radius) of each image circle, in the order of k
        for lam, samples in sorted(points_by_lambda(output).items()):
            radii = []
            for _, p in samples:
                self.assertTrue(all(math.isfinite(c) for c in p))
                self.assertTrue(tip < p[0] <= 1e-12, "between the fixed point and the base circle")
                radii.append(math.hypot(p[1], p[2]))
            # each image is a circle around the axis, in the plane x = p[0]
            self.assertAlmostEqual(min(radii), max(radii), delta=TOLERANCE)
            self.assertAlmostEqual(min(x for _, (x, _, _) in samples),
                                   max(x for _, (x, _, _) in samples), delta=TOLERANCE)
            profile.append((samples[0][1][0], radii[0]))
        # A horn: the circles move toward the tip and shrink ...
        for (x0, r0), (x1, r1) in zip(profile, profile[1:]):
            self.assertLess(x1, x0)
            self.assertLess(r1, r0)
        # ... along a meridian r(x) that bends away from the axis (r'' > 0: the slope grows with
        # x): with the circles bending around the axis, the Gaussian curvature is negative.
        profile.sort()
        for (x0, r0), (x1, r1), (x2, r2) in zip(profile, profile[1:], profile[2:]):
            self.assertGreater((r2 - r1) / (x2 - x1), (r1 - r0) / (x1 - x0))
        normals = output.GetPointData().GetNormals()
        for i in range(normals.GetNumberOfTuples()):
            self.assertTrue(all(math.isfinite(c) for c in normals.GetTuple3(i)))


if __name__ == "__main__":
    unittest.main()
