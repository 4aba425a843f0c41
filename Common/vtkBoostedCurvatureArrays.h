/**
 * @class   vtkBoostedCurvatureArrays
 * @brief   the curvature point arrays of the grid sources (their ComputeCurvatures option)
 *
 * A grid source that knows its surface's derivatives hands them to this class at every sample.
 * It always sets the grid's exact normals (cga::surfaceNormal of the first derivatives); with
 * the arrays it computes cga::surfaceCurvature (which needs the second ones too) and fills the
 * point arrays
 * "PrincipalCurvatures" (k1 >= k2), "PrincipalDirections" (6 components: the unit tangents of k1,
 * then of k2), "GaussianCurvature" and "MeanCurvature" of the grid (vtkBoostedGridBuilder's
 * sample arrays), and the grid's exact normals. Sign convention (docs/conventions.md section 6,
 * vtkCurvatures'): a curvature is positive where the surface bends away from its Normals.
 * At a degenerate sample (cga::SurfaceCurvature::regular false) every value is 0 and the
 * directions are zero vectors; its normal is the grid's central difference.
 *
 * Points made by the cut at the clip sphere get these arrays interpolated along their edge like
 * every point array, the directions renormalized (RenormalizeDirections).
 */
#ifndef vtkBoostedCurvatureArrays_h
#define vtkBoostedCurvatureArrays_h

#include "BoostedSurfacesCommonModule.h" // for export macro
#include "vtkBoostedGridBuilder.h"       // for the grid
#include "vtkType.h"                     // for vtkIdType

class vtkPointData;

namespace cga
{
struct SurfaceCurvature;
struct SurfaceDerivatives;
struct Vec3;
}

class BOOSTEDSURFACESCOMMON_EXPORT vtkBoostedCurvatureArrays
{
public:
  static constexpr const char* PrincipalCurvaturesName = "PrincipalCurvatures";
  static constexpr const char* PrincipalDirectionsName = "PrincipalDirections";
  static constexpr const char* GaussianCurvatureName = "GaussianCurvature";
  static constexpr const char* MeanCurvatureName = "MeanCurvature";
  /// The point arrays' size per grid sample in the builder and in the output (10 doubles each),
  /// for the sources' memory estimates.
  static constexpr double BytesPerSample = 160.0;

  /// `withArrays` false: only the exact normals (the arrays are not added).
  vtkBoostedCurvatureArrays(vtkBoostedGridBuilder& grid, bool withArrays);

  /// The sample's normal (where regular) and, with the arrays, its values. Thread-safe for
  /// distinct samples.
  void Set(int row, int column, const cga::SurfaceDerivatives& derivatives);
  /// The same from the sample's curvature (cga::surfaceCurvature of its derivatives): its normal
  /// and, with the arrays, its values.
  void SetCurvature(int row, int column, const cga::SurfaceCurvature& curvature);
  /// The sample's exact normal alone (a unit vector: cga::surfaceNormal's), for a source that
  /// computes its normals itself. Thread-safe for distinct samples.
  void SetNormal(int row, int column, const cga::Vec3& normal);

  /// Point `id` of `data` was interpolated: its two principal directions back to unit length
  /// (zero vectors stay zero). Nothing when `data` has no PrincipalDirections.
  static void RenormalizeDirections(vtkPointData* data, vtkIdType id);

private:
  vtkBoostedGridBuilder& Grid;
  int Curvatures = -1, Directions = -1, Gaussian = -1, Mean = -1;
};

#endif
