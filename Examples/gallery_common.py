"""Helpers shared by the figure scripts: command line, colours, tubes, offscreen render to PNG.

Every figure script builds a vtkRenderer with its actors and hands it to `render_to_png`, mostly
through `render_figure`, the main() of a figure script.
"""
import argparse
import os

from vtkmodules.vtkCommonColor import vtkNamedColors
from vtkmodules.vtkCommonCore import vtkLookupTable
from vtkmodules.vtkFiltersCore import vtkArrayCalculator, vtkTubeFilter
from vtkmodules.vtkFiltersSources import vtkArrowSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
from vtkmodules.vtkRenderingCore import (
    vtkActor,
    vtkColorTransferFunction,
    vtkGlyph3DMapper,
    vtkLightKit,
    vtkPolyDataMapper,
    vtkRenderer,
    vtkRenderWindow,
    vtkTextActor,
    vtkWindowToImageFilter,
)

# Importing these registers the OpenGL render window and the text renderer (for the scalar bar).
import vtkmodules.vtkRenderingFreeType  # noqa: F401
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401

COLORS = vtkNamedColors()

# Control points of matplotlib's "viridis", without its darkest tenth (too dark once shaded):
# readable on white, and monotone in lightness, so the order of the values can be read off.
_VIRIDIS = [
    (0.00, (0.283, 0.141, 0.458)),
    (0.25, (0.190, 0.407, 0.556)),
    (0.50, (0.128, 0.567, 0.551)),
    (0.75, (0.369, 0.789, 0.383)),
    (1.00, (0.993, 0.906, 0.144)),
]


def parse_args(description, default_output, argv=None, default_size=(900, 700)):
    """The options every figure script takes: --output PATH and --size W H."""
    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--output", default=default_output,
                        help="PNG file to write (default: %(default)s)")
    parser.add_argument("--size", nargs=2, type=int, default=list(default_size),
                        metavar=("W", "H"), help="image size in pixels (default: %(default)s)")
    return parser.parse_args(argv)


def lambda_lookup_table(value_range):
    """A 256-colour viridis lookup table over value_range (used to colour by "lambda")."""
    ctf = vtkColorTransferFunction()
    for t, rgb in _VIRIDIS:
        ctf.AddRGBPoint(value_range[0] + t * (value_range[1] - value_range[0]), *rgb)
    lut = vtkLookupTable()
    lut.SetNumberOfTableValues(256)
    lut.SetTableRange(value_range)
    for i in range(256):
        x = value_range[0] + (value_range[1] - value_range[0]) * i / 255.0
        lut.SetTableValue(i, *ctf.GetColor(x), 1.0)
    lut.Build()
    return lut


def colored_actor(algorithm, lut=None, array="lambda", color=None):
    """An actor for the output of `algorithm`, coloured through `lut` by a point array, or in one
    `color`."""
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(algorithm.GetOutputPort())
    if lut is not None:
        mapper.SetLookupTable(lut)
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray(array)
        mapper.SetUseLookupTableScalarRange(True)
        # Interpolate the parameter, not the colours: smooth bands on coarse meshes.
        mapper.InterpolateScalarsBeforeMappingOn()
    else:
        mapper.ScalarVisibilityOff()
    return styled_actor(mapper, color)


def styled_actor(mapper, color=None):
    """An actor for `mapper` with the figures' lighting, in one `color` when given."""
    actor = vtkActor()
    actor.SetMapper(mapper)
    if color is not None:
        actor.GetProperty().SetColor(COLORS.GetColor3d(color) if isinstance(color, str) else color)
    actor.GetProperty().SetAmbient(0.2)  # keeps the dark end of viridis readable in shadow
    actor.GetProperty().SetDiffuse(0.8)
    actor.GetProperty().SetSpecular(0.3)
    actor.GetProperty().SetSpecularPower(30)
    return actor


def generator_arrows(algorithm, length=1.0, color="Tomato", signed=False, shaft_radius=0.03,
                     tip_radius=0.08, tip_length=0.3, resolution=16):
    """An arrow of `length` at each generator of `algorithm` (its last output port, the class's
    Generators port), along its Direction (reversed where its Weight is negative when `signed`),
    drawn by a vtkGlyph3DMapper. The actor keeps its pipeline alive."""
    port = algorithm.GetOutputPort(algorithm.GetNumberOfOutputPorts() - 1)
    orientation = "Direction"
    pipeline = [algorithm]
    if signed:
        calculator = vtkArrayCalculator()
        calculator.SetInputConnection(port)
        calculator.AddScalarArrayName("Weight")
        calculator.AddVectorArrayName("Direction")
        calculator.SetFunction("Direction*Weight")
        orientation = "SignedDirection"
        calculator.SetResultArrayName(orientation)
        port = calculator.GetOutputPort()
        pipeline.append(calculator)
    arrow = vtkArrowSource()  # along +x from the origin, length 1
    arrow.SetShaftRadius(shaft_radius)
    arrow.SetTipRadius(tip_radius)
    arrow.SetTipLength(tip_length)
    arrow.SetShaftResolution(resolution)
    arrow.SetTipResolution(resolution)
    actor = glyph_actor(port, arrow, length, color, orientation)
    actor.pipeline += pipeline
    return actor


def glyph_actor(port, glyph, scale, color, orientation=None):
    """`glyph` (an algorithm) at every point of the output `port`, `scale` times its size, turned
    along the point array `orientation` when given, by a vtkGlyph3DMapper, in one colour. The
    actor keeps `glyph` alive."""
    mapper = vtkGlyph3DMapper()
    mapper.SetInputConnection(port)
    mapper.SetSourceConnection(glyph.GetOutputPort())
    if orientation:
        mapper.SetOrientationArray(orientation)
        mapper.OrientOn()
    else:
        mapper.OrientOff()
    mapper.ScalingOn()  # (with scaling off the mapper ignores the scale factor)
    mapper.SetScaleModeToNoDataScaling()  # every glyph `scale` times its size
    mapper.SetScaleFactor(scale)
    mapper.ScalarVisibilityOff()
    actor = styled_actor(mapper, color)
    actor.pipeline = [glyph]  # ports do not keep their filters alive in Python
    return actor


def tubes(algorithm, radius, sides=16):
    """Thin tubes around the polylines of `algorithm`'s output: lines of width 1 pixel vanish in a
    large image.

    Returns the filter, not its output port: a port does not keep its filter alive in Python.
    """
    tube = vtkTubeFilter()
    tube.SetInputConnection(algorithm.GetOutputPort())
    tube.SetRadius(radius)
    tube.SetNumberOfSides(sides)
    tube.CappingOn()
    return tube


def scalar_bar(lut, title):
    """A vertical colour legend at the right edge, dark text for the white background."""
    bar = vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle(title)
    bar.SetNumberOfLabels(5)
    bar.SetLabelFormat("%.2g")
    bar.SetPosition(0.88, 0.15)
    bar.SetWidth(0.08)
    bar.SetHeight(0.7)
    bar.UnconstrainedFontSizeOn()
    for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        text.SetColor(0.1, 0.1, 0.1)
        text.ShadowOff()
        text.ItalicOff()
        text.SetFontSize(18)
    return bar


def label(text, world_position, font_size=20, justification="centered"):
    """A 2D text anchored at a point of the scene. The bundled fonts have no Greek letters, so
    write "lambda", not the symbol."""
    actor = vtkTextActor()
    actor.SetInput(text)
    actor.GetPositionCoordinate().SetCoordinateSystemToWorld()
    actor.GetPositionCoordinate().SetValue(*world_position)
    prop = actor.GetTextProperty()
    prop.SetFontSize(font_size)
    prop.SetColor(0.1, 0.1, 0.1)
    getattr(prop, "SetJustificationTo" + justification.capitalize())()
    prop.SetVerticalJustificationToCentered()
    prop.SetBackgroundColor(1.0, 1.0, 1.0)  # stays readable where it overlaps the curves
    prop.SetBackgroundOpacity(0.85)
    return actor


def new_renderer():
    """A renderer with a white background and a light kit (softer than the single headlight)."""
    renderer = vtkRenderer()
    renderer.SetBackground(1.0, 1.0, 1.0)
    lights = vtkLightKit()
    lights.SetKeyLightIntensity(1.0)  # default 0.75 leaves the dark colours murky
    lights.AddLightsToRenderer(renderer)
    return renderer


def render_to_png(renderer, path, size, view_direction=(0, 0, 1), view_up=(0, 1, 0), zoom=1.0,
                  parallel=False):
    """Render `renderer` offscreen into a `size` window and write it to `path`; return the path.

    The camera looks at the scene's center from `view_direction` (a vector from the scene toward
    the camera), is moved back until the whole scene is in view, then zoomed by `zoom`.
    """
    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)  # no window on screen; an X server is still needed
    window.SetMultiSamples(8)  # smooth edges of thin tubes
    window.SetSize(*size)
    window.AddRenderer(renderer)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(*view_direction)
    camera.SetViewUp(*view_up)
    camera.SetParallelProjection(parallel)
    renderer.ResetCamera()  # keeps the direction, fits the distance (or parallel scale)
    camera.Zoom(zoom)
    renderer.ResetCameraClippingRange()
    window.Render()

    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()  # read what was just rendered, not a stale front buffer
    grab.Update()

    path = os.path.abspath(path)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()
    window.Finalize()  # release the OpenGL context before the next figure makes its own
    return path


def render_figure(description, default_output, build_scene, argv=None, default_size=(900, 700),
                  **view):
    """The main() of a figure script: parse --output/--size, render build_scene() to PNG (`view`:
    the keywords of render_to_png), print and return the path."""
    args = parse_args(description, default_output, argv, default_size=default_size)
    path = render_to_png(build_scene(), args.output, args.size, **view)
    print(path)
    return path
