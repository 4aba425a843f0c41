"""Paper Fig 3: a horn, made by a boost whose fixed point lies on the circle's axis.

The base circle C is the unit circle in the yz plane. Its axis is the x axis (the dual line
-ni⌋C). The tangent along the axis, no^d, translated to a point L on the axis, is the null point
pair tau = tau(L, d); the boosts K = 1 + k tau for k in [0, 1] slide C along the axis toward L and
shrink it (docs/conventions.md section 3 item 3). Every point of C moves on a circular arc that
would reach L tangent to the axis (as k grows without bound), so the meridians of the surface bend
away from the axis while its circles go around it: the surface is negatively curved, a horn whose
tip is L.

vtkBoostedSurfaceSource does this with BoostAtCircleCenter off, BoostLocation = L and
BoostDirection = d; its "lambda" is the paper's k.

    python3 fig3_horn.py --output fig3.png --size 900 700
"""
from boostedsurfaces import vtkBoostedSurfaceSource
from vtkmodules.vtkFiltersSources import vtkLineSource, vtkSphereSource

import gallery_common as gc

# L = (LOCATION, 0, 0) and d = (DIRECTION, 0, 0). With L * d < 0 (L behind the circle, d pointing
# forward) the radius 1/(1 - 2 k L d + k^2 d^2 (1 + L^2)) falls monotonically: a horn. (With
# L * d > 0 the circles first grow, then shrink: a bulb, not a horn.) The weight |d| = 1.5 takes
# the radius down to 0.08 at k = 1 while spreading k evenly enough along the horn for the colours.
LOCATION = -1.5
DIRECTION = 1.5
K_RANGE = (0.0, 1.0)


def horn(k_range=K_RANGE, output_type=vtkBoostedSurfaceSource.SURFACE):
    source = vtkBoostedSurfaceSource()
    source.SetCircleCenter(0, 0, 0)
    source.SetCircleNormal(1, 0, 0)  # C: the unit circle of the yz plane, axis x
    source.SetCircleRadius(1)
    source.SetBoostAtCircleCenter(False)
    source.SetBoostLocation(LOCATION, 0, 0)  # L: a point on the axis
    source.SetBoostDirection(DIRECTION, 0, 0)  # d: along the axis; its length is the weight
    source.SetLambdaRange(*k_range)
    source.SetLambdaResolution(96)
    source.SetThetaResolution(96)
    source.SetOutputType(output_type)
    return source


def build_scene():
    lut = gc.lambda_lookup_table(K_RANGE)
    renderer = gc.new_renderer()
    renderer.AddActor(gc.colored_actor(horn(), lut))
    # The base circle C (k = 0) ...
    base = horn((0.0, 0.0), vtkBoostedSurfaceSource.CIRCLES)
    renderer.AddActor(gc.colored_actor(gc.tubes(base, 0.015), color="Black"))
    # ... its axis, and the boost's fixed point L on it.
    axis = vtkLineSource()
    axis.SetPoint1(LOCATION - 0.5, 0, 0)
    axis.SetPoint2(1.0, 0, 0)
    renderer.AddActor(gc.colored_actor(gc.tubes(axis, 0.008), color="DimGray"))
    tip = vtkSphereSource()
    tip.SetCenter(LOCATION, 0, 0)
    tip.SetRadius(0.04)
    tip.SetThetaResolution(24)
    tip.SetPhiResolution(24)
    renderer.AddActor(gc.colored_actor(tip, color="Crimson"))
    renderer.AddActor2D(gc.label("L", (LOCATION, 0.0, 0.2)))
    renderer.AddActor2D(gc.scalar_bar(lut, "k"))
    return renderer


def main(argv=None):
    return gc.render_figure(__doc__.splitlines()[0], "fig3_horn.png", build_scene, argv,
                            view_direction=(-0.4, -1.0, 0.4), view_up=(0, 0, 1), zoom=1.3)


if __name__ == "__main__":
    main()
