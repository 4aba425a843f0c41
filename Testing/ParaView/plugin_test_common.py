"""Shared by the ParaView tests: argument parsing, plugin loading and image comparison.

The tests run in pvpython or pvbatch and receive, from CMake, the plugin's path, the baseline
image and a directory for the images they write.
"""
import argparse
import os
import sys

# largest(): the maximum that keeps a NaN (max() drops it, so a NaN error would pass its check),
# shared with the Python tests (Testing/Support/python_test_common.py).
sys.path.append(os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, "Support"))
from python_test_common import largest  # noqa: E402,F401


def parse_arguments():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True, help="path of BoostedSurfaces.so")
    parser.add_argument("--baseline", help="baseline PNG to compare with")
    parser.add_argument("--output-dir", default=".", help="where rendered images are written")
    parser.add_argument("--threshold", type=float, required=True,
                        help="largest accepted vtkImageDifference thresholded error (CMake passes "
                             "BOOSTEDSURFACES_IMAGE_THRESHOLD, the one policy of every image test)")
    return parser.parse_args()


def load_plugin(path, namespace):
    from paraview import simple
    simple.LoadPlugin(path, remote=False, ns=namespace)


def compare_png(image_path, baseline_path, threshold):
    """True when image_path matches baseline_path; with no baseline, say where the image is."""
    from vtkmodules.vtkIOImage import vtkPNGReader
    from vtkmodules.vtkImagingCore import vtkImageDifference
    if not os.path.exists(baseline_path):
        print("no baseline %s; the rendered image is %s" % (baseline_path, image_path))
        return False
    readers = []
    for path in (image_path, baseline_path):
        reader = vtkPNGReader()
        reader.SetFileName(path)
        reader.Update()
        readers.append(reader)
    difference = vtkImageDifference()
    difference.SetInputConnection(readers[0].GetOutputPort())
    difference.SetImageConnection(readers[1].GetOutputPort())
    difference.Update()
    error = difference.GetThresholdedError()
    print("image %s vs baseline %s: thresholded error %g (threshold %g)"
          % (image_path, baseline_path, error, threshold))
    return error <= threshold


def finish(ok, message):
    """Ends a test. Success returns normally so that pvbatch can finalize MPI on every rank
    (sys.exit would abort the other ranks); failure raises, which makes the process exit non-zero."""
    if not ok:
        raise RuntimeError("FAILED: " + message)
    print("PASSED: " + message)


def white_render_view(size):
    """A render view of `size` pixels with a white background and no orientation axes."""
    from paraview import simple
    view = simple.CreateRenderView()
    view.ViewSize = list(size)
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass
    return view


def screenshot_matches(view, arguments, size):
    """Save the view into --output-dir under the baseline's name and compare it with --baseline."""
    from paraview import simple
    image = os.path.join(arguments.output_dir, os.path.basename(arguments.baseline))
    simple.SaveScreenshot(image, view, ImageResolution=list(size))
    return compare_png(image, arguments.baseline, arguments.threshold)


def render_and_compare(source, color_array, camera_position, focal_point, view_up, arguments,
                       failures):
    """Show `source` coloured by a point array in a 400 x 400 white render view with the given
    camera (then fitted to the data), and, with --baseline, compare its screenshot; a difference is
    appended to `failures`."""
    from paraview import simple
    view = white_render_view([400, 400])
    display = simple.Show(source, view)
    simple.ColorBy(display, ("POINTS", color_array))
    look_and_compare(view, camera_position, focal_point, view_up, arguments, failures)


def look_and_compare(view, camera_position, focal_point, view_up, arguments, failures):
    """Place the camera of a 400 x 400 `view` (then fit it to the data), render, and, with
    --baseline, compare its screenshot; a difference is appended to `failures`."""
    from paraview import simple
    view.CameraPosition = list(camera_position)
    view.CameraFocalPoint = list(focal_point)
    view.CameraViewUp = list(view_up)
    view.ResetCamera()
    simple.Render(view)
    if arguments.baseline and not screenshot_matches(view, arguments, [400, 400]):
        failures.append("image differs from the baseline")


def report(failures, message):
    """Print each failure, then finish(): the end of every plugin test."""
    for failure in failures:
        print("FAILED:", failure)
    finish(not failures, message)


def check_defaults(proxy, defaults, failures):
    """Compare each property named in `defaults` with its documented value."""
    for name, expected in defaults.items():
        value = proxy.GetPropertyValue(name)
        value = list(value) if isinstance(expected, list) else value
        if value != expected:
            failures.append("default %s is %r, expected %r" % (name, value, expected))


# The column names of the plugin's tables; the generator table is the same in every class.
GENERATOR_COLUMNS = ("X", "Y", "Z", "Direction X", "Direction Y", "Direction Z", "Weight",
                     "Kind", "Pitch")
BASE_POINT_COLUMNS = ("Theta", "Phi")
SEED_COLUMNS = ("X", "Y", "Z")
CONTROL_POINT_COLUMNS = ("X", "Y", "Z", "Normal X", "Normal Y", "Normal Z", "U Direction X",
                         "U Direction Y", "U Direction Z", "Kappa U", "Kappa V")


def check_table(proxy, row, columns, failures):
    """The table of rows `row` ("Generator", "Base Point", ...) follows the one table protocol:
    property <Row>List labelled "<row> List", pushed as SetNumberOf<Row>s(n) then Set<Row>(i, ...)
    for each row (no clean command), with one named column per value."""
    name = row.replace(" ", "")
    prop = proxy.GetProperty(name + "List")
    if prop is None:
        failures.append("%s has no property %sList" % (proxy.GetXMLName(), name))
        return
    sm = prop.SMProperty
    layout = (sm.GetXMLLabel(), sm.GetCommand(), sm.GetSetNumberCommand(), sm.GetCleanCommand(),
              sm.GetUseIndex(), sm.GetRepeatCommand(), sm.GetNumberOfElementsPerCommand())
    expected = (row + " List", "Set" + name, "SetNumberOf" + name + "s", None, 1, 1, len(columns))
    if layout != expected:
        failures.append("%s table layout %r, expected %r" % (name, layout, expected))
    hints = sm.GetHints()
    labels = hints.FindNestedElementByName("ShowComponentLabels") if hints else None
    found = tuple(labels.GetNestedElement(i).GetAttribute("label")
                  for i in range(labels.GetNumberOfNestedElements())) if labels else ()
    if found != tuple(columns):
        failures.append("%s table columns %r, expected %r" % (name, found, tuple(columns)))


def check_point_arrays(info, names, failures, what="point array"):
    """Each point array of `names` must be in the data information `info`."""
    for array in names:
        if info.GetPointDataInformation().GetArrayInformation(array) is None:
            failures.append("%s %s is missing" % (what, array))


# Under `mpiexec -np N pvbatch`: the distributed pipeline against one process.

def mpi_ranks(failures):
    """The number of MPI ranks; fewer than two is a failure (the test would prove nothing)."""
    from paraview import servermanager
    ranks = servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()
    if ranks < 2:
        failures.append("expected at least 2 MPI ranks, got %d" % ranks)
    return ranks


def whole_in_one_process(proxy):
    """The output of `proxy`'s algorithm run whole in this process only, never through the
    parallel pipeline."""
    algorithm = proxy.GetClientSideObject()
    algorithm.UpdatePiece(0, 1, 0)
    return algorithm.GetOutput()


def compare_cell_counts(label, ranks, distributed, single, failures, gathered=None):
    """Print the counts; the cells summed over the ranks (`distributed`, a data information) and,
    when given, those gathered on this process (`gathered`) must be those of one process."""
    print("%s: %d ranks: %d points %d cells; one process: %d points %d cells"
          % (label, ranks, distributed.GetNumberOfPoints(), distributed.GetNumberOfCells(),
             single.GetNumberOfPoints(), single.GetNumberOfCells()))
    if distributed.GetNumberOfCells() != single.GetNumberOfCells():
        failures.append("%s: %d cells over the ranks, %d in one process"
                        % (label, distributed.GetNumberOfCells(), single.GetNumberOfCells()))
    if gathered is not None and gathered.GetNumberOfCells() != single.GetNumberOfCells():
        failures.append("%s: %d cells gathered, %d in one process"
                        % (label, gathered.GetNumberOfCells(), single.GetNumberOfCells()))


def compare_point_sets(label, gathered, single, failures):
    """The points gathered from the ranks must be exactly those of one process, bit for bit (bands
    may repeat their shared row, so the comparison is of sets)."""
    have = {gathered.GetPoint(i) for i in range(gathered.GetNumberOfPoints())}
    wanted = {single.GetPoint(i) for i in range(single.GetNumberOfPoints())}
    if have != wanted:
        failures.append("%s: %d points differ between the ranks and one process"
                        % (label, len(have ^ wanted)))


def compare_bounds(label, distributed, single, failures):
    """The bounds over the ranks must be those of one process (to 1e-12)."""
    for got, expected in zip(distributed.GetBounds(), single.GetBounds()):
        if not abs(got - expected) <= 1e-12:  # not `> 1e-12`, which a NaN passes
            failures.append("%s: bounds %r over the ranks, %r in one process"
                            % (label, distributed.GetBounds(), single.GetBounds()))
            break
