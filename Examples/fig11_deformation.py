"""Paper Fig 11: a plane (left) and a sphere (right) warped by fields of point-pair generators.

Each generator is a null point pair tau(x, v) at a location x with a direction v and a weight w
(drawn as an arrow from x along v). At every mesh point p the generators sum, weighted by the
inverse squared distance, into B(p) = sum w tau(x, v) / (k |p - x|^2 + eps), and p moves to fn(K
up(p) ~K) with K = exp(-B(p)) (eq 23, docs/conventions.md section 3 item 9).
vtkPointPairDeformationFilter does this for any mesh; the colour is the length of its "Displacement"
array.

    python3 fig11_deformation.py --output fig11.png --size 900 700
"""
from boostedsurfaces import vtkPointPairDeformationFilter
from vtkmodules.vtkFiltersCore import vtkArrayCalculator, vtkPolyDataNormals
from vtkmodules.vtkFiltersSources import vtkPlaneSource, vtkSphereSource

import gallery_common as gc

# (location, direction, weight). The plane z = 0 spans [-2, 2]^2; the sphere of radius 1 is
# centred at SPHERE_CENTER. Directions normal to a surface push it in or out (bumps and dimples);
# tangential ones bend it sideways.
PLANE_GENERATORS = [
    ((-1.0, -0.8, 0.4), (0, 0, 1), 0.7),
    ((1.0, -0.7, -0.4), (0, 0, 1), -0.7),
    ((-0.3, 0.9, 0.3), (1, 0, 0), 0.6),
    ((1.1, 1.0, 0.3), (0, 0, -1), 0.5),
]
SPHERE_CENTER = (5.0, 0.0, 0.0)
SPHERE_GENERATORS = [
    ((5.0, 0.0, 1.4), (0, 0, 1), 0.6),
    ((6.4, 0.0, 0.2), (1, 0, 0), -0.5),
    ((4.6, -1.4, -0.4), (0, 1, 0), 0.5),
    ((4.3, 0.9, -1.0), (-1, 1, -1), 0.4),
]
FALLOFF = 4.0
EPSILON = 0.05
DISPLACEMENT_RANGE = (0.0, 0.6)
# The camera and default size of the figure (and of its regression test,
# Python.PointPairDeformationImage).
VIEW = dict(view_direction=(0.15, -1.0, 0.6), view_up=(0, 0, 1), zoom=1.1)
SIZE = (900, 700)


def deformation_filter(source, generators):
    deformation = vtkPointPairDeformationFilter()
    deformation.SetInputConnection(source.GetOutputPort())
    for location, direction, weight in generators:
        deformation.AddGenerator(*location, *direction, weight)
    deformation.SetFalloff(FALLOFF)
    deformation.SetEpsilon(EPSILON)
    return deformation


def deformed(deformation):
    """The warped mesh with smooth normals and a point array "|Displacement|"."""
    length = vtkArrayCalculator()
    length.SetInputConnection(deformation.GetOutputPort())
    length.AddVectorArrayName("Displacement")
    length.SetFunction("mag(Displacement)")
    length.SetResultArrayName("|Displacement|")
    normals = vtkPolyDataNormals()  # the filter drops normals; recompute them on the warped mesh
    normals.SetInputConnection(length.GetOutputPort())
    normals.SplittingOff()
    return normals


def build_scene():
    plane = vtkPlaneSource()
    plane.SetOrigin(-2, -2, 0)
    plane.SetPoint1(2, -2, 0)
    plane.SetPoint2(-2, 2, 0)
    plane.SetResolution(120, 120)
    sphere = vtkSphereSource()
    sphere.SetCenter(*SPHERE_CENTER)
    sphere.SetRadius(1.0)
    sphere.SetThetaResolution(128)
    sphere.SetPhiResolution(96)

    lut = gc.lambda_lookup_table(DISPLACEMENT_RANGE)
    renderer = gc.new_renderer()
    for source, generators in ((plane, PLANE_GENERATORS), (sphere, SPHERE_GENERATORS)):
        deformation = deformation_filter(source, generators)
        renderer.AddActor(gc.colored_actor(deformed(deformation), lut, "|Displacement|"))
        # The generators from the filter's Generators port, reversed where a weight is negative.
        renderer.AddActor(gc.generator_arrows(deformation, 0.45, "Crimson", signed=True,
                                              tip_radius=0.1, tip_length=0.35, resolution=24))
    renderer.AddActor2D(gc.scalar_bar(lut, "|displacement|"))
    return renderer


def main(argv=None):
    return gc.render_figure(__doc__.splitlines()[0], "fig11_deformation.png", build_scene, argv,
                            default_size=SIZE, **VIEW)


if __name__ == "__main__":
    main()
