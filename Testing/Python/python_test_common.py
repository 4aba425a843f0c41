"""Shared by the Python tests: error observation and the regression-image comparison."""
from vtkmodules.util.misc import calldata_type
from vtkmodules.vtkCommonCore import VTK_STRING, vtkCommand
from vtkmodules.vtkRenderingCore import vtkRenderWindow
from vtkmodules.vtkTestingRendering import vtkTesting
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (registers the OpenGL render window)


class ErrorRecorder:
    """Observes vtkCommand.ErrorEvent: the messages go here instead of to the output window."""

    def __init__(self, algorithm):
        self.messages = []

        # VTK looks for CallDataType on the callback itself: a function, not a callable object.
        @calldata_type(VTK_STRING)
        def record(caller, event, message):
            self.messages.append(message)

        algorithm.AddObserver(vtkCommand.ErrorEvent, record)


def regression_test(renderer, camera_position, view_up, zoom, baseline, output_dir, threshold,
                    size=(400, 300)):
    """Render `renderer` offscreen, the camera looking at the origin from camera_position and fitted
    to the scene, and compare with `baseline` by vtkTesting (as vtkRegressionTestImage). A missing
    baseline fails after writing the image to output_dir. Returns the exit code (0: passed)."""
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetMultiSamples(0)  # no antialiasing: keeps the image the same from run to run
    window.SetSize(*size)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(*camera_position)
    camera.SetViewUp(*view_up)
    renderer.ResetCamera()
    camera.Zoom(zoom)
    window.Render()

    testing = vtkTesting()
    for argument in ("-V", baseline, "-T", output_dir):
        testing.AddArgument(argument)
    testing.SetRenderWindow(window)
    result = testing.RegressionTest(threshold)
    return 0 if result == vtkTesting.PASSED else 1
