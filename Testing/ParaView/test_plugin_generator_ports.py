"""pvpython: every proxy's Generators port is shown as 3D Glyphs (arrows, orientation array
Direction, scale array Weight) by the plugin's representation hint, aimed (Orient on, Direction
mode) and all one length, 0.2 times the largest extent of output 0 and the generators together
(the plugin's GeneratorArrowDefaults), its other ports as before; a value the user passes to
Show() and a loaded state's values are kept; and the Point Pair Deformation filter created as the GUI creates it (inputs first, then the
domains' defaults) takes the Generators input's only vector array as its direction array."""
import os
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())
from paraview import servermanager  # noqa: E402
from paraview import simple  # noqa: E402



def largest_extent(*ports):
    """The largest extent of the points of the fetched outputs together, point by point."""
    import numpy
    points = []
    for proxy, port in ports:
        data = servermanager.Fetch(proxy, None, port)
        leaves = [data]
        if data.IsA("vtkCompositeDataSet"):
            iterator = data.NewIterator()
            iterator.InitTraversal()
            leaves = []
            while not iterator.IsDoneWithTraversal():
                leaves.append(iterator.GetCurrentDataObject())
                iterator.GoToNextItem()
        for leaf in leaves:
            points.extend(leaf.GetPoint(i) for i in range(leaf.GetNumberOfPoints()))
    every = numpy.array(points)
    return float((every.max(axis=0) - every.min(axis=0)).max())


failures = []
view = simple.GetActiveViewOrCreate("RenderView")
sphere = simple.Sphere()
deformed = PointPairDeformation(Input=sphere)  # noqa: F821
# label: (proxy, Generators port, number of ports, output 0's representation)
proxies = {
    "Dipole Field": (DipoleField(), 1, 2, "Slice"),  # noqa: F821
    "Curvature Patch": (CurvaturePatch(), 1, 2, "Surface"),  # noqa: F821
    "Hopf Fibration": (HopfFibration(), 1, 2, "Surface"),  # noqa: F821
    "Conformal Orbit": (ConformalOrbit(), 2, 3, "Surface"),  # noqa: F821
    "Point Pair Deformation": (deformed, 1, 2, "Surface"),
    "Point Pair Fit": (PointPairFit(Input=sphere, Target=deformed), 1, 3, "Surface"),  # noqa: F821
}
for label, (proxy, port, ports, first) in proxies.items():
    if proxy.GetNumberOfOutputPorts() != ports:
        failures.append("%s: %d output ports" % (label, proxy.GetNumberOfOutputPorts()))
        continue
    display = simple.Show(simple.OutputPort(proxy, port), view)
    seen = (display.Representation, display.GlyphType.GetXMLLabel(),
            display.SelectOrientationVectors, display.SelectScaleArray)
    print("%s: Generators port shown as %r" % (label, seen))
    if seen != ("3D Glyphs", "Arrow", "Direction", "Weight"):
        failures.append("%s: the Generators port is shown as %r" % (label, seen))
    aim = (display.Orient, display.OrientationMode, display.Scaling, display.ScaleMode)
    print("%s: Orient, OrientationMode, Scaling, ScaleMode = %r, ScaleFactor %g"
          % (label, aim, display.ScaleFactor))
    if aim != (1, "Direction", 1, "No Data Scaling Off"):
        failures.append("%s: the arrows are not aimed and sized: %r" % (label, aim))
    expected = 0.2 * largest_extent((proxy, 0), (proxy, port))
    if not abs(display.ScaleFactor - expected) <= 1e-12 * expected:  # (a NaN fails too)
        failures.append("%s: ScaleFactor %r, not 0.2 x the largest extent = %r"
                        % (label, display.ScaleFactor, expected))
    if simple.Show(simple.OutputPort(proxy, 0), view).Representation != first:
        failures.append("%s: output 0 is no longer shown as %s" % (label, first))

# What the user passes to Show() wins over the plugin's defaults.
dipoles = DipoleField(registrationName="UnaimedDipoles")  # noqa: F821
display = simple.Show(simple.OutputPort(dipoles, 1), view, Orient=0, ScaleFactor=0.5)
if (display.Orient, display.ScaleFactor) != (0, 0.5):
    failures.append("Show(..., Orient=0, ScaleFactor=0.5) gives %r"
                    % ((display.Orient, display.ScaleFactor),))

# A state's values are kept when it is loaded (in a new session, as the GUI's File > Load State).
display.Orient = 0
display.Scaling = 0
state = os.path.join(tempfile.mkdtemp(), "unaimed.pvsm")
simple.SaveState(state)
simple.ResetSession()
common.load_plugin(arguments.plugin, globals())
simple.LoadState(state)
loaded = simple.FindSource("UnaimedDipoles")
if loaded is None:
    failures.append("the state has no UnaimedDipoles")
else:
    reloaded = simple.GetDisplayProperties(simple.OutputPort(loaded, 1),
                                           simple.GetActiveViewOrCreate("RenderView"))
    print("after loading the state: Orient %r, Scaling %r" % (reloaded.Orient, reloaded.Scaling))
    if (reloaded.Orient, reloaded.Scaling) != (0, 0):
        failures.append("loading a state changed Orient, Scaling to %r"
                        % ((reloaded.Orient, reloaded.Scaling),))
    # The hook follows the new session: a port shown now is aimed again.
    fresh = simple.Show(simple.OutputPort(CurvaturePatch(), 1),  # noqa: F821
                        simple.GetActiveViewOrCreate("RenderView"))
    if fresh.Orient != 1:
        failures.append("after ResetSession the Generators arrows are not aimed")
view = simple.GetActiveViewOrCreate("RenderView")
sphere = simple.Sphere()

# The GUI sets the inputs before the domains give the other properties their defaults.
points = simple.Calculator(Input=simple.PointSource(NumberOfPoints=3), ResultArrayName="Aim",
                           Function="coordsX*iHat+jHat")
points.UpdatePipeline()
raw = servermanager.ProxyManager().SMProxyManager.NewProxy("filters", "PointPairDeformationFilter")
controller = servermanager.ParaViewPipelineController()
controller.PreInitializeProxy(raw)
deformation = servermanager._getPyProxy(raw)
deformation.Input = sphere
deformation.Generators = points
raw.UpdateVTKObjects()
controller.PostInitializeProxy(raw)
print("direction array picked from the Generators input: %r" % deformation.GeneratorDirectionArrayName)
if deformation.GeneratorDirectionArrayName != "Aim":
    failures.append("the direction array is %r, not the input's only vector array 'Aim'"
                    % deformation.GeneratorDirectionArrayName)
deformation.UpdatePipeline()
if deformation.GetDataInformation(1).GetNumberOfPoints() != 1 + 3:  # the default row, the input's
    failures.append("the filter gives %d generators for its row and the input's 3 points"
                    % deformation.GetDataInformation(1).GetNumberOfPoints())

common.report(failures, "the Generators ports in pvpython")
