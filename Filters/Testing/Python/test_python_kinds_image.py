"""Regression images of the generator kinds: the scenes of Examples/twisted_bar.py (a bar twisted
by ROTATION generators along its axis) and Examples/boost_versus_twist.py (the same rows as
POINT_PAIR and as TWIST), compared with committed baselines by vtkTesting. The scenes are the
examples' own build_scene(), so the figures and their tests cannot drift apart.

    python3 test_python_kinds_image.py --figure TwistedBar --baseline <dir>/PythonTwistedBar.png --output-dir <dir> --threshold <t>

A missing baseline makes the test fail after writing the image to --output-dir (look at it, then
copy it to Testing/Data/Baseline/).
"""
import os
import sys

import python_test_common as common

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "Examples"))
import boost_versus_twist  # noqa: E402
import twisted_bar  # noqa: E402

FIGURES = {"TwistedBar": twisted_bar, "BoostVersusTwist": boost_versus_twist}


def main():
    args = common.parse_image_arguments(__doc__.splitlines()[0], FIGURES)
    figure = FIGURES[args.figure]
    return common.example_regression_test(figure, args)


if __name__ == "__main__":
    sys.exit(main())
