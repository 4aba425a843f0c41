"""One update of vtkPointPairDeformationFilter for instruction counts under callgrind.

The benchmarks' wall and CPU times swing by 2 to 10 times on a shared machine; instruction
counts do not. This deforms a 200 x 200 sheet of the shape of the benchmarks' mesh (40,000
points) by M generators (fixed pseudo-random ones, weights 0.1 to 0.4, falloff 1, epsilon 0.05,
strength 0.5, as bench/README.md's field but not the same draws), with or without float unit
"Normals" (0, 0.6, 0.8), in one Update:

    BOOSTEDSURFACES_KERNEL_ISA=avx2 PYTHONPATH=build/lib/python3.11/site-packages \\
      valgrind --tool=callgrind --toggle-collect='vtkPointPairDeformationFilter::RequestData*' \\
      /usr/bin/python3 bench/callgrind_filter.py <Paper|Exact> <M> <plain|normals> [side]

("Collected" is the update's count; callgrind_annotate --inclusive=yes on the output file splits
off cga::PointPairField::mapPoints or mapPointsWith*.) valgrind runs AVX2 but not AVX-512 code.
"""
import math
import random
import sys

from boostedsurfaces import vtkPointPairDeformationFilter
from vtkmodules.vtkCommonCore import vtkFloatArray, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkStructuredGrid


def deformation(rule, generators, mode, side=200):
    """The filter on the side x side sheet, set up as above and not yet updated."""
    points = vtkPoints()
    points.SetDataTypeToDouble()
    points.SetNumberOfPoints(side * side)
    normals = vtkFloatArray()
    normals.SetName("Normals")
    normals.SetNumberOfComponents(3)
    normals.SetNumberOfTuples(side * side)
    for j in range(side):
        for i in range(side):
            x = -2 + 4 * i / (side - 1)
            y = -2 + 4 * j / (side - 1)
            points.SetPoint(j * side + i, x, y, 0.3 * math.sin(2 * x) * math.cos(3 * y))
            normals.SetTuple3(j * side + i, 0.0, 0.6, 0.8)
    grid = vtkStructuredGrid()
    grid.SetDimensions(side, side, 1)
    grid.SetPoints(points)
    if mode == "normals":
        grid.GetPointData().SetNormals(normals)
    filter = vtkPointPairDeformationFilter()
    filter.SetInputData(grid)
    draws = random.Random(20140601)
    for _ in range(generators):
        d = [draws.uniform(-1, 1) for _ in range(3)]
        length = math.sqrt(sum(c * c for c in d))
        filter.AddGenerator(draws.uniform(-2, 2), draws.uniform(-2, 2), draws.uniform(-0.5, 0.5),
                            d[0] / length, d[1] / length, d[2] / length, draws.uniform(0.1, 0.4))
    filter.SetFalloff(1.0)
    filter.SetEpsilon(0.05)
    filter.SetStrength(0.5)
    filter.SetExponentialRule(
        vtkPointPairDeformationFilter.EXACT if rule == "Exact" else vtkPointPairDeformationFilter.PAPER)
    return filter


if __name__ == "__main__":
    rule, generators, mode = sys.argv[1], int(sys.argv[2]), sys.argv[3]
    side = int(sys.argv[4]) if len(sys.argv) > 4 else 200
    deformation(rule, generators, mode, side).Update()
