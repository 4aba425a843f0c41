"""Orbits of exp(t B): torus knots about two linked circles, and the orbits of point-pair boosts.

vtkConformalOrbitSource evaluates exp(t B) in closed form at every t (the invariant decomposition
of B into commuting 2-blades) and closes an orbit after its computed period.

Left, the Torus Knot preset: B = (pi/P) A* + (pi/Q) C*, A* and C* the unit duals of two
orthogonal circles A and C linked once (grey tubes; the circles of a Hopf link, as two antipodal
fibers of the classical Hopf fibration). The (2, 3) trefoil and the (3, 5) knot, coloured by t over
their periods lcm(P, Q) = 6 and 15, link A Q times and C P times. Under each knot, the orbit of the
same seed for (P, Q) = (1, 60) winds 60 times about A and draws the torus they lie on.

Right, the orbits of boosts (the paper's "orbits" after Dorst and Valkenburg): one null point pair
at the origin along x (Generator List, POINT_PAIR): a transversion, whose orbits are circles
through its location, tangent there to x (cut at the clip sphere where they pass through
infinity); and two point pairs at (-1, 0, 0) along z and (1, 0, 0) along y: B is a rotation about
a circle combined with a boost, and the orbits spiral about that core circle (grey) without
closing.

    python3 torus_knots_and_orbits.py --output orbits.png --size 1200 500
"""
import sys

from boostedsurfaces import vtkConformalOrbitSource

import gallery_common as gc

VIEW = dict(view_direction=(0.1, -0.8, 1.0), view_up=(0, 0, 1), zoom=2.1)
SIZE = (1200, 500)
SEED = (0.2, 0.0, 0.0)  # a torus about the default knot's circle A, near it


def knot(p, q, center, resolution=None):
    """The (p, q) torus knot of the default circles moved to `center`, through the default seed
    moved alike."""
    source = vtkConformalOrbitSource()
    source.SetKnotP(p)
    source.SetKnotQ(q)
    source.SetKnotCenter(*center)
    source.SetSeedPoint(*(c + s for c, s in zip(center, SEED)))
    source.SetTResolution(resolution or 200 * p * q)
    return source


def boosts(rows, seeds, t_range, center):
    """Orbits of exp(t B) for generator rows (location, direction, weight, kind, pitch) and seeds,
    both moved to `center`."""
    source = vtkConformalOrbitSource()
    source.SetGeneratorTypeToGeneratorList()
    for row in rows:
        source.AddGenerator(*(v + c for v, c in zip(row[:3], center)), *row[3:])
    source.SetSeedModeToSeedList()
    for seed in seeds:
        source.AddSeed(*(v + c for v, c in zip(seed, center)))
    source.SetTRange(*t_range)
    source.SetTResolution(800)
    source.SetClipCenter(*center)
    source.SetClipRadius(2.0)
    return source


class CorePort:
    """Output 1 (the cores) of an orbit source, where the helpers expect an algorithm."""

    def __init__(self, source):
        self.source = source

    def GetOutputPort(self):
        return self.source.GetOutputPort(1)


def build_scene():
    renderer = gc.new_renderer()
    for (p, q), center in (((2, 3), (-6.0, 0.0, 0.0)), ((3, 5), (-2.5, 0.0, 0.0))):
        source = knot(p, q, center)
        source.Update()
        period = source.GetOutput().GetFieldData().GetArray("Period").GetValue(0)
        lut = gc.lambda_lookup_table((0.0, period))
        renderer.AddActor(gc.colored_actor(gc.tubes(source, 0.045), lut, "t"))
        renderer.AddActor(gc.colored_actor(gc.tubes(CorePort(source), 0.03), color="Gray"))
        torus = knot(1, 60, center, resolution=12000)
        torus_actor = gc.colored_actor(gc.tubes(torus, 0.01, sides=6), color="LightSteelBlue")
        torus_actor.GetProperty().SetOpacity(0.8)
        renderer.AddActor(torus_actor)
        renderer.AddActor2D(gc.label("(%d, %d), period %g" % (p, q, period), (center[0], 0, -2.4)))
    transversion = boosts([(0, 0, 0, 1, 0, 0, 1, 0, 0)],
                          [(0.0, 0.5 * k, 0.3 * k - 0.6) for k in range(-3, 4) if k],
                          (-6, 6), (1.5, 0.0, 0.0))
    renderer.AddActor(gc.colored_actor(gc.tubes(transversion, 0.02), color="SteelBlue"))
    renderer.AddActor2D(gc.label("one point pair", (1.5, 0, -1.6)))
    spiral = boosts([(-1, 0, 0, 0, 0, 1, 1, 0, 0), (1, 0, 0, 0, 1, 0, 1, 0, 0)],
                    [(0.2 * k, 0.1, 0.0) for k in range(-3, 4)], (-4, 4), (5.0, 0.0, 0.0))
    renderer.AddActor(gc.colored_actor(gc.tubes(spiral, 0.015), color="IndianRed"))
    renderer.AddActor(gc.colored_actor(gc.tubes(CorePort(spiral), 0.02), color="Gray"))
    renderer.AddActor2D(gc.label("two point pairs", (5.0, 0, -1.6)))
    return renderer


def main(argv=None):
    return gc.render_figure(__doc__.splitlines()[0], "torus_knots_and_orbits.png", build_scene,
                            argv, default_size=SIZE, **VIEW)


if __name__ == "__main__":
    main()
