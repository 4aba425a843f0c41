"""The plugin in pvpython or pvbatch: the Point Pair Deformation filter exists with its documented
defaults, one generator of the table gives the closed form of docs/conventions.md section 2, the
optional Generators input and the selected-generator handle act as documented, and the Fig 11 sphere
renders like the baseline."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines PointPairDeformation()
from paraview import servermanager, simple  # noqa: E402

failures = []


def points_of(proxy):
    data = servermanager.Fetch(proxy)
    return [data.GetPoint(i) for i in range(data.GetNumberOfPoints())]


def largest_distance(a, b):
    if len(a) != len(b):
        return float("inf")
    return common.largest(math.dist(p, q) for p, q in zip(a, b))  # NaN if any is


sphere = simple.Sphere(Radius=1.0, ThetaResolution=32, PhiResolution=24)
deformation = PointPairDeformation(Input=sphere)  # noqa: F821
defaults = {
    "GeneratorList": [0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.5, 0.0, 0.0],
    "SelectedGenerator": -1,
    "Strength": 1.0,
    "Falloff": 1.0,
    "Epsilon": 0.01,
    "ExponentialRule": "Exact",
    "GeneratorDirectionArrayName": "Direction",
    "UseGeneratorWeightArray": 0,
    "TransformNormals": 1,
    "VectorArrays": [],
    "NormalArrays": [],
    "ComputeConformalScale": 0,
    "ComputeConformalityDefect": 0,
}
common.check_defaults(deformation, defaults, failures)
# The generator table: the same protocol and columns as the Dipole Field's.
common.check_table(deformation, "Generator", common.GENERATOR_COLUMNS, failures)

# One generator: p -> x + SCT_u(p - x) with u = -w v / (k |p - x|^2 + eps).
x, v, w, k, eps = (0.2, 0.0, 0.9), (0.0, 0.0, 1.0), 0.6, 4.0, 0.05
deformation.GeneratorList = list(x) + list(v) + [w, 0, 0]  # kind 0 (Point Pair), pitch 0
deformation.Falloff = k
deformation.Epsilon = eps
deformation.UpdatePipeline()
info = deformation.GetDataInformation()
if info.GetPointDataInformation().GetArrayInformation("Displacement") is None:
    failures.append("no Displacement array")
if info.GetPointDataInformation().GetArrayInformation("Normals") is None:
    failures.append("the Normals were not transformed (TransformNormals is on by default)")
source_points = points_of(sphere)
expected = []
for p in source_points:
    y = [p[i] - x[i] for i in range(3)]
    y2 = sum(c * c for c in y)
    u = [-w / (k * y2 + eps) * c for c in v]
    denominator = 1.0 + 2.0 * sum(u[i] * y[i] for i in range(3)) + sum(c * c for c in u) * y2
    expected.append([x[i] + (y[i] + u[i] * y2) / denominator for i in range(3)])
error = largest_distance(points_of(deformation), expected)
print("one generator vs closed form: %g" % error)
# `not error <= bound`, not `error > bound`: a NaN error must fail
if not error <= 1e-5:  # the sphere's points are float
    failures.append("one generator differs from the closed form by %g" % error)

# The arrays through the derivative: the sphere's normals copied into "Copy" (a plain point
# array), picked in Normal Arrays, come out as the transformed active normals; picked in Vector
# Arrays they are J n instead, another direction; the scalars are added when asked for.
copied = simple.Calculator(Input=sphere, ResultArrayName="Copy", Function="Normals")
for mode in ("NormalArrays", "VectorArrays"):
    through = PointPairDeformation(Input=copied, GeneratorList=list(x) + list(v) + [w, 0, 0],  # noqa: F821
                                   Falloff=k, Epsilon=eps, ComputeConformalScale=1,
                                   ComputeConformalityDefect=1, **{mode: ["Copy"]})
    data = servermanager.Fetch(through)
    normals, copy = data.GetPointData().GetNormals(), data.GetPointData().GetArray("Copy")
    largest = common.largest(math.dist(normals.GetTuple3(i), copy.GetTuple3(i))
                             for i in range(data.GetNumberOfPoints()))
    print("%s: Copy vs the transformed Normals: %g" % (mode, largest))
    if (not largest <= 1e-6) if mode == "NormalArrays" else (not largest >= 1e-2):
        failures.append("%s=['Copy'] did not transform it as documented (%g)" % (mode, largest))
    for name in ("ConformalScale", "ConformalityDefect"):
        if data.GetPointData().GetArray(name) is None:
            failures.append("no %s array" % name)

# The same generator from the optional Generators input: one point with Direction and w arrays.
point = simple.PointSource(Center=list(x), NumberOfPoints=1, Radius=0.0)
directions = simple.Calculator(Input=point, ResultArrayName="Direction",
                               Function="%g*iHat+%g*jHat+%g*kHat" % v)
weights = simple.Calculator(Input=directions, ResultArrayName="w", Function="%g" % w)
from_port = PointPairDeformation(Input=sphere, Generators=weights, GeneratorList=[],  # noqa: F821
                                 Falloff=k, Epsilon=eps, GeneratorDirectionArrayName="Direction",
                                 UseGeneratorWeightArray=1, GeneratorWeightArrayName="w")
error = largest_distance(points_of(from_port), points_of(deformation))
print("Generators input vs table: %g" % error)
if not error <= 1e-6:
    failures.append("the Generators input differs from the table by %g" % error)

# The handle moves the selected row.
moved = PointPairDeformation(Input=sphere, GeneratorList=[0.5, 0.5, 0.5] + list(v) + [w, 0, 0],  # noqa: F821
                             SelectedGenerator=0, SelectedGeneratorLocation=list(x),
                             Falloff=k, Epsilon=eps)
error = largest_distance(points_of(moved), points_of(deformation))
if not error <= 1e-12:
    failures.append("the selected generator did not take the handle's location (%g)" % error)

# The Kind column: a Rotation row (kind 1) turns p about the axis through x along v by
# w |v| / (k |p - x|^2 + eps) radians, right-handed (here v is z: a turn in the xy plane).
rotation = PointPairDeformation(Input=sphere, GeneratorList=list(x) + [0, 0, 2.0, w, 1, 0],  # noqa: F821
                                Falloff=k, Epsilon=eps)
expected = []
for p in source_points:
    c = w * 2.0 / (k * sum((p[i] - x[i]) ** 2 for i in range(3)) + eps)
    y = [p[i] - x[i] for i in range(3)]
    expected.append([x[0] + math.cos(c) * y[0] - math.sin(c) * y[1],
                     x[1] + math.sin(c) * y[0] + math.cos(c) * y[1], p[2]])
error = largest_distance(points_of(rotation), expected)
print("a Rotation row vs closed form: %g" % error)
if not error <= 1e-5:  # the sphere's points are float
    failures.append("a Rotation row differs from the closed form by %g" % error)

# Fig 11 style image: four generators around the sphere.
deformation.GeneratorList = [0.0, 0.0, 1.4, 0, 0, 1, 0.6, 0, 0,
                             1.4, 0.0, 0.2, 1, 0, 0, -0.5, 0, 0,
                             -0.4, -1.4, -0.4, 0, 1, 0, 0.5, 0, 0,
                             -0.7, 0.9, -1.0, -1, 1, -1, 0.4, 0, 0]
deformation.Falloff = 4.0
view = common.white_render_view([400, 400])
normals = simple.GenerateSurfaceNormals(Input=deformation, Splitting=0)
display = simple.Show(normals, view)
simple.ColorBy(display, ("POINTS", "Displacement", "Magnitude"))
display.LookupTable.RescaleTransferFunction(0.0, 0.6)
common.look_and_compare(view, [0.6, -4.0, 2.4], [0.0, 0.0, 0.0], [0.0, 0.0, 1.0], arguments,
                        failures)

common.report(failures, "Point Pair Deformation through the plugin")
