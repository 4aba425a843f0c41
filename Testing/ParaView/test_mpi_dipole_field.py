"""Run under `mpiexec -np N pvbatch`: the Dipole Field source split over N ranks gives the same
field as one process. Each rank computes only its sub-extent of the grid (CAN_PRODUCE_SUB_EXTENT);
the gathered pieces, point by point, equal the whole field computed in one process."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines DipoleField()
from paraview import servermanager  # noqa: E402

failures = []
ranks = common.mpi_ranks(failures)

ARRAYS = ("DisplacementSummedGenerators", "DisplacementSummedDisplacements",
          "DisplacementDifference", "DisplacementDifferenceMagnitude", "DipolePotential")
parameters = dict(GeneratorList=[-1, 0, 0, 0, 1, 0, 0.35, 0, 0, 1, 0, 0.2, 1, 0, 0, 0.35, 0, 0],
                  Origin=[-2, -2, -1], Spacing=[0.25, 0.2, 0.5], Dimensions=[17, 21, 5])
whole_points = 17 * 21 * 5

for rule in ("Exact", "Paper"):
    source = DipoleField(ExponentialRule=rule, **parameters)  # noqa: F821
    source.UpdatePipeline()
    distributed = source.GetDataInformation()  # summed over the ranks
    # Each rank's piece, brought to this process (Fetch with a rank passes that rank's data).
    pieces = [servermanager.Fetch(source, rank) for rank in range(ranks)]

    # The same source run whole in this process only, never through the parallel pipeline.
    single = common.whole_in_one_process(DipoleField(ExponentialRule=rule, **parameters))  # noqa: F821

    print("%s: %d ranks: %d points (with shared boundaries); one process: %d points"
          % (rule, ranks, distributed.GetNumberOfPoints(), single.GetNumberOfPoints()))
    if single.GetNumberOfPoints() != whole_points:
        failures.append("%s: one process has %d points, expected %d"
                        % (rule, single.GetNumberOfPoints(), whole_points))
    # Sub-extents share at most a layer of boundary points: far fewer than N whole grids.
    if not whole_points <= distributed.GetNumberOfPoints() < 2 * whole_points:
        failures.append("%s: %d points over the ranks, expected each rank to compute a part"
                        % (rule, distributed.GetNumberOfPoints()))

    seen = set()
    largest = 0.0
    for rank, piece in enumerate(pieces):
        print("rank %d: extent %r, %d points" % (rank, piece.GetExtent(), piece.GetNumberOfPoints()))
        if piece.GetNumberOfPoints() >= whole_points:
            failures.append("%s: rank %d computed the whole grid" % (rule, rank))
        for i in range(piece.GetNumberOfPoints()):
            p = piece.GetPoint(i)
            ijk = [int(round((p[c] - parameters["Origin"][c]) / parameters["Spacing"][c]))
                   for c in range(3)]
            index = single.ComputePointId(ijk)
            seen.add(index)
            q = single.GetPoint(index)
            # common.largest keeps a NaN (max() drops it; NaN != 0.0 then fails below)
            largest = common.largest([largest] + [abs(p[c] - q[c]) for c in range(3)])
            for name in ARRAYS:
                a = piece.GetPointData().GetArray(name)
                b = single.GetPointData().GetArray(name)
                for c in range(a.GetNumberOfComponents()):
                    largest = common.largest(
                        [largest, abs(a.GetComponent(i, c) - b.GetComponent(index, c))])
    if len(seen) != whole_points:
        failures.append("%s: the ranks covered %d of %d grid points" % (rule, len(seen), whole_points))
    if largest != 0.0:
        failures.append("%s: the distributed field differs from one process by %g" % (rule, largest))

common.report(failures, "Dipole Field over MPI ranks")
