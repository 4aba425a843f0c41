"""Paper Fig 2: surfaces swept by boosting a circle along its normal.

The unit circle in the yz plane is transformed by K = exp(lambda no^e1) = 1 + lambda no e1, a boost
at its center along x, which is the circle's normal (docs/conventions.md section 3 item 2). Each
image is a circle in the plane x = lambda/(1+lambda^2) with radius 1/(1+lambda^2); sweeping lambda
over a range gives a surface. As in the paper, three ranges side by side: [0, 1], [0, 2] and [0, 4].
The first flares out to x = 1/2 at lambda = 1, the others turn back toward the circle's center.

vtkBoostedSurfaceSource with its default OutputType SURFACE gives quads with normals and the point
array "lambda", used for the colours (one colour scale for all three).

    python3 fig2_boosted_surfaces.py --output fig2.png --size 1200 500
"""
from boostedsurfaces import vtkBoostedSurfaceSource
from vtkmodules.vtkCommonCore import vtkMath

import gallery_common as gc

LAMBDA_RANGES = [(0.0, 1.0), (0.0, 2.0), (0.0, 4.0)]
VIEW_DIRECTION = (0.7, -1.0, 0.35)  # from the scene toward the camera: from the side, +x and above
VIEW_UP = (0.0, 0.0, 1.0)
SPACING = 2.6  # distance between the circles' centers


def screen_right():
    """The unit vector pointing right on the screen: the surfaces are lined up along it."""
    right = [0.0, 0.0, 0.0]
    vtkMath.Cross(VIEW_UP, VIEW_DIRECTION, right)
    vtkMath.Normalize(right)
    return right


def boosted_surface(center, lambda_range):
    """The unit circle of the plane x = center[0], boosted at its center along its normal x."""
    source = vtkBoostedSurfaceSource()
    source.SetCircleCenter(center)
    source.SetCircleNormal(1, 0, 0)  # the yz plane
    source.SetCircleRadius(1)
    source.SetBoostDirection(1, 0, 0)  # the normal
    source.SetBoostAtCircleCenter(True)  # the boost moves along with the circle
    source.SetLambdaRange(*lambda_range)
    source.SetLambdaResolution(64)
    source.SetThetaResolution(96)
    return source


def build_scene():
    # One colour scale for all three. Above lambda = 2 the circles are small (radius < 0.2), so
    # the scale stops there (larger values get its last colour) and spends its colours where the
    # surfaces are.
    lut = gc.lambda_lookup_table((0.0, 2.0))
    renderer = gc.new_renderer()
    right = screen_right()
    for i, lambda_range in enumerate(LAMBDA_RANGES):
        center = [(i - 1) * SPACING * r for r in right]
        surface = boosted_surface(center, lambda_range)
        renderer.AddActor(gc.colored_actor(surface, lut))
        # the original circle (lambda = 0), for reference
        circle = boosted_surface(center, (0.0, 0.0))
        circle.SetOutputTypeToCircles()
        renderer.AddActor(gc.colored_actor(gc.tubes(circle, 0.015), color="Black"))
        text = "lambda from %g to %g" % lambda_range
        renderer.AddActor2D(gc.label(text, (center[0], center[1], -1.4)))
    renderer.AddActor2D(gc.scalar_bar(lut, "lambda"))
    return renderer


def main(argv=None):
    return gc.render_figure(__doc__.splitlines()[0], "fig2_boosted_surfaces.png", build_scene,
                            argv, default_size=(1200, 500), view_direction=VIEW_DIRECTION,
                            view_up=VIEW_UP, zoom=1.8, parallel=True)


if __name__ == "__main__":
    main()
