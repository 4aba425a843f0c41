"""Tests of the Python-wrapped vtkDipoleFieldSource: the class imports from the package, its
one-generator field is the closed form of docs/conventions.md section 2, errors reach Python, the time steps
scale the weights, and the methods differ for two generators. Plain Python, no numpy.

    PYTHONPATH=<build>/lib/python3.11/site-packages python3 test_dipole_field_source.py -v
"""
import math
import unittest

from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline

from boostedsurfaces import vtkDipoleFieldSource

import python_test_common as common


def closed_form(x, v, w, k, eps, p):
    """One generator: an SCT of weight u = -w v / (k |p - x|^2 + eps) about x, minus p."""
    y = [p[c] - x[c] for c in range(3)]
    y2 = sum(t * t for t in y)
    u = [-w / (k * y2 + eps) * t for t in v]
    denominator = 1.0 + 2.0 * sum(u[c] * y[c] for c in range(3)) + sum(t * t for t in u) * y2
    return [x[c] + (y[c] + u[c] * y2) / denominator - p[c] for c in range(3)]


class DipoleFieldSourceTest(unittest.TestCase):
    def test_one_generator_is_the_closed_form_for_both_methods(self):
        source = vtkDipoleFieldSource()
        source.RemoveAllGenerators()
        source.AddGenerator(0.25, 0.1, 0.0, 0.0, 1.0, 0.0, 0.6)
        source.SetDimensions(9, 7, 3)
        source.SetOrigin(-1.0, -1.0, -0.2)
        source.SetSpacing(0.25, 0.3, 0.2)
        source.Update()
        output = source.GetOutput()
        self.assertEqual(output.GetNumberOfPoints(), 9 * 7 * 3)
        a = output.GetPointData().GetArray("DisplacementSummedGenerators")
        b = output.GetPointData().GetArray("DisplacementSummedDisplacements")
        for i in range(output.GetNumberOfPoints()):
            expected = closed_form((0.25, 0.1, 0.0), (0.0, 1.0, 0.0), 0.6, 1.0, 0.1,
                                   output.GetPoint(i))
            for c in range(3):
                self.assertAlmostEqual(a.GetComponent(i, c), expected[c], delta=1e-12)
                self.assertEqual(a.GetComponent(i, c), b.GetComponent(i, c))

    def test_two_generators_methods_differ(self):
        source = vtkDipoleFieldSource()
        source.RemoveAllGenerators()
        source.AddGenerator(-1, 0, 0, 0, 1, 0, 0.35)
        source.AddGenerator(1, 0, 0, 1, 0, 0, 0.35)
        self.assertEqual(source.GetNumberOfGenerators(), 2)
        source.Update()
        largest = source.GetOutput().GetPointData().GetArray(
            "DisplacementDifferenceMagnitude").GetRange()[1]
        self.assertGreater(largest, 0.1)

    def test_bad_input_reaches_python_as_an_error(self):
        for setup in (lambda s: s.SetDimensions(0, 5, 1),
                      lambda s: s.SetSpacing(0.1, 0.0, 1.0),
                      lambda s: s.AddGenerator(0, 0, 0, 1, float("nan"), 0, 1)):
            source = vtkDipoleFieldSource()
            errors = common.ErrorRecorder(source)
            setup(source)
            source.Update()
            self.assertEqual(source.GetOutput().GetNumberOfPoints(), 0)
            self.assertEqual(len(errors.messages), 1)

    def test_time_steps_scale_the_weights(self):
        source = vtkDipoleFieldSource()  # one generator of weight 0.5
        source.SetNumberOfTimeSteps(3)
        source.UpdateInformation()
        info = source.GetOutputInformation(0)
        times = [info.Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS(), i) for i in range(3)]
        self.assertEqual(times, [0.0, 0.5, 1.0])
        source.UpdateTimeStep(0.5)
        half = source.GetOutput()
        p = half.GetPoint(7)
        expected = closed_form((0, 0, 0), (1, 0, 0), 0.25, 1.0, 0.1, p)
        got = half.GetPointData().GetArray("DisplacementSummedGenerators").GetTuple3(7)
        for c in range(3):
            self.assertAlmostEqual(got[c], expected[c], delta=1e-12)
        self.assertGreater(math.sqrt(sum(t * t for t in got)), 0.01)

    def test_tolerance_approximates_method_a_only(self):
        """Tolerance (the generator tree of method a): 0 by default; a tolerance moves method a's
        displacements by little, leaves method b's bit for bit; a negative one is an error."""
        import random
        rng = random.Random(5)
        arrays = {}
        for tolerance in (0.0, 1e-3, -1.0):
            source = vtkDipoleFieldSource()
            events = common.ErrorRecorder(source)
            source.RemoveAllGenerators()
            for _ in range(10000):  # the tree's crossover (treeMinimumGenerators)
                source.AddGenerator(rng.uniform(-2, 2), rng.uniform(-2, 2), 0.0,
                                    rng.uniform(-1, 1), rng.uniform(-1, 1), 0.0, 1e-4)
            rng.seed(5)
            self.assertEqual(source.GetTolerance(), 0.0)
            source.SetTolerance(tolerance)
            source.SetDimensions(5, 5, 1)
            source.Update()
            output = source.GetOutput()
            if tolerance < 0:
                self.assertEqual(output.GetNumberOfPoints(), 0)
                self.assertEqual(len(events.messages), 1)
                continue
            arrays[tolerance] = [
                [output.GetPointData().GetArray(name).GetTuple3(i)
                 for i in range(output.GetNumberOfPoints())]
                for name in ("DisplacementSummedGenerators", "DisplacementSummedDisplacements")]
        exact, approximate = arrays[0.0], arrays[1e-3]
        self.assertEqual(exact[1], approximate[1])
        # common.largest, not max(): max() drops a NaN, which would then pass the checks below
        largest = common.largest(math.dist(e, (0, 0, 0)) for e in exact[0])
        error = common.largest(math.dist(a, e) for a, e in zip(approximate[0], exact[0]))
        self.assertGreater(largest, 0.01)
        self.assertGreater(error, 0.0)
        self.assertLess(error, 1e-3 * largest)


if __name__ == "__main__":
    unittest.main()
