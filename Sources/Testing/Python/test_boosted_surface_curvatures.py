"""vtkBoostedSurfaceSource's exact Normals and ComputeCurvatures arrays against closed forms.

A boost along the circle's axis makes a surface of revolution: every circle point moves on a
circle through the boost's location x0, tangent to the axis, of diameter |q|^2 / |q_perp|
(q = p - x0): a horn torus about x0 whose tube radius r equals the distance of the tube's center
from the axis (docs/conventions.md section 6). Plain Python, no numpy.

    PYTHONPATH=<build>/lib/python3.11/site-packages python3 test_boosted_surface_curvatures.py -v
"""
import math
import statistics
import unittest

from vtkmodules.vtkCommonCore import vtkIdList
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersGeneral import vtkCurvatures

from boostedsurfaces import vtkBoostedSurfaceSource

import python_test_common as common

TOLERANCE = 1e-9
ARRAYS = {"PrincipalCurvatures": 2, "PrincipalDirections": 6, "GaussianCurvature": 1,
          "MeanCurvature": 1}


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def sub(a, b):
    return [x - y for x, y in zip(a, b)]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def norm(a):
    return math.sqrt(dot(a, a))


def unit(a):
    length = norm(a)
    return [x / length for x in a]


def horn_torus(p, center, axis, r):
    """(outward normal, K, H with the outward normal, k_meridian, k_parallel) of the horn torus
    about `center` along the unit `axis` with tube radius r, at its point p."""
    offset = sub(p, center)
    radial = sub(offset, [dot(offset, axis) * a for a in axis])
    rho = norm(radial)
    tube_center = [c + r / rho * x for c, x in zip(center, radial)]
    outward = [x / r for x in sub(p, tube_center)]
    cos_v = (rho - r) / r
    return outward, cos_v / (r * rho), 0.5 * (1.0 / r + cos_v / rho), 1.0 / r, cos_v / rho


def fig2_source(resolution=32, lambda_range=(-1.0, 1.0)):
    """Fig 2 moved and turned: the circle's axis along a general direction, the boost on it."""
    source = vtkBoostedSurfaceSource()
    source.SetCircleCenter(0.3, -1.0, 2.0)
    source.SetCircleNormal(1.0, 2.0, -0.5)
    source.SetCircleRadius(1.7)
    source.SetBoostDirection(0.8, 1.6, -0.4)
    source.SetLambdaRange(*lambda_range)
    source.SetLambdaResolution(resolution)
    source.SetThetaResolution(resolution)
    source.SetComputeCurvatures(True)
    return source


FIG2_AXIS = unit([1.0, 2.0, -0.5])
FIG2_CENTER = [0.3, -1.0, 2.0]
FIG2_TUBE = 0.5 * 1.7


class BoostedSurfaceCurvaturesTest(unittest.TestCase):
    def check_horn_torus(self, output, center, axis, r, tolerance=TOLERANCE, points=None):
        data = output.GetPointData()
        normals = data.GetNormals()
        k = data.GetArray("PrincipalCurvatures")
        d = data.GetArray("PrincipalDirections")
        gaussian = data.GetArray("GaussianCurvature")
        mean = data.GetArray("MeanCurvature")
        ids = range(output.GetNumberOfPoints()) if points is None else points
        for i in ids:
            p = output.GetPoint(i)
            outward, big_k, big_h, meridian, parallel = horn_torus(p, center, axis, r)
            n = normals.GetTuple3(i)
            # Float normals: exact to single precision.
            self.assertLess(norm(cross(n, outward)), 1e-6, i)
            side = 1.0 if dot(n, outward) > 0 else -1.0
            k1, k2 = k.GetTuple2(i)
            expected = sorted([side * meridian, side * parallel], reverse=True)
            self.assertAlmostEqual(k1, expected[0], delta=tolerance)
            self.assertAlmostEqual(k2, expected[1], delta=tolerance)
            self.assertAlmostEqual(gaussian.GetValue(i), big_k, delta=tolerance)
            self.assertAlmostEqual(mean.GetValue(i), side * big_h, delta=tolerance)
            directions = d.GetTuple(i)
            d1, d2 = directions[:3], directions[3:]
            self.assertAlmostEqual(norm(d1), 1.0, delta=1e-12)
            self.assertAlmostEqual(norm(d2), 1.0, delta=1e-12)
            self.assertAlmostEqual(dot(d1, d2), 0.0, delta=1e-12)
            self.assertAlmostEqual(dot(d1, n), 0.0, delta=1e-6)

    def test_off_by_default_and_the_option_only_adds_arrays(self):
        plain = vtkBoostedSurfaceSource()
        self.assertFalse(plain.GetComputeCurvatures())
        plain.Update()
        for name in ARRAYS:
            self.assertIsNone(plain.GetOutput().GetPointData().GetArray(name))
        with_arrays = vtkBoostedSurfaceSource()
        with_arrays.ComputeCurvaturesOn()
        with_arrays.Update()
        a, b = plain.GetOutput(), with_arrays.GetOutput()
        self.assertEqual(a.GetNumberOfPoints(), b.GetNumberOfPoints())
        self.assertEqual(a.GetNumberOfCells(), b.GetNumberOfCells())
        for i in range(a.GetNumberOfPoints()):
            self.assertEqual(a.GetPoint(i), b.GetPoint(i))
            self.assertEqual(a.GetPointData().GetNormals().GetTuple3(i),
                             b.GetPointData().GetNormals().GetTuple3(i))
        for name, components in ARRAYS.items():
            array = b.GetPointData().GetArray(name)
            self.assertIsNotNone(array, name)
            self.assertEqual(array.GetNumberOfComponents(), components)
            self.assertEqual(array.GetNumberOfTuples(), b.GetNumberOfPoints())
        # Circles: no surface, no curvature arrays.
        with_arrays.SetOutputTypeToCircles()
        with_arrays.Update()
        for name in ARRAYS:
            self.assertIsNone(with_arrays.GetOutput().GetPointData().GetArray(name))

    def test_boost_along_the_axis_at_the_center_gives_a_horn_torus(self):
        source = fig2_source()
        source.Update()
        self.check_horn_torus(source.GetOutput(), FIG2_CENTER, FIG2_AXIS, FIG2_TUBE)

    def test_horn_of_fig3_is_a_horn_torus_about_the_boost_location(self):
        source = vtkBoostedSurfaceSource()
        source.BoostAtCircleCenterOff()
        source.SetBoostLocation(-1.5, 0.0, 0.0)
        source.SetBoostDirection(0.7, 0.0, 0.0)
        source.SetLambdaRange(-0.8, 2.0)
        source.SetComputeCurvatures(True)
        source.Update()
        self.check_horn_torus(source.GetOutput(), [-1.5, 0.0, 0.0], [1.0, 0.0, 0.0],
                              (1.5 ** 2 + 1.0) / 2.0)

    def test_exact_normals_are_more_exact_than_the_central_differences(self):
        # The central differences the grid gave before (and still gives at degenerate samples),
        # from the same output's grid, against the closed form. Measured: at 32 x 32 the
        # differences are off by up to 2.5e-3 rad, the exact normals by 1e-7 (float rounding).
        resolution = 32
        source = fig2_source(resolution)
        source.Update()
        output = source.GetOutput()
        data = output.GetPointData()
        lam, theta = data.GetArray("lambda"), data.GetArray("theta")
        grid = {}
        for i in range(output.GetNumberOfPoints()):
            row = round((lam.GetValue(i) + 1.0) / 2.0 * resolution)
            column = round(theta.GetValue(i) / (2.0 * math.pi) * resolution)
            grid[(row, column)] = i
        exact_error = difference_error = 0.0  # folded by common.largest: max() would drop a NaN
        for (row, column), i in grid.items():
            outward = horn_torus(output.GetPoint(i), FIG2_CENTER, FIG2_AXIS, FIG2_TUBE)[0]
            exact_error = common.largest(
                [exact_error, norm(cross(data.GetNormals().GetTuple3(i), outward))])
            if 0 < row < resolution:
                c = column % resolution
                along_theta = unit(sub(output.GetPoint(grid[(row, (c + 1) % resolution)]),
                                       output.GetPoint(grid[(row, (c - 1) % resolution)])))
                along_lambda = unit(sub(output.GetPoint(grid[(row + 1, column)]),
                                        output.GetPoint(grid[(row - 1, column)])))
                difference = unit(cross(along_theta, along_lambda))
                difference_error = common.largest(
                    [difference_error, norm(cross(difference, outward))])
        self.assertLess(exact_error, 1e-6)
        self.assertGreater(difference_error, 1e-3)

    def test_arrays_survive_the_cut_at_the_clip_sphere(self):
        # The horn torus reaches 2 r = 1.7 from the circle's center: a clip sphere of radius 1.2
        # cuts it. Kept points keep their exact values; points made by the cut have them
        # interpolated along a grid edge, with unit directions (measured largest error of k2 and
        # K there: 7.9e-2, 2.5e-2, 2.9e-3, 1.2e-3 at 32, 64, 128, 256 steps; the normals'
        # 5e-8, float rounding).
        source = fig2_source(64, (-3.0, 3.0))
        source.SetClipRadius(1.2)
        source.Update()
        output = source.GetOutput()
        data = output.GetPointData()
        cut, kept = [], []
        for i in range(output.GetNumberOfPoints()):
            distance = norm(sub(output.GetPoint(i), FIG2_CENTER))
            (cut if abs(distance - 1.2) < 1e-9 else kept).append(i)
        self.assertGreater(len(cut), 100)
        self.check_horn_torus(output, FIG2_CENTER, FIG2_AXIS, FIG2_TUBE, points=kept)
        self.check_horn_torus(output, FIG2_CENTER, FIG2_AXIS, FIG2_TUBE, tolerance=0.03, points=cut)

    def test_merged_seam_keeps_the_exact_arrays(self):
        source = fig2_source()
        source.SetMergeSeam(True)
        source.Update()
        output = source.GetOutput()
        self.assertEqual(output.GetNumberOfPoints(), 33 * 32)  # the seam column shared
        self.check_horn_torus(output, FIG2_CENTER, FIG2_AXIS, FIG2_TUBE)

    def test_a_fixed_point_on_the_circle_is_degenerate_with_zero_curvatures(self):
        # The boost located on the circle leaves that point where it is for every lambda:
        # x_lambda = 0 there, so the curvatures are not defined: zeros and zero directions, and
        # the normal of the grid's differences. Nothing is NaN.
        probe = vtkBoostedSurfaceSource()
        probe.SetLambdaRange(0.0, 0.0)
        probe.SetOutputTypeToCircles()
        probe.Update()
        theta = probe.GetOutput().GetPointData().GetArray("theta")
        first = [i for i in range(probe.GetOutput().GetNumberOfPoints()) if theta.GetValue(i) == 0]
        fixed = probe.GetOutput().GetPoint(first[0])
        source = vtkBoostedSurfaceSource()
        source.BoostAtCircleCenterOff()
        source.SetBoostLocation(*fixed)
        source.SetComputeCurvatures(True)
        source.Update()
        output = source.GetOutput()
        data = output.GetPointData()
        degenerate = 0
        for i in range(output.GetNumberOfPoints()):
            values = []
            for name in ARRAYS:
                values += list(data.GetArray(name).GetTuple(i))
            self.assertTrue(all(math.isfinite(v) for v in values), i)
            self.assertAlmostEqual(norm(data.GetNormals().GetTuple3(i)), 1.0, delta=1e-6)
            if norm(sub(output.GetPoint(i), fixed)) < 1e-12:
                degenerate += 1
                self.assertEqual(values, [0.0] * 10)
            else:
                d = data.GetArray("PrincipalDirections").GetTuple(i)
                self.assertAlmostEqual(norm(d[:3]), 1.0, delta=1e-12)
        self.assertEqual(degenerate, 2 * 65)  # theta = 0 and its seam copy, every row

    def test_vtk_curvatures_on_the_mesh_converges_to_the_arrays(self):
        # vtkCurvatures on the surface split into triangles along one diagonal of every quad
        # (every vertex of valence 6): the median error of K and H over |lambda| <= 0.5 falls by
        # 4 per halving of the step (measured: K 4.8e-2, 1.2e-2, 3.0e-3, 7.6e-4 at 16 ... 128,
        # H 1.7e-2, 4.5e-3, 1.2e-3, 3.2e-4). vtkTriangleFilter's own diagonals vary from quad to
        # quad, and there vtkCurvatures does not converge (median error in K 6.6e-2, 5.3e-2,
        # 4.6e-2, 4.5e-2): the arrays are the reference a mesh estimate is checked against.
        errors = {}
        for resolution in (16, 32, 64, 128):
            source = fig2_source(resolution)
            source.SetMergeSeam(True)
            source.Update()
            mesh = split_quads(source.GetOutput())
            for mode, estimate, exact in ((0, "Gauss_Curvature", "GaussianCurvature"),
                                          (1, "Mean_Curvature", "MeanCurvature")):
                curvatures = vtkCurvatures()
                curvatures.SetInputData(mesh)
                curvatures.SetCurvatureType(mode)
                curvatures.Update()
                data = curvatures.GetOutput().GetPointData()
                lam = data.GetArray("lambda")
                errors.setdefault(mode, []).append(statistics.median(
                    abs(data.GetArray(estimate).GetValue(i) - data.GetArray(exact).GetValue(i))
                    for i in range(mesh.GetNumberOfPoints()) if abs(lam.GetValue(i)) <= 0.5))
        for mode, series in errors.items():
            for coarse, fine in zip(series, series[1:]):
                self.assertGreater(coarse / fine, 3.5, (mode, series))
            self.assertLess(series[-1], 1e-3, (mode, series))


def split_quads(mesh):
    """The polygons of `mesh` as triangles fanned from their first point (one diagonal per quad)."""
    out = vtkPolyData()
    out.SetPoints(mesh.GetPoints())
    out.GetPointData().ShallowCopy(mesh.GetPointData())
    cells = vtkCellArray()
    ids = vtkIdList()
    polys = mesh.GetPolys()
    polys.InitTraversal()
    while polys.GetNextCell(ids):
        p = [ids.GetId(k) for k in range(ids.GetNumberOfIds())]
        for k in range(1, len(p) - 1):
            cells.InsertNextCell(3)
            for q in (p[0], p[k], p[k + 1]):
                cells.InsertCellPoint(q)
    out.SetPolys(cells)
    return out


if __name__ == "__main__":
    unittest.main()
