"""Pieces shared by the dipole figures (fig13_dipole.py, fig14_dipole_methods.py): the field source,
its arrows, its equipotential lines and the generators' markers (from its Generators port).

Arrows: vtkGlyph3D on a displacement array of vtkDipoleFieldSource, all of one length (the
displacements span orders of magnitude), so they show the direction; the colour shows the
displacement's length (magnitude_range gives the scale). Lines: contours of the "DipolePotential" array (the
superposed dipole potentials; their level sets cross one generator's field at right angles).
"""
from boostedsurfaces import vtkDipoleFieldSource
from vtkmodules.vtkFiltersCore import vtkContourFilter, vtkGlyph3D
from vtkmodules.vtkFiltersSources import vtkArrowSource, vtkSphereSource

import gallery_common as gc



def magnitude_range(source, *arrays):
    """[0, largest length] of the displacement `arrays` of `source`: one colour scale for all."""
    source.Update()
    largest = max(source.GetOutput().GetPointData().GetArray(a).GetRange(-1)[1] for a in arrays)
    return (0.0, largest)


def field(generators, dimensions=(21, 21, 1), origin=(-2.0, -2.0, 0.0), spacing=(0.2, 0.2, 1.0)):
    """A vtkDipoleFieldSource on the grid, with `generators` as (x, y, z, dx, dy, dz, weight)."""
    source = vtkDipoleFieldSource()
    source.RemoveAllGenerators()
    for generator in generators:
        source.AddGenerator(*generator)
    source.SetDimensions(*dimensions)
    source.SetOrigin(*origin)
    source.SetSpacing(*spacing)
    return source


def arrows(source, array, spacing, lut):
    """Arrows of the displacement `array`, 0.9 grid spacings long, coloured through `lut` by the
    displacement's length."""
    arrow = vtkArrowSource()
    arrow.SetTipResolution(12)
    arrow.SetShaftResolution(12)
    glyph = vtkGlyph3D()
    glyph.SetInputConnection(source.GetOutputPort())
    glyph.SetSourceConnection(arrow.GetOutputPort())
    glyph.SetInputArrayToProcess(1, 0, 0, 0, array)  # vectors: the orientation
    glyph.SetVectorModeToUseVector()
    glyph.SetScaleModeToDataScalingOff()
    glyph.SetColorModeToColorByVector()  # "VectorMagnitude": the displacement's length
    glyph.SetScaleFactor(0.9 * spacing)
    return gc.colored_actor(glyph, lut, array="VectorMagnitude")


def equipotential_lines(source, values, radius):
    """Dark tubes along the contours of "DipolePotential" at `values`."""
    contour = vtkContourFilter()
    contour.SetInputConnection(source.GetOutputPort())
    contour.SetInputArrayToProcess(0, 0, 0, 0, "DipolePotential")
    for i, value in enumerate(values):
        contour.SetValue(i, value)
    return gc.colored_actor(gc.tubes(contour, radius, sides=8), color="DimGray")


def generator_markers(source, radius=0.07):
    """A sphere at each generator of `source` and an arrow along its direction, from its
    Generators port (output 1)."""
    sphere = vtkSphereSource()
    sphere.SetRadius(radius)
    sphere.SetThetaResolution(24)
    sphere.SetPhiResolution(24)
    spheres = gc.glyph_actor(source.GetOutputPort(1), sphere, 1.0, "Crimson")
    spheres.pipeline.append(source)
    return [spheres, gc.generator_arrows(source, 0.5, "Crimson", tip_radius=0.1, tip_length=0.35,
                                         resolution=6)]
