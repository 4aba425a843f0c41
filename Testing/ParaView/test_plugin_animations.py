"""The plugin in pvpython: every source and the filter play their time sweep (NumberOfTimeSteps)
in ParaView's animation scene, and the first and the last frame equal the static outputs, point
for point (the sweep's start, and the current parameters); and merged seams (MergeSeam) give
closed meshes that survive STL and PLY exports with their point and cell counts."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())
from paraview import simple  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkPolyData  # noqa: E402
import math  # noqa: E402

failures = []
STEPS = 6


def output_copy(proxy):
    """A copy of the output the proxy's algorithm produced last (pvpython: the builtin session)."""
    data = proxy.GetClientSideObject().GetOutputDataObject(0)
    copy = data.NewInstance()
    copy.DeepCopy(data)
    return copy


def static_output(factory, parameters):
    proxy = factory(**parameters)
    proxy.UpdatePipeline()
    copy = output_copy(proxy)
    simple.Delete(proxy)
    return copy


def difference(expected, actual, array=None):
    """None when both have the same cells and the same points (or point array), bit for bit."""
    if (expected.GetNumberOfPoints(), expected.GetNumberOfCells()) != \
            (actual.GetNumberOfPoints(), actual.GetNumberOfCells()):
        return "%d points %d cells, expected %d and %d" % (
            actual.GetNumberOfPoints(), actual.GetNumberOfCells(),
            expected.GetNumberOfPoints(), expected.GetNumberOfCells())
    if expected.GetNumberOfPoints() == 0:
        return "no points"
    for i in range(expected.GetNumberOfPoints()):
        if array:
            a = expected.GetPointData().GetArray(array).GetTuple(i)
            b = actual.GetPointData().GetArray(array).GetTuple(i)
        else:
            a, b = expected.GetPoint(i), actual.GetPoint(i)
        if a != b:
            return "point %d is %r, expected %r" % (i, b, a)
    return None


def play(label, factory, parameters, start, array=None, make_input=None):
    """Plays the proxy's time steps in the animation scene; frame 0 must be the static output of
    `parameters` updated with `start`, the last frame the static output of `parameters`."""
    extra = {"Input": make_input()} if make_input else {}
    proxy = factory(NumberOfTimeSteps=STEPS, **dict(parameters, **extra))
    proxy.UpdatePipelineInformation()
    times = list(proxy.TimestepValues)
    expected_times = [k / (STEPS - 1.0) for k in range(STEPS)]
    if [round(t, 12) for t in times] != [round(t, 12) for t in expected_times]:
        failures.append("%s: time steps %r" % (label, times))
    view = simple.CreateRenderView()
    simple.Show(proxy, view)
    scene = simple.GetAnimationScene()
    scene.UpdateAnimationUsingDataTimeSteps()
    frames = []
    for time in times:  # each frame of the animation, as the VCR's Next gives them
        scene.AnimationTime = time
        simple.Render(view)  # the representation updates the proxy at the scene's time
        frames.append((time, output_copy(proxy)))
    if len(frames) != STEPS:
        failures.append("%s: %d frames played, expected %d" % (label, len(frames), STEPS))
    first = static_output(factory, dict(parameters, **dict(start, **extra)))
    last = static_output(factory, dict(parameters, **extra))
    for name, (time, frame), still in (("first", frames[0], first), ("last", frames[-1], last)):
        problem = difference(still, frame, array)
        print("%s: %s frame at t = %g: %s" % (label, name, time, problem or "the static output"))
        if problem:
            failures.append("%s: %s frame: %s" % (label, name, problem))
    # Frames in between differ from both ends (the sweep moves).
    if difference(first, frames[STEPS // 2][1], array) is None or \
            difference(last, frames[STEPS // 2][1], array) is None:
        failures.append("%s: the middle frame equals an end" % label)
    simple.Delete(proxy)
    simple.Delete(view)


play("Boosted Surface", BoostedSurface,  # noqa: F821
     dict(LambdaRange=[0.0, 4.0], LambdaResolution=32, ThetaResolution=32),
     dict(LambdaRange=[0.0, 0.0]))
play("Hopf Fibration (Fig 4)", HopfFibration,  # noqa: F821
     dict(OutputType="Twistor Mesh", ThetaRange=[0.0, 0.0], ThetaResolution=1,
          PhiRange=[-math.pi / 2, 1.3], PhiResolution=24, FiberResolution=48, ClipRadius=3.0),
     dict(PhiRange=[-math.pi / 2, -math.pi / 2]))
play("Curvature Patch", CurvaturePatch,  # noqa: F821
     dict(CurvaturePreset="Hyperbolic", UResolution=16, VResolution=16),
     dict(CurvaturePreset="Custom", KappaU=0.0, KappaV=0.0))
play("Dipole Field", DipoleField,  # noqa: F821
     dict(GeneratorList=[0, 0, 0, 1, 0, 0, 0.5, 0, 0]),
     dict(GeneratorList=[0, 0, 0, 1, 0, 0, 0.0, 0, 0]), array="DisplacementSummedGenerators")
play("Conformal Orbit (trefoil)", ConformalOrbit,  # noqa: F821
     dict(TResolution=64),
     dict(ClosePeriodicOrbits=0, TRange=[0.0, 0.0]))
play("Point Pair Deformation", PointPairDeformation,  # noqa: F821
     dict(GeneratorList=[0, 0, 0.7, 0, 0, 1, 0.5, 0, 0], Strength=2.0),
     dict(Strength=0.0),
     make_input=lambda: simple.Sphere(ThetaResolution=24, PhiResolution=12))

# Merged seams: Hopf tori (Latitudes over a full turn) and the boosted tube.
for label, factory, parameters, boundary in (
        ("Hopf tori", HopfFibration,  # noqa: F821
         dict(OutputType="Twistor Mesh", MeshSweep="Latitudes", ThetaResolution=24,
              PhiRange=[-1.2, 0.9], PhiResolution=3, FiberResolution=32, ClipRadius=1e6), 0),
        ("Boosted tube", BoostedSurface,  # noqa: F821
         dict(LambdaResolution=16, ThetaResolution=32), 2 * 32)):
    merged = factory(MergeSeam=1, **parameters)
    edges = simple.FeatureEdges(Input=merged, BoundaryEdges=1, FeatureEdges=0,
                                NonManifoldEdges=0, ManifoldEdges=0)
    edges.UpdatePipeline()
    found = edges.GetDataInformation().GetNumberOfCells()
    print("%s: %d boundary edges merged" % (label, found))
    if found != boundary:
        failures.append("%s: %d boundary edges, expected %d" % (label, found, boundary))
    non_manifold = simple.FeatureEdges(Input=merged, BoundaryEdges=0, FeatureEdges=0,
                                       NonManifoldEdges=1, ManifoldEdges=0)
    non_manifold.UpdatePipeline()
    if non_manifold.GetDataInformation().GetNumberOfCells() != 0:
        failures.append("%s: non-manifold edges" % label)
    mesh = output_copy(merged)
    triangles = simple.Triangulate(Input=merged)
    triangles.UpdatePipeline()
    for extension, cells in ((".ply", mesh.GetNumberOfCells()),
                             (".stl", triangles.GetDataInformation().GetNumberOfCells())):
        path = os.path.join(arguments.output_dir, "Animations_%s%s" % (label.replace(" ", ""),
                                                                     extension))
        simple.SaveData(path, proxy=merged)
        reader = simple.OpenDataFile(path)
        reader.UpdatePipeline()
        info = reader.GetDataInformation()
        print("%s%s: %d points %d cells read back (written %d and %d)" % (
            label, extension, info.GetNumberOfPoints(), info.GetNumberOfCells(),
            mesh.GetNumberOfPoints(), cells))
        if (info.GetNumberOfPoints(), info.GetNumberOfCells()) != (mesh.GetNumberOfPoints(), cells):
            failures.append("%s%s: %d points %d cells read back, expected %d and %d" % (
                label, extension, info.GetNumberOfPoints(), info.GetNumberOfCells(),
                mesh.GetNumberOfPoints(), cells))
        simple.Delete(reader)
        os.remove(path)

common.report(failures, "time sweeps and merged seams through the plugin")
