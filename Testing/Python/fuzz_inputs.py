"""The property fuzz's input data: every data-set type and array layout, built from the spec of a
recipe (fuzz_recipe.data_spec) and its own seed, and whether all of its values are finite.

Kinds: polydata (vertices, lines, polygons and strips), unstructured grid (cells of several
types), structured grid, image data (any extent, origin and spacing), rectilinear grid, each also
empty, and a vtkTable (not a data set). Points and arrays: double, float, int and unsigned char
arrays of VTK's usual layout, and double or float vtkSOADataArrayTemplate (struct of arrays).
"""
import math
import random

from vtkmodules.vtkCommonCore import (vtkDoubleArray, vtkFloatArray, vtkIntArray, vtkPoints,
                                      vtkSOADataArrayTemplate, vtkUnsignedCharArray)
from vtkmodules.vtkCommonDataModel import (VTK_HEXAHEDRON, VTK_LINE, VTK_POLY_VERTEX, VTK_QUAD,
                                           VTK_TETRA, VTK_TRIANGLE, VTK_VERTEX, vtkCellArray,
                                           vtkImageData, vtkPolyData, vtkRectilinearGrid,
                                           vtkStructuredGrid, vtkTable, vtkUnstructuredGrid)

from fuzz_recipe import EXTREME_DOUBLES, NON_FINITE

LAYOUTS = {
    "double": vtkDoubleArray,
    "float": vtkFloatArray,
    "int": vtkIntArray,
    "uchar": vtkUnsignedCharArray,
    "soa-double": vtkSOADataArrayTemplate["float64"],
    "soa-float": vtkSOADataArrayTemplate["float32"],
}
INTEGER_LAYOUTS = {"int", "uchar"}
CELL_SIZES = {VTK_VERTEX: 1, VTK_LINE: 2, VTK_TRIANGLE: 3, VTK_QUAD: 4, VTK_TETRA: 4,
              VTK_HEXAHEDRON: 8}


def number(rng, regime):
    """A coordinate or array value of the trial's regime."""
    if regime == "non-finite" and rng.random() < 0.05:
        return rng.choice(NON_FINITE)
    if regime == "extreme" and rng.random() < 0.1:
        return rng.choice(EXTREME_DOUBLES)
    return rng.uniform(-2.0, 2.0)


def filled_array(rng, regime, layout, components, tuples, name=None):
    array = LAYOUTS[layout]()
    array.SetNumberOfComponents(components)
    array.SetNumberOfTuples(tuples)
    if name is not None:
        array.SetName(name)
    for i in range(tuples):
        for c in range(components):
            if layout in INTEGER_LAYOUTS:  # a double cast to an integer type must fit it
                array.SetComponent(i, c, rng.randint(0, 255))
            else:
                array.SetComponent(i, c, number(rng, regime))
    return array


def finite(array):
    return all(math.isfinite(array.GetComponent(i, c))
               for i in range(array.GetNumberOfTuples())
               for c in range(array.GetNumberOfComponents()))


def point_set_points(rng, spec, count):
    points = vtkPoints()
    points.SetData(filled_array(rng, spec["regime"], spec["points"], 3, count))
    return points


def cells(rng, count, types):
    """Cells of the given types over `count` points, every id valid."""
    chosen = []
    for _ in range(rng.randint(1, 2 * count) if count else 0):
        cell_type = rng.choice(types)
        size = CELL_SIZES.get(cell_type, rng.randint(1, 4))
        if size <= count:
            chosen.append((cell_type, rng.sample(range(count), size)))
    return chosen


def polydata(rng, spec, count):
    data = vtkPolyData()
    data.SetPoints(point_set_points(rng, spec, count))
    arrays = {VTK_VERTEX: vtkCellArray(), VTK_LINE: vtkCellArray(), VTK_TRIANGLE: vtkCellArray(),
              VTK_QUAD: vtkCellArray(), "strip": vtkCellArray()}
    for cell_type, ids in cells(rng, count, [VTK_VERTEX, VTK_LINE, VTK_TRIANGLE, VTK_QUAD,
                                            "strip"]):
        if cell_type == "strip" and len(ids) < 3:
            continue
        arrays[cell_type].InsertNextCell(len(ids), ids)
    polygons = arrays[VTK_TRIANGLE]
    polygons.Append(arrays[VTK_QUAD])
    data.SetVerts(arrays[VTK_VERTEX])
    data.SetLines(arrays[VTK_LINE])
    data.SetPolys(polygons)
    data.SetStrips(arrays["strip"])
    return data


def unstructured(rng, spec, count):
    data = vtkUnstructuredGrid()
    data.SetPoints(point_set_points(rng, spec, count))
    data.Allocate(1)
    for cell_type, ids in cells(rng, count, [VTK_VERTEX, VTK_POLY_VERTEX, VTK_LINE, VTK_TRIANGLE,
                                            VTK_TETRA, VTK_HEXAHEDRON]):
        data.InsertNextCell(cell_type, len(ids), ids)
    return data


def structured(rng, spec, size):
    dimensions = [size, rng.randint(1, max(size, 1)), rng.randint(1, 2)]
    data = vtkStructuredGrid()
    data.SetDimensions(dimensions)
    data.SetPoints(point_set_points(rng, spec, dimensions[0] * dimensions[1] * dimensions[2]))
    return data


def image(rng, spec, size):
    regime = spec["regime"]
    extent = []
    for axis in range(3):
        start = rng.choice([0, 0, -3, 5, 2 ** 30]) if regime != "typical" else rng.randint(-3, 3)
        extent += [start, start + (rng.randint(0, size - 1) if axis < 2 else rng.randint(0, 1))]
    data = vtkImageData()
    data.SetExtent(extent)
    spacing = [rng.uniform(0.05, 1.0) for _ in range(3)]
    origin = [rng.uniform(-2.0, 2.0) for _ in range(3)]
    if regime != "typical" and rng.random() < 0.5:
        axis = rng.randrange(3)
        spacing[axis] = rng.choice(EXTREME_DOUBLES + (NON_FINITE if regime == "non-finite" else []))
        origin[rng.randrange(3)] = number(rng, regime)
    data.SetSpacing(spacing)
    data.SetOrigin(origin)
    return data


def image_finite(data):
    """Whether every point of the image (origin + index * spacing) is finite."""
    extent = data.GetExtent()
    origin, spacing = data.GetOrigin(), data.GetSpacing()
    return all(math.isfinite(origin[a] + extent[2 * a + end] * spacing[a])
               for a in range(3) for end in (0, 1))


def rectilinear(rng, spec, size):
    layout = spec["points"]
    data = vtkRectilinearGrid()
    lengths = [size, rng.randint(1, max(size, 1)), rng.randint(1, 2)]
    data.SetDimensions(lengths)
    coordinates = [filled_array(rng, spec["regime"], layout, 1, n) for n in lengths]
    data.SetXCoordinates(coordinates[0])
    data.SetYCoordinates(coordinates[1])
    data.SetZCoordinates(coordinates[2])
    return data


def build(spec):
    """(data object, whether its values are all finite) for a spec of fuzz_recipe.data_spec."""
    rng = random.Random(spec["seed"])
    kind = spec["kind"]
    if kind == "table":
        table = vtkTable()
        table.AddColumn(filled_array(rng, "typical", "double", 1, 3, "column"))
        return table, True
    empty = kind.startswith("empty-")
    kind = kind[len("empty-"):] if empty else kind
    size = spec["size"]
    if kind == "image":
        data = image(rng, spec, size)
        if empty:
            data.SetExtent(0, -1, 0, -1, 0, -1)
    elif kind == "rectilinear":
        data = rectilinear(rng, spec, 0 if empty else size)
    elif kind == "structured":
        data = structured(rng, spec, 0 if empty else size)
    else:
        count = 0 if empty else size * size
        data = (polydata if kind == "polydata" else unstructured)(rng, spec, count)
    if "moved" in spec and data.IsA("vtkPointSet") and data.GetPoints() is not None:
        # The same data set with its points moved (a fit target with the mesh's points in order).
        moves = random.Random(spec["moved"])
        for i in range(data.GetNumberOfPoints()):
            data.GetPoints().SetPoint(i, [x + moves.uniform(-0.3, 0.3) for x in data.GetPoint(i)])
    points = data.GetNumberOfPoints()
    all_finite = image_finite(data) if kind == "image" else True
    if kind == "rectilinear":
        all_finite = all(finite(data.GetXCoordinates() if a == 0 else
                                data.GetYCoordinates() if a == 1 else data.GetZCoordinates())
                         for a in range(3))
    elif kind not in ("image",) and data.GetPoints() is not None:
        all_finite = finite(data.GetPoints().GetData())
    for name, components, layout, wrong_by in spec["arrays"]:
        array = filled_array(rng, spec["regime"], layout, components, max(0, points + wrong_by),
                             name)
        data.GetPointData().AddArray(array)
        if name == "Normals" and components == 3:
            data.GetPointData().SetActiveNormals(name)  # the normals a filter may transform
        all_finite = all_finite and finite(array)
    for k in range(spec["cell_arrays"]):
        array = filled_array(rng, spec["regime"], "double", 1, data.GetNumberOfCells(),
                             "CellValues%d" % k)
        data.GetCellData().AddArray(array)
        all_finite = all_finite and finite(array)
    return data, all_finite


def summary(spec):
    """A short text for a recipe's printout."""
    if spec is None:
        return "None"
    return "<%s: %s points, size %d, %d point arrays, seed %d%s>" % (
        spec["kind"], spec["points"], spec["size"], len(spec["arrays"]), spec["seed"],
        ", moved by seed %d" % spec["moved"] if "moved" in spec else "")
