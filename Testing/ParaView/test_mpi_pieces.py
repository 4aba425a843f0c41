"""Run under `mpiexec -np N pvbatch`: the Boosted Surface source split over N ranks gives the same
geometry as one process. Each rank generates only its band of lambda rows; ParaView gathers the
data information over all ranks."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines BoostedSurface()
from paraview import servermanager  # noqa: E402

failures = []
ranks = common.mpi_ranks(failures)

lambda_resolution, theta_resolution = 31, 40


def cleaned_point_count(polydata):
    """Number of points once coincident ones are merged (surface bands share a row of points)."""
    from vtkmodules.vtkFiltersCore import vtkCleanPolyData
    clean = vtkCleanPolyData()
    clean.SetInputData(polydata)
    clean.SetTolerance(0.0)
    clean.Update()
    return clean.GetOutput().GetNumberOfPoints()


for output_type in ("Surface", "Circles"):
    parameters = dict(CircleNormal=[0, 0, 1], LambdaRange=[-3, 3],
                      LambdaResolution=lambda_resolution, ThetaResolution=theta_resolution,
                      ClipRadius=5, OutputType=output_type)
    source = BoostedSurface(**parameters)  # noqa: F821
    source.UpdatePipeline()
    distributed = source.GetDataInformation()  # summed over the ranks
    gathered = servermanager.Fetch(source)  # all pieces appended, on this (root) process

    # The same source run whole in this process only, never through the parallel pipeline.
    single = common.whole_in_one_process(BoostedSurface(**parameters))  # noqa: F821

    common.compare_cell_counts(output_type, ranks, distributed, single, failures, gathered)
    if output_type == "Circles":
        # whole circles go to one rank each: the points are partitioned exactly
        if distributed.GetNumberOfPoints() != single.GetNumberOfPoints():
            failures.append("Circles: %d points over the ranks, %d in one process"
                            % (distributed.GetNumberOfPoints(), single.GetNumberOfPoints()))
    else:
        # neighbouring surface bands repeat their shared row of points; merged, they agree
        if cleaned_point_count(gathered) != cleaned_point_count(single):
            failures.append("Surface: %d merged points over the ranks, %d in one process"
                            % (cleaned_point_count(gathered), cleaned_point_count(single)))
        if distributed.GetNumberOfPoints() <= single.GetNumberOfPoints() - 1:
            failures.append("Surface: points were lost over the ranks")
    common.compare_point_sets(output_type, gathered, single, failures)
    common.compare_bounds(output_type, distributed, single, failures)

common.report(failures, "Boosted Surface over MPI ranks")
