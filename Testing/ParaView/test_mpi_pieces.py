"""Run under `mpiexec -np N pvbatch`: the Boosted Surface source split over N ranks gives the same
geometry as one process. Each rank generates only its band of lambda rows; ParaView gathers the
data information over all ranks."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines BoostedSurface()
from paraview import servermanager, simple  # noqa: E402

ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
failures = []
if ranks < 2:
    failures.append("expected at least 2 MPI ranks, got %d" % ranks)

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
    single_proxy = BoostedSurface(**parameters)  # noqa: F821
    single_algorithm = single_proxy.GetClientSideObject()
    single_algorithm.UpdatePiece(0, 1, 0)
    single = single_algorithm.GetOutput()

    print("%s: %d ranks: %d points %d cells; one process: %d points %d cells"
          % (output_type, ranks, distributed.GetNumberOfPoints(), distributed.GetNumberOfCells(),
             single.GetNumberOfPoints(), single.GetNumberOfCells()))
    if distributed.GetNumberOfCells() != single.GetNumberOfCells():
        failures.append("%s: %d cells over the ranks, %d in one process"
                        % (output_type, distributed.GetNumberOfCells(), single.GetNumberOfCells()))
    if gathered.GetNumberOfCells() != single.GetNumberOfCells():
        failures.append("%s: %d cells gathered, %d in one process"
                        % (output_type, gathered.GetNumberOfCells(), single.GetNumberOfCells()))
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
    for got, expected in zip(distributed.GetBounds(), single.GetBounds()):
        if abs(got - expected) > 1e-12:
            failures.append("%s: bounds %r over the ranks, %r in one process"
                            % (output_type, distributed.GetBounds(), single.GetBounds()))
            break

for failure in failures:
    print("FAILED:", failure)
common.finish(not failures, "Boosted Surface over MPI ranks")
