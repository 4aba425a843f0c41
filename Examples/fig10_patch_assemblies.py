"""Paper Fig 10: surfaces assembled from many uv control points (eq 21-22).

A larger plane carries a 3 x 3 lattice of the four-corner patches of Fig 9 (4 x 4 control points,
spacing 2). Every point sums the generators of all control points, each weighted by its osculating
circle distances and by 1/(k |p - x_i|^2 + eps):

a) hyperbolic saddles (kappa_u = -kappa_v, alternating), b) umbilic points (alternating sign),
c) an assortment of curvatures, d) tangents tilted in various directions.

    python3 fig10_patch_assemblies.py --output fig10.png --size 1000 800
"""
import math

import gallery_common as gc
import curvature_common as cc

SPACING = 2.0
EPSILON = 0.5
OFFSET = 9.0  # between the four surfaces


def lattice(center, rule):
    """4 x 4 control points around `center`; rule(i, j) gives (normal, kappa_u, kappa_v)."""
    points = []
    for i in range(4):
        for j in range(4):
            normal, ku, kv = rule(i, j)
            points.append((center[0] + (i - 1.5) * SPACING, center[1] + (j - 1.5) * SPACING, 0.0,
                           *normal, 1, 0, 0, ku, kv))
    return points


def saddles(i, j):
    s = 0.5 if (i + j) % 2 == 0 else -0.5
    return (0, 0, 1), s, -s


def umbilics(i, j):
    s = 0.5 if (i + j) % 2 == 0 else -0.5
    return (0, 0, 1), s, s


def assortment(i, j):
    values = [0.6, -0.3, 0.2, -0.6, 0.4, 0.0, -0.4, 0.3]
    return (0, 0, 1), values[(3 * i + j) % 8], values[(i + 5 * j) % 8]


def tilted(i, j):
    angle = 0.5 * (i - j)
    return (math.sin(angle), 0.3 * math.sin(i + j), math.cos(angle)), 0.5, 0.5


CASES = [("a) saddles", saddles), ("b) umbilics", umbilics), ("c) assortment", assortment),
         ("d) tilted tangents", tilted)]


def panel_center(k):
    return ((k % 2) * OFFSET, -(k // 2) * OFFSET, 0.0)


def build_scene():
    sources = [cc.patch(lattice(panel_center(k), rule), Method=3, Origin=panel_center(k),
                        Size=(8.0, 8.0), UResolution=96, VResolution=96, Falloff=1.0,
                        Epsilon=EPSILON)
               for k, (_, rule) in enumerate(CASES)]
    renderer = gc.new_renderer()
    cc.add_height_colored(renderer, sources)
    for k, (source, (name, _)) in enumerate(zip(sources, CASES)):
        center = panel_center(k)
        cc.add_arrows(renderer, source, length=0.6)
        renderer.AddActor2D(gc.label(name, (center[0], center[1] - 4.8, 0.0), font_size=20))
    return renderer


def main(argv=None):
    return cc.render_figure(__doc__.splitlines()[0], "fig10_patch_assemblies.png", build_scene,
                            argv, default_size=(1000, 800), view_direction=(0.0, -0.8, 1.0),
                            view_up=(0, 1, 0), zoom=1.3)


if __name__ == "__main__":
    main()
