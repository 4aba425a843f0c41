"""Paper Fig 5: twistor meshes of the Hopf fibration, with fibers as tubes.

vtkHopfFibrationSource in its default Paper mode (eq 11-14) with OutputType TWISTOR_MESH: every
meridian theta of the base 2-sphere gives the surface swept by its fibers, from the base circle C
(phi = -pi/2, the unit circle of the xy plane) to C's axis (phi = pi/2). These are the settings
that reproduce Fig 5:

    ThetaResolution 6 (six meridians, theta = 0, 60, ..., 300 degrees), PhiResolution 96,
    FiberResolution 128, OutputType TWISTOR_MESH (MeshSweep MERIDIANS), ClipRadius 3.

Over the meshes, the fibers of a coarse theta/phi grid are drawn as tubes (OutputType FIBERS,
vtkTubeFilter); the meshes are coloured by phi. Pass --classical for the round (stereographic S^3) fibration.

    python3 fig5_hopf_fibration.py --output fig5.png --size 900 800
"""
import math
import sys

from boostedsurfaces import vtkHopfFibrationSource

import gallery_common as gc

CLIP = 3.0  # clip radius about the circle center (circle radius 1): the fibers near the north pole are cut there


def fig5_source(classical=False):
    """The Fig 5 preset: six meridian strips."""
    mesh = vtkHopfFibrationSource()
    mesh.SetMode(vtkHopfFibrationSource.CLASSICAL if classical else vtkHopfFibrationSource.PAPER)
    mesh.SetOutputTypeToTwistorMesh()
    mesh.SetMeshSweepToMeridians()
    mesh.SetThetaResolution(6)
    mesh.SetPhiResolution(96)
    mesh.SetFiberResolution(128)
    mesh.SetClipRadius(CLIP)
    return mesh


def fiber_source(classical=False):
    """A coarse grid of fibers: three meridians (every other strip), five latitudes strictly
    between the poles."""
    fibers = vtkHopfFibrationSource()
    fibers.SetMode(vtkHopfFibrationSource.CLASSICAL if classical else vtkHopfFibrationSource.PAPER)
    fibers.SetThetaResolution(3)
    fibers.SetPhiRange(-math.pi / 2 + math.pi / 8, math.pi / 2 - math.pi / 8)
    fibers.SetPhiResolution(5)
    fibers.SetFiberResolution(256)
    fibers.SetClipRadius(CLIP)
    return fibers


def build_scene(classical=False):
    phis = gc.lambda_lookup_table((-math.pi / 2, math.pi / 2))
    renderer = gc.new_renderer()
    mesh = gc.colored_actor(fig5_source(classical), phis, "phi")
    mesh.GetProperty().SetOpacity(0.5)
    renderer.AddActor(mesh)
    renderer.AddActor(gc.colored_actor(gc.tubes(fiber_source(classical), 0.015), color="DimGray"))
    renderer.AddActor2D(gc.scalar_bar(phis, "phi"))
    return renderer


def main(argv=None):
    argv = list(sys.argv[1:] if argv is None else argv)
    classical = "--classical" in argv
    if classical:
        argv.remove("--classical")
    return gc.render_figure(__doc__.splitlines()[0], "fig5_hopf_fibration.png",
                            lambda: build_scene(classical), argv, default_size=(900, 800),
                            view_direction=(0.6, -1.0, 0.7), view_up=(0, 0, 1), zoom=1.2)


if __name__ == "__main__":
    main()
