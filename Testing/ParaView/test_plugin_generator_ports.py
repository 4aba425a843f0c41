"""pvpython: every proxy's Generators port is shown as 3D Glyphs (arrows, orientation array
Direction, scale array Weight) by the plugin's representation hint, its other ports as before;
and the Point Pair Deformation filter created as the GUI creates it (inputs first, then the
domains' defaults) takes the Generators input's only vector array as its direction array."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())
from paraview import servermanager  # noqa: E402
from paraview import simple  # noqa: E402

failures = []
view = simple.GetActiveViewOrCreate("RenderView")
sphere = simple.Sphere()
proxies = {
    "Dipole Field": (DipoleField(), 1, "Slice"),  # noqa: F821
    "Curvature Patch": (CurvaturePatch(), 1, "Surface"),  # noqa: F821
    "Hopf Fibration": (HopfFibration(), 1, "Surface"),  # noqa: F821
    "Conformal Orbit": (ConformalOrbit(), 2, "Surface"),  # noqa: F821
    "Point Pair Deformation": (PointPairDeformation(Input=sphere), 1, "Surface"),  # noqa: F821
}
for label, (proxy, port, first) in proxies.items():
    if proxy.GetNumberOfOutputPorts() != port + 1:
        failures.append("%s: %d output ports" % (label, proxy.GetNumberOfOutputPorts()))
        continue
    display = simple.Show(simple.OutputPort(proxy, port), view)
    seen = (display.Representation, display.GlyphType.GetXMLLabel(),
            display.SelectOrientationVectors, display.SelectScaleArray)
    print("%s: Generators port shown as %r" % (label, seen))
    if seen != ("3D Glyphs", "Arrow", "Direction", "Weight"):
        failures.append("%s: the Generators port is shown as %r" % (label, seen))
    if simple.Show(simple.OutputPort(proxy, 0), view).Representation != first:
        failures.append("%s: output 0 is no longer shown as %s" % (label, first))

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
