"""The plugin in pvpython: the Point Pair Fit filter exists with its documented defaults and the
one generator table, recovers the weights of a Point Pair Deformation of a sphere from its Target
input (to 1e-6, RMS residual <= 1e-10), puts the summary in its field data, and its Generators
output drives a Point Pair Deformation to the same mesh."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines PointPairFit(), PointPairDeformation()
from paraview import servermanager, simple  # noqa: E402

failures = []
sphere = simple.Sphere(Radius=1.0, ThetaResolution=24, PhiResolution=16)
truth = [0.0, 0.0, 1.5, 0.0, 0.0, 1.0, 0.3, 0, 0,
         1.4, 0.0, 0.2, 1.0, 0.0, 0.0, -0.25, 0, 0]
# Double output points: the fit then reaches the round-off of the deformation itself.
target = PointPairDeformation(Input=sphere, GeneratorList=truth,  # noqa: F821
                              OutputPointsPrecision="Double")
start = list(truth)
start[6] = start[15] = 0.0
fit = PointPairFit(Input=sphere, Target=target)  # noqa: F821
common.check_defaults(fit, {
    "GeneratorList": [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0],
    "SelectedGenerator": -1, "SelectedGeneratorLocation": [0.0, 0.0, 0.0],
    "AimSelectedGenerator": 0, "SelectedGeneratorTip": [0.0, 0.0, 1.0],
    "TargetMode": "Point To Point",
    "FitWeights": 1, "FitLocations": 0, "FitDirections": 0,
    "RegularizationWeight": 0.0, "WeightRange": [-1000.0, 1000.0],
    "MaximumLocationChange": 0.25, "MaximumDirectionChange": 1.0,
    "MaximumNumberOfIterations": 100, "Strength": 1.0, "Falloff": 1.0, "Epsilon": 0.01,
    "ExponentialRule": "Exact", "UseGeneratorWeightArray": 0,
}, failures)
common.check_table(fit, "Generator", common.GENERATOR_COLUMNS, failures)
fit.GeneratorList = start
fit.OutputPointsPrecision = "Double"
fit.UpdatePipeline()

table = servermanager.Fetch(fit, None, None, 2)
for row, expected in ((0, truth[6]), (1, truth[15])):
    weight = table.GetValueByName(row, "Weight").ToDouble() if table.GetNumberOfRows() > row \
        else math.nan
    print("weight %d: %.12g (expected %g)" % (row, weight, expected))
    if not abs(weight - expected) <= 1e-6:
        failures.append("weight %d is %r, expected %r" % (row, weight, expected))
mesh = servermanager.Fetch(fit)
final = mesh.GetFieldData().GetArray("FitFinalRMS")
print("final RMS residual:", final.GetValue(0) if final else None)
if final is None or not final.GetValue(0) <= 1e-10:
    failures.append("FitFinalRMS is %r" % (final.GetValue(0) if final else None))
common.check_point_arrays(fit.GetDataInformation(), ["FitResidual", "Displacement"], failures)
termination = mesh.GetFieldData().GetAbstractArray("FitTermination")
if termination is None or not termination.GetValue(0).startswith("CONVERGENCE"):
    failures.append("FitTermination: %r" % (termination.GetValue(0) if termination else None))

# The Generators output (port 1) drives a Point Pair Deformation to the fitted mesh.
generators = simple.OutputPort(fit, 1)
again = PointPairDeformation(Input=sphere, Generators=generators, GeneratorList=[],  # noqa: F821
                             UseGeneratorWeightArray=1, OutputPointsPrecision="Double")
ours, theirs = mesh, servermanager.Fetch(again)
difference = common.largest(math.dist(ours.GetPoint(i), theirs.GetPoint(i))
                 for i in range(ours.GetNumberOfPoints())) if ours.GetNumberOfPoints() == \
    theirs.GetNumberOfPoints() else math.inf
print("fitted mesh vs the deformation of the Generators output: %g" % difference)
if difference != 0.0:
    failures.append("the Generators output deforms to another mesh (%g)" % difference)

common.report(failures, "Point Pair Fit through the plugin")
