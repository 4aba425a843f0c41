"""Helpers shared by the curvature-control figure scripts (paper Fig 6-10, 12): a configured
vtkCurvaturePatchSource and arrows for its generators."""
from boostedsurfaces import vtkCurvaturePatchSource

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


def surface_actor(source, color):
    """The patch in one colour, lit from both sides."""
    actor = gc.colored_actor(source, color=color)
    actor.GetProperty().BackfaceCullingOff()
    return actor


def render_figure(description, default_output, build_scene, argv=None, default_size=(1200, 450),
                  view_direction=(0.0, -1.0, 0.9), view_up=(0, 0, 1), zoom=2.0, parallel=False):
    """gc.render_figure with the curvature figures' defaults: a view of a row of patches in the xy
    plane from the front and above."""
    return gc.render_figure(description, default_output, build_scene, argv, default_size,
                            view_direction=view_direction, view_up=view_up, zoom=zoom,
                            parallel=parallel)
