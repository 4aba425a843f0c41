"""Regression image of the fit filter: the scene of Examples/fit_generators.py (a bumped target, the
unit sphere with its three initial generators, and the fit coloured by FitResidual with the fitted
generators), compared with a committed baseline by vtkTesting. The scene is the example's own
build_scene(), so the figure and its test cannot drift apart.

    python3 test_python_fit_image.py --baseline <dir>/PythonFitGenerators.png --output-dir <dir> --threshold <t>

A missing baseline makes the test fail after writing the image to --output-dir (look at it, then
copy it to Testing/Data/Baseline/).
"""
import os
import sys

import python_test_common as common

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "Examples"))
import fit_generators  # noqa: E402


def main():
    args = common.parse_image_arguments(__doc__.splitlines()[0])
    return common.example_regression_test(fit_generators, args)


if __name__ == "__main__":
    sys.exit(main())
