/**
 * @class   vtkPointPairJacobianArrays
 * @brief   the deformation filter's point arrays that come from the map's derivative
 *
 * Internal to vtkPointPairDeformationFilter (not wrapped). Given J = d p' / d p at each point
 * (row-major, from cga::PointPairField::mapPointsWithJacobians), it writes
 *
 * * normals (the input's active normals when TransformNormals is on, and the point arrays named
 *   in NormalArrays): n' = |n| cof(J) n / |cof(J) n|, the direction of J^-T n (cof(J) =
 *   det(J) J^-T, so the cofactor form needs no inverse and is defined where J is singular) with
 *   the input's length (unit normals stay unit). cof(J)(a x b) = (J a) x (J b): it is the normal
 *   of the image of the tangent plane, oriented as the mapped cells' winding, also where det J <= 0.
 *   Where cof(J) n = 0 (J collapses the tangent plane to a line or a point) the normal has no
 *   direction: it is left as it was and counted (Collapsed);
 * * vectors (the point arrays named in VectorArrays): v' = J v;
 * * ConformalScale s = |det J|^(1/3) and ConformalityDefect 1 - sigma_min / sigma_max (the
 *   singular values of J, Eigen's JacobiSVD): s for a conformal map J = s R,
 *   and 0 exactly then; 1 where J is singular (docs/conventions.md section 3 item 16).
 *
 * A normal or vector that is not finite passes unchanged and is counted (NonFinite), as is a
 * normal or vector whose image overflows its type (Overflowed: a float normal longer than the
 * largest float may turn into one with a component beyond it). Input arrays
 * of any layout and value type are read (float and double AOS in place); an output array holds
 * float when its input does, double otherwise; the two scalar arrays hold the output points'
 * type.
 */
#ifndef vtkPointPairJacobianArrays_h
#define vtkPointPairJacobianArrays_h

#include "vtkSmartPointer.h" // for the arrays
#include "vtkType.h"         // for vtkIdType

#include <atomic> // for the counters
#include <string> // for the problems
#include <vector> // for the arrays

class vtkDataArray;
class vtkDataArraySelection;
class vtkPointData;

class vtkPointPairJacobianArrays
{
public:
  /// What the filter's properties ask for.
  struct Request
  {
    bool TransformNormals = true;
    vtkDataArraySelection* VectorArrays = nullptr;
    vtkDataArraySelection* NormalArrays = nullptr;
    bool ConformalScale = false;
    bool ConformalityDefect = false;
  };

  /// The output bytes per point a request can need at most (every named array 3 doubles, the
  /// scalars in `scalarBytes` each), for the memory budget.
  static double BytesPerPoint(const Request& request, vtkPointData* input, int scalarBytes);

  /// Resolves the request against the input's point data: false with `problem` set when a named
  /// array is not a numeric array of 3 components or is asked as a vector and as a normal; names
  /// of arrays that do not exist go to `missing` (the caller warns). Allocates the output arrays
  /// (`count` tuples; `scalarType` VTK_FLOAT or VTK_DOUBLE for the scalar arrays).
  bool Prepare(const Request& request, vtkPointData* input, vtkIdType count, int scalarType,
    std::string& problem, std::string& missing);

  /// True when some output needs J.
  bool Any() const { return !this->Arrays.empty() || this->Scale || this->Defect; }

  /// Writes points first ... first + count - 1 from their 9 Jacobian entries each.
  void Write(vtkIdType first, vtkIdType count, const double* jacobians);

  /// True when the only output is one normals array: then two directional derivatives per point
  /// give it (Tangents, WriteNormal) for about two thirds of the work of J.
  bool OnlyOneNormal() const
  {
    return this->Arrays.size() == 1 && this->Arrays[0].AsNormal && !this->Scale && !this->Defect;
  }

  /// For OnlyOneNormal: two unit tangents t1, t2 per point with t1 x t2 = n / |n| (6 doubles per
  /// point, t1 then t2), zero where n is zero or not finite.
  void Tangents(vtkIdType first, vtkIdType count, double* tangents) const;

  /// For OnlyOneNormal: writes the normals of points first ... first + count - 1 from the
  /// tangents of Tangents and their images J t1, J t2 (6 doubles per point each):
  /// n' = |n| (J t1 x J t2) / |J t1 x J t2|, the direction of cof(J) n (Write) to rounding;
  /// n itself where J t1 = t1 and J t2 = t2 (J = I where a point is left in place).
  void WriteNormal(
    vtkIdType first, vtkIdType count, const double* tangents, const double* tangentImages);

  /// Puts the arrays into the output's point data (replacing the input's arrays of the same
  /// name; a transformed active normals array stays the active normals).
  void AddTo(vtkPointData* output) const;

  /// Normals or vectors not finite in the input, normals whose direction J collapsed, vectors
  /// whose image overflowed their type (each left unchanged), and ConformalScale values beyond
  /// the largest float in a float array (the caller's single-precision error).
  std::atomic<vtkIdType> NonFinite{ 0 };
  std::atomic<vtkIdType> Collapsed{ 0 };
  std::atomic<vtkIdType> Overflowed{ 0 };
  std::atomic<vtkIdType> ScaleBeyondFloat{ 0 };
  /// Mapped points whose J is not finite (counted by the caller; J is the identity there).
  std::atomic<vtkIdType> NonFiniteJacobians{ 0 };

private:
  struct Transformed
  {
    vtkDataArray* Input;
    vtkSmartPointer<vtkDataArray> Output;
    bool AsNormal;
    bool ActiveNormals;
  };
  std::vector<Transformed> Arrays;
  vtkSmartPointer<vtkDataArray> Scale;
  vtkSmartPointer<vtkDataArray> Defect;
};

#endif
