"""Paper Fig 6: a line bent into circles by a tangent translated to one of its points (eq 15).

The line through the origin along x is transformed by K = 1 - kappa/2 tau, with tau the tangent
along +z translated to the origin (docs/conventions.md section 3 item 5). The image is the circle of
radius 1/|kappa| tangent to the line at the origin, with center -z/kappa: kappa is the true
curvature. The family sweeps kappa from -2 to 2 (colours); kappa = 0 is the line itself (black). The
arrow is the generating tangent. The far ends of the line approach, but never reach, the point
opposite the origin on each circle.

vtkCurvaturePatchSource with Method BENT_LINE and Size (length, 0) gives one polyline.

    python3 fig6_bent_line.py --output fig6.png --size 900 700
"""
import gallery_common as gc
import curvature_common as cc

KAPPAS = [-2.0, -1.0, -0.5, -0.25, 0.25, 0.5, 1.0, 2.0]


def bent_line(kappa):
    """The x axis from -6 to 6 bent with curvature kappa at the origin, in the xz plane."""
    return cc.patch(Method=0, Origin=(0, 0, 0), UDirection=(1, 0, 0), VDirection=(0, 1, 0),
                    Size=(12.0, 0.0), UResolution=400, KappaU=kappa)


def build_scene():
    lut = gc.lambda_lookup_table((min(KAPPAS), max(KAPPAS)))
    renderer = gc.new_renderer()
    for kappa in KAPPAS:
        line = bent_line(kappa)
        rgb = [0.0, 0.0, 0.0]
        lut.GetColor(kappa, rgb)
        renderer.AddActor(gc.colored_actor(gc.tubes(line, 0.03), color=rgb))
    renderer.AddActor(gc.colored_actor(gc.tubes(bent_line(0.0), 0.05), color="Black"))
    cc.add_arrows(renderer, bent_line(0.0), length=1.0, color="Tomato")  # at the origin along z
    renderer.AddActor2D(gc.scalar_bar(lut, "kappa"))
    renderer.AddActor2D(gc.label("kappa > 0: center below", (0.0, 0.0, -4.6)))
    renderer.AddActor2D(gc.label("kappa < 0: center above", (0.0, 0.0, 4.6)))
    renderer.GetActiveCamera().SetWindowCenter(0.15, 0.0)  # the line ends left of the bar
    return renderer


def main(argv=None):
    return cc.render_figure(__doc__.splitlines()[0], "fig6_bent_line.png", build_scene, argv,
                            default_size=(900, 700), view_direction=(0, -1, 0), view_up=(0, 0, 1),
                            zoom=1.1, parallel=True)


if __name__ == "__main__":
    main()
