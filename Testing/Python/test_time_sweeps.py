"""NumberOfTimeSteps and MergeSeam from Python, for every class that has them: the time steps
reported, the first and the last frame equal to the static outputs (the sweep's start and the
current parameters) point for point, and merged Hopf tori without boundary edges."""
import unittest
from collections import Counter

from boostedsurfaces import (vtkBoostedSurfaceSource, vtkConformalOrbitSource,
                             vtkCurvaturePatchSource, vtkDipoleFieldSource,
                             vtkHopfFibrationSource, vtkPointPairDeformationFilter)
from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkFiltersSources import vtkSphereSource


def points(data, array=None):
    if array:
        values = data.GetPointData().GetArray(array)
        return [values.GetTuple(i) for i in range(data.GetNumberOfPoints())]
    return [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]


def boundary_edges(mesh):
    uses = Counter()
    polys = mesh.GetPolys()
    polys.InitTraversal()

    ids = vtkIdList()
    while polys.GetNextCell(ids):
        n = ids.GetNumberOfIds()
        for k in range(n):
            a, b = ids.GetId(k), ids.GetId((k + 1) % n)
            uses[(min(a, b), max(a, b))] += 1
    return sum(1 for count in uses.values() if count == 1)


class TimeSweeps(unittest.TestCase):
    def check(self, make, start, array=None):
        """make(): a configured static algorithm; start(algorithm): sets the sweep's start."""
        timed = make()
        timed.SetNumberOfTimeSteps(4)
        timed.UpdateInformation()
        info = timed.GetOutputInformation(0)
        key = vtkStreamingDemandDrivenPipeline.TIME_STEPS()
        self.assertEqual([info.Get(key, i) for i in range(info.Length(key))],
                         [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0])
        first, last = make(), make()
        start(first)
        for algorithm in (first, last):
            algorithm.Update()
        timed.UpdateTimeStep(0.0)
        self.assertEqual(points(timed.GetOutput(), array), points(first.GetOutput(), array))
        self.assertGreater(len(points(first.GetOutput(), array)), 0)
        timed.UpdateTimeStep(1.0)
        self.assertEqual(points(timed.GetOutput(), array), points(last.GetOutput(), array))
        self.assertEqual(timed.GetOutput().GetNumberOfCells(), last.GetOutput().GetNumberOfCells())
        timed.UpdateTimeStep(0.5)
        self.assertNotEqual(points(timed.GetOutput(), array), points(last.GetOutput(), array))

    def test_boosted_surface(self):
        def make():
            source = vtkBoostedSurfaceSource()
            source.SetLambdaRange(0.5, 3.0)
            source.SetLambdaResolution(8)
            source.SetThetaResolution(12)
            return source
        self.check(make, lambda s: s.SetLambdaRange(0.5, 0.5))

    def test_hopf_fibration(self):
        def make():
            source = vtkHopfFibrationSource()
            source.SetPhiRange(-1.0, 1.2)
            return source
        self.check(make, lambda s: s.SetPhiRange(-1.0, -1.0))

    def test_curvature_patch(self):
        def make():
            source = vtkCurvaturePatchSource()
            source.SetUResolution(8)
            source.SetVResolution(8)
            return source
        def start(source):
            source.SetKappaU(0.0)
            source.SetKappaV(0.0)
        self.check(make, start)

    def test_dipole_field(self):
        def start(source):
            source.SetGenerator(0, 0, 0, 0, 1, 0, 0, 0.0)
        self.check(vtkDipoleFieldSource, start, "DisplacementSummedGenerators")

    def test_conformal_orbit(self):
        def make():
            source = vtkConformalOrbitSource()
            source.SetTResolution(48)
            return source
        def start(source):
            source.SetClosePeriodicOrbits(False)
            source.SetTRange(0.0, 0.0)
        self.check(make, start)
        # The trefoil closes only when the sweep reaches its period: open arcs before.
        timed = make()
        timed.SetNumberOfTimeSteps(4)
        for time, closed in ((1.0 / 3.0, False), (2.0 / 3.0, False), (1.0, True)):
            timed.UpdateTimeStep(time)
            lines = timed.GetOutput().GetLines()
            self.assertEqual(lines.GetNumberOfCells(), 1)
            ids = vtkIdList()
            lines.InitTraversal()
            lines.GetNextCell(ids)
            self.assertEqual(ids.GetNumberOfIds(), 49)
            self.assertEqual(ids.GetId(0) == ids.GetId(48), closed, "time %g" % time)

    def test_deformation_filter(self):
        sphere = vtkSphereSource()
        def make():
            deformation = vtkPointPairDeformationFilter()
            deformation.SetInputConnection(sphere.GetOutputPort())
            deformation.AddGenerator(0, 0, 0.7, 0, 0, 1, 0.5)
            deformation.SetStrength(2.0)
            return deformation
        self.check(make, lambda f: f.SetStrength(0.0))

    def test_the_filter_keeps_its_inputs_time_steps_unless_it_has_its_own(self):
        source = vtkBoostedSurfaceSource()
        source.SetNumberOfTimeSteps(3)
        deformation = vtkPointPairDeformationFilter()
        deformation.SetInputConnection(source.GetOutputPort())
        key = vtkStreamingDemandDrivenPipeline.TIME_STEPS()
        for steps, expected in ((0, 3), (5, 5)):
            deformation.SetNumberOfTimeSteps(steps)
            deformation.UpdateInformation()
            self.assertEqual(deformation.GetOutputInformation(0).Length(key), expected)
        # its time reaches the input too: at t = 0 the input is the first circle, undeformed
        deformation.AddGenerator(0, 0, 0.7, 0, 0, 1, 0.5)
        deformation.UpdateTimeStep(0.0)
        first = vtkBoostedSurfaceSource()
        first.SetLambdaRange(0.0, 0.0)
        first.Update()
        self.assertEqual(points(deformation.GetOutput()), points(first.GetOutput()))


class MergedSeams(unittest.TestCase):
    def test_hopf_tori_are_closed(self):
        source = vtkHopfFibrationSource()
        source.SetOutputTypeToTwistorMesh()
        source.SetMeshSweepToLatitudes()
        source.SetThetaResolution(12)
        source.SetPhiRange(-1.0, 0.5)
        source.SetPhiResolution(2)
        source.SetFiberResolution(16)
        source.SetClipRadius(1e6)
        source.Update()
        self.assertEqual(boundary_edges(source.GetOutput()), 2 * (2 * 12 + 2 * 16))
        self.assertIsNotNone(source.GetOutput().GetPointData().GetTCoords())
        source.MergeSeamOn()
        source.Update()
        self.assertEqual(boundary_edges(source.GetOutput()), 0)
        self.assertEqual(source.GetOutput().GetNumberOfPoints(), 2 * 12 * 16)
        self.assertIsNone(source.GetOutput().GetPointData().GetTCoords())


if __name__ == "__main__":
    unittest.main()
