"""Paper Fig 14: two dipoles, summed generators (a) against summed displacements (b), and what differs.

Two null point pairs, tau_a at (-1, 0, 0) pointing along y and tau_b at (1, 0, 0) pointing along x,
act on a grid of points p (docs/conventions.md section 3 item 12, eq 27-28), with
d_i^2 = k |p - x_i|^2 + eps:

* a) the paper's method: one boost K = exp(-(w tau_a / d_a^2 + w tau_b / d_b^2)), v = fn(K up(p) ~K) - p;
* b) vector field topology's: v = sum over i of (fn(K_i up(p) ~K_i) - p), K_i = exp(-w tau_i / d_i^2);
* c) the difference a - b.

vtkDipoleFieldSource computes both in one pass ("DisplacementSummedGenerators" and
"DisplacementSummedDisplacements"). The arrows point along the displacements and are coloured by
their length, a and b on one common scale, c on its own; the grey lines in a and b are streamlines
of that panel's own field, so that the panels show where the flows part. The methods agree to first
order in the weights and visibly differ where both generators act.

    python3 fig14_dipole_methods.py --output fig14.png --size 1500 600
"""
from vtkmodules.vtkFiltersCore import vtkArrayCalculator
from vtkmodules.vtkFiltersFlowPaths import vtkStreamTracer
from vtkmodules.vtkFiltersSources import vtkPlaneSource

import dipole_scene as ds
import gallery_common as gc

WEIGHT = 0.35
GENERATORS = [(-1.0, 0.0, 0.0, 0.0, 1.0, 0.0, WEIGHT),  # tau_a: x, y, z, dx, dy, dz, weight
              (1.0, 0.0, 0.0, 1.0, 0.0, 0.0, WEIGHT)]   # tau_b
SPACING = 0.2
METHODS = (("a) summed generators", "DisplacementSummedGenerators", -5.0),
           ("b) summed displacements", "DisplacementSummedDisplacements", 0.0))
DIFFERENCE = ("c) difference a - b", "Difference", 5.0)
SEEDS = 6  # streamline seeds per side of the grid


def difference(source):
    """`source` with the point array "Difference" = method a's displacement - method b's."""
    calculator = vtkArrayCalculator()
    calculator.SetInputConnection(source.GetOutputPort())
    for _, array, _ in METHODS:
        calculator.AddVectorArrayName(array)
    calculator.SetFunction("%s - %s" % tuple(array for _, array, _ in METHODS))
    calculator.SetResultArrayName(DIFFERENCE[1])
    return calculator


def streamlines(source, array, radius):
    """Dark tubes along streamlines of the displacement `array`, seeded on a SEEDS x SEEDS grid
    and traced both ways."""
    seeds = vtkPlaneSource()
    seeds.SetOrigin(-1.9, -1.9, 0.0)
    seeds.SetPoint1(1.9, -1.9, 0.0)
    seeds.SetPoint2(-1.9, 1.9, 0.0)
    seeds.SetResolution(SEEDS - 1, SEEDS - 1)
    tracer = vtkStreamTracer()
    tracer.SetInputConnection(source.GetOutputPort())
    tracer.SetSourceConnection(seeds.GetOutputPort())
    tracer.SetInputArrayToProcess(0, 0, 0, 0, array)
    tracer.SetIntegrationDirectionToBoth()
    tracer.SetIntegratorTypeToRungeKutta45()
    tracer.SetMaximumPropagation(3.0)
    tracer.SetInitialIntegrationStep(0.1)
    tracer.SetComputeVorticity(False)
    return gc.colored_actor(gc.tubes(tracer, radius, sides=8), color="DimGray")


def bar_with_title(lut, title, left):
    """A horizontal colour bar below the panels from `left` (viewport fraction), its title to its
    left (a horizontal bar's own title collides with its labels)."""
    bar = gc.scalar_bar(lut, "")
    bar.SetOrientationToHorizontal()
    bar.SetPosition(left, 0.01)
    bar.SetWidth(0.25)
    bar.SetHeight(0.11)
    text = gc.label(title, (0, 0, 0), justification="right")
    text.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    text.GetPositionCoordinate().SetValue(left - 0.01, 0.085)
    return [bar, text]


def build_scene():
    source = ds.field(GENERATORS, spacing=(SPACING, SPACING, 1.0))
    with_difference = difference(source)
    lut = gc.lambda_lookup_table(ds.magnitude_range(source, *[array for _, array, _ in METHODS]))
    difference_lut = gc.lambda_lookup_table(ds.magnitude_range(with_difference, DIFFERENCE[1]))
    renderer = gc.new_renderer()
    for title, array, shift in METHODS + (DIFFERENCE,):
        if array == DIFFERENCE[1]:
            actors = [ds.arrows(with_difference, array, SPACING, difference_lut)]
        else:
            actors = [ds.arrows(source, array, SPACING, lut), streamlines(source, array, 0.012)]
        actors += ds.generator_markers(source)
        for actor in actors:
            actor.AddPosition(shift, 0.0, 0.0)  # the panels side by side
            renderer.AddActor(actor)
        renderer.AddActor2D(gc.label(title, (shift, 2.4, 0.0)))
    for actor in bar_with_title(lut, "|v| in a and b", 0.2) + bar_with_title(
            difference_lut, "|a - b|", 0.68):
        renderer.AddActor2D(actor)
    return renderer


def main(argv=None):
    return gc.render_figure(__doc__.splitlines()[0], "fig14_dipole_methods.png", build_scene,
                            argv, default_size=(1500, 600), parallel=True, zoom=2.3)


if __name__ == "__main__":
    main()
