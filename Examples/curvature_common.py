"""Helpers shared by the curvature-control figure scripts (paper Fig 6-10, 12): a configured
vtkCurvaturePatchSource and arrows for the point-pair generators."""
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import vtkArrowSource

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


def arrow(start, direction, length=1.0, shaft_radius=0.03, tip_radius=0.08):
    """An arrow from `start` along `direction` (scaled to `length`): a generator's tangent.
    Returns the filter (keep it alive)."""
    import math
    dx, dy, dz = direction
    norm = math.sqrt(dx * dx + dy * dy + dz * dz)
    source = vtkArrowSource()
    source.SetShaftRadius(shaft_radius)
    source.SetTipRadius(tip_radius)
    source.SetTipLength(0.3)
    source.SetShaftResolution(16)
    source.SetTipResolution(16)
    # vtkArrowSource points along +x from the origin with length 1: rotate x onto the direction.
    transform = vtkTransform()
    transform.Translate(*start)
    ax, ay, az = 0.0, -dz / norm, dy / norm  # x cross d
    sine = math.sqrt(ay * ay + az * az)
    angle = math.degrees(math.atan2(sine, dx / norm))
    if sine > 1e-12:
        transform.RotateWXYZ(angle, ax, ay, az)
    elif dx < 0:
        transform.RotateWXYZ(180.0, 0, 0, 1)
    transform.Scale(length, length, length)
    moved = vtkTransformPolyDataFilter()
    moved.SetInputConnection(source.GetOutputPort())
    moved.SetTransform(transform)
    return moved


def add_arrows(renderer, starts_and_directions, length=1.0, color="Tomato"):
    """One arrow actor per (start, direction)."""
    for start, direction in starts_and_directions:
        renderer.AddActor(gc.colored_actor(arrow(start, direction, length), color=color))


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
