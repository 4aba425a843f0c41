"""Run under `mpiexec -np N pvbatch`: the Curvature Patch source split over N ranks gives the same
geometry as one process (each rank generates only its band of v rows): the gathered points are
those of one process, bit for bit."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines CurvaturePatch()
from paraview import servermanager  # noqa: E402

failures = []
ranks = common.mpi_ranks(failures)

for output_type in ("Surface", "Lines"):
    parameters = dict(Method="Bilinear", UResolution=20, VResolution=17,
                      Corner2Direction=[1, 0, 0.5], OutputType=output_type)
    source = CurvaturePatch(**parameters)  # noqa: F821
    source.UpdatePipeline()
    distributed = source.GetDataInformation()  # summed over the ranks
    gathered = servermanager.Fetch(source)  # all pieces appended, on this (root) process

    single = common.whole_in_one_process(CurvaturePatch(**parameters))  # noqa: F821

    common.compare_cell_counts(output_type, ranks, distributed, single, failures, gathered)
    # Surface bands repeat their shared row: every point of one process appears, and only those.
    common.compare_point_sets(output_type, gathered, single, failures)
    if output_type == "Lines" and distributed.GetNumberOfPoints() != single.GetNumberOfPoints():
        failures.append("Lines: %d points over the ranks, %d in one process"
                        % (distributed.GetNumberOfPoints(), single.GetNumberOfPoints()))
    common.compare_bounds(output_type, distributed, single, failures)

common.report(failures, "Curvature Patch over MPI ranks")
