"""Paper Fig 13: the dipole field of one point-pair generator.

A null point pair tau = tau(x, v) at the origin with direction v along x boosts every point p of a
grid by K = exp(-w tau / d^2), d^2 = k |p - x|^2 + eps (docs/conventions.md section 3 item 12, eq
27-28). The arrows point along the displacements v = fn(K up(p) ~K) - p, coloured by their length:
they leave the generator on one side and come back on the other, like the field of a dipole. Because
d^2 grows like |p - x|^2, the displacement does not fade far away: it is smallest near the
generator, which is the boost's fixed point. With one generator both methods of Fig 14 give this
same field. The grey lines are contours of "DipolePotential", which cross the arrows at right
angles.

vtkDipoleFieldSource computes the field on a 21 x 21 slice of [-2, 2]^2 (its defaults).

    python3 fig13_dipole.py --output fig13.png --size 900 700
"""
import dipole_scene as ds
import gallery_common as gc

GENERATORS = [(0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.5)]  # x, y, z, dx, dy, dz, weight
SPACING = 0.2
POTENTIALS = (-0.8, -0.4, -0.2, -0.1, 0.1, 0.2, 0.4, 0.8)


def build_scene():
    source = ds.field(GENERATORS, spacing=(SPACING, SPACING, 1.0))
    lut = gc.lambda_lookup_table(ds.magnitude_range(source, "DisplacementSummedGenerators"))
    renderer = gc.new_renderer()
    renderer.AddActor(ds.arrows(source, "DisplacementSummedGenerators", SPACING, lut))
    renderer.AddActor(ds.equipotential_lines(source, POTENTIALS, 0.008))
    for actor in ds.generator_markers(source):
        renderer.AddActor(actor)
    renderer.AddActor2D(gc.scalar_bar(lut, "|v|"))
    return renderer


def main(argv=None):
    return gc.render_figure(__doc__.splitlines()[0], "fig13_dipole.png", build_scene, argv,
                            parallel=True, zoom=1.1)


if __name__ == "__main__":
    main()
