"""Paper Fig 9: patches bent by four uv control points at their corners (eq 21-22).

Each control point i states curvatures kappa_u, kappa_v at its location x_i; a point p of the plane
is boosted by K = exp(-sum_i W_i tau_i) with W_i = (kappa_ui/(d_ui^2 + eps) + kappa_vi/(d_vi^2 +
eps)) / (k |p - x_i|^2 + eps), d_ui and d_vi the eq 18 distances to the control point's osculating
circles (docs/conventions.md section 3 item 8). The arrows are the control points' tangents (their
normals):

a) positive umbilic (all 0.5, 0.5), b) negative umbilic, c) hyperbolic (0.5, -0.5),
d) hyperbolic with alternating signs.

    python3 fig9_control_point_patches.py --output fig9.png --size 1300 420
"""
import gallery_common as gc
import curvature_common as cc

HALF = 1.5  # control points at (+-HALF, +-HALF) from each patch's center
CORNERS = [(-1, -1), (1, -1), (-1, 1), (1, 1)]
CASES = [
    ("a) positive umbilic", [(0.5, 0.5)] * 4),
    ("b) negative umbilic", [(-0.5, -0.5)] * 4),
    ("c) hyperbolic", [(0.5, -0.5)] * 4),
    ("d) hyperbolic", [(0.5, -0.5), (-0.5, 0.5), (-0.5, 0.5), (0.5, -0.5)]),
]
SPACING = 6.0
EPSILON = 0.5  # the default, stated: smooth bumps around each control point


def control_points(x, curvatures):
    """Four control points (location, normal +z, u direction +x, kappa_u, kappa_v)."""
    return [(x + sx * HALF, sy * HALF, 0.0, 0, 0, 1, 1, 0, 0, ku, kv)
            for (sx, sy), (ku, kv) in zip(CORNERS, curvatures)]


def four_corner_patch(x, curvatures, resolution=64):
    return cc.patch(control_points(x, curvatures), Method=3, Origin=(x, 0, 0), Size=(5.0, 5.0),
                    UResolution=resolution, VResolution=resolution, Falloff=1.0, Epsilon=EPSILON)


def build_scene():
    sources = [four_corner_patch(i * SPACING, curvatures)
               for i, (_, curvatures) in enumerate(CASES)]
    renderer = gc.new_renderer()
    cc.add_height_colored(renderer, sources)
    for i, (source, (name, _)) in enumerate(zip(sources, CASES)):
        cc.add_arrows(renderer, source, length=0.8)
        renderer.AddActor2D(gc.label(name, (i * SPACING, -3.6, 0.0), font_size=22))
    return renderer


def main(argv=None):
    return cc.render_figure(__doc__.splitlines()[0], "fig9_control_point_patches.png", build_scene,
                            argv)


if __name__ == "__main__":
    main()
