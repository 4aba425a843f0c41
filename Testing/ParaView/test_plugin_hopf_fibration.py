"""The plugin in pvpython: the Hopf Fibration source exists with its documented defaults, and its
three ways of choosing base points (grid, the repeatable Base Points list, the optional Sphere
Points input) and its twistor mesh work through the proxy."""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines HopfFibration()
from paraview import servermanager, simple  # noqa: E402

failures = []


def fiber_ids(proxy):
    data = servermanager.Fetch(proxy)
    array = data.GetPointData().GetArray("FiberId")
    return sorted({int(array.GetTuple1(i)) for i in range(data.GetNumberOfPoints())}), data


source = HopfFibration()  # noqa: F821
defaults = {
    "Mode": "Paper",
    "CircleCenter": [0.0, 0.0, 0.0],
    "CircleNormal": [0.0, 0.0, 1.0],
    "CircleRadius": 1.0,
    "SamplingMode": "Grid",
    "ThetaResolution": 8,
    "PhiResolution": 9,
    "FiberResolution": 128,
    "ClipRadius": 10.0,
    "OutputType": "Fibers",
}
common.check_defaults(source, defaults, failures)

# Grid: 8 x 9 fibers, with the documented arrays, nothing beyond the clip radius.
source.UpdatePipeline()
ids, data = fiber_ids(source)
if ids != list(range(72)):
    failures.append("grid gives fibers %r, expected 0..71" % (ids,))
for array in ("theta", "phi", "FiberId"):
    if data.GetPointData().GetArray(array) is None:
        failures.append("point array %s is missing" % array)
if not common.largest(abs(b) for b in data.GetBounds()) <= 10.0 + 1e-9:  # (NaN bounds fail)
    failures.append("points beyond the clip radius: bounds %r" % (data.GetBounds(),))

# Base Points: a repeatable (theta, phi) list.
source.SamplingMode = "Base Points"
# The table's two columns are named in the GUI, with the protocol of every table.
common.check_table(source, "Base Point", common.BASE_POINT_COLUMNS, failures)
source.BasePointList = [0.0, -1.0, 1.0, 0.0, 2.0, 0.5]
source.UpdatePipeline()
ids, data = fiber_ids(source)
if ids != [0, 1, 2]:
    failures.append("three base points give fibers %r" % (ids,))
phis = sorted({round(data.GetPointData().GetArray("phi").GetTuple1(i), 12)
               for i in range(data.GetNumberOfPoints())})
if phis != [-1.0, 0.0, 0.5]:
    failures.append("base points give phi values %r" % (phis,))

# Sphere Points input: the points of a sphere source, one fiber each.
sphere = simple.Sphere(Radius=2.0, ThetaResolution=6, PhiResolution=5)
source.SpherePoints = sphere
source.SamplingMode = "Input Points"
source.UpdatePipeline()
sphere_points = sphere.GetDataInformation().GetNumberOfPoints()
ids, data = fiber_ids(source)
if len(ids) != sphere_points:
    failures.append("%d sphere points give %d fibers" % (sphere_points, len(ids)))

# Twistor mesh over a meridian band: quads with normals.
mesh = HopfFibration(OutputType="Twistor Mesh", ThetaResolution=3, PhiResolution=10,  # noqa: F821
                     PhiRange=[-math.pi / 2, 1.0], FiberResolution=24)
mesh.UpdatePipeline()
info = mesh.GetDataInformation()
if info.GetNumberOfCells() != 3 * 9 * 24:
    failures.append("twistor mesh has %d cells, expected %d" % (info.GetNumberOfCells(), 3 * 9 * 24))
common.check_point_arrays(info, ("Normals", "TextureCoordinates", "StripId"), failures, what="mesh point array")

common.report(failures, "Hopf Fibration through the plugin")
