"""BoostedSurfaces: VTK sources and filters from point-pair boosts (Colapinto 2014).

    from boostedsurfaces import vtkBoostedSurfaceSource
    from boostedsurfaces import vtkPointPairDeformationFilter
    from boostedsurfaces import vtkPointPairFitFilter    # generators fitted to a target shape
    from boostedsurfaces import vtkConformalOrbitSource  # orbits of exp(t B), torus knots
"""
# The wrapped module depends on these VTK modules; importing them first makes the classes'
# base types known to Python.
import vtkmodules.vtkCommonCore  # noqa: F401
import vtkmodules.vtkCommonExecutionModel  # noqa: F401

from .BoostedSurfacesSources import *  # noqa: F401,F403
from .BoostedSurfacesFilters import *  # noqa: F401,F403
