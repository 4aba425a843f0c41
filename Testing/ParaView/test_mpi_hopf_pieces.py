"""Run under `mpiexec -np N pvbatch`: the Hopf Fibration source split over N ranks gives the same
fibers as one process. Each rank generates its share of the fibers; the gathered fibers are
compared point by point, by FiberId; twistor meshes (also with merged seams) by their point sets."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines HopfFibration()
from paraview import servermanager  # noqa: E402

failures = []
ranks = common.mpi_ranks(failures)


def fibers(polydata):
    """FiberId -> list of points, in output order."""
    ids = polydata.GetPointData().GetArray("FiberId")
    out = {}
    for i in range(polydata.GetNumberOfPoints()):
        out.setdefault(int(ids.GetTuple1(i)), []).append(polydata.GetPoint(i))
    return out


# The third: latitude tori with merged seams (MergeSeam): each rank's band shares its seam and,
# when it holds a strip's first fiber, its closing fiber; a piece boundary is not a seam.
for mode in ("Paper", "Classical"):
    for output_type, extra in (("Fibers", {}), ("Twistor Mesh", {}),
                               ("Twistor Mesh", dict(MeshSweep="Latitudes", MergeSeam=1,
                                                     PhiRange=[-1.2, 0.9]))):
        parameters = dict(Mode=mode, OutputType=output_type, ThetaResolution=5, PhiResolution=7,
                          FiberResolution=32, **extra)
        source = HopfFibration(**parameters)  # noqa: F821
        source.UpdatePipeline()
        distributed = source.GetDataInformation()  # summed over the ranks
        gathered = servermanager.Fetch(source)  # all pieces appended, on this (root) process

        single = common.whole_in_one_process(HopfFibration(**parameters))  # noqa: F821
        label = "%s %s%s" % (mode, output_type, " merged" if extra else "")
        common.compare_cell_counts(label, ranks, distributed, single, failures, gathered)
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
            if extra:
                # merged: a strip's closing fiber on another rank than its first keeps its
                # points (theta0 + 2 pi), equal to the first fiber's to round-off only
                extra_points = have - wanted
                if not wanted <= have or any(
                        not min(common.largest(abs(a - b) for a, b in zip(p, q))
                                for q in wanted) <= 1e-9  # a NaN point fails
                        for p in extra_points):
                    failures.append("%s: the mesh points differ" % label)
            elif wanted != have:
                failures.append("%s: the mesh points differ" % label)

common.report(failures, "Hopf Fibration over MPI ranks")
