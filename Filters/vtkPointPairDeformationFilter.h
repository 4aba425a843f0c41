/**
 * @class   vtkPointPairDeformationFilter
 * @brief   warps any mesh through a field of point-pair generators (Colapinto 2014, eq 23, Fig 11)
 *
 * Generators i sit at locations x_i with directions v_i, weights w_i and kinds. At each point p
 * of the input the generators sum, weighted by their inverse squared distance, into the bivector
 *
 *   B(p) = sum_i w_i G_i / (Falloff |p - x_i|^2 + Epsilon),
 *
 * and p moves to p' = fn(K up(p) ~K) with K = exp(-Strength B(p)) (docs/conventions.md section 3
 * item 9). G_i is given by the generator's kind (docs/conventions.md section 2 item 11; |v_i|
 * multiplies the weight, c = Strength w_i |v_i| / (Falloff |p - x_i|^2 + Epsilon) below):
 * POINT_PAIR (the default) tau(x_i, v_i), a boost; ROTATION the turn by the angle c (radians,
 * right-handed) about the axis through x_i along v_i; TWIST that turn with the advance Pitch * c
 * along v_i (Pitch a length per radian; 0 is a ROTATION); DILATION the scaling about x_i by e^c
 * (a positive weight grows); TRANSLATION the translation by c along v_i (x_i only places the
 * falloff). Kinds mix in one sum.
 *
 * ExponentialRule: EXACT (default) uses the true exponential of B, so K is a versor and every image
 * point is null (each K is a conformal map); PAPER uses eq 9-10 of the paper, cosh/sinh of
 * s = <B B>_0, which is exact only when B is a blade (one generator of any kind but a TWIST of
 * non-zero pitch, and some sums: docs/conventions.md section 2 item 11) and otherwise not a versor.
 *
 * Generators come from the list set by AddGenerator()/SetGenerator() (the ParaView table), and from
 * the optional second input port "Generators": any vtkPointSet whose points are the locations,
 * with a 3-component point array named GeneratorDirectionArrayName and, when
 * UseGeneratorWeightArray is on, a 1-component point array named GeneratorWeightArrayName (the
 * weights; otherwise every weight is 1), and optionally 1-component point arrays named
 * GeneratorKindArrayName and GeneratorPitchArrayName (read when the input has them; otherwise every
 * generator there is a POINT_PAIR of pitch 0). Both sources are summed. The Generators input is
 * always requested whole, so every MPI rank sees every generator.
 *
 * Output: the input's topology, cells and arrays with moved points, plus the point vector
 * "Displacement" = p' - p. Vectors go through the map's derivative J = d p' / d p
 * (cga::PointPairField::mapPointsWithJacobians; docs/conventions.md section 3 items 15-16): the
 * active point normals (TransformNormals, on by default) and the point arrays named in
 * NormalArrays become n' = |n| cof(J) n / |cof(J) n| (the direction of J^-T n, the input's
 * length), those named in VectorArrays J v; ConformalScale and ConformalityDefect add the point
 * arrays |det J|^(1/3) and 1 - sigma_min / sigma_max. When one normals array is all that is
 * asked, J is taken along two tangents of each normal only
 * (cga::PointPairField::mapPointsWithDirectionalDerivatives: cof(J) n = J t1 x J t2 for
 * t1 x t2 = n), the same normal for less work. Other arrays pass unchanged; cell normals
 * are dropped (they would be wrong once the points moved), and so are the point normals when
 * TransformNormals is off.
 * vtkImageData and vtkRectilinearGrid inputs give a vtkStructuredGrid, as vtkWarpVector does.
 * Output 1, "Generators" (vtkBoostedGeneratorGlyphs, for glyphs): one vertex per generator as
 * used (the list's rows, the selected one at SelectedGeneratorLocation, then the Generators
 * input's points), with point arrays "Direction", "Weight", "Kind" and "Pitch"; on piece 0 only,
 * and empty after an error. It is in the Generators input's format, so it can be fed back there.
 *
 * Transformed arrays: a name that the input's point data does not have is skipped with one
 * warning; a named array that is not numeric with 3 components (also active normals of another
 * size), or one asked both as a vector and as a normal, is an error and gives an empty output.
 * A normal or vector that is not finite passes unchanged (one warning counts them); so does a
 * normal whose direction J collapses (cof(J) n = 0: the map flattens the tangent plane there)
 * and a vector whose image overflows its type. Where a point is left in place (below) J is the
 * identity.
 *
 * Bad input: points that are NaN or infinite pass through unchanged (Displacement 0) and are
 * counted in one warning; so are points whose image would be at infinity. Generators with a zero
 * or non-finite direction, location or weight, or a TWIST with a non-finite pitch, are ignored
 * with one warning. No generators (or Strength 0) is the identity. A kind that is none of the five
 * constants (in a row or in the kind array) is an error and gives an empty output, as is a missing
 * or wrongly typed array on the Generators port (or one
 * with another number of tuples than the port's points), a non-finite Strength, a NaN Falloff or Epsilon, or a NaN or negative Tolerance, is an error and gives an empty output.
 *
 * The per-point work runs in vtkSMPTools. Note that Debian's VTK uses the Sequential backend
 * unless the environment sets VTK_SMP_BACKEND_IN_USE=STDThread; the filter does not change the
 * process-wide backend.
 */
#ifndef vtkPointPairDeformationFilter_h
#define vtkPointPairDeformationFilter_h

#include "BoostedSurfacesFiltersModule.h" // for export macro
#include "vtkDataArraySelection.h"       // for the transformed arrays
#include "vtkNew.h"                      // for the transformed arrays
#include "vtkPointPairFieldAlgorithm.h"

#include <memory> // for the last tree

class vtkDataSet;
namespace cga
{
class PointPairField;
}

class BOOSTEDSURFACESFILTERS_EXPORT vtkPointPairDeformationFilter
  : public vtkPointPairFieldAlgorithm
{
public:
  static vtkPointPairDeformationFilter* New();
  vtkTypeMacro(vtkPointPairDeformationFilter, vtkPointPairFieldAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // The generator list (AddGenerator ...) and its selected row (SelectedGenerator ...), the
  // Generators input (port 1, SetGeneratorsConnection) and its Generator*ArrayName properties,
  // Strength, Falloff, Epsilon, ExponentialRule, OutputPointsPrecision and the EXACT/PAPER and
  // kind constants are vtkPointPairFieldAlgorithm's.

  ///@{
  /// 0 (default): no time. N >= 1: the filter reports N time steps t in [0, 1]
  /// (vtkBoostedTimeSweep), replacing its input's, and at time t deforms with t Strength, so the
  /// deformation grows from the identity to Strength as an animation plays (the time requested
  /// upstream is then t too: a time-dependent input sees the same t).
  vtkSetClampMacro(NumberOfTimeSteps, int, 0, 100000);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

  ///@{
  /// The far-field approximation of B (cga::PointPairField::setTolerance): 0 (default) sums every
  /// generator at every point; t > 0 sums far generators by a tree that keeps each image's error,
  /// to first order, within t times the field's displacement scale (README, "Many generators";
  /// the bound is enforced at every point). Values above 1 are used as 1; NaN or negative is an
  /// error and gives an empty output. Fields of fewer than 10,000 generators, and tolerances below
  /// 1e-4 (10,000/M)^3 (1e-7 at M = 100,000), always sum directly (the measured crossovers).
  /// The tree's cells are fitted to the input's points (cga::PointPairField::planTreeCells:
  /// wider on a sparse mesh). The arrays through the map's derivative (normals, vectors,
  /// ConformalScale, ConformalityDefect) come from the tree's approximation too (measured, not
  /// bounded).
  /// The filter keeps its last tree (with its field: 510 to 540 bytes per generator) and shares it
  /// with the next update while the generators, Falloff, Epsilon and Tolerance stay the same, so
  /// that a new Strength or time step, input or array selection does not build it again
  /// (cga::PointPairField::shareTree: the same bits as a new tree). While a tree is built, before
  /// any point moves, the progress is 0 and the progress text "Building the generator tree".
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// Transform the input's active point normals through the map's derivative (default on): n'
  /// is the normal of the deformed surface, exactly, as the image of the input's. Off: they are
  /// dropped, as the cell normals always are.
  vtkSetMacro(TransformNormals, bool);
  vtkGetMacro(TransformNormals, bool);
  vtkBooleanMacro(TransformNormals, bool);
  ///@}

  ///@{
  /// The point arrays (3 components) transformed as vectors, J v (velocities, tangents,
  /// displacements of the input), and as normals, the direction of J^-T n with n's length
  /// (normals other than the active ones): the enabled names of each selection
  /// (GetVectorArraySelection()->EnableArray("Velocity")). Both empty by default; other arrays
  /// pass unchanged. ParaView: VectorArrays and NormalArrays, lists of the input's 3-component
  /// point arrays.
  vtkDataArraySelection* GetVectorArraySelection() { return this->VectorArraySelection; }
  vtkDataArraySelection* GetNormalArraySelection() { return this->NormalArraySelection; }
  ///@}

  ///@{
  /// Add the point array "ConformalScale", s = |det J|^(1/3) (s for a conformal map J = s R),
  /// and "ConformalityDefect", 1 - sigma_min / sigma_max of J's singular values (0 for a
  /// scaled rotation, 1 for a singular J). Both off by default.
  vtkSetMacro(ComputeConformalScale, bool);
  vtkGetMacro(ComputeConformalScale, bool);
  vtkBooleanMacro(ComputeConformalScale, bool);
  vtkSetMacro(ComputeConformalityDefect, bool);
  vtkGetMacro(ComputeConformalityDefect, bool);
  vtkBooleanMacro(ComputeConformalityDefect, bool);
  ///@}

  /// Includes the array selections' modification times.
  vtkMTimeType GetMTime() override;

protected:
  vtkPointPairDeformationFilter();
  ~vtkPointPairDeformationFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int ExecuteInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int ComputeInputUpdateExtent(
    vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Tolerance = 0.0;
  int NumberOfTimeSteps = 0;
  bool TransformNormals = true;
  vtkNew<vtkDataArraySelection> VectorArraySelection;
  vtkNew<vtkDataArraySelection> NormalArraySelection;
  bool ComputeConformalScale = false;
  bool ComputeConformalityDefect = false;

private:
  /// RequestData's allocating part, after the validation and the memory estimate: the explicit
  /// copy of an image or rectilinear grid, the output points and Displacement, the deformation;
  /// false after an abort or an error (the output then empty). With a tree, its cells are fitted
  /// to the input's points first (cga::PointPairField::planTreeCells).
  bool Deform(
    vtkDataSet* input, cga::PointPairField& field, double strength, vtkPointSet* output);

  /// The last update's field while it holds a tree (Tolerance), for the next update to share.
  std::shared_ptr<const cga::PointPairField> LastTreeField;

  vtkPointPairDeformationFilter(const vtkPointPairDeformationFilter&) = delete;
  void operator=(const vtkPointPairDeformationFilter&) = delete;
};

#endif
