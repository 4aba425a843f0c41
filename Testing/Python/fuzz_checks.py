"""The property fuzz's check of one update's output: after an error it must be empty; otherwise it
must be a valid data set: every cell's point ids within its points, every point and cell array as
long as its points and cells, and, when the inputs were finite, every value finite.

A problem is (category, text); the categories let test_property_fuzz.KNOWN_ISSUES excuse exactly
the failures another branch fixes.
"""
import numpy
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import VTK_FLOAT, vtkDataArray
from vtkmodules.vtkCommonDataModel import (vtkImageData, vtkPointSet, vtkPolyData,
                                           vtkStructuredGrid, vtkTable, vtkUnstructuredGrid)

# vtkStreamingDemandDrivenPipeline::ExecuteDataEnd adds this array to every structured output of a
# piece request with ghost levels; on an empty output (extent 0 -1 0 -1 0 -1) VTK 9.2's
# vtkDataSet::GenerateGhostArray gives it 1 tuple for no cell. Not the algorithm's: ignored there.
GHOST_ARRAY = "vtkGhostType"


def values(array):
    """The array's values as a numpy array (any layout)."""
    try:
        return vtk_to_numpy(array)
    except Exception:  # not VTK's usual layout: copy tuple by tuple
        return numpy.array([array.GetTuple(i) for i in range(array.GetNumberOfTuples())],
                           dtype=float)


def non_finite(array, what):
    """A problem when `array` holds a NaN or an infinity, else None."""
    data = values(array)
    if not numpy.issubdtype(data.dtype, numpy.floating):
        return None
    bad = ~numpy.isfinite(data)
    if not bad.any():
        return None
    nans = int(numpy.isnan(data).sum())
    infinities = int(bad.sum()) - nans
    category = "non-finite"
    if nans == 0 and array.GetDataType() == VTK_FLOAT:
        category = "infinity-in-float"  # a finite double beyond FLT_MAX stored as float
    first = tuple(numpy.argwhere(bad)[0])
    return (category, "%s holds %d NaN and %d infinite values (first at %s: %r)" % (
        what, nans, infinities, first, data[first]))


def cell_problems(cell_arrays, points):
    problems = []
    for name, cells in cell_arrays:
        if cells is None or cells.GetNumberOfCells() == 0:
            continue
        if not cells.IsValid():
            problems.append(("bad-cells", "the %s cell array is not valid" % name))
            continue
        ids = values(cells.GetConnectivityArray())
        if ids.size and (ids.min() < 0 or ids.max() >= points):
            problems.append(("bad-cells", "a %s cell points at point %d of %d" % (
                name, ids.max() if ids.max() >= points else ids.min(), points)))
    return problems


def array_problems(data, attributes, tuples, where, check_values):
    problems = []
    for i in range(attributes.GetNumberOfArrays()):
        array = attributes.GetAbstractArray(i)
        if array.GetName() == GHOST_ARRAY and data.GetNumberOfPoints() == 0:
            continue  # VTK's executive marks ghosts of an empty structured piece (see GHOST_ARRAY)
        what = "%s array %r" % (where, array.GetName())
        if array.GetNumberOfTuples() != tuples:
            problems.append(("bad-array-length", "%s has %d tuples for %d %ss" % (
                what, array.GetNumberOfTuples(), tuples, where)))
        elif check_values and isinstance(array, vtkDataArray):
            problem = non_finite(array, what)
            if problem:
                problems.append(problem)
    return problems


def output_problems(output, own_errors, pipeline_errors, unchanged, finite_inputs):
    """The problems of an update's output. `own_errors`: the messages the algorithm reported,
    after which its output must be empty. `pipeline_errors`: the other objects' (VTK's executive
    refusing a request, an input's producer that lacks a requested extent); after those alone the
    output is either the previous one, `unchanged` (the algorithm did not run, as for any VTK
    algorithm), or the algorithm ran on what it got and its output must be valid."""
    if output is None:  # no output object at all (an input of the wrong type)
        return []
    if isinstance(output, vtkTable):  # the fit filter's generator table
        return table_problems(output, own_errors, pipeline_errors, unchanged, finite_inputs)
    points, cells = output.GetNumberOfPoints(), output.GetNumberOfCells()
    if own_errors:
        if points or cells:
            return [("error-but-output", "%d error(s) (%s) but the output has %d points and %d "
                     "cells" % (len(own_errors), own_errors[0].strip().splitlines()[-1][:200],
                                points, cells))]
        return []
    if pipeline_errors and unchanged:
        return []
    problems = []
    if isinstance(output, vtkPointSet) and points:
        data = output.GetPoints().GetData()
        if data.GetNumberOfTuples() != points:
            problems.append(("bad-points", "%d point coordinates for %d points" % (
                data.GetNumberOfTuples(), points)))
        elif finite_inputs:
            problem = non_finite(data, "the points")
            if problem:
                problems.append(problem)
    if isinstance(output, vtkPolyData):
        problems += cell_problems([("vertex", output.GetVerts()), ("line", output.GetLines()),
                                   ("polygon", output.GetPolys()),
                                   ("strip", output.GetStrips())], points)
    elif isinstance(output, vtkUnstructuredGrid):
        problems += cell_problems([("unstructured", output.GetCells())], points)
        types = output.GetCellTypesArray()
        if cells and (types is None or types.GetNumberOfTuples() != cells):
            problems.append(("bad-cells", "cell types do not match the %d cells" % cells))
    elif isinstance(output, vtkStructuredGrid) and points:
        dimensions = output.GetDimensions()
        if dimensions[0] * dimensions[1] * dimensions[2] != points:
            problems.append(("bad-points", "dimensions %s for %d points" % (dimensions, points)))
    elif isinstance(output, vtkImageData):
        geometry = list(output.GetOrigin()) + list(output.GetSpacing())
        if points and finite_inputs and not numpy.isfinite(geometry).all():
            problems.append(("non-finite", "image origin and spacing %s" % geometry))
    problems += array_problems(output, output.GetPointData(), points, "point", finite_inputs)
    problems += array_problems(output, output.GetCellData(), cells, "cell", finite_inputs)
    return problems


def table_problems(table, own_errors, pipeline_errors, unchanged, finite_inputs):
    """output_problems for a vtkTable: no rows after an error, else every column as long as the
    rows and, when the inputs were finite, finite."""
    rows = table.GetNumberOfRows()
    if own_errors:
        if rows:
            return [("error-but-output", "%d error(s) (%s) but the table has %d rows" % (
                len(own_errors), own_errors[0].strip().splitlines()[-1][:200], rows))]
        return []
    if pipeline_errors and unchanged:
        return []
    return array_problems(table, table.GetRowData(), rows, "row", finite_inputs)
