"""Paper Fig 7: principal curvatures stated at a point by two translated tangents (eq 16).

Each patch is the plane z = 0 around its origin, boosted point by point with K = exp(-1/2 (kappa_u
tau(o + b v, n) + kappa_v tau(o + a u, n))) (docs/conventions.md section 3 item 6). The principal
curvatures at the origin are kappa_u along u (x) and kappa_v along v (y). The four presets of
vtkCurvaturePatchSource (CurvaturePreset) reproduce Fig 7:

a) parabolic (0.5, 0), b) elliptic (0.5, 0.25), c) umbilic (0.5, 0.5), d) hyperbolic (-0.5, 0.5).

The arrow is the tangent along the normal at the origin; colours show the height z, on one scale
for the four patches that spans their heights.

    python3 fig7_translated_tangents.py --output fig7.png --size 1300 420
"""
from vtkmodules.vtkFiltersCore import vtkElevationFilter

import gallery_common as gc
import curvature_common as cc

PRESETS = [(1, "a) parabolic"), (2, "b) elliptic"), (3, "c) umbilic"), (4, "d) hyperbolic")]
SPACING = 4.0


def preset_patch(preset, x):
    return cc.patch(Method=1, CurvaturePreset=preset, Origin=(x, 0, 0), Size=(3.0, 3.0),
                    UResolution=48, VResolution=48)


def build_scene():
    sources = [preset_patch(preset, i * SPACING) for i, (preset, _) in enumerate(PRESETS)]
    heights = []
    for source in sources:
        source.Update()
        heights += source.GetOutput().GetBounds()[4:6]
    z_range = (min(heights), max(heights))
    lut = gc.lambda_lookup_table(z_range)
    renderer = gc.new_renderer()
    for i, (source, (_, name)) in enumerate(zip(sources, PRESETS)):
        height = vtkElevationFilter()  # colour by z: kappa > 0 bends toward -z
        height.SetInputConnection(source.GetOutputPort())
        height.source = source  # a port does not keep its filter alive in Python
        height.SetLowPoint(0, 0, z_range[0])
        height.SetHighPoint(0, 0, z_range[1])
        height.SetScalarRange(*z_range)
        actor = gc.colored_actor(height, lut, array="Elevation")
        renderer.AddActor(actor)
        cc.add_arrows(renderer, source, length=0.8)
        renderer.AddActor2D(gc.label(name, (i * SPACING, -2.4, 0.0), font_size=22))
    bar = gc.scalar_bar(lut, "height z")
    bar.SetPosition(0.9, 0.12)
    bar.SetWidth(0.07)
    bar.SetHeight(0.76)
    renderer.AddActor2D(bar)
    renderer.GetActiveCamera().SetWindowCenter(0.1, 0.0)  # the patches left of the bar
    return renderer


def main(argv=None):
    return cc.render_figure(__doc__.splitlines()[0], "fig7_translated_tangents.png", build_scene,
                            argv, default_size=(1300, 420), zoom=2.5)


if __name__ == "__main__":
    main()
