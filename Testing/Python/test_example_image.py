"""Regression image of the scene of one script of Examples/: its own build_scene(), VIEW and SIZE
(so that a figure and its test cannot drift apart), compared with a committed baseline by
vtkTesting.

    python3 test_example_image.py --figure fig11_deformation --baseline <dir>/PythonPointPairDeformation.png --output-dir <dir> --threshold <t>

--figure names the script (a module of Examples/). A missing baseline makes the test fail after
writing the image to --output-dir (look at it, then copy it to Testing/Data/Baseline/).
"""
import glob
import importlib
import os
import sys

import python_test_common as common

EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "Examples")


def scene_scripts():
    """The module names of the scripts of Examples/ that build a scene (define build_scene)."""
    names = []
    for script in glob.glob(os.path.join(EXAMPLES, "*.py")):
        with open(script, encoding="utf-8") as text:
            if "\ndef build_scene(" in text.read():
                names.append(os.path.splitext(os.path.basename(script))[0])
    return names


def main():
    args = common.parse_image_arguments(__doc__.splitlines()[0], scene_scripts())
    sys.path.insert(0, EXAMPLES)
    return common.example_regression_test(importlib.import_module(args.figure), args)


if __name__ == "__main__":
    sys.exit(main())
