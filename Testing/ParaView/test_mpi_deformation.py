"""Run under `mpiexec -np N pvbatch`: the Point Pair Deformation of a sphere distributed over N
ranks gives the same points as one process. Part of the generators come from the optional
Generators input, which every rank must receive whole (the filter requests it as one piece)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import plugin_test_common as common  # noqa: E402

arguments = common.parse_arguments()
common.load_plugin(arguments.plugin, globals())  # defines PointPairDeformation()
from paraview import servermanager, simple  # noqa: E402

failures = []
ranks = common.mpi_ranks(failures)


def pipeline():
    sphere = simple.Sphere(Radius=1.0, ThetaResolution=40, PhiResolution=30)
    # Three generators on a line, directions from a Calculator: a distributed source of its own.
    line = simple.Line(Point1=[-0.8, 0.0, 1.2], Point2=[0.8, 0.3, 1.2], Resolution=2)
    directions = simple.Calculator(Input=line, ResultArrayName="Direction",
                                   Function="coordsX*iHat+kHat")
    return PointPairDeformation(Input=sphere, Generators=directions,  # noqa: F821
                                GeneratorList=[1.3, 0.0, 0.0, 1.0, 0.0, 0.0, -0.4, 0, 0],
                                Falloff=2.0, Epsilon=0.05)


def keyed(points):
    return {tuple(round(c, 9) for c in p) for p in points}


distributed_proxy = pipeline()
distributed_proxy.UpdatePipeline()
distributed = distributed_proxy.GetDataInformation()  # summed over the ranks
gathered = servermanager.Fetch(distributed_proxy)  # all pieces appended, on this (root) process

single = common.whole_in_one_process(pipeline())

print("%d ranks: %d points %d cells; one process: %d points %d cells"
      % (ranks, distributed.GetNumberOfPoints(), distributed.GetNumberOfCells(),
         single.GetNumberOfPoints(), single.GetNumberOfCells()))
if gathered.GetNumberOfCells() != single.GetNumberOfCells():
    failures.append("%d cells gathered, %d in one process"
                    % (gathered.GetNumberOfCells(), single.GetNumberOfCells()))
gathered_points = keyed(gathered.GetPoint(i) for i in range(gathered.GetNumberOfPoints()))
single_points = keyed(single.GetPoint(i) for i in range(single.GetNumberOfPoints()))
if gathered_points != single_points:
    failures.append("%d deformed points differ between the ranks and one process"
                    % len(gathered_points ^ single_points))
moved = common.largest(abs(a - b) for a, b in zip(single.GetBounds(), (-1, 1, -1, 1, -1, 1)))
if not moved >= 1e-2:  # (a NaN bound must fail too)
    failures.append("the sphere was hardly deformed (%g): the test would prove nothing" % moved)

common.report(failures, "Point Pair Deformation over MPI ranks")
