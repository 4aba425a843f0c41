/**
 * @class   vtkBoostedSphereClip
 * @brief   cuts sampled curves and meshes exactly at a sphere
 *
 * Keeps the points of a vtkPolyData that lie inside a ball (distance to the center <= radius) and
 * cuts every polyline segment and polygon edge that crosses the sphere at the crossing itself
 * (cga::segmentSphereExitPoint), so the cut boundary lies on the sphere to round-off instead of
 * following the sampling grid. New points get the point data interpolated along their edge
 * (normals renormalized); crossings are shared by the cells meeting at an edge. Polygons are cut
 * vertex by vertex (Sutherland-Hodgman); a segment whose both ends lie outside is dropped even if
 * it passes through the ball (the samples are assumed fine enough). Only lines and polygons are
 * handled (what vtkBoostedGridBuilder writes); points that are not finite count as outside.
 */
#ifndef vtkBoostedSphereClip_h
#define vtkBoostedSphereClip_h

#include "BoostedSurfacesCommonModule.h" // for export macro

#include <cmath>  // for Inside
#include <limits> // for Inside

class vtkPolyData;

class BOOSTEDSURFACESCOMMON_EXPORT vtkBoostedSphereClip
{
public:
  static void Clip(vtkPolyData* input, const double center[3], double radius, vtkPolyData* output);

  /// Whether p is kept: finite and |p - center|^2 <= radius2 (the radius squared). Clip's test,
  /// also made by vtkBoostedGridBuilder as it writes its points; without branches, so that a loop
  /// over points stays vectorized (the finite test against the largest double: VTK_DOUBLE_MAX is
  /// 1e299). In plain doubles, so that the builder's header needs no header of the core.
  static bool Inside(double x, double y, double z, const double center[3], double radius2)
  {
    constexpr double largest = std::numeric_limits<double>::max();
    const double dx = x - center[0], dy = y - center[1], dz = z - center[2];
    return (std::abs(x) <= largest) & (std::abs(y) <= largest) & (std::abs(z) <= largest) &
      (dx * dx + dy * dy + dz * dz <= radius2);
  }
};

#endif
