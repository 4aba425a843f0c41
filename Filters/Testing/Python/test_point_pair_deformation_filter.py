"""Tests of the Python-wrapped vtkPointPairDeformationFilter: one generator against the closed form
of docs/conventions.md section 2, the Generators input from a Python pipeline, SOA point arrays (the AOS result
bit for bit), errors Python can see, and the two exponential rules on the Fig 11 example. Plain
Python, no numpy.

    PYTHONPATH=<build>/lib/python3.11/site-packages python3 test_point_pair_deformation_filter.py -v
"""
import math
import os
import sys
import unittest

from vtkmodules.vtkCommonCore import (vtkDoubleArray, vtkFloatArray, vtkPoints,
                                      vtkSOADataArrayTemplate)
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource

from boostedsurfaces import vtkPointPairDeformationFilter

import python_test_common as common

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "Examples"))


def sct_about(x, u, p):
    """x + SCT_u(p - x) (docs/conventions.md section 2)."""
    y = [p[i] - x[i] for i in range(3)]
    y2 = sum(c * c for c in y)
    uy = sum(u[i] * y[i] for i in range(3))
    u2 = sum(c * c for c in u)
    denominator = 1.0 + 2.0 * uy + u2 * y2
    return [x[i] + (y[i] + u[i] * y2) / denominator for i in range(3)]


def distance(a, b):
    return math.sqrt(sum((a[i] - b[i]) ** 2 for i in range(3)))


def generator_cloud(generators, direction_name="Direction", weight_name="Weight"):
    data = vtkPolyData()
    points = vtkPoints()
    points.SetDataTypeToDouble()
    directions = vtkDoubleArray()
    directions.SetName(direction_name)
    directions.SetNumberOfComponents(3)
    weights = vtkDoubleArray()
    weights.SetName(weight_name)
    for location, direction, weight in generators:
        points.InsertNextPoint(*location)
        directions.InsertNextTuple3(*direction)
        weights.InsertNextValue(weight)
    data.SetPoints(points)
    data.GetPointData().AddArray(directions)
    data.GetPointData().AddArray(weights)
    return data


class PointPairDeformationFilterTest(unittest.TestCase):
    def sphere(self):
        sphere = vtkSphereSource()
        sphere.SetThetaResolution(24)
        sphere.SetPhiResolution(16)
        sphere.Update()
        return sphere

    def test_one_generator_is_the_closed_form(self):
        sphere = self.sphere()
        x, v, w, k, eps = (0.2, -0.1, 0.3), (0.0, 0.6, 0.8), 0.7, 1.5, 0.05
        deformation = vtkPointPairDeformationFilter()
        deformation.SetInputConnection(sphere.GetOutputPort())
        deformation.AddGenerator(*x, *v, w)
        deformation.SetFalloff(k)
        deformation.SetEpsilon(eps)
        deformation.Update()
        output = deformation.GetOutput()
        source = sphere.GetOutput()
        self.assertEqual(output.GetNumberOfCells(), source.GetNumberOfCells())
        for i in range(source.GetNumberOfPoints()):
            p = source.GetPoint(i)
            c = -w / (k * distance(p, x) ** 2 + eps)
            expected = sct_about(x, [c * vi for vi in v], p)
            self.assertLess(distance(output.GetPoint(i), expected), 1e-6)  # float points

    def test_one_generator_of_each_other_kind_is_its_closed_form(self):
        # docs/conventions.md section 2 item 11, c = w |v| / (k |p - x|^2 + eps): a DILATION
        # scales about x by exp(c), a TRANSLATION moves by c along v, a TWIST turns by c about the
        # axis through x along v and advances by pitch * c (here the axis is z: the turn is in xy).
        sphere = self.sphere()
        x, w, k, eps, pitch = (0.2, -0.1, 0.3), 0.7, 1.5, 0.05, 0.4
        v = (0.0, 0.0, 2.0)
        for kind in ("DILATION", "TRANSLATION", "TWIST"):
            with self.subTest(kind=kind):
                deformation = vtkPointPairDeformationFilter()
                deformation.SetInputConnection(sphere.GetOutputPort())
                deformation.AddGenerator(*x, *v, w, getattr(deformation, kind), pitch)
                deformation.SetFalloff(k)
                deformation.SetEpsilon(eps)
                deformation.Update()
                output, source = deformation.GetOutput(), sphere.GetOutput()
                for i in range(source.GetNumberOfPoints()):
                    p = source.GetPoint(i)
                    c = w * 2.0 / (k * distance(p, x) ** 2 + eps)
                    y = [p[j] - x[j] for j in range(3)]
                    if kind == "DILATION":
                        expected = [x[j] + math.exp(c) * y[j] for j in range(3)]
                    elif kind == "TRANSLATION":
                        expected = [p[0], p[1], p[2] + c]
                    else:
                        expected = [x[0] + math.cos(c) * y[0] - math.sin(c) * y[1],
                                    x[1] + math.sin(c) * y[0] + math.cos(c) * y[1],
                                    p[2] + pitch * c]
                    # float points: relative to the image's size (a dilation grows points a lot)
                    self.assertLess(distance(output.GetPoint(i), expected),
                                    1e-6 * (1.0 + distance(expected, (0, 0, 0))))

    def test_generators_port_equals_the_list(self):
        sphere = self.sphere()
        generators = [((0.0, 0.0, 0.8), (0.0, 0.0, 1.0), 0.5),
                      ((0.7, 0.0, 0.0), (0.0, 1.0, 0.0), -0.4)]
        from_list = vtkPointPairDeformationFilter()
        from_list.SetInputConnection(sphere.GetOutputPort())
        for location, direction, weight in generators:
            from_list.AddGenerator(*location, *direction, weight)
        from_port = vtkPointPairDeformationFilter()
        from_port.SetInputConnection(sphere.GetOutputPort())
        from_port.SetGeneratorsData(generator_cloud(generators, "v", "w"))
        from_port.SetGeneratorDirectionArrayName("v")
        from_port.SetGeneratorWeightArrayName("w")
        from_port.UseGeneratorWeightArrayOn()
        from_list.Update()
        from_port.Update()
        for i in range(from_list.GetOutput().GetNumberOfPoints()):
            self.assertEqual(from_list.GetOutput().GetPoint(i), from_port.GetOutput().GetPoint(i))

    def test_missing_generator_array_is_an_error_python_sees(self):
        deformation = vtkPointPairDeformationFilter()
        events = common.ErrorRecorder(deformation)
        sphere = self.sphere()  # kept alive: an output port does not hold its algorithm
        deformation.SetInputConnection(sphere.GetOutputPort())
        deformation.SetGeneratorsData(generator_cloud([((0, 0, 0), (1, 0, 0), 1.0)]))
        deformation.SetGeneratorDirectionArrayName("NoSuchArray")
        deformation.Update()
        self.assertEqual(len(events.messages), 1)
        self.assertEqual(deformation.GetOutput().GetNumberOfPoints(), 0)

    def test_soa_points_give_the_aos_result_bit_for_bit(self):
        sphere = self.sphere().GetOutput()
        for aos, value_type in ((vtkFloatArray, "float32"), (vtkDoubleArray, "float64")):
            outputs = []
            for array in (aos(), vtkSOADataArrayTemplate[value_type]()):
                array.SetNumberOfComponents(3)
                array.SetNumberOfTuples(sphere.GetNumberOfPoints())
                for i in range(sphere.GetNumberOfPoints()):
                    array.SetTuple(i, sphere.GetPoint(i))
                points = vtkPoints()
                points.SetData(array)
                cloud = vtkPolyData()
                cloud.SetPoints(points)
                deformation = vtkPointPairDeformationFilter()
                deformation.SetInputData(cloud)
                deformation.AddGenerator(0.2, -0.1, 0.3, 0.0, 0.6, 0.8, 0.7)
                deformation.Update()
                output = deformation.GetOutput()
                displacement = output.GetPointData().GetArray("Displacement")
                outputs.append([(output.GetPoint(i), displacement.GetTuple3(i))
                                for i in range(output.GetNumberOfPoints())])
            self.assertEqual(len(outputs[0]), sphere.GetNumberOfPoints())
            self.assertEqual(outputs[0], outputs[1], value_type)

    def test_short_generator_array_is_an_error_python_sees(self):
        deformation = vtkPointPairDeformationFilter()
        events = common.ErrorRecorder(deformation)
        sphere = self.sphere()
        deformation.SetInputConnection(sphere.GetOutputPort())
        generators = generator_cloud([((0, 0, 0), (1, 0, 0), 1.0), ((1, 0, 0), (0, 1, 0), 0.5)])
        generators.GetPointData().GetArray("Direction").SetNumberOfTuples(1)
        deformation.SetGeneratorsData(generators)
        deformation.Update()
        self.assertEqual(len(events.messages), 1)
        self.assertIn("has 1 tuples for 2 points", events.messages[0])
        self.assertEqual(deformation.GetOutput().GetNumberOfPoints(), 0)

    def test_zero_direction_is_a_warning(self):
        deformation = vtkPointPairDeformationFilter()
        events = common.ErrorRecorder(deformation)
        source = self.sphere()
        deformation.SetInputConnection(source.GetOutputPort())
        deformation.AddGenerator(0, 0, 0, 0, 0, 0, 1.0)
        deformation.Update()
        self.assertEqual((len(events.messages), len(events.warnings)), (0, 1))
        sphere = source.GetOutput()
        for i in range(sphere.GetNumberOfPoints()):  # nothing left: the identity
            self.assertEqual(deformation.GetOutput().GetPoint(i), sphere.GetPoint(i))

    def test_rules_differ_on_the_fig11_plane(self):
        import fig11_deformation as fig11
        plane = vtkPlaneSource()
        plane.SetOrigin(-2, -2, 0)
        plane.SetPoint1(2, -2, 0)
        plane.SetPoint2(-2, 2, 0)
        plane.SetResolution(60, 60)
        outputs = []
        for rule in (vtkPointPairDeformationFilter.EXACT, vtkPointPairDeformationFilter.PAPER):
            deformation = vtkPointPairDeformationFilter()
            deformation.SetInputConnection(plane.GetOutputPort())
            for location, direction, weight in fig11.PLANE_GENERATORS:
                deformation.AddGenerator(*location, *direction, weight)
            deformation.SetFalloff(fig11.FALLOFF)
            deformation.SetEpsilon(fig11.EPSILON)
            deformation.SetExponentialRule(rule)
            deformation.Update()
            outputs.append(deformation.GetOutput())
        largest = common.largest(distance(outputs[0].GetPoint(i), outputs[1].GetPoint(i))
                                 for i in range(outputs[0].GetNumberOfPoints()))  # keeps a NaN
        print("Fig 11 plane: Exact and Paper differ by up to %.3g" % largest)
        # Several generators at different places: B is not a blade, the rules must differ.
        self.assertGreater(largest, 1e-3)


if __name__ == "__main__":
    unittest.main()
