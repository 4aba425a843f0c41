"""Paper Fig 1: a unit circle boosted in its own plane.

The unit circle in the xy plane is transformed by K = exp(lambda no^e1) = 1 + lambda no e1, a boost
at the origin along x (docs/conventions.md section 3 item 1). The image is the circle with center
lambda/(lambda^2-1) e1 and radius 1/|lambda^2-1|:

* lambda < 1: the circle grows to the left (blue),
* lambda = 1: it passes through infinity and is the line x = 1/2 (black),
* lambda > 1: it comes back from the right, turned inside out, and shrinks onto its old center.

vtkBoostedSurfaceSource with OutputType CIRCLES gives one polyline per lambda, carrying the point
array "lambda" used for the colours. The circles are cut exactly at the clip sphere, radius
ClipRadius about the center.

    python3 fig1_boosted_circle.py --output fig1.png --size 900 700
"""
from boostedsurfaces import vtkBoostedSurfaceSource

import gallery_common as gc

LAMBDA_RANGE = (0.0, 2.0)


def circles(lambda_range, resolution):
    """The boosted unit circle of the xy plane, one polyline per lambda."""
    source = vtkBoostedSurfaceSource()
    source.SetCircleCenter(0, 0, 0)
    source.SetCircleNormal(0, 0, 1)  # the xy plane
    source.SetCircleRadius(1)
    source.SetBoostDirection(1, 0, 0)  # in the plane: along x
    source.SetLambdaRange(*lambda_range)
    source.SetLambdaResolution(resolution)
    source.SetThetaResolution(256)  # the large circles near lambda = 1 need many samples
    source.SetClipRadius(3.5)
    source.SetOutputTypeToCircles()
    return source


def build_scene():
    lut = gc.lambda_lookup_table(LAMBDA_RANGE)
    renderer = gc.new_renderer()
    # lambda in steps of 0.125; 1 is one of them
    family = circles(LAMBDA_RANGE, 16)
    renderer.AddActor(gc.colored_actor(gc.tubes(family, 0.015), lut))
    # lambda = 0 (the original circle) and lambda = 1 (the line) drawn thicker, in black
    for value in (0.0, 1.0):
        special = circles((value, value), 1)
        renderer.AddActor(gc.colored_actor(gc.tubes(special, 0.03), color="Black"))
    renderer.AddActor2D(gc.scalar_bar(lut, "lambda"))
    renderer.AddActor2D(gc.label("lambda < 1", (-2.6, -3.0, 0.0)))
    renderer.AddActor2D(gc.label("lambda = 1", (0.6, 3.2, 0.0), justification="left"))
    renderer.AddActor2D(gc.label("lambda > 1", (2.6, -3.0, 0.0)))
    return renderer


def main(argv=None):
    # Look down on the xy plane; the parallel projection keeps the circles round.
    return gc.render_figure(__doc__.splitlines()[0], "fig1_boosted_circle.png", build_scene, argv,
                            zoom=1.2, parallel=True)


if __name__ == "__main__":
    main()
