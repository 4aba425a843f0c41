"""Tests of the Python-wrapped vtkHopfFibrationSource: it imports from the package, errors reach
Python, the base points can be given from Python and from an input of sphere points, and the Fig 5
example's preset is the twistor mesh the README documents. Plain Python, no numpy.

    PYTHONPATH=<build>/lib/python3.11/site-packages python3 test_hopf_fibration_source.py -v
"""
import math
import os
import sys
import unittest

from vtkmodules.vtkFiltersSources import vtkSphereSource

from boostedsurfaces import vtkHopfFibrationSource

import python_test_common as common

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "Examples"))


def fiber_ids(output):
    ids = output.GetPointData().GetArray("FiberId")
    return sorted({int(ids.GetValue(i)) for i in range(output.GetNumberOfPoints())})


class HopfFibrationSourceTest(unittest.TestCase):
    def test_zero_resolution_gives_an_error_in_python_and_an_empty_output(self):
        source = vtkHopfFibrationSource()
        errors = common.ErrorRecorder(source).messages
        source.SetPhiResolution(0)
        source.Update()
        self.assertEqual(len(errors), 1)
        self.assertIn("PhiResolution", errors[0])
        self.assertEqual(source.GetOutput().GetNumberOfPoints(), 0)
        source.SetPhiResolution(3)
        source.Update()
        self.assertEqual(fiber_ids(source.GetOutput()), list(range(8 * 3)))

    def test_base_points_from_python(self):
        source = vtkHopfFibrationSource()
        source.SetSamplingModeToBasePoints()
        source.AddBasePoint(0.5, -0.25)
        source.AddBasePoint(2.0, 0.75)
        source.Update()
        output = source.GetOutput()
        self.assertEqual(fiber_ids(output), [0, 1])
        phis = {round(output.GetPointData().GetArray("phi").GetValue(i), 12)
                for i in range(output.GetNumberOfPoints())}
        self.assertEqual(phis, {-0.25, 0.75})

    def test_sphere_points_input(self):
        sphere = vtkSphereSource()
        sphere.SetCenter(1, 2, 3)
        sphere.SetThetaResolution(5)
        sphere.SetPhiResolution(4)
        sphere.Update()
        source = vtkHopfFibrationSource()
        source.SetInputConnection(sphere.GetOutputPort())
        source.SetSphereCenter(1, 2, 3)
        source.SetSamplingModeToInputPoints()
        source.Update()
        output = source.GetOutput()
        self.assertEqual(len(fiber_ids(output)), sphere.GetOutput().GetNumberOfPoints())
        # The sphere's poles are the base sphere's poles.
        phis = [output.GetPointData().GetArray("phi").GetValue(i)
                for i in range(output.GetNumberOfPoints())]
        self.assertAlmostEqual(max(phis), math.pi / 2, places=6)
        self.assertAlmostEqual(min(phis), -math.pi / 2, places=6)

    def test_fig5_preset_is_six_meridian_strips(self):
        import fig5_hopf_fibration  # only its pipeline is used, nothing is rendered

        source = fig5_hopf_fibration.fig5_source()
        source.Update()
        output = source.GetOutput()
        strips = output.GetPointData().GetArray("StripId")
        self.assertEqual({int(strips.GetValue(i)) for i in range(output.GetNumberOfPoints())},
                         set(range(6)))
        self.assertGreater(output.GetNumberOfPolys(), 0)
        self.assertIsNotNone(output.GetPointData().GetNormals())

    def test_print_self(self):
        text = str(vtkHopfFibrationSource())
        for expected in ("Mode: PAPER", "CircleNormal: (0, 0, 1)", "ThetaResolution: 8",
                         "PhiResolution: 9", "FiberResolution: 128", "ClipRadius: 10",
                         "OutputType: FIBERS"):
            self.assertIn(expected, text)


if __name__ == "__main__":
    unittest.main()
