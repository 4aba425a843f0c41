"""The plugin in pvpython or pvbatch: the Curvature Patch source exists with its documented
defaults, takes control points through its table property, builds every method, and renders the
Fig 7 umbilic preset like the baseline."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines CurvaturePatch()

failures = []

source = CurvaturePatch()  # noqa: F821
defaults = {
    "Method": "Translated Tangents",
    "ExponentialRule": "Exact",
    "Origin": [0.0, 0.0, 0.0],
    "UDirection": [1.0, 0.0, 0.0],
    "VDirection": [0.0, 1.0, 0.0],
    "Size": [4.0, 4.0],
    "UResolution": 32,
    "VResolution": 32,
    "KappaU": 0.5,
    "KappaV": 0.5,
    "CurvaturePreset": "Custom",
    "Falloff": 1.0,
    "Epsilon": 0.5,
    "SelectedControlPoint": -1,
    "CornerWeights": [0.5, -0.5, -0.5, 0.5],
}
common.check_defaults(source, defaults, failures)

source.UpdatePipeline()
info = source.GetDataInformation()
if info.GetNumberOfPoints() != 33 * 33 or info.GetNumberOfCells() != 32 * 32:
    failures.append("default patch has %d points and %d cells"
                    % (info.GetNumberOfPoints(), info.GetNumberOfCells()))
common.check_point_arrays(info, ("u", "v", "GeneratorWeight", "Normals", "TextureCoordinates"), failures)

# Control points through the repeatable table property: two rows of 11 numbers.
source.Method = "Control Points"
source.ControlPointList = [-1, 0, 0, 0, 0, 1, 1, 0, 0, 0.5, 0.5,
                        1, 0, 0, 0, 0, 1, 1, 0, 0, -0.5, 0.5]
source.UpdatePipeline()
if source.GetDataInformation().GetNumberOfCells() != 32 * 32:
    failures.append("control point patch is incomplete")
two_rows = source.GetDataInformation().GetBounds()
source.ControlPointList = [-1, 0, 0, 0, 0, 1, 1, 0, 0, 0.5, 0.5]
source.UpdatePipeline()
if source.GetDataInformation().GetBounds() == two_rows:
    failures.append("the second control point row changed nothing")
# The table's 11 columns are named in the GUI, with the protocol of every table.
common.check_table(source, "Control Point", common.CONTROL_POINT_COLUMNS, failures)
source.ControlPointList = []  # no control point: an error and an empty output
source.UpdatePipeline()
if source.GetDataInformation().GetNumberOfPoints() != 0:
    failures.append("no control points should give an empty output")

for method in ("Bent Line", "Osculating Circles", "Linear",
               "Bilinear"):
    source.Method = method
    source.UpdatePipeline()
    if source.GetDataInformation().GetNumberOfCells() != 32 * 32:
        failures.append("%s gives %d cells" % (method, source.GetDataInformation().GetNumberOfCells()))

source.Method = "Translated Tangents"
source.CurvaturePreset = "Umbilic"
common.render_and_compare(source, "v", [0.0, -6.0, 4.0], [0.0, 0.0, -0.5], [0.0, 0.0, 1.0],
                          arguments, failures)

common.report(failures, "Curvature Patch through the plugin")
