"""Run under `mpiexec -np N pvbatch`: the Curvature Patch source split over N ranks gives the same
geometry as one process (each rank generates only its band of v rows)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines CurvaturePatch()
from paraview import servermanager  # noqa: E402

ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
failures = []
if ranks < 2:
    failures.append("expected at least 2 MPI ranks, got %d" % ranks)

for output_type in ("Surface", "Lines"):
    parameters = dict(Method="Bilinear (eq 25)", UResolution=20, VResolution=17,
                      Corner2Direction=[1, 0, 0.5], OutputType=output_type)
    source = CurvaturePatch(**parameters)  # noqa: F821
    source.UpdatePipeline()
    distributed = source.GetDataInformation()  # summed over the ranks

    single_proxy = CurvaturePatch(**parameters)  # noqa: F821
    single_algorithm = single_proxy.GetClientSideObject()
    single_algorithm.UpdatePiece(0, 1, 0)
    single = single_algorithm.GetOutput()

    print("%s: %d ranks: %d points %d cells; one process: %d points %d cells"
          % (output_type, ranks, distributed.GetNumberOfPoints(), distributed.GetNumberOfCells(),
             single.GetNumberOfPoints(), single.GetNumberOfCells()))
    if distributed.GetNumberOfCells() != single.GetNumberOfCells():
        failures.append("%s: %d cells over the ranks, %d in one process"
                        % (output_type, distributed.GetNumberOfCells(), single.GetNumberOfCells()))
    if output_type == "Lines" and distributed.GetNumberOfPoints() != single.GetNumberOfPoints():
        failures.append("Lines: %d points over the ranks, %d in one process"
                        % (distributed.GetNumberOfPoints(), single.GetNumberOfPoints()))
    for got, expected in zip(distributed.GetBounds(), single.GetBounds()):
        if abs(got - expected) > 1e-12:
            failures.append("%s: bounds %r over the ranks, %r in one process"
                            % (output_type, distributed.GetBounds(), single.GetBounds()))
            break

for failure in failures:
    print("FAILED:", failure)
common.finish(not failures, "Curvature Patch over MPI ranks")
