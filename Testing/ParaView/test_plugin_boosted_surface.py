"""The plugin in pvpython or pvbatch: the Boosted Surface source exists with its documented
defaults, produces the Fig 2 surface, and renders like the baseline."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines BoostedSurface()

failures = []

source = BoostedSurface()  # noqa: F821
defaults = {
    "CircleCenter": [0.0, 0.0, 0.0],
    "CircleNormal": [1.0, 0.0, 0.0],
    "CircleRadius": 1.0,
    "BoostDirection": [1.0, 0.0, 0.0],
    "LambdaRange": [0.0, 2.0],
    "LambdaResolution": 64,
    "ThetaResolution": 64,
}
common.check_defaults(source, defaults, failures)

source.LambdaResolution = 16
source.ThetaResolution = 32
source.UpdatePipeline()
info = source.GetDataInformation()
if info.GetNumberOfPoints() != 17 * 33 or info.GetNumberOfCells() != 16 * 32:
    failures.append("Fig 2 surface has %d points and %d cells, expected %d and %d"
                    % (info.GetNumberOfPoints(), info.GetNumberOfCells(), 17 * 33, 16 * 32))
bounds = info.GetBounds()
# x runs from 0 (lambda = 0) to the largest plane x = lambda/(1+lambda^2) = 1/2 (lambda = 1).
# `not ... <= 1e-12`, not `> 1e-12`: NaN bounds must fail
if not (abs(bounds[0]) <= 1e-12 and abs(bounds[1] - 0.5) <= 1e-12 and abs(bounds[3] - 1.0) <= 1e-12):
    failures.append("unexpected bounds %r" % (bounds,))
common.check_point_arrays(info, ("lambda", "theta", "Normals", "TextureCoordinates"), failures)

common.render_and_compare(source, "lambda", [3.0, 2.0, 2.5], [0.25, 0.0, 0.0], [0.0, 0.0, 1.0],
                          arguments, failures)

common.report(failures, "Boosted Surface through the plugin")
