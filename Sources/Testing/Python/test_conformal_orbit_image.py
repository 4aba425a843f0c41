"""Regression image of vtkConformalOrbitSource: the scene of Examples/torus_knots_and_orbits.py
(the (2, 3) and (3, 5) torus knots on their torus with their core circles, the orbits of one and
of two point-pair boosts), compared with the committed baseline by vtkTesting. The scene is the
example's own build_scene(), so the figure and its test cannot drift apart.

    python3 test_conformal_orbit_image.py --baseline <dir>/PythonConformalOrbit.png --output-dir <dir> --threshold <t>

A missing baseline makes the test fail after writing the image to --output-dir (look at it, then
copy it to Testing/Data/Baseline/).
"""
import os
import sys

import python_test_common as common

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "Examples"))
import torus_knots_and_orbits as figure  # noqa: E402


def main():
    args = common.parse_image_arguments(__doc__.splitlines()[0])
    return common.example_regression_test(figure, args)


if __name__ == "__main__":
    sys.exit(main())
