"""The "Generators" output port of every class with generators (vtkBoostedGeneratorGlyphs): one
vertex per generator at its location, with "Direction", "Weight" and, where they apply, "Kind",
"Pitch" and "Curvature", each value against the parameters that were set; the port is empty after
an error, comes only with piece 0, follows the time sweep, and feeds vtkGlyph3D and the filter's
Generators input.

    PYTHONPATH=<build>/lib/python3.11/site-packages:Testing/Support python3 test_generator_ports.py -v
"""
import math
import unittest

from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkFiltersCore import vtkGlyph3D
from vtkmodules.vtkFiltersSources import vtkArrowSource, vtkPlaneSource

from boostedsurfaces import (vtkConformalOrbitSource, vtkCurvaturePatchSource,
                             vtkDipoleFieldSource, vtkHopfFibrationSource,
                             vtkPointPairDeformationFilter)

import python_test_common as common

SDDP = vtkStreamingDemandDrivenPipeline


def table(port):
    """The port's rows: [(point, {array name: tuple})], and the number of vertex cells."""
    rows = []
    data = port.GetPointData()
    for i in range(port.GetNumberOfPoints()):
        values = {}
        for a in range(data.GetNumberOfArrays()):
            array = data.GetArray(a)
            values[array.GetName()] = array.GetTuple(i)
        rows.append((port.GetPoint(i), values))
    return rows, port.GetNumberOfVerts()


def piece_counts(algorithm, pieces=2):
    """The Generators port's points when each of `pieces` pieces is requested in turn."""
    port = algorithm.GetNumberOfOutputPorts() - 1
    counts = []
    for piece in range(pieces):
        algorithm.UpdatePiece(piece, pieces, 0)
        counts.append(algorithm.GetOutputDataObject(port).GetNumberOfPoints())
    return counts


def generators_port(algorithm):
    port = algorithm.GetNumberOfOutputPorts() - 1
    algorithm.Update(port)
    output = algorithm.GetOutputDataObject(port)
    assert isinstance(output, vtkPolyData)
    return output


class GeneratorPortsTest(unittest.TestCase):
    def assertRow(self, row, point, direction, weight, **others):
        self.assertEqual(len(row[0]), 3)
        for c in range(3):
            self.assertAlmostEqual(row[0][c], point[c], places=12)
            self.assertAlmostEqual(row[1]["Direction"][c], direction[c], places=12)
        self.assertAlmostEqual(row[1]["Weight"][0], weight, places=12)
        for name, value in others.items():
            self.assertEqual(len(row[1][name]), len(value), name)
            for got, expected in zip(row[1][name], value):
                self.assertAlmostEqual(got, expected, places=12, msg=name)

    def test_filter_lists_rows_handle_and_input_generators(self):
        deformation = vtkPointPairDeformationFilter()
        plane = vtkPlaneSource()
        deformation.SetInputConnection(plane.GetOutputPort())
        deformation.AddGenerator(1, 2, 3, 0, 0, 1, 0.5)                 # a point pair
        deformation.AddGenerator(-1, 0, 0, 1, 0, 0, 0.25, 2, 0.75)      # a twist
        deformation.SetSelectedGenerator(1)
        deformation.SetSelectedGeneratorLocation(4, 5, 6)
        extra = vtkPolyData()
        from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
        points = vtkPoints()
        points.InsertNextPoint(7, 8, 9)
        extra.SetPoints(points)
        directions = vtkDoubleArray()
        directions.SetName("Direction")
        directions.SetNumberOfComponents(3)
        directions.InsertNextTuple3(0, 2, 0)
        extra.GetPointData().AddArray(directions)
        deformation.SetGeneratorsData(extra)
        self.assertEqual(deformation.GetNumberOfOutputPorts(), 2)
        rows, vertices = table(generators_port(deformation))
        self.assertEqual((len(rows), vertices), (3, 3))
        self.assertRow(rows[0], (1, 2, 3), (0, 0, 1), 0.5, Kind=(0,), Pitch=(0,))
        self.assertRow(rows[1], (4, 5, 6), (1, 0, 0), 0.25, Kind=(2,), Pitch=(0.75,))
        self.assertRow(rows[2], (7, 8, 9), (0, 2, 0), 1.0, Kind=(0,), Pitch=(0,))
        # Port 0 is still the deformed plane.
        self.assertEqual(deformation.GetOutputDataObject(0).GetNumberOfPoints(), 4)
        # The port is in the Generators input's format: fed back, it gives the same field.
        again = vtkPointPairDeformationFilter()
        again.SetInputConnection(plane.GetOutputPort())
        again.SetGeneratorsConnection(deformation.GetOutputPort(1))
        again.SetUseGeneratorWeightArray(True)
        again.Update()
        for i in range(4):
            for c in range(3):
                self.assertAlmostEqual(again.GetOutput().GetPoint(i)[c],
                                       deformation.GetOutputDataObject(0).GetPoint(i)[c], places=12)

    def test_filter_aims_the_selected_generator(self):
        plane = vtkPlaneSource()
        aimed = vtkPointPairDeformationFilter()
        aimed.SetInputConnection(plane.GetOutputPort())
        aimed.AddGenerator(9, 9, 9, 0, 0, 1, 0.5, 1, 0)  # a rotation, aimed below
        aimed.SetSelectedGenerator(0)
        aimed.SetSelectedGeneratorLocation(0.2, 0.1, 0.3)
        aimed.SetSelectedGeneratorTip(0.2, 2.1, 0.3)
        rows, _ = table(generators_port(aimed))
        self.assertRow(rows[0], (0.2, 0.1, 0.3), (0, 0, 1), 0.5, Kind=(1,))  # not aimed yet
        aimed.AimSelectedGeneratorOn()
        rows, _ = table(generators_port(aimed))
        self.assertRow(rows[0], (0.2, 0.1, 0.3), (0, 2, 0), 0.5, Kind=(1,), Pitch=(0,))
        # The same field as the row written out with that location and direction.
        written = vtkPointPairDeformationFilter()
        written.SetInputConnection(plane.GetOutputPort())
        written.AddGenerator(0.2, 0.1, 0.3, 0, 2, 0, 0.5, 1, 0)
        written.Update()
        for i in range(4):
            self.assertEqual(aimed.GetOutputDataObject(0).GetPoint(i),
                             written.GetOutput().GetPoint(i))
        self.assertNotEqual(written.GetOutput().GetPoint(0), plane.GetOutput().GetPoint(0))

    def test_filter_port_is_empty_after_an_error(self):
        deformation = vtkPointPairDeformationFilter()
        plane = vtkPlaneSource()  # kept: the connection does not hold its algorithm
        deformation.SetInputConnection(plane.GetOutputPort())
        deformation.AddGenerator(0, 0, 0, 0, 0, 1, 1.0, 7, 0)  # no such kind
        recorder = common.ErrorRecorder(deformation)
        port = generators_port(deformation)
        self.assertTrue(recorder.messages)
        self.assertEqual(port.GetNumberOfPoints(), 0)

    def test_dipole_rows_moved_and_weighted_by_time(self):
        source = vtkDipoleFieldSource()
        source.RemoveAllGenerators()
        source.AddGenerator(0.5, 0, 0, 0, 1, 0, 0.6)
        source.AddGenerator(-0.5, 0, 0, 0, 0, 1, 0.2, 1, 0)
        source.SetGeneratorsTranslation(0, 0, 2)
        source.SetNumberOfTimeSteps(5)
        port_index = source.GetNumberOfOutputPorts() - 1
        self.assertEqual(port_index, 1)
        source.UpdateTimeStep(0.5)
        rows, vertices = table(source.GetOutputDataObject(1))
        self.assertEqual((len(rows), vertices), (2, 2))
        self.assertRow(rows[0], (0.5, 0, 2), (0, 1, 0), 0.3, Kind=(0,), Pitch=(0,))
        self.assertRow(rows[1], (-0.5, 0, 2), (0, 0, 1), 0.1, Kind=(1,), Pitch=(0,))
        self.assertEqual(source.GetOutputDataObject(0).GetNumberOfPoints(), 21 * 21)

    def test_dipole_generators_come_with_piece_zero_only(self):
        self.assertEqual(piece_counts(vtkDipoleFieldSource()), [1, 0])

    def test_curvature_patch_each_method(self):
        patch = vtkCurvaturePatchSource()
        patch.SetOrigin(1, 2, 3)
        patch.SetSize(4, 2)
        patch.SetKappaU(0.3)
        patch.SetKappaV(-0.2)
        rows, _ = table(generators_port(patch))  # TRANSLATED_TANGENTS
        self.assertEqual(len(rows), 1)
        self.assertRow(rows[0], (1, 2, 3), (0, 0, 1), 1.0, Curvature=(0.3, -0.2))
        self.assertNotIn("Kind", rows[0][1])
        patch.SetMethod(patch.BENT_LINE)
        rows, _ = table(generators_port(patch))
        self.assertRow(rows[0], (1, 2, 3), (0, 0, 1), 1.0, Curvature=(0.3, 0.0))

        patch.SetMethod(patch.BILINEAR)
        patch.SetCorner2Direction(0, 2, 0)
        patch.SetCornerWeights(0.1, 0.2, 0.3, 0.4)
        rows, _ = table(generators_port(patch))
        self.assertEqual(len(rows), 4)
        corners = [(-1, 1), (3, 1), (-1, 3), (3, 3)]
        for i, (x, y) in enumerate(corners):
            direction = (0, 2, 0) if i == 1 else (0, 0, 1)
            self.assertRow(rows[i], (x, y, 3), direction, 0.1 * (i + 1), Curvature=(0, 0))
        patch.SetMethod(patch.LINEAR)
        rows, _ = table(generators_port(patch))
        self.assertEqual(len(rows), 2)
        self.assertRow(rows[0], (-1, 2, 3), (0, 0, 1), 0.1, Curvature=(0, 0))
        self.assertRow(rows[1], (3, 2, 3), (0, 2, 0), 0.2, Curvature=(0, 0))

        patch.SetMethod(patch.CONTROL_POINTS)
        patch.AddControlPoint(0, 0, 0, 0, 0, 2, 1, 0, 0, 0.5, 0.25)
        patch.AddControlPoint(1, 1, 0, 0, 3, 0, 1, 0, 0, -0.5, 0.0)
        patch.SetSelectedControlPoint(1)
        patch.SetSelectedControlPointLocation(2, 2, 2)
        patch.SetNumberOfTimeSteps(3)
        patch.UpdateTimeStep(0.5)
        rows, _ = table(patch.GetOutputDataObject(1))
        self.assertEqual(len(rows), 2)
        self.assertRow(rows[0], (0, 0, 0), (0, 0, 1), 1.0, Curvature=(0.25, 0.125))
        self.assertRow(rows[1], (2, 2, 2), (0, 1, 0), 1.0, Curvature=(-0.25, 0.0))

    def test_curvature_patch_port_is_empty_after_an_error(self):
        patch = vtkCurvaturePatchSource()
        patch.SetMethod(patch.CONTROL_POINTS)  # without control points: an error
        recorder = common.ErrorRecorder(patch)
        self.assertEqual(generators_port(patch).GetNumberOfPoints(), 0)
        self.assertTrue(recorder.messages)

    def test_hopf_base_points(self):
        hopf = vtkHopfFibrationSource()
        hopf.SetSamplingModeToBasePoints()
        hopf.SetCircleCenter(1, 0, 0)
        hopf.SetCircleRadius(2)
        hopf.AddBasePoint(0.0, 0.0)
        hopf.AddBasePoint(math.pi / 2, math.pi / 4)
        rows, vertices = table(generators_port(hopf))
        self.assertEqual((len(rows), vertices), (2, 2))
        # theta = 0 points along C's frame vector a = orthogonalUnit(z), whatever it is: check the
        # geometry instead of the frame: on the base sphere, v_theta horizontal and unit, k.
        for (point, values), (theta, phi) in zip(rows, [(0.0, 0.0), (math.pi / 2, math.pi / 4)]):
            radial = [point[0] - 1, point[1], point[2]]
            self.assertAlmostEqual(math.sqrt(sum(x * x for x in radial)), 2.0, places=12)
            self.assertAlmostEqual(radial[2], 2 * math.sin(phi), places=12)
            direction = values["Direction"]
            self.assertAlmostEqual(math.sqrt(sum(x * x for x in direction)), 1.0, places=12)
            self.assertAlmostEqual(direction[2], 0.0, places=12)
            # v_theta is the horizontal direction of the base point: parallel to radial's.
            horizontal = math.hypot(radial[0], radial[1])
            self.assertAlmostEqual(direction[0] * horizontal, radial[0], places=12)
            self.assertAlmostEqual(direction[1] * horizontal, radial[1], places=12)
            self.assertAlmostEqual(values["Weight"][0], 0.5 + phi / math.pi, places=12)
        # The points follow FiberId: base point 1 is the second fiber.
        self.assertAlmostEqual(rows[1][0][2], 2 * math.sin(math.pi / 4), places=12)

    def test_hopf_grid_has_one_point_per_fiber(self):
        hopf = vtkHopfFibrationSource()
        rows, vertices = table(generators_port(hopf))
        self.assertEqual((len(rows), vertices), (8 * 9, 8 * 9))

    def test_orbit_generator_list_and_torus_knot(self):
        orbit = vtkConformalOrbitSource()
        self.assertEqual(orbit.GetNumberOfOutputPorts(), 3)
        rows, _ = table(generators_port(orbit))  # TORUS_KNOT (2, 3), radius 1
        self.assertEqual(len(rows), 2)
        r = 1 / math.sqrt(2)
        self.assertRow(rows[0], (-r, 0, 0), (0, 0, 1), math.pi / 2)
        self.assertRow(rows[1], (r, 0, 0), (0, 1, 0), math.pi / 3)
        orbit.SetGeneratorTypeToGeneratorList()
        orbit.AddGenerator(0, 0, 1, 0, 0, 1, 1.0, 1, 0)
        orbit.AddGenerator(1, 1, 1, 0, 1, 0, 0.5, 2, 0.1)
        rows, _ = table(generators_port(orbit))
        self.assertEqual(len(rows), 2)
        self.assertRow(rows[0], (0, 0, 1), (0, 0, 1), 1.0, Kind=(1,), Pitch=(0,))
        self.assertRow(rows[1], (1, 1, 1), (0, 1, 0), 0.5, Kind=(2,), Pitch=(0.1,))
        # Ports 0 and 1 stay the orbits and the cores.
        self.assertGreater(orbit.GetOutputDataObject(0).GetNumberOfPoints(), 0)
        self.assertGreater(orbit.GetOutputDataObject(1).GetNumberOfPoints(), 0)
        self.assertEqual(piece_counts(orbit), [2, 0])

    def test_glyph3d_draws_one_arrow_per_generator(self):
        source = vtkDipoleFieldSource()
        source.RemoveAllGenerators()
        source.AddGenerator(0, 0, 0, 1, 0, 0, 0.5)
        source.AddGenerator(1, 0, 0, 0, 1, 0, 0.5)
        arrow = vtkArrowSource()
        arrow.Update()
        glyphs = vtkGlyph3D()
        glyphs.SetInputConnection(source.GetOutputPort(1))
        glyphs.SetSourceConnection(arrow.GetOutputPort())
        glyphs.OrientOn()
        glyphs.SetVectorModeToUseVector()
        glyphs.Update()
        self.assertEqual(glyphs.GetOutput().GetNumberOfPoints(),
                         2 * arrow.GetOutput().GetNumberOfPoints())
        # The second arrow points along y and is scaled by its Weight (the active scalars): its
        # tip is at y = 0.5.
        bounds = glyphs.GetOutput().GetBounds()
        self.assertAlmostEqual(bounds[3], 0.5, places=6)


if __name__ == "__main__":
    unittest.main()
