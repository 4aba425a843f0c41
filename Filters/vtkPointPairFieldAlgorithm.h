/**
 * @class   vtkPointPairFieldAlgorithm
 * @brief   the generators and the deformation parameters shared by vtkPointPairDeformationFilter
 *          and vtkPointPairFitFilter (abstract)
 *
 * A field of generators i at locations x_i with directions v_i, weights w_i, kinds and pitches
 * deforms a point p into p' = fn(K up(p) ~K), K = exp(-Strength B(p)),
 * B(p) = sum_i w_i G_i / (Falloff |p - x_i|^2 + Epsilon) (docs/conventions.md section 3 item 9;
 * the kinds in section 2 item 11). This class holds what both filters read to build that field:
 *
 * * the generator list (AddGenerator ..., the ParaView table): rows of location (x, y, z),
 *   direction (vx, vy, vz), weight, kind (one of GeneratorKinds) and pitch (TWIST only: the
 *   advance along the axis per radian of turn), with the list API and the cap of
 *   vtkBoostedRowList (Common/): AddGenerator returns the new row's index, SetGenerator(i, ...)
 *   changes row i < GetNumberOfGenerators(), SetNumberOfGenerators resizes (new rows are zero,
 *   hence ignored until set), GetGenerator copies a row of 9 values (false if there is none); at
 *   most 10^6 rows (more come through the Generators input). The forms without kind and pitch
 *   give a POINT_PAIR of pitch 0;
 * * the optional "Generators" input port (SetGeneratorsConnection; its number is the subclass's):
 *   any vtkPointSet whose points are the locations, with a 3-component point array named
 *   GeneratorDirectionArrayName and, when UseGeneratorWeightArray is on, a 1-component point
 *   array named GeneratorWeightArrayName (the weights; otherwise every weight is 1), and
 *   optionally 1-component point arrays named GeneratorKindArrayName and GeneratorPitchArrayName
 *   (absent: every generator there is a POINT_PAIR of pitch 0), summed with the list's;
 * * Strength (default 1, finite), Falloff k (default 1), Epsilon (default 0.01, at least 1e-10),
 *   ExponentialRule (EXACT, default, or PAPER) and the output's OutputPointsPrecision.
 */
#ifndef vtkPointPairFieldAlgorithm_h
#define vtkPointPairFieldAlgorithm_h

#include "BoostedSurfacesFiltersModule.h" // for export macro
#include "vtkPointSetAlgorithm.h"
#include "vtkSmartPointer.h" // for the Generators output's cache

#include <memory> // for the generator list
#include <vector> // for the generators read

class vtkBoostedRowList;
class vtkDataSet;
class vtkPolyData;
namespace cga
{
struct GeneratorParameters;
}

class BOOSTEDSURFACESFILTERS_EXPORT vtkPointPairFieldAlgorithm : public vtkPointSetAlgorithm
{
public:
  vtkTypeMacro(vtkPointPairFieldAlgorithm, vtkPointSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ExponentialRules
  {
    EXACT = 0,
    PAPER = 1
  };

  /// The kinds of generator (docs/conventions.md section 2 item 11).
  enum GeneratorKinds
  {
    POINT_PAIR = 0,
    ROTATION = 1,
    TWIST = 2,
    DILATION = 3,
    TRANSLATION = 4
  };

  ///@{
  /// The generator list (see the class description).
  int AddGenerator(double x, double y, double z, double vx, double vy, double vz, double weight);
  int AddGenerator(double x, double y, double z, double vx, double vy, double vz, double weight,
    double kind, double pitch);
  void SetGenerator(int index, double x, double y, double z, double vx, double vy, double vz,
    double weight);
  void SetGenerator(int index, double x, double y, double z, double vx, double vy, double vz,
    double weight, double kind, double pitch);
  void SetNumberOfGenerators(int count);
  bool GetGenerator(int index, double values[9]) const;
  void RemoveAllGenerators();
  int GetNumberOfGenerators() const;
  ///@}

  ///@{
  /// One generator of the list moved and aimed by itself (ParaView's line widget from its location
  /// to its tip): when SelectedGenerator is a valid row index, that row starts at
  /// SelectedGeneratorLocation and, when AimSelectedGenerator is on, points along
  /// SelectedGeneratorTip - SelectedGeneratorLocation (its length, as a row's direction's,
  /// multiplies the weight). -1 (the default) selects none; defaults location (0, 0, 0), aim off,
  /// tip (0, 0, 1). A non-finite location or (aimed) tip makes that row unusable, as a non-finite
  /// row value.
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
  /// The optional Generators input: a vtkPointSet of generators (see the class description), in
  /// the format of every class's Generators output.
  void SetGeneratorsConnection(vtkAlgorithmOutput* output);
  void SetGeneratorsData(vtkDataObject* data);
  ///@}

  ///@{
  /// Names of the point arrays of the Generators input: directions (3 components, default
  /// "Direction") and weights (1 component, default "Weight", read only when
  /// UseGeneratorWeightArray is on, default off; otherwise every weight is 1), and the optional
  /// 1-component arrays of kinds (default "Kind", values of GeneratorKinds) and pitches (default
  /// "Pitch"): an array that is absent means POINT_PAIR or pitch 0 for every generator there.
  vtkSetStringMacro(GeneratorDirectionArrayName);
  vtkGetStringMacro(GeneratorDirectionArrayName);
  vtkSetStringMacro(GeneratorWeightArrayName);
  vtkGetStringMacro(GeneratorWeightArrayName);
  vtkSetStringMacro(GeneratorKindArrayName);
  vtkGetStringMacro(GeneratorKindArrayName);
  vtkSetStringMacro(GeneratorPitchArrayName);
  vtkGetStringMacro(GeneratorPitchArrayName);
  vtkSetMacro(UseGeneratorWeightArray, bool);
  vtkGetMacro(UseGeneratorWeightArray, bool);
  vtkBooleanMacro(UseGeneratorWeightArray, bool);
  ///@}

  ///@{
  /// Global factor on B: 0 is the identity, 1 the field as given. Default 1. Must be finite.
  vtkSetMacro(Strength, double);
  vtkGetMacro(Strength, double);
  ///@}

  ///@{
  /// k of the weighting w / (k |p - x|^2 + eps). Default 1; k = 0 makes B the same everywhere.
  vtkSetClampMacro(Falloff, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Falloff, double);
  ///@}

  ///@{
  /// eps of the weighting: keeps B finite on a generator's location. Default 0.01. Clamped to at
  /// least 1e-10 (smaller values only make B huge, where no exponential is accurate).
  vtkSetClampMacro(Epsilon, double, 1e-10, VTK_DOUBLE_MAX);
  vtkGetMacro(Epsilon, double);
  ///@}

  ///@{
  /// EXACT (default) or PAPER.
  vtkSetClampMacro(ExponentialRule, int, EXACT, PAPER);
  vtkGetMacro(ExponentialRule, int);
  void SetExponentialRuleToExact() { this->SetExponentialRule(EXACT); }
  void SetExponentialRuleToPaper() { this->SetExponentialRule(PAPER); }
  ///@}

  ///@{
  /// vtkAlgorithm::DEFAULT_PRECISION (default: as the input's points), SINGLE_PRECISION or
  /// DOUBLE_PRECISION.
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DEFAULT_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

protected:
  /// `generatorsPort`: the number of the subclass's optional Generators input port.
  explicit vtkPointPairFieldAlgorithm(int generatorsPort);
  ~vtkPointPairFieldAlgorithm() override;

  /// False, with an error, when Strength is not finite or Falloff or Epsilon is NaN (the clamp
  /// macros let NaN through).
  bool CheckFieldParameters();

  /// False, with an error, when `mesh` is a vtkStructuredGrid whose extent does not count its
  /// points: VTK does not check it, and the output's cells would index points that do not exist.
  bool CheckMeshStructure(vtkDataSet* mesh, const char* name);

  /// The generators to use, in order: the list's rows (the selected one moved and aimed, see
  /// SelectedGenerator), then those of the Generators input when connected. False, with an error
  /// naming the row, array or property, when a row or the input's arrays are bad
  /// (vtkBoostedGeneratorRows::Read, vtkBoostedGeneratorPort::Read).
  bool ReadGenerators(
    vtkInformationVector** inputVector, std::vector<cga::GeneratorParameters>& generators);

  std::unique_ptr<vtkBoostedRowList> Generators;
  char* GeneratorDirectionArrayName = nullptr;
  char* GeneratorWeightArrayName = nullptr;
  char* GeneratorKindArrayName = nullptr;
  char* GeneratorPitchArrayName = nullptr;
  bool UseGeneratorWeightArray = false;
  int SelectedGenerator = -1;
  double SelectedGeneratorLocation[3] = { 0.0, 0.0, 0.0 };
  bool AimSelectedGenerator = false;
  double SelectedGeneratorTip[3] = { 0.0, 0.0, 1.0 };
  double Strength = 1.0;
  double Falloff = 1.0;
  double Epsilon = 0.01;
  int ExponentialRule = EXACT;
  int OutputPointsPrecision = DEFAULT_PRECISION;

  /// The "Generators" output of the last update, which the next one shares as long as the
  /// generators written there (the deformation filter's as used, the fit's fitted ones) stay the
  /// same (vtkBoostedGeneratorGlyphs::Write with a cache).
  vtkSmartPointer<vtkPolyData> GeneratorGlyphs;

private:
  const int GeneratorsPort;

  vtkPointPairFieldAlgorithm(const vtkPointPairFieldAlgorithm&) = delete;
  void operator=(const vtkPointPairFieldAlgorithm&) = delete;
};

#endif
