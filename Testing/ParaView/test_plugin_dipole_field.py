"""The plugin in pvpython or pvbatch: the Dipole Field source exists with its documented
defaults, takes its generators from the table property, reports time steps when asked, gives the
closed-form field of one generator, and renders like the baseline."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines DipoleField()
from paraview import servermanager, simple  # noqa: E402

failures = []

source = DipoleField()  # noqa: F821
defaults = {
    "GeneratorList": [0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.5, 0.0, 0.0],
    "GeneratorsTranslation": [0.0, 0.0, 0.0],
    "SelectedGenerator": -1,
    "SelectedGeneratorLocation": [0.0, 0.0, 0.0],
    "AimSelectedGenerator": 0,
    "SelectedGeneratorTip": [1.0, 0.0, 0.0],
    "Origin": [-2.0, -2.0, 0.0],
    "Spacing": [0.2, 0.2, 1.0],
    "Dimensions": [21, 21, 1],
    "Falloff": 1.0,
    "Epsilon": 0.1,
    "ExponentialRule": "Exact",
    "NumberOfTimeSteps": 0,
}
common.check_defaults(source, defaults, failures)
# The generator table: the same protocol and columns as the deformation filter's.
common.check_table(source, "Generator", common.GENERATOR_COLUMNS, failures)

# One generator off the grid's symmetry: the field must be the closed form, an SCT about x of
# weight u = -w v / (k |p - x|^2 + eps) (docs/conventions.md section 2).
x, v, w, k, eps = (0.3, -0.2, 0.0), (0.0, 1.0, 0.0), 0.8, 1.5, 0.05
source.GeneratorList = list(x) + list(v) + [w, 0, 0]  # kind 0 (Point Pair), pitch 0
source.Falloff = k
source.Epsilon = eps
source.Dimensions = [11, 9, 1]
source.UpdatePipeline()
info = source.GetDataInformation()
if info.GetNumberOfPoints() != 11 * 9:
    failures.append("%d points, expected %d" % (info.GetNumberOfPoints(), 11 * 9))
common.check_point_arrays(info, ("DisplacementSummedGenerators", "DisplacementSummedDisplacements",
              "DisplacementDifference", "DisplacementDifferenceMagnitude", "DipolePotential"), failures)

image = servermanager.Fetch(source)
field = image.GetPointData().GetArray("DisplacementSummedGenerators")
largest_error = 0.0
for i in range(image.GetNumberOfPoints()):
    p = image.GetPoint(i)
    y = [p[c] - x[c] for c in range(3)]
    y2 = sum(t * t for t in y)
    c = -w / (k * y2 + eps)
    u = [c * t for t in v]
    denominator = 1.0 + 2.0 * sum(u[j] * y[j] for j in range(3)) + sum(t * t for t in u) * y2
    expected = [x[j] + (y[j] + u[j] * y2) / denominator - p[j] for j in range(3)]
    got = field.GetTuple3(i)
    # common.largest keeps a NaN, which `not largest_error < 1e-12` then fails (max() drops it)
    largest_error = common.largest([largest_error] + [abs(got[j] - expected[j]) for j in range(3)])
if not largest_error < 1e-12:
    failures.append("one generator differs from the closed form by %g" % largest_error)

# Two rows in the table: two generators, and the methods differ (for one they are equal).
source.GeneratorList = [-1, 0, 0, 0, 1, 0, 0.35, 0, 0, 1, 0, 0, 1, 0, 0, 0.35, 0, 0]
source.Falloff = 1.0
source.Epsilon = 0.1
source.Dimensions = [21, 21, 1]
source.UpdatePipeline()
magnitude = source.PointData["DisplacementDifferenceMagnitude"].GetRange()
if not magnitude[1] > 0.1:
    failures.append("two generators: largest |a - b| is %g, expected > 0.1" % magnitude[1])

# The line widget's properties: the selected row at the line's start (Generators Translation does
# not move it), aimed at its end, gives the field of the table with that row written out.
translation = [0.25, -0.5, 0.0]
aimed = DipoleField(GeneratorList=[-1, 0, 0, 0, 1, 0, 0.35, 0, 0, 1, 0, 0, 1, 0, 0, 0.35, 0, 0],  # noqa: F821
                    GeneratorsTranslation=translation, SelectedGenerator=1,
                    SelectedGeneratorLocation=[0.5, 0.5, 0.0], AimSelectedGenerator=1,
                    SelectedGeneratorTip=[0.5, 1.5, 0.0])
written = DipoleField(GeneratorList=[-1, 0, 0, 0, 1, 0, 0.35, 0, 0,  # noqa: F821
                                     0.25, 1.0, 0.0, 0, 1, 0, 0.35, 0, 0],
                      GeneratorsTranslation=translation)
fields = [servermanager.Fetch(proxy).GetPointData().GetArray("DisplacementSummedGenerators")
          for proxy in (aimed, written)]
difference = common.largest(abs(fields[0].GetValue(i) - fields[1].GetValue(i))
                            for i in range(fields[0].GetNumberOfValues()))
print("selected and aimed generator vs the row written out: %g" % difference)
if not difference < 1e-12:
    failures.append("the selected, aimed generator differs from its row written out by %g"
                    % difference)

# Time steps: 0 .. 1, and the field at t = 0 is zero.
source.NumberOfTimeSteps = 5
source.UpdatePipelineInformation()
times = list(source.TimestepValues)
if [round(t, 12) for t in times] != [0.0, 0.25, 0.5, 0.75, 1.0]:
    failures.append("time steps %r, expected 0, 0.25, ..., 1" % times)
source.UpdatePipeline(0.0)
at_zero = source.PointData["DisplacementSummedDisplacements"].GetRange(-1)
if at_zero[1] != 0.0:
    failures.append("at t = 0 the displacement is %g, expected 0" % at_zero[1])
source.NumberOfTimeSteps = 0
source.UpdatePipeline()

view = common.white_render_view([400, 400])
display = simple.Show(source, view)
display.Representation = "Surface"
simple.ColorBy(display, ("POINTS", "DisplacementDifferenceMagnitude"))
display.RescaleTransferFunctionToDataRange(True)
contours = simple.Contour(Input=source, ContourBy=["POINTS", "DipolePotential"],
                          Isosurfaces=[-0.3, -0.15, -0.05, 0.05, 0.15, 0.3])
contour_display = simple.Show(contours, view)
simple.ColorBy(contour_display, None)
contour_display.AmbientColor = contour_display.DiffuseColor = [0.0, 0.0, 0.0]
contour_display.LineWidth = 2
common.look_and_compare(view, [0, 0, 10], [0, 0, 0], [0, 1, 0], arguments, failures)

common.report(failures, "Dipole Field through the plugin")
