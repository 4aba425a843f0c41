"""Run under `mpiexec -np N pvbatch`: the "Generators" output port of every class with generators
comes once over N ranks (from rank 0, like the orbit source's cores), not once per rank: its
points summed over the ranks and those gathered on the root are those of one process, while
output 0 is still split among the ranks."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())
from paraview import servermanager  # noqa: E402

failures = []
ranks = common.mpi_ranks(failures)

sphere = Sphere(ThetaResolution=32, PhiResolution=32)  # noqa: F821 (paraview.simple)
cases = {
    "Dipole Field": (lambda: DipoleField(GeneratorList=[  # noqa: F821
        -0.5, 0, 0, 1, 0, 0, 0.5, 0, 0, 0.5, 0, 0, 0, 1, 0, 0.5, 1, 0]), 1),
    "Curvature Patch": (lambda: CurvaturePatch(Method="Bilinear"), 1),  # noqa: F821
    "Hopf Fibration": (lambda: HopfFibration(), 1),  # noqa: F821
    "Conformal Orbit": (lambda: ConformalOrbit(), 2),  # noqa: F821
    "Point Pair Deformation": (lambda: PointPairDeformation(  # noqa: F821
        Input=sphere, GeneratorList=[0, 0, 0, 1, 0, 0, 0.5, 0, 0, 0, 0, 1, 0, 0, 1, 0.3, 1, 0]), 1),
}
for label, (make, port) in cases.items():
    proxy = make()
    proxy.UpdatePipeline()
    algorithm = make().GetClientSideObject()
    algorithm.UpdatePiece(0, 1, 0)
    single = algorithm.GetOutputDataObject(port)
    distributed = proxy.GetDataInformation(port)  # summed over the ranks
    gathered = servermanager.Fetch(proxy, idx=port)  # every rank's piece, appended on the root
    print("%s: %d ranks: %d generator points over the ranks, %d gathered; one process: %d"
          % (label, ranks, distributed.GetNumberOfPoints(), gathered.GetNumberOfPoints(),
             single.GetNumberOfPoints()))
    if single.GetNumberOfPoints() == 0:
        failures.append("%s: no generators in one process" % label)
    if distributed.GetNumberOfPoints() != single.GetNumberOfPoints() or \
            gathered.GetNumberOfPoints() != single.GetNumberOfPoints():
        failures.append("%s: %d generator points over the ranks (%d gathered), %d in one process"
                        % (label, distributed.GetNumberOfPoints(), gathered.GetNumberOfPoints(),
                           single.GetNumberOfPoints()))
    for i in range(gathered.GetNumberOfPoints()):
        if gathered.GetPoint(i) != single.GetPoint(i):
            failures.append("%s: generator %d is at %r over the ranks, %r in one process"
                            % (label, i, gathered.GetPoint(i), single.GetPoint(i)))
            break

common.report(failures, "the Generators ports over MPI ranks")
