"""The plugin in pvpython (and pvbatch): the Conformal Orbit source exists with its documented
defaults, the torus knot closes after its period with its two cores on the second output, the
generator table (with kinds) and the seed table follow the one table protocol, seeds come from an
input, and the trefoil renders as its baseline image."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines ConformalOrbit()
from paraview import servermanager, simple  # noqa: E402

failures = []

source = ConformalOrbit()  # noqa: F821
defaults = {
    "GeneratorType": "Torus Knot",
    "SelectedGenerator": -1,
    "SelectedGeneratorLocation": [0.0, 0.0, 0.0],
    "AimSelectedGenerator": 0,
    "SelectedGeneratorTip": [0.0, 0.0, 1.0],
    "KnotP": 2,
    "KnotQ": 3,
    "KnotCenter": [0.0, 0.0, 0.0],
    "KnotNormal": [0.0, 0.0, 1.0],
    "KnotDirection": [1.0, 0.0, 0.0],
    "KnotRadius": 1.0,
    "SeedMode": "Seed Point",
    "SeedPoint": [0.15, 0.0, 0.0],
    "TRange": [0.0, 1.0],
    "TResolution": 512,
    "ClosePeriodicOrbits": 1,
    "CoreResolution": 256,
    "ClipRadius": 100.0,
}
common.check_defaults(source, defaults, failures)

# The trefoil: one closed polyline of 512 points over the period 6, the cores on output 1.
source.UpdatePipeline()
data = servermanager.Fetch(source)
period = data.GetFieldData().GetArray("Period").GetValue(0)
if not abs(period - 6.0) <= 1e-12:  # (`> 1e-12` would pass a NaN period)
    failures.append("the trefoil's period is %r, expected 6" % period)
if data.GetNumberOfPoints() != 512 or data.GetNumberOfLines() != 1:
    failures.append("the trefoil has %d points in %d lines" % (data.GetNumberOfPoints(), data.GetNumberOfLines()))
common.check_point_arrays(source.GetDataInformation(), ("t", "OrbitId"), failures)
core_data = servermanager.Fetch(source, idx=1)
if core_data.GetNumberOfLines() != 2:
    failures.append("the cores output has %d lines, expected 2" % core_data.GetNumberOfLines())

# The generator table (rows of every kind) and the seed table.
source.GeneratorType = "Generator List"
common.check_table(source, "Generator", common.GENERATOR_COLUMNS, failures)
source.GeneratorList = [0, 0, 0, 0, 0, 1, 1, 1, 0]  # a rotation about z: period 2 pi
source.SeedMode = "Seed List"
common.check_table(source, "Seed", common.SEED_COLUMNS, failures)
source.SeedList = [1, 0, 0, 2, 0, 0.5, 0.5, 0.5, 0]
source.UpdatePipeline()
data = servermanager.Fetch(source)
period = data.GetFieldData().GetArray("Period").GetValue(0)
if not abs(period - 6.283185307179586) <= 1e-12:
    failures.append("a unit rotation row has the period %r, expected 2 pi" % period)
if data.GetNumberOfLines() != 3:
    failures.append("three seeds give %d orbits" % data.GetNumberOfLines())

# Seeds from an input: one orbit per point.
points = simple.PointSource(NumberOfPoints=5, Center=[1.15, 0, 0], Radius=0.05)
source.Seeds = points
source.SeedMode = "Input Points"
source.GeneratorType = "Torus Knot"
source.KnotCenter = [1.0, 0.0, 0.0]  # the seeds then lie on tori about A
source.UpdatePipeline()
if source.GetDataInformation().GetNumberOfCells() != 5:
    failures.append("five input points give %d orbits" % source.GetDataInformation().GetNumberOfCells())

# The trefoil as tubes, against the baseline.
knot = ConformalOrbit(TResolution=600)  # noqa: F821
tubes = simple.Tube(Input=knot, Radius=0.04, NumberofSides=12)
common.render_and_compare(tubes, "t", [0.5, -3.0, 4.0], [0.0, 0.0, 0.0], [0, 0, 1], arguments,
                          failures)

common.report(failures, "Conformal Orbit in %s" % os.path.basename(sys.executable))
