"""The pvpython client of test_client_server.py: every proxy of the plugin built on a pvserver of
two MPI ranks gives, port by port, what the built-in (local) connection gives.

Built-in first: the plugin loaded locally, each proxy's whole output fetched. Then the client
connects to the server at localhost:<port>, loads the plugin on the server (remote=True) and on
itself (remote=False, already loaded), builds the same proxies there and fetches each rank's part
of each output port. The parts together must be the local output: the same array names, the same
points with the same point values (as sets: neighbouring pieces repeat their shared row), the
same cells with their points and cell values (as multisets), all exactly; and the first port of
each proxy must have cells and really be split (both ranks hold some).
"""
import argparse

from paraview import servermanager, simple
from vtkmodules.vtkCommonCore import vtkIdList

RANKS = 2


def parse_arguments():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--port", type=int, required=True)
    return parser.parse_args()


def build_proxies(plugin):
    """Each source and the filter, small enough to compare point by point; `plugin` holds the
    functions that LoadPlugin defined for its proxies."""
    def source(name, **properties):
        simple.SetActiveSource(None)  # or the optional inputs take the active source
        return plugin[name](**properties)
    surface = source("BoostedSurface", LambdaRange=[-2, 2], LambdaResolution=24, ThetaResolution=20)
    return [
        ("BoostedSurface", surface),
        ("HopfFibration", source("HopfFibration", ThetaResolution=6, PhiResolution=12)),
        ("CurvaturePatch", source("CurvaturePatch", CurvaturePreset="Parabolic")),
        ("DipoleField", source(
            "DipoleField",
            GeneratorList=[-1, 0, 0, 0, 1, 0, 0.35, 0, 0, 1, 0, 0, 0, 1, 0, 0.35, 0, 0])),
        ("ConformalOrbit", source("ConformalOrbit", SeedMode="Seed List", TResolution=64,
                                   SeedList=[0.15, 0, 0, 0.3, 0, 0, 0.45, 0, 0, 0.6, 0, 0])),
        ("PointPairDeformation", plugin["PointPairDeformation"](
            Input=surface, GeneratorList=[0, 0, 0.5, 0, 0, 1, 0.5, 0, 0])),
    ]


def data_arrays(attributes):
    arrays = [attributes.GetArray(i) for i in range(attributes.GetNumberOfArrays())]
    return sorted((a for a in arrays if a is not None), key=lambda a: a.GetName())


def canonical(parts):
    """(array names, set of points with their values, sorted cells) of the union of `parts`."""
    names, points, cells = None, set(), []
    ids = vtkIdList()
    for data in parts:
        point_arrays = data_arrays(data.GetPointData())
        cell_arrays = data_arrays(data.GetCellData())
        part_names = ([a.GetName() for a in point_arrays], [a.GetName() for a in cell_arrays])
        if data.GetNumberOfPoints() == 0 and data.GetNumberOfCells() == 0:
            continue  # an empty part may lack the arrays
        if names is None:
            names = part_names
        elif names != part_names:
            raise RuntimeError("parts with different arrays: %r and %r" % (names, part_names))
        keys = [data.GetPoint(i) + sum((a.GetTuple(i) for a in point_arrays), ())
                for i in range(data.GetNumberOfPoints())]
        points.update(keys)
        for c in range(data.GetNumberOfCells()):
            data.GetCellPoints(c, ids)
            cells.append((data.GetCellType(c),) + tuple(keys[ids.GetId(k)]
                                                        for k in range(ids.GetNumberOfIds()))
                         + sum((a.GetTuple(c) for a in cell_arrays), ()))
    cells.sort()
    return names, points, cells


def output_ports(proxy):
    return range(proxy.SMProxy.GetNumberOfOutputPorts())


def fetch_local(proxies):
    """{(name, port): canonical form} of the built-in connection's whole outputs."""
    result = {}
    for name, proxy in proxies:
        for port in output_ports(proxy):
            result[(name, port)] = canonical([servermanager.Fetch(proxy, None, None, port)])
    return result


def compare_remote(proxies, local, failures):
    for name, proxy in proxies:
        if len(output_ports(proxy)) != len([key for key in local if key[0] == name]):
            failures.append("%s: %d output ports remotely" % (name, len(output_ports(proxy))))
        for port in output_ports(proxy):
            proxy.UpdatePipeline()
            parts = [servermanager.Fetch(proxy, rank, None, port) for rank in range(RANKS)]
            cells_per_rank = [part.GetNumberOfCells() for part in parts]
            names, points, cells = canonical(parts)
            want_names, want_points, want_cells = local[(name, port)]
            print("%s port %d: cells per rank %r, remote %d points %d cells, local %d points %d"
                  " cells" % (name, port, cells_per_rank, len(points), len(cells),
                              len(want_points), len(want_cells)), flush=True)
            if port == 0 and min(cells_per_rank) == 0:
                failures.append("%s: not split over the ranks (%r cells)" % (name, cells_per_rank))
            if port == 0 and not want_cells:  # other ports (generators, cores) may be empty
                failures.append("%s: empty output" % name)
            if names != want_names:
                failures.append("%s port %d: arrays %r remotely, %r locally"
                                % (name, port, names, want_names))
            if points != want_points:
                failures.append("%s port %d: %d points differ" % (name, port,
                                                                  len(points ^ want_points)))
            if cells != want_cells:
                failures.append("%s port %d: the cells differ" % (name, port))


def main():
    arguments = parse_arguments()
    failures = []
    plugin = globals()  # LoadPlugin defines the proxies' functions there (a dict it can fill)
    simple.LoadPlugin(arguments.plugin, remote=False, ns=plugin)
    local = fetch_local(build_proxies(plugin))

    simple.Disconnect()
    simple.Connect("localhost", arguments.port)
    ranks = servermanager.ActiveConnection.GetNumberOfDataPartitions()
    if ranks != RANKS:
        failures.append("the server has %d ranks, expected %d" % (ranks, RANKS))
    simple.LoadPlugin(arguments.plugin, remote=True, ns=plugin)
    simple.LoadPlugin(arguments.plugin, remote=False, ns=plugin)
    compare_remote(build_proxies(plugin), local, failures)
    simple.Disconnect()

    for failure in failures:
        print("FAILED:", failure)
    if failures:
        raise SystemExit(1)
    print("PASSED: every proxy on a 2-rank pvserver equals the built-in connection")


main()
