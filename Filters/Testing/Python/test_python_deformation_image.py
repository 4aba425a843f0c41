"""Regression image of a Python pipeline: the paper's Fig 11 scene of Examples/fig11_deformation.py
(a plane and a sphere warped by point-pair generators through vtkPointPairDeformationFilter,
normals recomputed downstream, coloured by |Displacement|), compared with a committed baseline by
vtkTesting. The scene is the example's own build_scene(), so the figure and its test cannot drift
apart.

    python3 test_python_deformation_image.py --baseline <dir>/PythonPointPairDeformation.png --output-dir <dir> --threshold <t>

A missing baseline makes the test fail after writing the image to --output-dir (look at it, then
copy it to Testing/Data/Baseline/).
"""
import os
import sys

import python_test_common as common

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "Examples"))
import fig11_deformation as fig11  # noqa: E402


def main():
    args = common.parse_image_arguments(__doc__.splitlines()[0])
    return common.example_regression_test(fig11, args)


if __name__ == "__main__":
    sys.exit(main())
