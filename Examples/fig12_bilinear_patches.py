"""Paper Fig 12: patches from four corner boosts by bilinear interpolation (eq 25-26).

Tangents are translated to the four corners of a grid (the arrows, reversed where a weight is
negative).
At each grid point (s, t) the corner point pairs are interpolated,
tau_st = (1-s)((1-t) tau_1 + t tau_2) + s((1-t) tau_3 + t tau_4), and the point is moved by
K = exp(-tau_st / 2) (docs/conventions.md section 3 item 11). Four choices of corner tangents:

a) all along the normal, weights (0.5, -0.5, -0.5, 0.5): a saddle (the paper's exponential is
   exact here), b) all along the normal, equal weights, c) tangents tilted 45 degrees along u,
   opposite at opposite corners, d) mixed directions.
In c) and d) the interpolated generator is not a blade: the exact exponential (the default) and
the paper's rule differ.

    python3 fig12_bilinear_patches.py --output fig12.png --size 1300 420
"""
import gallery_common as gc
import curvature_common as cc

SIZE = 3.0
SPACING = 5.0
CASES = [
    ("a) saddle", [(0, 0, 1)] * 4, (0.5, -0.5, -0.5, 0.5)),
    ("b) equal weights", [(0, 0, 1)] * 4, (0.4, 0.4, 0.4, 0.4)),
    ("c) tilted along u", [(1, 0, 1), (-1, 0, 1), (1, 0, -1), (-1, 0, -1)], (0.4, 0.4, 0.4, 0.4)),
    ("d) mixed directions", [(0, 0, 1), (1, 0, 0.5), (0, 1, -0.5), (-1, -1, 1)],
     (0.5, 0.4, 0.4, 0.5)),
]


def bilinear_patch(x, directions, weights, resolution=48):
    settings = dict(Method=5, Origin=(x, 0, 0), Size=(SIZE, SIZE), UResolution=resolution,
                    VResolution=resolution, CornerWeights=weights)
    for i, direction in enumerate(directions):
        settings["Corner%dDirection" % (i + 1)] = direction
    return cc.patch(**settings)


def build_scene():
    sources = [bilinear_patch(i * SPACING, directions, weights)
               for i, (_, directions, weights) in enumerate(CASES)]
    renderer = gc.new_renderer()
    cc.add_height_colored(renderer, sources)
    for i, (source, (name, _, _)) in enumerate(zip(sources, CASES)):
        cc.add_arrows(renderer, source, length=0.8, signed=True)  # every weight is non-zero
        renderer.AddActor2D(gc.label(name, (i * SPACING, -2.6, 0.0), font_size=22))
    return renderer


def main(argv=None):
    return cc.render_figure(__doc__.splitlines()[0], "fig12_bilinear_patches.png", build_scene,
                            argv)


if __name__ == "__main__":
    main()
