"""A bar twisted by rotation generators along its axis (after Wareham, Cameron and Lasenby).

Seven ROTATION generators sit on the bar's axis (the x axis) at x = -3 ... 3, all with the axis
direction (1, 0, 0), and weights that grow linearly along the bar, w = TWIST_RATE x. Each turns a
point p about the axis by w / (k |p - x_i|^2 + eps) radians, right-handed (docs/conventions.md
section 2 item 11). Their dual lines all lie on the one axis, so B(p) stays a rotation about it
and K = exp(-B(p)) turns each point about the axis by an angle that grows along the bar: the end
faces turn by about -80 and +80 degrees (a weak falloff, k = 0.25 with eps = 1, keeps the turn
within about 12 % of itself across a section). Both exponential rules agree here: the sum is a
blade. vtkPointPairDeformationFilter does the warp; the
colour is the turn angle (the "Angle" array, in degrees). The straight bar is drawn as a grey
outline.

    python3 twisted_bar.py --output twisted_bar.png --size 900 500
"""
import math

from boostedsurfaces import vtkPointPairDeformationFilter
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkFiltersCore import vtkArrayCalculator, vtkPolyDataNormals
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter
from vtkmodules.vtkFiltersModeling import vtkOutlineFilter

import gallery_common as gc

HALF_LENGTH = 3.0
HALF_WIDTH = 0.5
LOCATIONS = [float(x) for x in range(-3, 4)]
TWIST_RATE = 0.36  # weight per unit length along the axis
FALLOFF = 0.25
EPSILON = 1.0
ANGLE_RANGE = (-90.0, 90.0)
VIEW = dict(view_direction=(0.6, -1.0, 0.5), view_up=(0, 0, 1), zoom=1.25)
SIZE = (900, 500)


def bar(center=(0.0, 0.0, 0.0), cells_along=60, cells_across=9):
    """The surface of a box of HALF_LENGTH by HALF_WIDTH about `center`, in fine quads (an odd
    number across: no point on the axis, where the turn angle has no direction)."""
    grid = vtkImageData()
    grid.SetDimensions(cells_along + 1, cells_across + 1, cells_across + 1)
    grid.SetOrigin(center[0] - HALF_LENGTH, center[1] - HALF_WIDTH, center[2] - HALF_WIDTH)
    grid.SetSpacing(2 * HALF_LENGTH / cells_along, 2 * HALF_WIDTH / cells_across,
                    2 * HALF_WIDTH / cells_across)
    surface = vtkDataSetSurfaceFilter()
    surface.SetInputData(grid)
    return surface


def deformed(source, rows, falloff=FALLOFF, epsilon=EPSILON):
    """`source` warped by the generator rows (x, y, z, dx, dy, dz, weight, kind, pitch), with
    normals (sharp edges kept) and the point array "|Displacement|"."""
    deformation = vtkPointPairDeformationFilter()
    deformation.SetInputConnection(source.GetOutputPort())
    for row in rows:
        deformation.AddGenerator(*row)
    deformation.SetFalloff(falloff)
    deformation.SetEpsilon(epsilon)
    length = vtkArrayCalculator()
    length.SetInputConnection(deformation.GetOutputPort())
    length.AddVectorArrayName("Displacement")
    length.SetFunction("mag(Displacement)")
    length.SetResultArrayName("|Displacement|")
    normals = vtkPolyDataNormals()
    normals.SetInputConnection(length.GetOutputPort())
    normals.SetFeatureAngle(60)
    return normals


def rotation_rows(center=(0.0, 0.0, 0.0)):
    """The seven ROTATION rows along the axis through `center`."""
    return [(center[0] + x, center[1], center[2], 1, 0, 0, TWIST_RATE * x,
             vtkPointPairDeformationFilter.ROTATION, 0) for x in LOCATIONS]


def turn_angle(source):
    """The point array "Angle": the turn about the x axis, in degrees, of each point's
    Displacement (the angle from p - (p.x, 0, 0) to p' - (p'.x, 0, 0))."""
    angle = vtkArrayCalculator()
    angle.SetInputConnection(source.GetOutputPort())
    angle.AddCoordinateScalarVariable("y", 1)
    angle.AddCoordinateScalarVariable("z", 2)
    angle.AddScalarVariable("dy", "Displacement", 1)
    angle.AddScalarVariable("dz", "Displacement", 2)
    angle.SetResultArrayName("Angle")
    # The output points are the moved ones: p = p' - Displacement.
    angle.SetFunction("%g * atan2((y - dy) * z - (z - dz) * y, (y - dy) * y + (z - dz) * z)"
                      % (180.0 / math.pi))
    return angle


def build_scene():
    renderer = gc.new_renderer()
    straight = bar()
    outline = vtkOutlineFilter()
    outline.SetInputConnection(straight.GetOutputPort())
    lut = gc.lambda_lookup_table(ANGLE_RANGE)
    renderer.AddActor(gc.colored_actor(turn_angle(deformed(straight, rotation_rows())), lut, "Angle"))
    renderer.AddActor(gc.colored_actor(gc.tubes(outline, 0.012), color="DarkGray"))
    renderer.AddActor2D(gc.scalar_bar(lut, "turn (degrees)"))
    return renderer


def main(argv=None):
    return gc.render_figure(__doc__.splitlines()[0], "twisted_bar.png", build_scene, argv,
                            default_size=SIZE, **VIEW)


if __name__ == "__main__":
    main()
