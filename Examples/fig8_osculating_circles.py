"""Paper Fig 8: curvatures weighted by the squared distance to two osculating circles (eq 17-18).

At the origin of each patch the osculating circles C_u and C_v of curvatures kappa_u, kappa_v are
the images of the u and v lines under eq 15. Every point p of the plane is boosted by K =
exp(-(kappa_u/(d_u^2 + eps) + kappa_v/(d_v^2 + eps)) tau), tau the tangent along the normal at the
origin and d^2 = (up(p) _| C*)^2 (docs/conventions.md section 3 item 7). The weights grow near the
circles, so the deformation falls off with the distance from them, as the paper observes:

a) kappa_u < 0, kappa_v = 0, b) both negative and different, c) both negative and equal,
d) kappa_u < 0 < kappa_v.

    python3 fig8_osculating_circles.py --output fig8.png --size 1200 450
"""
import gallery_common as gc
import curvature_common as cc

CASES = [((-0.5, 0.0), "a)"), ((-0.5, -0.25), "b)"), ((-0.5, -0.5), "c)"), ((-0.5, 0.5), "d)")]
SPACING = 5.0
EPSILON = 0.5  # the default, stated: smooth bumps (0.01 gives sharp pinches)


def build_scene():
    renderer = gc.new_renderer()
    for i, ((ku, kv), name) in enumerate(CASES):
        x = i * SPACING
        source = cc.patch(Method=2, Origin=(x, 0, 0), Size=(4.0, 4.0), UResolution=64,
                          VResolution=64, KappaU=ku, KappaV=kv, Epsilon=EPSILON)
        renderer.AddActor(cc.surface_actor(source, "LightSteelBlue"))
        cc.add_arrows(renderer, source, length=0.8)
        renderer.AddActor2D(gc.label(name, (x, -3.0, 0.0), font_size=22))
    return renderer


def main(argv=None):
    return cc.render_figure(__doc__.splitlines()[0], "fig8_osculating_circles.png", build_scene,
                            argv, view_direction=(0.0, -1.0, 0.8), zoom=1.5)


if __name__ == "__main__":
    main()
