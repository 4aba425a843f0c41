"""The plugin's four tables (Generator List of the deformation filter and of the Dipole Field,
Base Point List of the Hopf Fibration, Control Point List of the Curvature Patch) in pvpython:
their rows reach the VTK object, survive a state file saved and loaded again, and a table of more
than 10^6 rows gives one error and an empty output instead of an error per row."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())
from paraview import servermanager, simple  # noqa: E402
from vtkmodules.vtkCommonCore import vtkOutputWindow, vtkStringOutputWindow  # noqa: E402

failures = []
MAXIMUM_ROWS = 1000000  # vtkBoostedRowList::MaximumRows


def tables():
    """(proxy name, row name, columns, rows) of each table, with rows other than the defaults."""
    # A rotation and a twist of pitch 0.3 (kinds 1 and 2).
    generators = [0.1, 0.2, 0.3, 0.0, 0.0, 1.0, 0.5, 1, 0.0,
                  -0.4, 0.0, 0.2, 1.0, 0.0, 0.0, -0.25, 2, 0.3]
    # The Hopf source first: created later it would take the active source as its input.
    proxies = {
        "Hopf": HopfFibration(registrationName="Hopf", SamplingMode="Base Points",  # noqa: F821
                              BasePointList=[0.5, -0.25, 2.0, 0.75, -1.0, 1.0]),
        "Patch": CurvaturePatch(registrationName="Patch", Method="Control Points",  # noqa: F821
                                ControlPointList=[-1, 0, 0, 0, 0, 1, 1, 0, 0, 0.5, 0.5,
                                                  1, 0, 0, 0, 0, 1, 1, 0, 0, -0.5, 0.5]),
        "Dipole": DipoleField(registrationName="Dipole", GeneratorList=generators),  # noqa: F821
    }
    sphere = simple.Sphere(registrationName="Mesh")
    proxies["Deformation"] = PointPairDeformation(registrationName="Deformation",  # noqa: F821
                                                  Input=sphere, GeneratorList=generators)
    return proxies, [("Deformation", "Generator", common.GENERATOR_COLUMNS),
                     ("Dipole", "Generator", common.GENERATOR_COLUMNS),
                     ("Hopf", "Base Point", common.BASE_POINT_COLUMNS),
                     ("Patch", "Control Point", common.CONTROL_POINT_COLUMNS)]


def output_of(proxy):
    """What the rows made: the output's point count and bounds (or the Dipole's field range)."""
    proxy.UpdatePipeline()
    info = proxy.GetDataInformation()
    field = info.GetPointDataInformation().GetArrayInformation("DisplacementSummedGenerators")
    return (info.GetNumberOfPoints(), info.GetBounds(),
            field.GetComponentRange(-1) if field else None)


proxies, layout = tables()
expected = {}
for key, row, columns in layout:
    proxy = proxies[key]
    common.check_table(proxy, row, columns, failures)
    table = list(proxy.GetPropertyValue(row.replace(" ", "") + "List"))
    expected[key] = (table, output_of(proxy))
    if expected[key][1][0] == 0:
        failures.append("%s: empty output" % key)
    # One row less changes the output: the rows reach the VTK object.
    setattr(proxy, row.replace(" ", "") + "List", table[:-len(columns)])
    if output_of(proxy) == expected[key][1]:
        failures.append("%s: dropping the last row changed nothing" % key)
    setattr(proxy, row.replace(" ", "") + "List", table)
    if output_of(proxy) != expected[key][1]:
        failures.append("%s: the table set again gives another output" % key)

# The tables survive a state file.
state = os.path.join(tempfile.mkdtemp(), "tables.pvsm")
simple.SaveState(state)
simple.ResetSession()
simple.LoadState(state)
for key, row, columns in layout:
    proxy = simple.FindSource(key)
    if proxy is None:
        failures.append("%s is missing after loading the state" % key)
        continue
    loaded = (list(proxy.GetPropertyValue(row.replace(" ", "") + "List")), output_of(proxy))
    if loaded != expected[key]:
        failures.append("%s: table and output after loading the state are %r, expected %r"
                        % (key, loaded, expected[key]))

# More rows than a list holds (the two-value table keeps the test short): one error when the
# table is pushed, one per update, an empty output; a table within the cap works again.
messages = vtkStringOutputWindow()
vtkOutputWindow.SetInstance(messages)
hopf = simple.FindSource("Hopf")
hopf.BasePointList = [0.5, 0.25] * (MAXIMUM_ROWS + 1)
pushed = messages.GetOutput().count("ERROR")
hopf.UpdatePipeline()
errors = messages.GetOutput().count("ERROR")
if pushed != 1 or errors != 2:
    failures.append("a table of %d rows gave %d errors when pushed and %d in all, expected 1 and 2"
                    % (MAXIMUM_ROWS + 1, pushed, errors))
if hopf.GetDataInformation().GetNumberOfPoints() != 0:
    failures.append("a table of %d rows gave a non-empty output" % (MAXIMUM_ROWS + 1))
if "1000001 rows" not in messages.GetOutput():
    failures.append("the error does not say how many rows were given: %s"
                    % messages.GetOutput()[-400:])
hopf.BasePointList = [0.5, 0.25]
hopf.UpdatePipeline()
if hopf.GetDataInformation().GetNumberOfPoints() == 0:
    failures.append("a table of one row after the refused one gives an empty output")
vtkOutputWindow.SetInstance(None)

common.report(failures, "the plugin's tables")
