"""Regression images of the dipole field (paper Fig 13 and Fig 14 a, b) through the Python package,
compared with committed baselines by vtkTesting (as vtkRegressionTestImage in the C++ tests).

    python3 test_dipole_field_image.py --figure 13|14a|14b --baseline <png> --output-dir <dir>

Fig 13: one dipole, arrows of "DisplacementSummedGenerators". Fig 14: two dipoles, arrows of
method a ("DisplacementSummedGenerators") or b ("DisplacementSummedDisplacements"). Each with the
contours of "DipolePotential". The pipeline is written out here rather than taken from Examples/,
so that restyling an example does not break this test. A missing baseline makes the test fail after
writing the image to --output-dir (look at it, then copy it to Testing/Data/Baseline/).
"""
import sys

from vtkmodules.vtkFiltersCore import vtkContourFilter, vtkGlyph3D
from vtkmodules.vtkFiltersSources import vtkArrowSource
from vtkmodules.vtkRenderingCore import vtkRenderer

from boostedsurfaces import vtkDipoleFieldSource

import python_test_common as common

FIGURES = {
    "13": ([(0, 0, 0, 1, 0, 0, 0.5)], "DisplacementSummedGenerators"),
    "14a": ([(-1, 0, 0, 0, 1, 0, 0.35), (1, 0, 0, 1, 0, 0, 0.35)], "DisplacementSummedGenerators"),
    "14b": ([(-1, 0, 0, 0, 1, 0, 0.35), (1, 0, 0, 1, 0, 0, 0.35)],
            "DisplacementSummedDisplacements"),
}


def main():
    args = common.parse_image_arguments(__doc__.splitlines()[0], FIGURES)
    generators, array = FIGURES[args.figure]

    source = vtkDipoleFieldSource()  # 21 x 21 points on [-2, 2]^2, z = 0
    source.RemoveAllGenerators()
    for generator in generators:
        source.AddGenerator(*generator)

    arrow = vtkArrowSource()
    glyph = vtkGlyph3D()
    glyph.SetInputConnection(source.GetOutputPort())
    glyph.SetSourceConnection(arrow.GetOutputPort())
    glyph.SetInputArrayToProcess(1, 0, 0, 0, array)
    glyph.SetVectorModeToUseVector()
    glyph.SetScaleModeToDataScalingOff()
    glyph.SetColorModeToColorByVector()
    glyph.SetScaleFactor(0.18)
    arrows = common.colored_actor(glyph, "VectorMagnitude", (0.0, 1.0))

    contour = vtkContourFilter()
    contour.SetInputConnection(source.GetOutputPort())
    contour.SetInputArrayToProcess(0, 0, 0, 0, "DipolePotential")
    for i, value in enumerate((-0.6, -0.3, -0.15, -0.05, 0.05, 0.15, 0.3, 0.6)):
        contour.SetValue(i, value)
    lines = common.colored_actor(contour, color=(0, 0, 0))
    lines.GetProperty().SetLineWidth(2)

    renderer = vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(arrows)
    renderer.AddActor(lines)
    # Looking down -z (VTK's default camera), parallel.
    return common.regression_test(renderer, (0, 0, 1), (0, 1, 0), 1.3, args.baseline,
                                  args.output_dir, args.threshold, size=(300, 300), parallel=True)


if __name__ == "__main__":
    sys.exit(main())
