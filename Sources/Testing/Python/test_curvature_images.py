"""Regression images of vtkCurvaturePatchSource for the paper's Fig 6, 7, 9 and 12, compared with
committed baselines by vtkTesting (the comparison of vtkRegressionTestImage).

    python3 test_curvature_images.py --figure fig6 --baseline <dir>/PythonCurvatureFig6.png --output-dir <dir>

A missing baseline makes the test fail after writing the image to --output-dir (look at it, then
copy it to Testing/Data/Baseline/). The pipelines are written out here rather than taken from
Examples/, so that restyling an example does not break these tests.
"""
import sys

from vtkmodules.vtkFiltersCore import vtkTubeFilter
from vtkmodules.vtkRenderingCore import vtkRenderer

from boostedsurfaces import vtkCurvaturePatchSource

import python_test_common as common


def patch(**settings):
    source = vtkCurvaturePatchSource()
    for name, value in settings.items():
        setter = getattr(source, "Set" + name)
        setter(*value) if isinstance(value, tuple) else setter(value)
    return source


def actor(algorithm, array, scalar_range):
    return common.colored_actor(algorithm, array, scalar_range, color=(0.7, 0.75, 0.9))


def fig6():
    """Bent lines (eq 15) for kappa in -1 ... 1, tubes coloured by u, seen in the xz plane."""
    actors = []
    for kappa in (-1.0, -0.5, -0.25, 0.0, 0.25, 0.5, 1.0):
        line = patch(Method=0, Size=(8.0, 0.0), UResolution=128, KappaU=kappa)
        tube = vtkTubeFilter()
        tube.SetInputConnection(line.GetOutputPort())
        tube.SetRadius(0.03)
        tube.SetNumberOfSides(8)
        tube.keep = line
        actors.append(actor(tube, "u", (-4, 4)))
    return actors, (0, -1, 0), (0, 0, 1)


def fig7():
    """The four presets of eq 16 side by side, coloured by v."""
    return ([actor(patch(Method=1, CurvaturePreset=preset, Origin=(4.0 * (preset - 1), 0, 0),
                         Size=(3.0, 3.0), UResolution=24, VResolution=24), "v", (-1.5, 1.5))
             for preset in (1, 2, 3, 4)], (0.0, -1.0, 0.9), (0, 0, 1))


def fig9():
    """Four-corner control point patches (eq 21): positive umbilic and hyperbolic."""
    actors = []
    for i, (ku, kv) in enumerate(((0.5, 0.5), (0.5, -0.5))):
        x = 6.0 * i
        source = patch(Method=3, Origin=(x, 0, 0), Size=(5.0, 5.0), UResolution=48,
                       VResolution=48, Epsilon=0.5)
        for sx, sy in ((-1, -1), (1, -1), (-1, 1), (1, 1)):
            source.AddControlPoint(x + 1.5 * sx, 1.5 * sy, 0, 0, 0, 1, 1, 0, 0, ku, kv)
        actors.append(actor(source, "v", (-2.5, 2.5)))
    return actors, (0.0, -1.0, 0.9), (0, 0, 1)


def fig12():
    """Bilinear corner boosts (eq 25): a normal-direction saddle and mixed directions."""
    saddle = patch(Method=5, Size=(3.0, 3.0), UResolution=32, VResolution=32,
                   CornerWeights=(0.5, -0.5, -0.5, 0.5))
    mixed = patch(Method=5, Origin=(4.5, 0, 0), Size=(3.0, 3.0), UResolution=32, VResolution=32,
                  Corner2Direction=(1, 0, 0.5), Corner3Direction=(0, 1, -0.5),
                  Corner4Direction=(-1, -1, 1), CornerWeights=(0.5, 0.4, 0.4, 0.5))
    return ([actor(saddle, "GeneratorWeight", (-0.25, 0.25)),
             actor(mixed, "GeneratorWeight", (0.0, 0.6))], (0.0, -1.0, 0.9), (0, 0, 1))


FIGURES = {"fig6": fig6, "fig7": fig7, "fig9": fig9, "fig12": fig12}


def main():
    args = common.parse_image_arguments(__doc__.splitlines()[0], FIGURES)

    actors, view_direction, view_up = FIGURES[args.figure]()
    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    for a in actors:
        renderer.AddActor(a)
    return common.regression_test(renderer, view_direction, view_up, 1.3, args.baseline,
                                  args.output_dir, args.threshold)


if __name__ == "__main__":
    sys.exit(main())
