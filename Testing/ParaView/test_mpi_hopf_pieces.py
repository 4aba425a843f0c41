"""Run under `mpiexec -np N pvbatch`: the Hopf Fibration source split over N ranks gives the same
fibers as one process. Each rank generates its share of the fibers; the gathered fibers are
compared point by point, by FiberId."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines HopfFibration()
from paraview import servermanager  # noqa: E402

ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
failures = []
if ranks < 2:
    failures.append("expected at least 2 MPI ranks, got %d" % ranks)


def fibers(polydata):
    """FiberId -> list of points, in output order."""
    ids = polydata.GetPointData().GetArray("FiberId")
    out = {}
    for i in range(polydata.GetNumberOfPoints()):
        out.setdefault(int(ids.GetTuple1(i)), []).append(polydata.GetPoint(i))
    return out


for mode in ("Paper", "Classical"):
    for output_type in ("Fibers", "Twistor Mesh"):
        parameters = dict(Mode=mode, OutputType=output_type, ThetaResolution=5, PhiResolution=7,
                          FiberResolution=32)
        source = HopfFibration(**parameters)  # noqa: F821
        source.UpdatePipeline()
        distributed = source.GetDataInformation()  # summed over the ranks
        gathered = servermanager.Fetch(source)  # all pieces appended, on this (root) process

        single_algorithm = HopfFibration(**parameters).GetClientSideObject()  # noqa: F821
        single_algorithm.UpdatePiece(0, 1, 0)
        single = single_algorithm.GetOutput()
        label = "%s %s" % (mode, output_type)
        print("%s: %d ranks: %d points %d cells; one process: %d points %d cells"
              % (label, ranks, distributed.GetNumberOfPoints(), distributed.GetNumberOfCells(),
                 single.GetNumberOfPoints(), single.GetNumberOfCells()))
        if distributed.GetNumberOfCells() != single.GetNumberOfCells():
            failures.append("%s: %d cells over the ranks, %d in one process"
                            % (label, distributed.GetNumberOfCells(), single.GetNumberOfCells()))
        if gathered.GetNumberOfCells() != single.GetNumberOfCells():
            failures.append("%s: %d cells gathered, %d in one process"
                            % (label, gathered.GetNumberOfCells(), single.GetNumberOfCells()))
        got, expected = fibers(gathered), fibers(single)
        if output_type == "Fibers":
            # whole fibers go to one rank each: the same fibers, point for point
            if sorted(got) != sorted(expected):
                failures.append("%s: fiber ids differ" % label)
            for fiber_id, points in expected.items():
                if got.get(fiber_id) != points:
                    failures.append("%s: fiber %d differs" % (label, fiber_id))
                    break
        else:
            # mesh bands repeat their shared row: every point of one process appears, and only those
            wanted = {p for points in expected.values() for p in points}
            have = {p for points in got.values() for p in points}
            if wanted != have:
                failures.append("%s: the mesh points differ" % label)

for failure in failures:
    print("FAILED:", failure)
common.finish(not failures, "Hopf Fibration over MPI ranks")
