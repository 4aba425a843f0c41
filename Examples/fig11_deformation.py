"""Paper Fig 11: a plane (a) and a sphere (b-h) warped by fields of point-pair generators.

Each generator is a null point pair tau(x, v) at a location x with a direction v and a weight w
(drawn as an arrow from x along v). At every mesh point p the generators sum, weighted by the
inverse squared distance, into B(p) = sum w tau(x, v) / (k |p - x|^2 + eps), and p moves to fn(K
up(p) ~K) with K = exp(-B(p)) (eq 23, docs/conventions.md section 3 item 9).
vtkPointPairDeformationFilter does this for any mesh; the colour is the length of its "Displacement"
array, on one scale for all panels that ends at the largest displacement.

    python3 fig11_deformation.py --output fig11.png --size 1200 700
"""
from boostedsurfaces import vtkPointPairDeformationFilter
from vtkmodules.vtkFiltersCore import vtkArrayCalculator
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource

import gallery_common as gc

# (location, direction, weight). Panel a: the plane z = 0 over [-2, 2]^2. Panels b-h: a unit sphere
# at the origin under one set of generators each (locations relative to its centre). Directions
# normal to a surface push it in or out (bumps and dimples); tangential ones bend it sideways.
PLANE_GENERATORS = [
    ((-1.0, -0.8, 0.4), (0, 0, 1), 0.7),
    ((1.0, -0.7, -0.4), (0, 0, 1), -0.7),
    ((-0.3, 0.9, 0.3), (1, 0, 0), 0.6),
    ((1.1, 1.0, 0.3), (0, 0, -1), 0.5),
]
SPHERE_PANELS = [
    ("b) one pull", [((0, 0, 1.4), (0, 0, 1), 0.6)]),
    ("c) two pulls", [((0, 0, 1.4), (0, 0, 1), 0.6), ((0, 0, -1.4), (0, 0, -1), 0.6)]),
    ("d) a push", [((0, 0, 1.4), (0, 0, 1), -0.6)]),
    ("e) four pulls", [((1.4 * x, 1.4 * y, 0), (x, y, 0), 0.5)
                       for x, y in ((1, 0), (0, 1), (-1, 0), (0, -1))]),
    ("f) sideways", [((0, -1.4, 0.6), (1, 0, 0), 0.7)]),
    ("g) pull and push", [((0, 0, 1.4), (0, 0, 1), 0.6), ((1.4, 0, 0), (1, 0, 0), -0.5),
                          ((-1.4, 0, 0), (-1, 0, 0), -0.5)]),
    ("h) assortment", [((0.0, 0.0, 1.4), (0, 0, 1), 0.6), ((1.4, 0.0, 0.2), (1, 0, 0), -0.5),
                       ((-0.4, -1.4, -0.4), (0, 1, 0), 0.5), ((-0.7, 0.9, -1.0), (-1, 1, -1), 0.4)]),
]
FALLOFF = 4.0
EPSILON = 0.05
# The panels on a 4 x 2 grid in the x-z plane (seen from -y): a and b-d on top, e-h below.
PANEL_SPACING = (3.6, 4.3)
PLANE_SCALE = 0.6  # the 4-unit plane drawn as large as the spheres around it
PLANE_TILT = 25.0  # degrees about x: the plane faces the camera instead of being seen edge-on
# The camera and default size of the figure (and of its regression test,
# Python.PointPairDeformationImage).
VIEW = dict(view_direction=(0.0, -1.0, 0.4), view_up=(0, 0, 1), zoom=1.5, parallel=True)
SIZE = (1200, 700)


def deformation_filter(source, generators):
    deformation = vtkPointPairDeformationFilter()
    deformation.SetInputConnection(source.GetOutputPort())
    for location, direction, weight in generators:
        deformation.AddGenerator(*location, *direction, weight)
    deformation.SetFalloff(FALLOFF)
    deformation.SetEpsilon(EPSILON)
    return deformation


def deformed(deformation):
    """The warped mesh with a point array "|Displacement|". Its normals are the plane's and the
    sphere's, carried through the map's derivative by the filter (TransformNormals): exact, no
    vtkPolyDataNormals needed."""
    length = vtkArrayCalculator()
    length.SetInputConnection(deformation.GetOutputPort())
    length.AddVectorArrayName("Displacement")
    length.SetFunction("mag(Displacement)")
    length.SetResultArrayName("|Displacement|")
    return length


def panel_offset(index):
    """Where panel `index` (0 = a) sits: row-major on the PANEL_SPACING grid, centred."""
    column, row = index % 4, index // 4
    return (PANEL_SPACING[0] * (column - 1.5), 0.0, PANEL_SPACING[1] * (0.5 - row))


def panels():
    """(title, deformation filter, scale, tilt) of every panel, a to h."""
    plane = vtkPlaneSource()
    plane.SetOrigin(-2, -2, 0)
    plane.SetPoint1(2, -2, 0)
    plane.SetPoint2(-2, 2, 0)
    plane.SetResolution(100, 100)
    sphere = vtkSphereSource()
    sphere.SetRadius(1.0)
    sphere.SetThetaResolution(96)
    sphere.SetPhiResolution(72)
    result = [("a) plane", deformation_filter(plane, PLANE_GENERATORS), PLANE_SCALE, PLANE_TILT)]
    for title, generators in SPHERE_PANELS:
        result.append((title, deformation_filter(sphere, generators), 1.0, 0.0))
    return result


def build_scene():
    shown = [(title, deformed(deformation), deformation, scale, tilt)
             for title, deformation, scale, tilt in panels()]
    largest = 0.0
    for _, warped, _, _, _ in shown:
        warped.Update()
        largest = max(largest, warped.GetOutput().GetPointData().GetArray("|Displacement|")
                      .GetRange()[1])
    lut = gc.lambda_lookup_table((0.0, largest))  # the bar ends at the largest displacement
    renderer = gc.new_renderer()
    for index, (title, warped, deformation, scale, tilt) in enumerate(shown):
        offset = panel_offset(index)
        # The generators from the filter's Generators port, reversed where a weight is negative.
        arrows = gc.generator_arrows(deformation, 0.45, "Crimson", signed=True, tip_radius=0.1,
                                     tip_length=0.35, resolution=24)
        for actor in (gc.colored_actor(warped, lut, "|Displacement|"), arrows):
            actor.SetScale(scale)
            actor.RotateX(tilt)
            actor.SetPosition(*offset)
            renderer.AddActor(actor)
        renderer.AddActor2D(gc.label(title, (offset[0], offset[1], offset[2] + 2.1)))
    renderer.AddActor2D(gc.scalar_bar(lut, "|displacement|"))
    return renderer


def main(argv=None):
    return gc.render_figure(__doc__.splitlines()[0], "fig11_deformation.png", build_scene, argv,
                            default_size=SIZE, **VIEW)


if __name__ == "__main__":
    main()
