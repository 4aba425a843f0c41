"""Helpers shared by the curvature-control figure scripts (paper Fig 6-10, 12): a configured
vtkCurvaturePatchSource and arrows for its generators."""
from boostedsurfaces import vtkCurvaturePatchSource
from vtkmodules.vtkFiltersCore import vtkElevationFilter

import gallery_common as gc


def patch(control_points=(), **settings):
    """A vtkCurvaturePatchSource with Set<Name>(value) called for every keyword (tuples are
    unpacked), and the given control points (each a tuple of 11 numbers)."""
    source = vtkCurvaturePatchSource()
    for name, value in settings.items():
        setter = getattr(source, "Set" + name)
        if isinstance(value, (tuple, list)):
            setter(*value)
        else:
            setter(value)
    for point in control_points:
        source.AddControlPoint(*point)
    return source


def add_arrows(renderer, source, length=1.0, color="Tomato", signed=False):
    """The arrows of the patch `source`'s generators (its Generators port, output 1)."""
    renderer.AddActor(gc.generator_arrows(source, length, color, signed))


def add_height_colored(renderer, sources):
    """The patches `sources` coloured by their height z on one scale that spans their z range (the
    data's, so that the colours use the whole map), with its colour bar at the right edge."""
    heights = []
    for source in sources:
        source.Update()
        heights += source.GetOutput().GetBounds()[4:6]
    z_range = (min(heights), max(heights))
    lut = gc.lambda_lookup_table(z_range)
    for source in sources:
        height = vtkElevationFilter()  # colour by z: kappa > 0 bends toward -z
        height.SetInputConnection(source.GetOutputPort())
        height.source = source  # a port does not keep its filter alive in Python
        height.SetLowPoint(0, 0, z_range[0])
        height.SetHighPoint(0, 0, z_range[1])
        height.SetScalarRange(*z_range)
        renderer.AddActor(gc.colored_actor(height, lut, array="Elevation"))
    bar = gc.scalar_bar(lut, "height z")
    bar.SetPosition(0.9, 0.12)
    bar.SetWidth(0.07)
    bar.SetHeight(0.76)
    renderer.AddActor2D(bar)
    renderer.GetActiveCamera().SetWindowCenter(0.1, 0.0)  # the patches left of the bar


def render_figure(description, default_output, build_scene, argv=None, default_size=(1300, 420),
                  view_direction=(0.0, -1.0, 0.9), view_up=(0, 0, 1), zoom=2.5, parallel=False):
    """gc.render_figure with the curvature figures' defaults: a view of a row of patches in the xy
    plane from the front and above."""
    return gc.render_figure(description, default_output, build_scene, argv, default_size,
                            view_direction=view_direction, view_up=view_up, zoom=zoom,
                            parallel=parallel)
