"""The filter's Tolerance (the generator tree, docs/conventions.md section 3 item 14) from Python:
0 is the default and the direct sum; a tolerance moves the images by little and not at all below
the tree's crossover; the normals through the derivative come from the tree too; NaN or negative
is an error and an empty output; a huge one is the cap.
Plain Python, no numpy.

    PYTHONPATH=<build>/lib/python3.11/site-packages python3 test_point_pair_deformation_tolerance.py -v
"""
import math
import random
import unittest

from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkFiltersSources import vtkPlaneSource

from boostedsurfaces import vtkPointPairDeformationFilter

import python_test_common as common

# cga::PointPairField::treeMinimumGenerators(): fewer generators always sum directly.
TREE_FROM = 10000


def generator_cloud(count, seed=20261202):
    """count point pairs over the plane's square, weights scaled so that B stays moderate."""
    rng = random.Random(seed)
    data = vtkPolyData()
    points = vtkPoints()
    points.SetDataTypeToDouble()
    directions = vtkDoubleArray()
    directions.SetName("Direction")
    directions.SetNumberOfComponents(3)
    for _ in range(count):
        points.InsertNextPoint(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-0.3, 0.3))
        directions.InsertNextTuple3(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
    data.SetPoints(points)
    data.GetPointData().AddArray(directions)
    return data


def square_plane(resolution=40):
    plane = vtkPlaneSource()
    plane.SetOrigin(-2, -2, 0)
    plane.SetPoint1(2, -2, 0)
    plane.SetPoint2(-2, 2, 0)
    plane.SetResolution(resolution, resolution)
    plane.Update()
    return plane


def output_points(algorithm):
    output = algorithm.GetOutput()
    return [output.GetPoint(i) for i in range(output.GetNumberOfPoints())]


class ToleranceTest(unittest.TestCase):
    def deform(self, generators, tolerance=None, transform_normals=True):
        plane = square_plane()
        deformation = vtkPointPairDeformationFilter()
        deformation.SetInputConnection(plane.GetOutputPort())
        deformation.SetGeneratorsData(generators)
        deformation.SetStrength(16.0 / generators.GetNumberOfPoints())
        deformation.SetEpsilon(0.05)
        if tolerance is not None:
            deformation.SetTolerance(tolerance)
        deformation.SetTransformNormals(transform_normals)
        self.events = common.ErrorRecorder(deformation)
        deformation.Update()
        output = deformation.GetOutput()
        normals = output.GetPointData().GetNormals()
        count = normals.GetNumberOfTuples() if normals else 0
        self.normals = [normals.GetTuple3(i) for i in range(count)]
        source = plane.GetOutput()
        images = [output.GetPoint(i) for i in range(output.GetNumberOfPoints())]
        originals = [source.GetPoint(i) for i in range(source.GetNumberOfPoints())]
        return images, originals

    def test_default_is_the_direct_sum(self):
        self.assertEqual(vtkPointPairDeformationFilter().GetTolerance(), 0.0)
        # At the tree's crossover (below it every tolerance sums directly, so the comparison would
        # hold whatever the default): the default's images are those of Tolerance 0 to the bit,
        # and not those of the tree, which moves them here.
        generators = generator_cloud(TREE_FROM)
        default = self.deform(generators)[0]
        self.assertEqual(default, self.deform(generators, 0.0)[0])
        self.assertNotEqual(default, self.deform(generators, 1e-3)[0])

    def test_a_tolerance_approximates_closely(self):
        generators = generator_cloud(TREE_FROM)
        exact, originals = self.deform(generators, 0.0)
        approximate, _ = self.deform(generators, 1e-3)
        self.assertEqual(len(approximate), len(exact))
        # common.largest, not max(): max() drops a NaN, which would then pass both checks below
        largest_displacement = common.largest(math.dist(e, p) for e, p in zip(exact, originals))
        largest_error = common.largest(math.dist(a, e) for a, e in zip(approximate, exact))
        self.assertGreater(largest_displacement, 0.01)
        self.assertGreater(largest_error, 0.0)  # the tree was used
        # The core tests check the a-priori bound (the first-order image error within t times the
        # field's displacement scale); here the images, measured: well below.
        self.assertLess(largest_error, 1e-3 * largest_displacement)

    def test_derivatives_come_from_the_tree(self):
        # The batch map with Jacobians differentiates the tree's approximation of B: its images are
        # the tree's, so transforming the plane's normals changes no image, and the normals come
        # within a small angle of the direct sum's (measured: the bound of Tolerance is on images).
        generators = generator_cloud(TREE_FROM)
        with_normals, _ = self.deform(generators, 1e-3)
        tree_normals = self.normals
        without, _ = self.deform(generators, 1e-3, transform_normals=False)
        self.assertEqual(self.normals, [])
        self.assertEqual(with_normals, without)
        exact, _ = self.deform(generators, 0.0)
        self.assertNotEqual(with_normals, exact)  # the tree was used
        self.assertEqual(len(tree_normals), len(exact))
        def angle_between(n, m):
            cosine = sum(a * b for a, b in zip(n, m)) / (math.hypot(*n) * math.hypot(*m))
            return math.acos(max(-1.0, min(1.0, cosine)))

        angle = common.largest(angle_between(n, m) for n, m in zip(tree_normals, self.normals))
        # 1.1e-5 rad measured: the tree's J, not the direct sum's (the float normals round at 6e-8)
        self.assertGreater(angle, 1e-6)
        self.assertLess(angle, 1e-3)

    def test_the_tree_is_built_again_only_when_it_changes(self):
        # One filter updated after each change keeps its last tree for the next update while the
        # generators, Falloff, Epsilon and Tolerance stay the same; the progress text tells when it
        # builds one. Every output is a new filter's to the bit, so a kept tree is never stale.
        generators = generator_cloud(TREE_FROM)
        plane = square_plane()
        kept = vtkPointPairDeformationFilter()
        kept.SetInputConnection(plane.GetOutputPort())
        kept.SetGeneratorsData(generators)
        texts = []
        kept.AddObserver("ProgressEvent",
                         lambda caller, event: texts.append(caller.GetProgressText()))
        settings = {"Strength": 16.0 / TREE_FROM, "Falloff": 1.0, "Epsilon": 0.05,
                    "Tolerance": 1e-3}

        def builds_tree(**changes):
            settings.update(changes)
            for name, value in settings.items():
                getattr(kept, "Set" + name)(value)
            del texts[:]
            kept.Update()
            self.assertTrue(texts, "the filter executed")
            fresh = vtkPointPairDeformationFilter()
            fresh.SetInputConnection(plane.GetOutputPort())
            fresh.SetGeneratorsData(generators)
            for name, value in settings.items():
                getattr(fresh, "Set" + name)(value)
            fresh.Update()
            self.assertEqual(output_points(kept), output_points(fresh), changes)
            self.assertGreater(len(output_points(kept)), 0)
            return common.BUILDING_TREE in texts

        self.assertTrue(builds_tree())
        self.assertFalse(builds_tree(Strength=8.0 / TREE_FROM))
        self.assertFalse(builds_tree(Strength=-16.0 / TREE_FROM))
        self.assertTrue(builds_tree(Epsilon=0.06))
        self.assertTrue(builds_tree(Falloff=1.5))
        self.assertTrue(builds_tree(Tolerance=2e-3))
        plane.SetResolution(30, 20)  # another input mesh
        self.assertFalse(builds_tree())
        generators.GetPoints().SetPoint(5, 0.5, -0.25, 0.1)  # a generator moved
        generators.Modified()
        self.assertTrue(builds_tree())
        self.assertFalse(builds_tree(Tolerance=0.0))  # the direct sum: no tree
        self.assertTrue(builds_tree(Tolerance=2e-3))  # none was kept
        self.assertFalse(builds_tree(Strength=4.0 / TREE_FROM))

    def test_few_generators_sum_directly(self):
        generators = generator_cloud(TREE_FROM - 1)
        self.assertEqual(self.deform(generators, 0.0)[0], self.deform(generators, 1e-2)[0])

    def test_huge_tolerance_is_the_cap(self):
        generators = generator_cloud(TREE_FROM)
        self.assertEqual(self.deform(generators, 1e300)[0], self.deform(generators, 1.0)[0])
        self.assertEqual(self.events.messages, [])

    def test_nan_or_negative_tolerance_is_an_error(self):
        generators = generator_cloud(300)
        for bad in (float("nan"), -1e-3):
            images, _ = self.deform(generators, bad)
            self.assertEqual(images, [])
            self.assertEqual(len(self.events.messages), 1)
            self.assertIn("Tolerance", self.events.messages[0])


if __name__ == "__main__":
    unittest.main()
