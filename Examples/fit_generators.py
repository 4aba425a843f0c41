"""Inverse design: point-pair generators fitted so that a sphere takes the shape of a bumped target.

Left, the target: the unit sphere with a Gaussian bump of height 0.3 about its north pole (not a
shape any generator made). Middle, the start: the unit sphere and three point-pair generators on
its axis at z = 0.3, 0.6 and 0.9, aimed up, of weight 0 (the identity). Right, the fit:
vtkPointPairFitFilter in POINT_TO_SURFACE mode finds their weights and locations (Ceres Solver,
Levenberg-Marquardt with the analytic Jacobian) that bring the sphere's points closest to the
target's surface; the sphere is coloured by each point's remaining distance ("FitResidual"), the
fitted generators are drawn as arrows from their Generators output, and the title gives the RMS
distance before and after.

    python3 fit_generators.py --output fit_generators.png --size 1200 500
"""
from boostedsurfaces import vtkPointPairFitFilter
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersCore import vtkArrayCalculator, vtkPolyDataNormals
from vtkmodules.vtkFiltersGeneral import vtkTransformFilter, vtkWarpScalar
from vtkmodules.vtkFiltersSources import vtkArrowSource, vtkSphereSource

import gallery_common as gc

BUMP_HEIGHT = 0.3
BUMP_WIDTH2 = 0.25  # the bump is BUMP_HEIGHT exp(-phi^2 / BUMP_WIDTH2), phi the polar angle
START_HEIGHTS = (0.9, 0.6, 0.3)
SPACING = 2.8  # between the panels' centres, along x
OPACITY = 0.6
RESIDUAL_RANGE = (0.0, 0.02)
VIEW = dict(view_direction=(0.0, -1.0, 0.25), view_up=(0, 0, 1), zoom=1.6)
SIZE = (1200, 500)


def sphere(theta, phi):
    source = vtkSphereSource()
    source.SetRadius(1.0)
    source.SetThetaResolution(theta)
    source.SetPhiResolution(phi)
    source.SetOutputPointsPrecision(vtkSphereSource.DOUBLE_PRECISION)
    return source


def bumped_target():
    """The unit sphere moved along its normals by the bump (a fine mesh: the target surface)."""
    fine = sphere(48, 32)
    height = vtkArrayCalculator()
    height.SetInputConnection(fine.GetOutputPort())
    height.AddCoordinateScalarVariable("z", 2)
    height.SetFunction("%g * exp(-(acos(z) ^ 2) / %g)" % (BUMP_HEIGHT, BUMP_WIDTH2))
    height.SetResultArrayName("bump")
    warp = vtkWarpScalar()
    warp.SetInputConnection(height.GetOutputPort())
    warp.SetInputArrayToProcess(0, 0, 0, 0, "bump")  # along the sphere's Normals
    warp.SetScaleFactor(1.0)
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(warp.GetOutputPort())
    normals.keep = [fine, height, warp]  # ports do not keep their filters alive in Python
    return normals


def fit_filter(target):
    """The fit of a 24 x 16 unit sphere to `target`, from the START_HEIGHTS generators."""
    mesh = sphere(24, 16)
    fit = vtkPointPairFitFilter()
    fit.SetInputConnection(mesh.GetOutputPort())
    fit.SetTargetConnection(target.GetOutputPort())
    fit.keep = [mesh, target]
    fit.SetTargetModeToPointToSurface()
    for z in START_HEIGHTS:
        fit.AddGenerator(0.0, 0.0, z, 0.0, 0.0, 1.0, 0.0)
    fit.FitLocationsOn()
    return fit


def moved(algorithm, dx, port=0):
    """The output `port` of `algorithm` translated by dx along x."""
    transform = vtkTransform()
    transform.Translate(dx, 0.0, 0.0)
    mover = vtkTransformFilter()
    mover.SetTransform(transform)
    mover.SetInputConnection(algorithm.GetOutputPort(port))
    mover.keep = algorithm
    return mover


def build_scene():
    renderer = gc.new_renderer()
    target = bumped_target()
    fit = fit_filter(target)
    fit.Update()
    small = sphere(8, 6)
    start = vtkPointPairFitFilter()  # the start's generators: a fit of 0 iterations
    start.SetInputConnection(small.GetOutputPort())
    start.SetTargetConnection(small.GetOutputPort())
    for z in START_HEIGHTS:
        start.AddGenerator(0.0, 0.0, z, 0.0, 0.0, 1.0, 0.0)
    start.SetMaximumNumberOfIterations(0)
    # Python does not keep a filter alive through its output port: every stage is kept here.
    shown_target = moved(target, -SPACING)
    shown_start = moved(sphere(24, 16), 0.0)
    fitted = vtkPolyDataNormals()
    shifted_fit = moved(fit, SPACING)
    fitted.SetInputConnection(shifted_fit.GetOutputPort())
    fitted_generators = moved(fit, SPACING, 1)
    renderer.keep = [target, fit, small, start, shown_target, shown_start, shifted_fit, fitted,
                     fitted_generators]

    lut = gc.lambda_lookup_table(RESIDUAL_RANGE)
    renderer.AddActor(gc.colored_actor(shown_target, color="Silver"))
    # The start and the fit are see-through: the generators sit inside the sphere.
    for actor in (gc.colored_actor(shown_start, color="LightSteelBlue"),
                  gc.colored_actor(fitted, lut, "FitResidual")):
        actor.GetProperty().SetOpacity(OPACITY)
        renderer.AddActor(actor)
    for port in (start.GetOutputPort(1), fitted_generators.GetOutputPort()):
        renderer.AddActor(gc.glyph_actor(port, arrow(), 0.35, "Tomato", "Direction"))
    renderer.AddActor2D(gc.scalar_bar(lut, "distance"))
    for text, x in (("target", -SPACING), ("start: RMS %.3f" % fit.GetInitialRMS(), 0.0),
                    ("fit: RMS %.4f" % fit.GetFinalRMS(), SPACING)):
        renderer.AddActor2D(gc.label(text, (x, 0.0, -1.45)))
    return renderer


def arrow():
    source = vtkArrowSource()  # along +x from the origin, length 1
    source.SetShaftRadius(0.05)
    source.SetTipRadius(0.12)
    return source


def main(argv=None):
    return gc.render_figure(__doc__.splitlines()[0], "fit_generators.png", build_scene, argv,
                            default_size=SIZE, **VIEW)


if __name__ == "__main__":
    main()
