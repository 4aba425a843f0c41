"""Paper Fig 14: two dipoles, summed generators (a) against summed displacements (b).

Two null point pairs, tau_a at (-1, 0, 0) pointing along y and tau_b at (1, 0, 0) pointing along x,
act on a grid of points p (docs/conventions.md section 3 item 12, eq 27-28), with
d_i^2 = k |p - x_i|^2 + eps:

* a) the paper's method: one boost K = exp(-(w tau_a / d_a^2 + w tau_b / d_b^2)), v = fn(K up(p) ~K) - p;
* b) vector field topology's: v = sum over i of (fn(K_i up(p) ~K_i) - p), K_i = exp(-w tau_i / d_i^2).

vtkDipoleFieldSource computes both in one pass ("DisplacementSummedGenerators" and
"DisplacementSummedDisplacements"). The arrows point along the displacements and are coloured by
their length on one common scale; the grey lines are contours of "DipolePotential", the sum of the
two dipole potentials, the same in both panels. The methods agree to first order in the weights
and visibly differ where both generators act.

    python3 fig14_dipole_methods.py --output fig14.png --size 1400 700
"""
import dipole_scene as ds
import gallery_common as gc

WEIGHT = 0.35
GENERATORS = [(-1.0, 0.0, 0.0, 0.0, 1.0, 0.0, WEIGHT),  # tau_a: x, y, z, dx, dy, dz, weight
              (1.0, 0.0, 0.0, 1.0, 0.0, 0.0, WEIGHT)]   # tau_b
SPACING = 0.2
POTENTIALS = (-0.6, -0.3, -0.15, -0.05, 0.05, 0.15, 0.3, 0.6)
PANELS = (("a) summed generators", "DisplacementSummedGenerators", -2.4),
          ("b) summed displacements", "DisplacementSummedDisplacements", 2.4))


def build_scene():
    source = ds.field(GENERATORS, spacing=(SPACING, SPACING, 1.0))
    lut = gc.lambda_lookup_table(ds.magnitude_range(source, *[array for _, array, _ in PANELS]))
    renderer = gc.new_renderer()
    for title, array, shift in PANELS:
        actors = [ds.arrows(source, array, SPACING, lut),
                  ds.equipotential_lines(source, POTENTIALS, 0.008)]
        actors += ds.generator_markers(source)
        for actor in actors:
            actor.AddPosition(shift, 0.0, 0.0)  # the two panels side by side
            renderer.AddActor(actor)
        renderer.AddActor2D(gc.label(title, (shift, 2.35, 0.0)))
    bar = gc.scalar_bar(lut, "|v|")
    bar.SetOrientationToHorizontal()  # below the panels, not over panel b
    bar.SetPosition(0.3, 0.01)
    bar.SetWidth(0.4)
    bar.SetHeight(0.1)
    renderer.AddActor2D(bar)
    return renderer


def main(argv=None):
    return gc.render_figure(__doc__.splitlines()[0], "fig14_dipole_methods.png", build_scene,
                            argv, default_size=(1400, 700), parallel=True, zoom=1.6)


if __name__ == "__main__":
    main()
