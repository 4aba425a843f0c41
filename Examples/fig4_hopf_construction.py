"""Paper Fig 4: the Hopf fibration built from one circle by a boost followed by a twist.

Four panels, left to right, each around its own copy of the base circle C (the unit circle of the
xy plane) and its axis, the z axis:
  a) C and its axis: the fibers over the south pole (phi = -pi/2) and the north pole (phi = pi/2).
  b) The boost K = 1 + k no v (v = e1, k in [0, 1]) straightens C into the line L_0 through
     (1/2, 0, 0) along y (vtkBoostedSurfaceSource with the boost in C's plane, as in Fig 1).
  c) The twist M(k) = exp(k/2 log(L / L_0)) screws L_0 into the axis L: a quarter turn about the
     x axis, the common perpendicular, while sliding from x = 1/2 to 0. The lines M(k) L_0 ~M(k)
     pass through ((1 - k)/2, 0, 0) along (0, cos(k pi/2), sin(k pi/2)) (this closed form is
     checked against the kernel's motor in CGA/Testing/TestHopfFibration.cpp).
  d) KH = M K applied to C for k = 1/2 + phi/pi: the fibers over one meridian (theta = 0) and the
     twistor mesh they sweep (vtkHopfFibrationSource, OutputType TWISTOR_MESH, one theta sample).

    python3 fig4_hopf_construction.py --output fig4.png --size 1400 520
"""
import math

from boostedsurfaces import vtkBoostedSurfaceSource, vtkHopfFibrationSource
from vtkmodules.vtkFiltersSources import vtkLineSource

import gallery_common as gc

SPACING = 3.6  # distance between the panels along x
CLIP = 2.2  # clip radius about the circle center (circle radius 1) of the huge fibers near phi = pi/2
PHI_RANGE = (-math.pi / 2, math.pi / 2)


def axis(x, length=CLIP):
    line = vtkLineSource()
    line.SetPoint1(x, 0, -length)
    line.SetPoint2(x, 0, length)
    return line


def base_fibers(x, phis, theta=0.0):
    """The fibers over (theta, phi) for each phi, around the circle centred at (x, 0, 0)."""
    source = vtkHopfFibrationSource()
    source.SetCircleCenter(x, 0, 0)
    source.SetSamplingModeToBasePoints()
    for phi in phis:
        source.AddBasePoint(theta, phi)
    source.SetFiberResolution(256)
    source.SetClipRadius(CLIP)
    return source


def panel_a(renderer, lut, x):
    renderer.AddActor(gc.colored_actor(gc.tubes(base_fibers(x, [PHI_RANGE[0]]), 0.03), lut, "phi"))
    renderer.AddActor(gc.colored_actor(gc.tubes(axis(x), 0.03), color=lut.GetTableValue(255)[:3]))
    renderer.AddActor2D(gc.label("a) circle and axis", (x, 0, -2.7)))


def panel_b(renderer, lut, x):
    boost = vtkBoostedSurfaceSource()
    boost.SetCircleCenter(x, 0, 0)
    boost.SetCircleNormal(0, 0, 1)
    boost.SetBoostDirection(1, 0, 0)  # v_0 = e1: K = 1 + k no e1
    boost.SetLambdaRange(0.0, 1.0)  # k; at k = 1 the circle is the line x = 1/2
    boost.SetLambdaResolution(6)
    boost.SetThetaResolution(256)
    boost.SetClipRadius(CLIP)
    boost.SetOutputTypeToCircles()
    renderer.AddActor(gc.colored_actor(gc.tubes(boost, 0.02), gc.lambda_lookup_table((0, 1))))
    renderer.AddActor(gc.colored_actor(gc.tubes(axis(x), 0.02), color="DimGray"))
    renderer.AddActor2D(gc.label("b) boost", (x, 0, -2.7)))


def panel_c(renderer, x, steps=6):
    k_lut = gc.lambda_lookup_table((0, 1))
    for i in range(steps + 1):
        k = i / steps
        center = (x + 0.5 * (1 - k), 0, 0)
        direction = (0, math.cos(0.5 * k * math.pi), math.sin(0.5 * k * math.pi))
        line = vtkLineSource()
        line.SetPoint1(*[c - CLIP * d for c, d in zip(center, direction)])
        line.SetPoint2(*[c + CLIP * d for c, d in zip(center, direction)])
        renderer.AddActor(gc.colored_actor(gc.tubes(line, 0.02), color=k_lut.GetTableValue(int(255 * k))[:3]))
    renderer.AddActor2D(gc.label("c) twist", (x, 0, -2.7)))


def panel_d(renderer, lut, x):
    mesh = vtkHopfFibrationSource()
    mesh.SetCircleCenter(x, 0, 0)
    mesh.SetOutputTypeToTwistorMesh()
    mesh.SetThetaRange(0.0, 0.0)
    mesh.SetThetaResolution(1)  # one meridian, theta = 0
    mesh.SetPhiResolution(64)
    mesh.SetFiberResolution(256)
    mesh.SetClipRadius(CLIP)
    surface = gc.colored_actor(mesh, lut, "phi")
    surface.GetProperty().SetOpacity(0.55)
    renderer.AddActor(surface)
    phis = [PHI_RANGE[0] + i * math.pi / 8 for i in range(9)]
    renderer.AddActor(gc.colored_actor(gc.tubes(base_fibers(x, phis), 0.02), lut, "phi"))
    renderer.AddActor2D(gc.label("d) boost and twist", (x, 0, -2.7)))


def build_scene():
    lut = gc.lambda_lookup_table(PHI_RANGE)
    renderer = gc.new_renderer()
    panel_a(renderer, lut, 0 * SPACING)
    panel_b(renderer, lut, 1 * SPACING)
    panel_c(renderer, 2 * SPACING)
    panel_d(renderer, lut, 3 * SPACING)
    return renderer


def main(argv=None):
    return gc.render_figure(__doc__.splitlines()[0], "fig4_hopf_construction.png", build_scene,
                            argv, default_size=(1400, 520), view_direction=(0.12, -1.0, 0.45),
                            view_up=(0, 0, 1), zoom=2.4, parallel=True)


if __name__ == "__main__":
    main()
