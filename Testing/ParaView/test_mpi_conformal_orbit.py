"""Run under `mpiexec -np N pvbatch`: the Conformal Orbit source split over N ranks gives the same
orbits as one process. Each rank computes its share of the orbits (whole orbits, by seed); the
gathered orbits are compared point by point, by OrbitId, for a torus knot and for generator rows;
the cores come once, from rank 0."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines ConformalOrbit()
from paraview import servermanager  # noqa: E402

failures = []
ranks = common.mpi_ranks(failures)


def orbits(polydata):
    """OrbitId -> list of points, in output order."""
    ids = polydata.GetPointData().GetArray("OrbitId")
    out = {}
    for i in range(polydata.GetNumberOfPoints()):
        out.setdefault(int(ids.GetTuple1(i)), []).append(polydata.GetPoint(i))
    return out


seeds = [c for k in range(7) for c in (0.15 + 0.02 * k, 0.01 * k, 0.0)]
cases = {
    "torus knot (3, 5)": dict(KnotP=3, KnotQ=5, TResolution=300),
    "generator rows": dict(GeneratorType="Generator List", TRange=[-2, 2], TResolution=100,
                           GeneratorList=[-1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0]),
}
for label, parameters in cases.items():
    parameters = dict(parameters, SeedMode="Seed List", SeedList=seeds)
    source = ConformalOrbit(**parameters)  # noqa: F821
    source.UpdatePipeline()
    distributed = source.GetDataInformation()  # summed over the ranks
    gathered = servermanager.Fetch(source)  # all pieces appended, on this (root) process
    single = common.whole_in_one_process(ConformalOrbit(**parameters))  # noqa: F821
    common.compare_cell_counts(label, ranks, distributed, single, failures, gathered)
    got, expected = orbits(gathered), orbits(single)
    if sorted(got) != list(range(7)) or sorted(expected) != list(range(7)):
        failures.append("%s: orbit ids %r over the ranks, %r in one process"
                        % (label, sorted(got), sorted(expected)))
    for orbit_id, points in expected.items():
        if got.get(orbit_id) != points:
            failures.append("%s: orbit %d differs" % (label, orbit_id))
            break
    cores = servermanager.Fetch(source, idx=1)
    single_cores = ConformalOrbit(**parameters).GetClientSideObject()  # noqa: F821
    single_cores.UpdatePiece(0, 1, 0)
    expected_cores = single_cores.GetOutputDataObject(1)
    if cores.GetNumberOfPoints() != expected_cores.GetNumberOfPoints() or cores.GetNumberOfPoints() == 0:
        failures.append("%s: %d core points over the ranks, %d in one process"
                        % (label, cores.GetNumberOfPoints(), expected_cores.GetNumberOfPoints()))

common.report(failures, "Conformal Orbit over MPI ranks")
