/**
 * @class   vtkDipoleFieldSource
 * @brief   the dipole displacement field of Colapinto 2014, section 7 (eq 27-28, Fig 13-14)
 *
 * On a regular grid (Origin, Spacing, Dimensions; by default a 21 x 21 slice of [-2, 2]^2 in the
 * xy plane, like Fig 13-14) every point p gets the displacement v = p' - p of the boost generated
 * by a list of generators (location x_i, direction v_i, weight w_i, kind and pitch as in
 * vtkPointPairDeformationFilter; docs/conventions.md section 2 item 11), with G_i the kind's
 * bivector (tau(x_i, v_i) for the default POINT_PAIR) and d_i^2 = Falloff |p - x_i|^2 + Epsilon,
 * computed two ways:
 *
 * - DisplacementSummedGenerators (method a, the paper's): K = exp(-sum_i w_i G_i / d_i^2),
 *   p' = fn(K up(p) ~K). ExponentialRule picks the exact exponential (default) or the paper's
 *   eq 9-10.
 * - DisplacementSummedDisplacements (method b, vector field topology's):
 *   v = sum_i (fn(K_i up(p) ~K_i) - p), K_i = exp(-w_i G_i / d_i^2).
 *
 * For one generator they are equal; for several they differ (Fig 14). Further point arrays:
 * DisplacementDifference (a - b), DisplacementDifferenceMagnitude, and DipolePotential, the
 * contour scalar phi = sum_i w_i (v_i . (p - x_i)) / (|p - x_i|^2 + Epsilon): the superposed
 * dipole potentials, whose level sets cross a single generator's field at right angles (the
 * "equipotential lines" of Fig 14). Only point pairs are dipoles: the other kinds add nothing
 * to DipolePotential (their first-order fields are not gradients; a rotation's circulates), so
 * without POINT_PAIR rows it is zero. The active vectors are DisplacementSummedGenerators, the
 * active scalars DipolePotential.
 *
 * Time: with NumberOfTimeSteps N >= 1 the source reports N time steps t_k = k / (N - 1) in [0, 1]
 * (t = 1 for N = 1) and scales every weight by the requested t, so the field grows from zero in
 * an animation. With N = 0 (default) there are no time steps and the weights are used as given.
 *
 * It is an image source in VTK's manner: WHOLE_EXTENT, CAN_PRODUCE_SUB_EXTENT, and only the
 * requested update extent is computed, so it streams and runs distributed. The points are
 * computed in parallel in vtkBoostedBlockLoop's blocks, with progress and abort (an aborted update
 * leaves the output empty).
 *
 * Bad input (a dimension < 1, a zero, negative or non-finite spacing, a non-finite origin,
 * GeneratorsTranslation, Falloff or Epsilon, a non-finite generator value or selected generator
 * location or tip, a kind that is none
 * of the five constants) gives an error and an empty output. A generator with a zero direction or weight contributes nothing. The field stays
 * finite at a generator on a grid point (Epsilon > 0); a single generator leaves its location
 * fixed. Where a boost sends a grid point to infinity the failed displacement is zero and a
 * warning counts those points. Every array saturates at the largest value of its precision where
 * huge weights would overflow it.
 *
 * Output 1, "Generators" (vtkBoostedGeneratorGlyphs, for glyphs): one vertex per row at its
 * location plus GeneratorsTranslation (the selected row at SelectedGeneratorLocation), point
 * arrays "Direction", "Weight" (the row's weight times the time sweep's factor), "Kind" and
 * "Pitch"; on piece 0 only, empty after an error.
 */
#ifndef vtkDipoleFieldSource_h
#define vtkDipoleFieldSource_h

#include "BoostedSurfacesSourcesModule.h" // for export macro
#include "vtkImageAlgorithm.h"
#include "vtkSmartPointer.h" // for the Generators output's cache

#include <string> // for Validate
#include <memory> // for the generator list

class vtkBoostedRowList;
class vtkPolyData;
namespace cga
{
struct GeneratorParameters;
}

class BOOSTEDSURFACESSOURCES_EXPORT vtkDipoleFieldSource : public vtkImageAlgorithm
{
public:
  static vtkDipoleFieldSource* New();
  vtkTypeMacro(vtkDipoleFieldSource, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ExponentialRules
  {
    EXACT = 0, ///< the true exponential
    PAPER = 1  ///< eq 9-10 with s = <B B>_0
  };

  ///@{
  /// The grid. Defaults: origin (-2, -2, 0), spacing (0.2, 0.2, 1), dimensions (21, 21, 1).
  /// An update computes at most 1e8 points, within the memory budget (vtkBoostedMemoryBudget,
  /// Common/; more is an error): stream larger grids in pieces.
  vtkSetVector3Macro(Origin, double);
  vtkGetVector3Macro(Origin, double);
  vtkSetVector3Macro(Spacing, double);
  vtkGetVector3Macro(Spacing, double);
  vtkSetVector3Macro(Dimensions, int);
  vtkGetVector3Macro(Dimensions, int);
  ///@}

  /// The kinds of generator, as vtkPointPairDeformationFilter's.
  enum GeneratorKinds
  {
    POINT_PAIR = 0,
    ROTATION = 1,
    TWIST = 2,
    DILATION = 3,
    TRANSLATION = 4
  };

  ///@{
  /// The generator list: rows of location (x, y, z), direction (dx, dy, dz; its length multiplies
  /// the weight), weight, kind (GeneratorKinds) and pitch (TWIST only), with the list API and
  /// the cap of vtkBoostedRowList (Common/): AddGenerator returns the new row's index,
  /// SetGenerator(i, ...) changes row i < GetNumberOfGenerators(), SetNumberOfGenerators resizes
  /// (new rows are zero, hence contribute nothing until set), GetGenerator copies a row of 9
  /// values (false if there is none); at most 10^6 rows. The forms without kind and pitch give a
  /// POINT_PAIR of pitch 0. Default: one point pair at the origin along x with weight 0.5 (Fig 13).
  int AddGenerator(double x, double y, double z, double dx, double dy, double dz, double weight);
  int AddGenerator(double x, double y, double z, double dx, double dy, double dz, double weight,
    double kind, double pitch);
  void SetGenerator(int index, double x, double y, double z, double dx, double dy, double dz,
    double weight);
  void SetGenerator(int index, double x, double y, double z, double dx, double dy, double dz,
    double weight, double kind, double pitch);
  void SetNumberOfGenerators(int count);
  bool GetGenerator(int index, double values[9]) const;
  void RemoveAllGenerators();
  int GetNumberOfGenerators() const;
  ///@}

  ///@{
  /// Added to every generator's location: moves the whole configuration (ParaView drags it with a
  /// handle widget). Default (0, 0, 0).
  vtkSetVector3Macro(GeneratorsTranslation, double);
  vtkGetVector3Macro(GeneratorsTranslation, double);
  ///@}

  ///@{
  /// One generator of the list aimed and moved by itself (ParaView's line widget from its location
  /// to its tip): when SelectedGenerator is a valid row index, that row is at
  /// SelectedGeneratorLocation (where the line widget starts: GeneratorsTranslation does not move
  /// it) and, when AimSelectedGenerator is on, its direction is SelectedGeneratorTip -
  /// SelectedGeneratorLocation (its length, as a row's direction's, multiplies the weight). -1
  /// (the default) selects none; defaults location (0, 0, 0), aim off, tip (1, 0, 0).
  vtkSetClampMacro(SelectedGenerator, int, -1, VTK_INT_MAX);
  vtkGetMacro(SelectedGenerator, int);
  vtkSetVector3Macro(SelectedGeneratorLocation, double);
  vtkGetVector3Macro(SelectedGeneratorLocation, double);
  vtkSetMacro(AimSelectedGenerator, bool);
  vtkGetMacro(AimSelectedGenerator, bool);
  vtkBooleanMacro(AimSelectedGenerator, bool);
  vtkSetVector3Macro(SelectedGeneratorTip, double);
  vtkGetVector3Macro(SelectedGeneratorTip, double);
  ///@}

  ///@{
  /// Falloff k >= 0 and Epsilon > 0 of d^2 = k |p - x|^2 + Epsilon. Defaults 1 and 0.1.
  vtkSetClampMacro(Falloff, double, 0.0, 1e12);
  vtkGetMacro(Falloff, double);
  vtkSetClampMacro(Epsilon, double, 1e-12, 1e12);
  vtkGetMacro(Epsilon, double);
  ///@}

  ///@{
  /// Method (a)'s far-field approximation of B (cga::PointPairField::setTolerance): 0 (default)
  /// is the direct sum; t > 0 keeps each displacement's error, to first order, within t times the
  /// field's displacement scale. Values above 1 are used as 1; NaN or negative is an error (empty output). Method (b)
  /// stays exact. Fewer than 10,000 generators, or a tolerance below 1e-4 (10,000/M)^3, always sum directly.
  /// The tree's cells are fitted to the grid's points (cga::DipoleField::planTreeCells).
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// EXACT (default) or PAPER: the exponential of both methods (they agree on method b's blades).
  vtkSetClampMacro(ExponentialRule, int, EXACT, PAPER);
  vtkGetMacro(ExponentialRule, int);
  void SetExponentialRuleToExact() { this->SetExponentialRule(EXACT); }
  void SetExponentialRuleToPaper() { this->SetExponentialRule(PAPER); }
  ///@}

  ///@{
  /// Number of time steps in [0, 1] that scale the weights (0, the default: no time).
  vtkSetClampMacro(NumberOfTimeSteps, int, 0, 100000);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

  ///@{
  /// vtkAlgorithm::SINGLE_PRECISION or DOUBLE_PRECISION (default) for the output arrays (the
  /// name every class uses; an image's points are implicit, its arrays take the precision).
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DOUBLE_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

protected:
  vtkDipoleFieldSource();
  ~vtkDipoleFieldSource() override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Origin[3] = { -2.0, -2.0, 0.0 };
  double Spacing[3] = { 0.2, 0.2, 1.0 };
  int Dimensions[3] = { 21, 21, 1 };
  std::unique_ptr<vtkBoostedRowList> Generators;
  double GeneratorsTranslation[3] = { 0.0, 0.0, 0.0 };
  int SelectedGenerator = -1;
  double SelectedGeneratorLocation[3] = { 0.0, 0.0, 0.0 };
  bool AimSelectedGenerator = false;
  double SelectedGeneratorTip[3] = { 1.0, 0.0, 0.0 };
  double Falloff = 1.0;
  double Epsilon = 0.1;
  double Tolerance = 0.0;
  int ExponentialRule = EXACT;
  int NumberOfTimeSteps = 0;
  int OutputPointsPrecision = DOUBLE_PRECISION;

private:
  /// The "Generators" output of the last update, which the next one shares while the generators as
  /// used it holds stay the same to the bit (vtkBoostedGeneratorGlyphs::Write with a cache).
  vtkSmartPointer<vtkPolyData> GeneratorGlyphs;

  vtkDipoleFieldSource(const vtkDipoleFieldSource&) = delete;
  void operator=(const vtkDipoleFieldSource&) = delete;

  // Empty when the parameters are valid, otherwise what is wrong.
  std::string Validate() const;
  // Row `index` (validated) as the field uses it: moved by GeneratorsTranslation, or the selected
  // row at SelectedGeneratorLocation, aimed at SelectedGeneratorTip.
  cga::GeneratorParameters GeneratorAsUsed(int index) const;
  // Output 1 after a successful update (on piece 0 only), with output 0's time.
  void WriteGenerators(vtkInformationVector* outputVector);
};

#endif
