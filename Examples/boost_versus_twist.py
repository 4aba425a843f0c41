"""One bar, two kinds of generator: point pairs (boosts) against twists (screws).

The same three generators sit on the bar's axis at x = -2, 0, 2, directed along it, (1, 0, 0),
with the weight WEIGHT. Top: they are POINT_PAIR rows, tau(x, v): each boost is a special
conformal transformation about its location, which swells and pinches the bar along its axis and
bends nothing sideways (every point moves within its plane through the axis). Bottom: the same
rows as TWIST with the pitch PITCH: each turns the bar about its axis by w / (k |p - x_i|^2 + eps)
radians and advances it along the axis by PITCH times that angle (docs/conventions.md section 2
item 11), so the bar keeps its width: its points only turn about the axis and slide along it.
Both bars are coloured by
|Displacement| on one scale; the straight bar's outline is grey.

    python3 boost_versus_twist.py --output boost_versus_twist.png --size 900 700
"""
from boostedsurfaces import vtkPointPairDeformationFilter
from vtkmodules.vtkFiltersModeling import vtkOutlineFilter

import gallery_common as gc
from twisted_bar import bar, deformed

LOCATIONS = (-2.0, 0.0, 2.0)
WEIGHT = 0.22
PITCH = 0.5
FALLOFF = 1.0
EPSILON = 0.5
OFFSET = 1.6  # the two bars sit at z = +OFFSET (boosts) and z = -OFFSET (twists)
DISPLACEMENT_RANGE = (0.0, 0.8)
VIEW = dict(view_direction=(0.25, -1.0, 0.3), view_up=(0, 0, 1), zoom=1.05)
SIZE = (900, 700)


def rows(center, kind, pitch):
    return [(x, center[1], center[2], 1, 0, 0, WEIGHT, kind, pitch) for x in LOCATIONS]


def build_scene():
    renderer = gc.new_renderer()
    lut = gc.lambda_lookup_table(DISPLACEMENT_RANGE)
    for z, kind, pitch, text in (
            (OFFSET, vtkPointPairDeformationFilter.POINT_PAIR, 0.0, "Point Pair (boost)"),
            (-OFFSET, vtkPointPairDeformationFilter.TWIST, PITCH, "Twist (pitch %g)" % PITCH)):
        center = (0.0, 0.0, z)
        straight = bar(center)
        outline = vtkOutlineFilter()
        outline.SetInputConnection(straight.GetOutputPort())
        warped = deformed(straight, rows(center, kind, pitch), FALLOFF, EPSILON)
        renderer.AddActor(gc.colored_actor(warped, lut, "|Displacement|"))
        renderer.AddActor(gc.colored_actor(gc.tubes(outline, 0.012), color="DarkGray"))
        renderer.AddActor2D(gc.label(text, (0.0, 0.0, z + 1.0)))
    renderer.AddActor2D(gc.scalar_bar(lut, "|displacement|"))
    return renderer


def main(argv=None):
    return gc.render_figure(__doc__.splitlines()[0], "boost_versus_twist.png", build_scene, argv,
                            default_size=SIZE, **VIEW)


if __name__ == "__main__":
    main()
