"""Regression image of a Python pipeline: a plane and a sphere warped by point-pair generators
(the paper's Fig 11) through vtkPointPairDeformationFilter, with normals recomputed downstream,
coloured by |Displacement| and compared with a committed baseline by vtkTesting.

    python3 test_python_deformation_image.py --baseline <dir>/PythonPointPairDeformation.png --output-dir <dir>

A missing baseline makes the test fail after writing the image to --output-dir (look at it, then
copy it to Testing/Data/Baseline/). The generators are written out here rather than taken from
Examples/, so that restyling the example does not break this test.
"""
import sys

from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer

from boostedsurfaces import vtkPointPairDeformationFilter

import python_test_common as common

PLANE_GENERATORS = [((-1.0, -0.8, 0.4), (0, 0, 1), 0.7), ((1.0, -0.7, -0.4), (0, 0, 1), -0.7),
                    ((-0.3, 0.9, 0.3), (1, 0, 0), 0.6)]
SPHERE_GENERATORS = [((5.0, 0.0, 1.4), (0, 0, 1), 0.6), ((6.4, 0.0, 0.2), (1, 0, 0), -0.5),
                     ((4.6, -1.4, -0.4), (0, 1, 0), 0.5)]


def deformed_actor(source, generators, keep):
    deformation = vtkPointPairDeformationFilter()
    deformation.SetInputConnection(source.GetOutputPort())
    for location, direction, weight in generators:
        deformation.AddGenerator(*location, *direction, weight)
    deformation.SetFalloff(4.0)
    deformation.SetEpsilon(0.05)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(deformation.GetOutputPort())
    normals.SplittingOff()
    lut = vtkLookupTable()
    lut.SetVectorModeToMagnitude()
    lut.SetRange(0.0, 0.6)
    lut.SetHueRange(0.66, 0.0)
    lut.Build()
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(normals.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("Displacement")
    mapper.SetLookupTable(lut)
    mapper.UseLookupTableScalarRangeOn()
    actor = vtkActor()
    actor.SetMapper(mapper)
    keep.extend([source, deformation, normals])  # ports do not keep their algorithms alive
    return actor


def main():
    args = common.parse_image_arguments(__doc__.splitlines()[0])

    plane = vtkPlaneSource()
    plane.SetOrigin(-2, -2, 0)
    plane.SetPoint1(2, -2, 0)
    plane.SetPoint2(-2, 2, 0)
    plane.SetResolution(60, 60)
    sphere = vtkSphereSource()
    sphere.SetCenter(5, 0, 0)
    sphere.SetRadius(1.0)
    sphere.SetThetaResolution(64)
    sphere.SetPhiResolution(48)

    keep = []
    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(deformed_actor(plane, PLANE_GENERATORS, keep))
    renderer.AddActor(deformed_actor(sphere, SPHERE_GENERATORS, keep))
    return common.regression_test(renderer, (0.15, -1.0, 0.6), (0, 0, 1), 1.3, args.baseline,
                                  args.output_dir, args.threshold, size=(500, 300))


if __name__ == "__main__":
    sys.exit(main())
