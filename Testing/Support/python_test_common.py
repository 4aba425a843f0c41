"""Shared by the Python tests: error observation, a NaN-aware maximum, the deformation filter's
progress text of its tree, and the image tests' arguments, actors, window, camera and
regression-image comparison."""
import argparse
import math

from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand
from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper, vtkRenderWindow
from vtkmodules.vtkTestingRendering import vtkTesting
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL render window)

# vtkPointPairDeformationFilter's progress text while it builds its generator tree (its header's
# Tolerance): how a test sees that an update built a tree.
BUILDING_TREE = "Building the generator tree"


def largest(values):
    """The largest of `values` (an iterable of numbers, floats or mpmath's), NaN if any is NaN.
    Python's max() keeps what it has against a NaN (every comparison with NaN is false), so a NaN
    error would vanish from the largest and `largest > bound` could never fail: fold errors with
    this and fail on `not (largest(...) <= bound)`."""
    result = None
    for value in values:
        if math.isnan(value):
            return math.nan
        if result is None or value > result:
            result = value
    if result is None:
        raise ValueError("largest() of no values")
    return result


class ErrorRecorder:
    """Observes vtkCommand.ErrorEvent and WarningEvent: the messages go here (errors in
    `messages`, warnings in `warnings`) instead of to the output window."""

    def __init__(self, algorithm):
        self.messages = []
        self.warnings = []

        # VTK looks for CallDataType on the callback itself: a function, not a callable object.
        @calldata_type(VTK_STRING)
        def record_error(caller, event, message):
            self.messages.append(message)

        @calldata_type(VTK_STRING)
        def record_warning(caller, event, message):
            self.warnings.append(message)

        algorithm.AddObserver(vtkCommand.ErrorEvent, record_error)
        algorithm.AddObserver(vtkCommand.WarningEvent, record_warning)


def parse_image_arguments(description, figures=None):
    """The command line of a regression-image test: --baseline, --output-dir, --threshold and,
    when `figures` is given, --figure (one of them)."""
    parser = argparse.ArgumentParser(description=description)
    if figures is not None:
        parser.add_argument("--figure", required=True, choices=sorted(figures))
    parser.add_argument("--baseline", required=True, help="absolute path of the baseline PNG")
    parser.add_argument("--output-dir", required=True, help="where the rendered image goes")
    parser.add_argument("--threshold", type=float, required=True,
                        help="largest accepted vtkImageDifference thresholded error (CMake passes "
                             "BOOSTEDSURFACES_IMAGE_THRESHOLD, the one policy of every image test)")
    return parser.parse_args()


def colored_actor(algorithm, array=None, scalar_range=(0, 1), color=None):
    """An actor of `algorithm`'s polygonal output, coloured by its point array `array` over
    scalar_range, or without scalars when `array` is None; `color` (if given) is the actor's own.
    The actor keeps the algorithm alive (an output port does not in Python)."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(algorithm.GetOutputPort())
    if array:
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray(array)
        mapper.SetScalarRange(scalar_range)
    else:
        mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    if color is not None:
        actor.GetProperty().SetColor(color)
    actor.keep = algorithm
    return actor


def offscreen_window(renderer, size):
    """An offscreen render window of `size` pixels showing `renderer`."""
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetMultiSamples(0)  # no antialiasing: keeps the image the same from run to run
    window.SetSize(*size)
    window.AddRenderer(renderer)
    return window


def compare_with_baseline(window, baseline, output_dir, threshold):
    """Compare the rendered `window` with `baseline` by vtkTesting (as vtkRegressionTestImage). A
    missing baseline fails after writing the image to output_dir. Returns the exit code (0: passed)."""
    testing = vtkTesting()
    for argument in ("-V", baseline, "-T", output_dir):
        testing.AddArgument(argument)
    testing.SetRenderWindow(window)
    result = testing.RegressionTest(threshold)
    return 0 if result == vtkTesting.PASSED else 1


def regression_test(renderer, camera_position, view_up, zoom, baseline, output_dir, threshold,
                    size=(400, 300), parallel=False):
    """Render `renderer` offscreen, the camera looking at the origin from camera_position and fitted
    to the scene, and compare with `baseline` (compare_with_baseline). Returns the exit code."""
    window = offscreen_window(renderer, size)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(*camera_position)
    camera.SetViewUp(*view_up)
    camera.SetParallelProjection(parallel)
    renderer.ResetCamera()
    camera.Zoom(zoom)
    window.Render()
    return compare_with_baseline(window, baseline, output_dir, threshold)


def example_regression_test(figure, args):
    """regression_test of an example module's own scene: its build_scene(), VIEW and SIZE, with
    the command line `args` of parse_image_arguments. Returns the exit code."""
    return regression_test(figure.build_scene(), figure.VIEW["view_direction"],
                           figure.VIEW["view_up"], figure.VIEW["zoom"], args.baseline,
                           args.output_dir, args.threshold, size=figure.SIZE,
                           parallel=figure.VIEW.get("parallel", False))
