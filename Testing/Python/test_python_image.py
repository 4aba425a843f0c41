"""Regression image of a Python pipeline: the paper's horn (Fig 3) as a surface coloured by lambda,
and a Fig 1 family of circles as lines, compared with a committed baseline by vtkTesting (the same
comparison as vtkRegressionTestImage in the C++ tests).

    python3 test_python_image.py --baseline <dir>/PythonBoostedSurfaceSource.png --output-dir <dir>

A missing baseline makes the test fail after writing the image to --output-dir: that is how a
baseline is made (look at it, then copy it to Testing/Data/Baseline/). The pipeline is written out
here rather than taken from Examples/, so that restyling an example does not break this test.
"""
import argparse
import sys

from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderer, vtkRenderWindow
from vtkmodules.vtkTestingRendering import vtkTesting
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL render window)

from boostedsurfaces import vtkBoostedSurfaceSource


def actor_for(source, scalar_range):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("lambda")
    mapper.SetScalarRange(scalar_range)
    actor = vtkActor()
    actor.SetMapper(mapper)
    return actor


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--baseline", required=True, help="absolute path of the baseline PNG")
    parser.add_argument("--output-dir", required=True, help="where the rendered image goes")
    parser.add_argument("--threshold", type=float, default=10.0,
                        help="vtkTesting error threshold (10, as vtkRegressionTestImage)")
    args = parser.parse_args()

    horn = vtkBoostedSurfaceSource()  # yz unit circle, boosted from (-1.5, 0, 0) along +x
    horn.SetBoostAtCircleCenter(False)
    horn.SetBoostLocation(-1.5, 0, 0)
    horn.SetBoostDirection(1.5, 0, 0)
    horn.SetLambdaRange(0, 1)
    horn.SetLambdaResolution(32)
    horn.SetThetaResolution(48)

    circles = vtkBoostedSurfaceSource()  # xy unit circle boosted in its plane, beside the horn
    circles.SetCircleCenter(0, 3, 0)
    circles.SetCircleNormal(0, 0, 1)
    circles.SetLambdaRange(0, 2)
    circles.SetLambdaResolution(8)
    circles.SetThetaResolution(96)
    circles.SetClipRadius(2.5)
    circles.SetOutputTypeToCircles()

    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(actor_for(horn, (0, 1)))
    circles_actor = actor_for(circles, (0, 2))
    circles_actor.GetProperty().SetLineWidth(2)
    renderer.AddActor(circles_actor)

    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetMultiSamples(0)  # no antialiasing: keeps the image the same from run to run
    window.SetSize(400, 300)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetPosition(-0.6, -0.5, 1.0)
    camera.SetViewUp(0, 0, 1)
    renderer.ResetCamera()
    camera.Zoom(1.5)
    window.Render()

    testing = vtkTesting()
    for argument in ("-V", args.baseline, "-T", args.output_dir):
        testing.AddArgument(argument)
    testing.SetRenderWindow(window)
    result = testing.RegressionTest(args.threshold)
    return 0 if result == vtkTesting.PASSED else 1


if __name__ == "__main__":
    sys.exit(main())
