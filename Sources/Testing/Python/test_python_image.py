"""Regression image of a Python pipeline: the paper's horn (Fig 3) as a surface coloured by lambda,
and a Fig 1 family of circles as lines, compared with a committed baseline by vtkTesting (the same
comparison as vtkRegressionTestImage in the C++ tests).

    python3 test_python_image.py --baseline <dir>/PythonBoostedSurfaceSource.png --output-dir <dir>

A missing baseline makes the test fail after writing the image to --output-dir: that is how a
baseline is made (look at it, then copy it to Testing/Data/Baseline/). The pipeline is written out
here rather than taken from Examples/, so that restyling an example does not break this test.
"""
import sys

from vtkmodules.vtkRenderingCore import vtkRenderer

from boostedsurfaces import vtkBoostedSurfaceSource

import python_test_common as common


def main():
    args = common.parse_image_arguments(__doc__.splitlines()[0])

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
    renderer.AddActor(common.colored_actor(horn, "lambda", (0, 1)))
    circles_actor = common.colored_actor(circles, "lambda", (0, 2))
    circles_actor.GetProperty().SetLineWidth(2)
    renderer.AddActor(circles_actor)

    return common.regression_test(renderer, (-0.6, -0.5, 1.0), (0, 0, 1), 1.5, args.baseline,
                                  args.output_dir, args.threshold)


if __name__ == "__main__":
    sys.exit(main())
