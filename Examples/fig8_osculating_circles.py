"""Paper Fig 8: curvatures weighted by the squared distance to two osculating circles (eq 17-18).

At the origin of each patch the osculating circles C_u and C_v of curvatures kappa_u, kappa_v are
the images of the u and v lines under eq 15. Every point p of the plane is boosted by K =
exp(-(kappa_u/(d_u^2 + eps) + kappa_v/(d_v^2 + eps)) tau), tau the tangent along the normal at the
origin and d^2 = (up(p) _| C*)^2 (docs/conventions.md section 3 item 7). The weights grow near the
circles, so the deformation falls off with the distance from them, as the paper observes:

a) kappa_u < 0, kappa_v = 0, b) both negative and different, c) both negative and equal,
d) kappa_u < 0 < kappa_v (parabolic, elliptic, umbilic and hyperbolic, as the paper names them).
Colours show the height z, on one scale for the four patches that spans their heights.

    python3 fig8_osculating_circles.py --output fig8.png --size 1300 420
"""
import gallery_common as gc
import curvature_common as cc

CASES = [((-0.5, 0.0), "a) parabolic"), ((-0.5, -0.25), "b) elliptic"),
         ((-0.5, -0.5), "c) umbilic"), ((-0.5, 0.5), "d) hyperbolic")]
SPACING = 5.0
EPSILON = 0.5  # the default, stated: smooth bumps (0.01 gives sharp pinches)


def build_scene():
    sources = [cc.patch(Method=2, Origin=(i * SPACING, 0, 0), Size=(4.0, 4.0), UResolution=96,
                        VResolution=96, KappaU=ku, KappaV=kv, Epsilon=EPSILON)
               for i, ((ku, kv), _) in enumerate(CASES)]
    renderer = gc.new_renderer()
    cc.add_height_colored(renderer, sources)
    for i, (source, (_, name)) in enumerate(zip(sources, CASES)):
        cc.add_arrows(renderer, source, length=0.8)
        renderer.AddActor2D(gc.label(name, (i * SPACING, -2.8, 0.0), font_size=22))
    return renderer


def main(argv=None):
    return cc.render_figure(__doc__.splitlines()[0], "fig8_osculating_circles.png", build_scene,
                            argv, view_direction=(0.0, -1.0, 0.8))


if __name__ == "__main__":
    main()
