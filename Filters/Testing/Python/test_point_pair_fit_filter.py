"""Tests of the Python-wrapped vtkPointPairFitFilter: known weights of mixed kinds recovered from
their deformation of a sphere (made by vtkPointPairDeformationFilter), a fit chained into the next
one and into the deformation filter through the Generators ports, the point-to-surface fit of
Examples/fit_generators.py (the figures the README states), the summary in field data and
PrintSelf, and errors Python can see. Plain Python, no numpy.

    PYTHONPATH=<build>/lib/python3.11/site-packages python3 test_point_pair_fit_filter.py -v
"""
import math
import os
import sys
import unittest

from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkSphereSource

from boostedsurfaces import vtkPointPairDeformationFilter, vtkPointPairFitFilter

import python_test_common as common

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "Examples"))
import fit_generators  # noqa: E402

# (x, y, z, vx, vy, vz, weight, kind, pitch): a point pair, a twist and a translation.
TRUTH = [(0.0, 0.0, 1.5, 0.0, 0.0, 1.0, 0.3, vtkPointPairFitFilter.POINT_PAIR, 0.0),
         (1.4, 0.2, 0.0, 0.0, 0.0, 1.0, -0.4, vtkPointPairFitFilter.TWIST, 0.2),
         (0.0, -1.5, 0.0, 1.0, 0.0, 0.0, 0.2, vtkPointPairFitFilter.TRANSLATION, 0.0)]


def sphere():
    source = vtkSphereSource()
    source.SetRadius(1.0)
    source.SetThetaResolution(20)
    source.SetPhiResolution(12)
    source.SetOutputPointsPrecision(vtkSphereSource.DOUBLE_PRECISION)
    source.Update()
    return source


def deformation_of(source, rows):
    deformation = vtkPointPairDeformationFilter()
    deformation.SetInputConnection(source.GetOutputPort())
    for row in rows:
        deformation.AddGenerator(*row)
    deformation.Update()
    return deformation


def field_value(data, name):
    return data.GetFieldData().GetAbstractArray(name).GetValue(0)


class PointPairFitFilterTest(unittest.TestCase):
    def fit(self, source, target, rows):
        fit = vtkPointPairFitFilter()
        fit.SetInputConnection(source.GetOutputPort())
        fit.SetTargetConnection(target.GetOutputPort())
        for row in rows:
            fit.AddGenerator(*row)
        return fit

    def test_known_weights_of_every_kind_are_recovered(self):
        source = sphere()
        target = deformation_of(source, TRUTH)
        fit = self.fit(source, target, [row[:6] + (0.0,) + row[7:] for row in TRUTH])
        errors = common.ErrorRecorder(fit)
        fit.Update()
        self.assertEqual(errors.messages + errors.warnings, [])
        table = fit.GetOutputDataObject(2)
        self.assertEqual(table.GetNumberOfRows(), 3)
        for i, row in enumerate(TRUTH):
            self.assertAlmostEqual(table.GetValueByName(i, "Weight").ToDouble(), row[6], delta=1e-6)
            self.assertEqual(table.GetValueByName(i, "Kind").ToDouble(), row[7])
            self.assertEqual(table.GetValueByName(i, "Pitch").ToDouble(), row[8])
        self.assertLessEqual(fit.GetFinalRMS(), 1e-10)
        residual = fit.GetOutput().GetPointData().GetArray("FitResidual")
        self.assertLessEqual(residual.GetRange()[1], 1e-10)
        output = fit.GetOutput()
        self.assertEqual(field_value(output, "FitFinalRMS"), fit.GetFinalRMS())
        self.assertEqual(field_value(output, "FitIterations"), fit.GetNumberOfIterations())
        self.assertTrue(field_value(output, "FitTermination").startswith("CONVERGENCE"))
        text = str(fit)
        self.assertIn("Last fit: %d iterations" % fit.GetNumberOfIterations(), text)
        self.assertIn("TargetMode: POINT_TO_POINT", text)

    def test_generators_output_feeds_the_deformation_filter_and_the_next_fit(self):
        source = sphere()
        target = deformation_of(source, TRUTH[:1])
        fit = self.fit(source, target, [TRUTH[0][:6] + (0.0, 0, 0)])
        fit.Update()
        # The deformation filter fed by the fit's Generators port gives the fit's mesh.
        again = vtkPointPairDeformationFilter()
        again.SetInputConnection(source.GetOutputPort())
        again.SetGeneratorsConnection(fit.GetOutputPort(1))
        again.UseGeneratorWeightArrayOn()
        again.Update()
        ours, theirs = fit.GetOutput(), again.GetOutput()
        self.assertEqual([ours.GetPoint(i) for i in range(ours.GetNumberOfPoints())],
                         [theirs.GetPoint(i) for i in range(theirs.GetNumberOfPoints())])
        # A fit started from the first one's Generators port is already at its minimum.
        chained = vtkPointPairFitFilter()
        chained.SetInputConnection(source.GetOutputPort())
        chained.SetTargetConnection(target.GetOutputPort())
        chained.SetGeneratorsConnection(fit.GetOutputPort(1))
        chained.UseGeneratorWeightArrayOn()
        chained.Update()
        self.assertAlmostEqual(chained.GetOutputDataObject(2).GetValueByName(0, "Weight")
                               .ToDouble(), TRUTH[0][6], delta=1e-6)
        self.assertLessEqual(chained.GetInitialRMS(), 1e-10)

    def test_kinds_and_pitches_through_the_wrapping(self):
        # From rotations of zero weight and pitch, FitKinds and FitPitches find TRUTH's point
        # pair, twist (with its pitch) and translation.
        source = sphere()
        target = deformation_of(source, TRUTH)
        fit = self.fit(source, target, [row[:6] + (0.0, vtkPointPairFitFilter.ROTATION, 0.0)
                                        for row in TRUTH])
        fit.FitKindsOn()
        fit.FitPitchesOn()
        errors = common.ErrorRecorder(fit)
        fit.Update()
        self.assertEqual(errors.messages + errors.warnings, [])
        table = fit.GetOutputDataObject(2)
        for i, row in enumerate(TRUTH):
            self.assertEqual(table.GetValueByName(i, "Kind").ToDouble(), row[7])
            self.assertAlmostEqual(table.GetValueByName(i, "Weight").ToDouble(), row[6], delta=1e-6)
            self.assertAlmostEqual(table.GetValueByName(i, "Pitch").ToDouble(), row[8], delta=1e-6)
        self.assertLessEqual(fit.GetFinalRMS(), 1e-10)
        self.assertEqual(fit.GetNumberOfUnidentifiedKinds(), 0)
        identified = fit.GetOutputDataObject(1).GetPointData().GetArray("KindIdentified")
        self.assertEqual([identified.GetValue(i) for i in range(3)], [1, 1, 1])
        self.assertIn("(%d fits, 0 kinds unidentified)" % fit.GetNumberOfFits(), str(fit))

    def test_point_to_surface_fit_of_the_example(self):
        target = fit_generators.bumped_target()
        fit = fit_generators.fit_filter(target)
        fit.Update()
        before, after = fit.GetInitialRMS(), fit.GetFinalRMS()
        print("\nExamples/fit_generators.py: RMS distance %.4f -> %.5f (%.1f %% less), %d "
              "iterations" % (before, after, 100 * (1 - after / before),
                              fit.GetNumberOfIterations()))
        self.assertGreater(before, 0.05)
        self.assertLessEqual(after, 0.1 * before)

    def test_errors_python_can_see(self):
        source = sphere()
        cloud = vtkPolyData()
        points = vtkPoints()
        points.InsertNextPoint(0, 0, 0)
        cloud.SetPoints(points)
        fit = vtkPointPairFitFilter()
        fit.SetInputConnection(source.GetOutputPort())
        fit.SetTargetData(cloud)
        fit.AddGenerator(0, 0, 1.5, 0, 0, 1, 0.0)
        errors = common.ErrorRecorder(fit)
        fit.Update()
        self.assertEqual(len(errors.messages), 1)
        self.assertIn("POINT_TO_POINT needs a target with the mesh's points", errors.messages[0])
        self.assertEqual(fit.GetOutput().GetNumberOfPoints(), 0)
        self.assertTrue(math.isnan(fit.GetFinalRMS()))


if __name__ == "__main__":
    unittest.main()
