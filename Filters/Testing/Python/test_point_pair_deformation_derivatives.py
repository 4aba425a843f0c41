"""The filter's normals from the map's derivative against the mesh: vtkPolyDataNormals on a finely
tessellated deformed sphere (an independent estimate from the deformed triangles alone), its
convergence under refinement, and the array selections from Python.

    PYTHONPATH=<build>/lib/python3.11/site-packages python3 test_point_pair_deformation_derivatives.py -v
"""
import unittest

import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import vtkSphereSource

from boostedsurfaces import vtkPointPairDeformationFilter

import python_test_common as common

# Away from the poles of vtkSphereSource's latitude-longitude mesh, where its triangles fan out
# around one point (a tessellation singularity: the mesh estimate there is first order only).
POLE_CAP = 0.99


def deformed_sphere(resolution, rule):
    """The unit sphere (radius 1) of resolution x resolution (double points, exact unit normals) under a point
    pair, a rotation and a twist, and vtkPolyDataNormals of the result (no splitting)."""
    sphere = vtkSphereSource()
    sphere.SetThetaResolution(resolution)
    sphere.SetPhiResolution(resolution)
    sphere.SetRadius(1.0)
    sphere.SetOutputPointsPrecision(vtkSphereSource.DOUBLE_PRECISION)
    deformation = vtkPointPairDeformationFilter()
    deformation.SetInputConnection(sphere.GetOutputPort())
    deformation.AddGenerator(0, 0, 0.7, 0, 0, 1, 0.5)
    deformation.AddGenerator(0.5, 0.3, 0, 1, 0, 0, 0.4, vtkPointPairDeformationFilter.ROTATION, 0)
    deformation.AddGenerator(-0.4, 0.2, 0.1, 0, 1, 1, 0.3, vtkPointPairDeformationFilter.TWIST, 0.2)
    deformation.SetFalloff(4.0)
    deformation.SetEpsilon(0.1)
    deformation.SetExponentialRule(rule)
    mesh = vtkPolyDataNormals()
    mesh.SetInputConnection(deformation.GetOutputPort())
    mesh.SplittingOff()
    mesh.ConsistencyOff()
    mesh.Update()
    sphere_points = vtk_to_numpy(sphere.GetOutput().GetPoints().GetData())
    exact = vtk_to_numpy(deformation.GetOutput().GetPointData().GetNormals()).astype(float)
    estimated = vtk_to_numpy(mesh.GetOutput().GetPointData().GetNormals()).astype(float)
    angles = numpy.arctan2(numpy.linalg.norm(numpy.cross(exact, estimated), axis=1),
                           (exact * estimated).sum(axis=1))
    away = numpy.abs(sphere_points[:, 2]) <= POLE_CAP
    displacement = vtk_to_numpy(deformation.GetOutput().GetPointData().GetArray("Displacement"))
    return angles[away].max(), angles.max(), numpy.linalg.norm(displacement, axis=1).max()


class DerivativesTest(unittest.TestCase):
    def test_normals_match_the_deformed_mesh(self):
        for rule in (vtkPointPairDeformationFilter.EXACT, vtkPointPairDeformationFilter.PAPER):
            coarse, _, _ = deformed_sphere(128, rule)
            fine, everywhere, moved = deformed_sphere(256, rule)
            print("rule %d: largest displacement %.3f; largest angle to vtkPolyDataNormals away "
                  "from the poles %.2e rad at 128 x 128, %.2e at 256 x 256 (ratio %.2f), %.2e "
                  "with the poles" % (rule, moved, coarse, fine, coarse / fine, everywhere))
            self.assertGreater(moved, 0.2)  # a real deformation
            self.assertLessEqual(fine, 1e-3)
            # The difference is the mesh estimate's second-order error: it falls four-fold when
            # the spacing halves (a wrong normal would not converge to it).
            self.assertGreater(coarse / fine, 3.5)

    def test_selections_from_python(self):
        sphere = vtkSphereSource()
        sphere.Update()
        data = sphere.GetOutput()
        velocity = vtkDoubleArray()
        velocity.SetName("Velocity")
        velocity.SetNumberOfComponents(3)
        for _ in range(data.GetNumberOfPoints()):
            velocity.InsertNextTuple3(1.0, 0.0, 0.0)
        data.GetPointData().AddArray(velocity)
        deformation = vtkPointPairDeformationFilter()
        events = common.ErrorRecorder(deformation)
        deformation.SetInputData(data)
        deformation.AddGenerator(0, 0, 0.7, 0, 0, 1, 0.5)
        self.assertTrue(deformation.GetTransformNormals())
        deformation.Update()
        self.assertEqual(deformation.GetOutput().GetPointData().GetArray("Velocity").GetTuple3(5),
                         (1.0, 0.0, 0.0))  # not selected: passed
        deformation.GetVectorArraySelection().EnableArray("Velocity")
        deformation.ComputeConformalScaleOn()
        deformation.Update()  # the selection's change re-executes the filter
        output = deformation.GetOutput().GetPointData()
        self.assertNotEqual(output.GetArray("Velocity").GetTuple3(5), (1.0, 0.0, 0.0))
        self.assertIsNotNone(output.GetArray("ConformalScale"))
        self.assertEqual(events.messages, [])
        deformation.GetVectorArraySelection().EnableArray("Missing")
        deformation.Update()
        self.assertEqual(len(events.warnings), 1)
        self.assertIn("no point array named 'Missing'", events.warnings[0])


if __name__ == "__main__":
    unittest.main()
