"""The memory budget (Common/vtkBoostedMemoryBudget.h) in every class: an update whose estimate
exceeds BOOSTEDSURFACES_MEMORY_BUDGET is one error and an empty output, allocating nothing; an
invalid budget is an error, not a crash; and an allocation that fails under an address-space limit
(the budget raised out of the way) is an error and an empty output, not an abort of the process.

    PYTHONPATH=<build>/lib/python3.11/site-packages:Testing/Support python3 test_memory_budget.py -v
"""
import os
import subprocess
import sys
import unittest

from vtkmodules.vtkCommonDataModel import vtkImageData, vtkRectilinearGrid, vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource

from boostedsurfaces import (vtkBoostedSurfaceSource, vtkConformalOrbitSource, vtkCurvaturePatchSource,
                             vtkDipoleFieldSource, vtkHopfFibrationSource,
                             vtkPointPairDeformationFilter, vtkPointPairFitFilter)

import python_test_common as common

BUDGET = "BOOSTEDSURFACES_MEMORY_BUDGET"


def sphere_filter():
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(64)
    sphere.SetPhiResolution(64)
    deform = vtkPointPairDeformationFilter()
    deform.SetInputConnection(sphere.GetOutputPort())
    deform.AddGenerator(0, 0, 0, 1, 0, 0, 0.5)
    return deform


def image_filter():
    image = vtkImageData()
    image.SetDimensions(64, 64, 2)
    deform = vtkPointPairDeformationFilter()
    deform.SetInputData(image)
    deform.AddGenerator(0, 0, 0, 1, 0, 0, 0.5)
    return deform


def hopf_mesh():
    hopf = vtkHopfFibrationSource()
    hopf.SetOutputTypeToTwistorMesh()
    return hopf


def fit_filter():
    # The target is VTK's (a filter of the package upstream would be refused by the budget too,
    # and the fit would only see an empty target): a larger sphere of the same points.
    sphere = vtkSphereSource()
    target = vtkSphereSource()
    target.SetRadius(0.55)
    fit = vtkPointPairFitFilter()
    fit.SetInputConnection(sphere.GetOutputPort())
    fit.SetTargetConnection(target.GetOutputPort())
    fit.AddGenerator(0, 0, 0.3, 0, 0, 1, 0.1)
    return fit


# Each class at its defaults (a few thousand samples: well above 1 KiB, far below any default).
ALGORITHMS = {
    "BoostedSurface": vtkBoostedSurfaceSource,
    "BoostedSurfaceCircles": lambda: (lambda s: (s.SetOutputTypeToCircles(), s)[1])(vtkBoostedSurfaceSource()),
    "CurvaturePatch": vtkCurvaturePatchSource,
    "HopfFibers": vtkHopfFibrationSource,
    "HopfTwistorMesh": hopf_mesh,
    "DipoleField": vtkDipoleFieldSource,
    "ConformalOrbit": vtkConformalOrbitSource,
    "DeformationPolyData": sphere_filter,
    "DeformationImage": image_filter,
    "Fit": fit_filter,
}


def point_count(algorithm):
    algorithm.Update()
    return algorithm.GetOutputDataObject(0).GetNumberOfPoints()


class MemoryBudgetTest(unittest.TestCase):
    def tearDown(self):
        os.environ.pop(BUDGET, None)

    def test_beyond_the_budget_is_one_error_and_an_empty_output(self):
        for name, make in ALGORITHMS.items():
            with self.subTest(name):
                algorithm = make()
                errors = common.ErrorRecorder(algorithm).messages
                os.environ[BUDGET] = "1K"
                self.assertEqual(point_count(algorithm), 0)
                self.assertEqual(len(errors), 1, errors)
                self.assertIn("more than the memory budget of 1.0 KiB", errors[0])
                self.assertIn(BUDGET, errors[0])
                # The same update within the (default) budget: the refusal was the budget's.
                del os.environ[BUDGET]
                algorithm.Modified()
                self.assertGreater(point_count(algorithm), 0)
                self.assertEqual(len(errors), 1, errors)

    def test_an_invalid_budget_is_an_error_and_an_empty_output(self):
        for value in ["banana", " ", "-5", "0", "12X", "5KK", "nan", "inf", "1e400", "GB"]:
            for name, make in ALGORITHMS.items():
                with self.subTest(value=value, algorithm=name):
                    algorithm = make()
                    errors = common.ErrorRecorder(algorithm).messages
                    os.environ[BUDGET] = value
                    self.assertEqual(point_count(algorithm), 0)
                    self.assertEqual(len(errors), 1, errors)
                    self.assertIn(BUDGET + " is '" + value + "'", errors[0])

    def test_an_empty_budget_is_the_default(self):
        for name, make in ALGORITHMS.items():
            with self.subTest(name):
                algorithm = make()
                errors = common.ErrorRecorder(algorithm).messages
                os.environ[BUDGET] = ""
                self.assertGreater(point_count(algorithm), 0)
                self.assertEqual(errors, [])

    def test_sizes_with_units(self):
        # Just above and just below a source's estimate: the hopf mesh's default grid is 72 x 129
        # samples at 265 bytes (about 2.35 MiB).
        for value, accepted in [("2M", False), ("3M", True), ("3 MiB", True), ("2.4mb", True),
                                ("2000000", False), ("3e6", True), ("1g", True), ("1T", True)]:
            with self.subTest(value):
                algorithm = hopf_mesh()
                errors = common.ErrorRecorder(algorithm).messages
                os.environ[BUDGET] = value
                self.assertEqual(point_count(algorithm) > 0, accepted, errors)
                self.assertEqual(len(errors), 0 if accepted else 1, errors)

    def test_a_huge_image_is_refused_before_its_conversion(self):
        # 1e10 points: its explicit copy alone would need 240 GB; nothing is allocated.
        for data in (vtkImageData(), vtkRectilinearGrid()):
            with self.subTest(data.GetClassName()):
                if isinstance(data, vtkImageData):
                    data.SetExtent(0, 99999, 0, 99999, 0, 0)
                else:
                    data.SetDimensions(100000, 100000, 1)
                deform = vtkPointPairDeformationFilter()
                deform.SetInputData(data)
                deform.AddGenerator(0, 0, 0, 1, 0, 0, 0.5)
                errors = common.ErrorRecorder(deform).messages
                self.assertEqual(point_count(deform), 0)
                self.assertEqual(len(errors), 1, errors)
                self.assertIn("deforming 10000000000 points of a " + data.GetClassName(), errors[0])

    def test_a_failed_allocation_is_an_error_not_an_abort(self):
        # A child process: the budget is raised out of the way, then the address space is limited
        # to what the process already maps plus 400 MB, and a twistor mesh of 72 x 100001 samples
        # (about 1.6 GB) is asked for. The threads exist before the limit (a small update first).
        child = r"""
import os, resource, sys
os.environ["BOOSTEDSURFACES_MEMORY_BUDGET"] = "1T"
import python_test_common as common
from boostedsurfaces import vtkHopfFibrationSource
hopf = vtkHopfFibrationSource()
hopf.SetOutputTypeToTwistorMesh()
hopf.Update()
assert hopf.GetOutput().GetNumberOfPoints() > 0
errors = common.ErrorRecorder(hopf).messages
with open("/proc/self/status") as status:
    mapped = [int(line.split()[1]) * 1024 for line in status if line.startswith("VmSize")][0]
resource.setrlimit(resource.RLIMIT_AS, (mapped + 400 * 1024 * 1024, resource.RLIM_INFINITY))
hopf.SetFiberResolution(100000)
hopf.Update()
print("points", hopf.GetOutput().GetNumberOfPoints(), "cells", hopf.GetOutput().GetNumberOfCells())
print("errors", len(errors))
print("\n".join(errors))
"""
        result = subprocess.run([sys.executable, "-c", child], capture_output=True, text=True,
                                timeout=300, env=dict(os.environ))
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        self.assertIn("points 0 cells 0", result.stdout)
        self.assertIn("errors 1", result.stdout)
        self.assertIn("which this process cannot allocate now", result.stdout)


if __name__ == "__main__":
    unittest.main()
