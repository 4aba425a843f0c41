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
import gallery_common as gc
import curvature_common as cc

PRESETS = [(1, "a) parabolic"), (2, "b) elliptic"), (3, "c) umbilic"), (4, "d) hyperbolic")]
SPACING = 4.0


def preset_patch(preset, x):
    return cc.patch(Method=1, CurvaturePreset=preset, Origin=(x, 0, 0), Size=(3.0, 3.0),
                    UResolution=48, VResolution=48)


def build_scene():
    sources = [preset_patch(preset, i * SPACING) for i, (preset, _) in enumerate(PRESETS)]
    renderer = gc.new_renderer()
    cc.add_height_colored(renderer, sources)
    for i, (source, (_, name)) in enumerate(zip(sources, PRESETS)):
        cc.add_arrows(renderer, source, length=0.8)
        renderer.AddActor2D(gc.label(name, (i * SPACING, -2.4, 0.0), font_size=22))
    return renderer


def main(argv=None):
    return cc.render_figure(__doc__.splitlines()[0], "fig7_translated_tangents.png", build_scene,
                            argv)


if __name__ == "__main__":
    main()
