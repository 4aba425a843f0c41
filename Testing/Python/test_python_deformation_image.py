"""Regression image of a Python pipeline: a plane and a sphere warped by point-pair generators
(the paper's Fig 11) through vtkPointPairDeformationFilter, with normals recomputed downstream,
coloured by |Displacement| and compared with a committed baseline by vtkTesting.

    python3 test_python_deformation_image.py --baseline <dir>/PythonPointPairDeformation.png --output-dir <dir>

A missing baseline makes the test fail after writing the image to --output-dir (look at it, then
copy it to Testing/Data/Baseline/). The generators are written out here rather than taken from
Examples/, so that restyling the example does not break this test.
"""
import argparse
import sys

from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkFiltersCore import vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow
from vtkmodules.vtkTestingRendering import vtkTesting
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL render window)

from boostedsurfaces import vtkPointPairDeformationFilter

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
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", required=True, help="absolute path of the baseline PNG")
    parser.add_argument("--output-dir", required=True, help="where the rendered image goes")
    parser.add_argument("--threshold", type=float, default=10.0,
                        help="vtkTesting error threshold (10, as vtkRegressionTestImage)")
    args = parser.parse_args()

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

    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetMultiSamples(0)  # no antialiasing: keeps the image the same from run to run
    window.SetSize(500, 300)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(0.15, -1.0, 0.6)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera()
    camera.Zoom(1.3)
    window.Render()

    testing = vtkTesting()
    for argument in ("-V", args.baseline, "-T", args.output_dir):
        testing.AddArgument(argument)
    testing.SetRenderWindow(window)
    result = testing.RegressionTest(args.threshold)
    return 0 if result == vtkTesting.PASSED else 1


if __name__ == "__main__":
    sys.exit(main())
