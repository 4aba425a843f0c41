/**
 * @class   vtkPointPairFitFilter
 * @brief   fits the generators of a point-pair field so that their deformation maps a mesh onto a
 *          target (inverse design; the inverse of vtkPointPairDeformationFilter)
 *
 * Input 0 is the mesh (any vtkPointSet), input 1 the target, input 2 (optional) generators. The
 * deformation is vtkPointPairDeformationFilter's: generators i at x_i with direction v_i, weight
 * w_i and kind, B(p) = sum_i w_i G_i / (Falloff |p - x_i|^2 + Epsilon), p' = fn(K up(p) ~K),
 * K = exp(-Strength B(p)) (docs/conventions.md section 3 item 9). Starting from the given
 * generators, the filter finds the unknowns theta (the weights by default; with FitLocations,
 * FitDirections and FitPitches also the locations, directions and twists' pitches) that minimize
 *
 *   cost(theta) = sum_p omega_p r_p(theta)^2 / sum_p omega_p + RegularizationWeight |theta - theta_0|^2
 *
 * with omega_p the per-point weights (PointWeightArrayName; 1 without) and r_p the residual of
 * point p: in POINT_TO_POINT mode |p' - t_p|, t_p the target's point of the same index (the
 * target has the mesh's number of points, in the same order); in POINT_TO_SURFACE mode the
 * distance from p' to the target's cells (vtkStaticCellLocator; any cells: polygons, lines,
 * vertices). The first term is the squared weighted RMS residual; the second, a Tikhonov term
 * toward the initial values theta_0 (default weight 0), keeps an under-determined fit (more
 * unknowns than the data fix, generators far from the mesh) near its start. Bounds: each weight
 * within WeightRange; each location coordinate within MaximumLocationChange times the mesh's
 * bounding-box diagonal of its initial value; each direction component within
 * MaximumDirectionChange times the initial direction's length of its initial value; each twist's
 * pitch within MaximumPitchChange times the diagonal of its initial value.
 *
 * Kinds (FitKinds, off by default) are discrete: the filter then runs a greedy coordinate search
 * (vtkPointPairFitSolver::SearchKinds): it fits the given kinds, then for each generator in turn
 * fits each other kind in its place (that generator restarted from its initial values, the others
 * from the best fit so far) and keeps a kind whose converged cost is lower by more than
 * KindSeparation times the initial cost (a ROTATION also replaces a TWIST it matches within that
 * margin: the twist contains it), sweeping until a sweep changes no kind (at most 4 sweeps): at
 * most 1 + 16 M fits of M generators. A search whose bound of work exceeds MaximumKindSearchWork
 * is refused (an error) rather than run for hours. A generator whose kind cannot be identified (another kind,
 * not counting a TWIST against a ROTATION, fits within the margin: a field the target does not
 * see there, or the identity) is named in a warning and has KindIdentified 0 in the Generators
 * output.
 *
 * Solver: Ceres Solver's Levenberg-Marquardt (trust region, dense QR) with the analytic Jacobian
 * (cga::mapWithGeneratorDerivatives: the core's derivative of the map by B(p), times the closed
 * form of dB/dtheta, GeneratorDerivatives.h). Iterations stop at MaximumNumberOfIterations or
 * at Ceres's FunctionTolerance, GradientTolerance and ParameterTolerance. Progress is reported
 * per iteration, and an abort (vtkAlgorithm::SetAbortExecute, ParaView's abort) stops the solver
 * at the next iteration: the outputs are then empty.
 *
 * Generators come as for vtkPointPairDeformationFilter: the list (AddGenerator ... , the ParaView
 * table) and the optional Generators input (the same arrays and *ArrayName properties), summed.
 * Generators with a zero or non-finite direction, location or weight, or a non-finite pitch
 * (whatever their kind: FitKinds may make any of them a twist), are ignored with a warning (and
 * left out of the outputs).
 *
 * Outputs: 0, the mesh deformed by the fitted generators (vtkPointPairDeformationFilter's output:
 * same topology and arrays, "Displacement", OutputPointsPrecision) with the point array
 * "FitResidual" (r_p, unweighted) and the field data "FitIterations", "FitInitialRMS",
 * "FitFinalRMS", "FitImproved" (1 or 0) and "FitTermination" (Ceres's termination type and
 * message); 1, "Generators": the fitted generators as points with "Direction", "Weight", "Kind",
 * "Pitch" (vtkBoostedGeneratorGlyphs: the format of the deformation filter's Generators input,
 * which it feeds directly) and, with FitKinds, "KindIdentified" (1 or 0); 2, the same generators as a vtkTable of the generator rows' nine
 * columns (X, Y, Z, DirectionX, DirectionY, DirectionZ, Weight, Kind, Pitch). The summary is also
 * in GetNumberOfIterations(), GetInitialRMS(), GetFinalRMS(), GetTerminationReason() and
 * PrintSelf. A fit that ends no lower than it started (nothing the unknowns can change reduces
 * the cost) says so in a warning (none for MaximumNumberOfIterations 0, which only evaluates the
 * start), and its outputs are the initial generators and the mesh as they deform it (the input
 * itself when they are the identity).
 *
 * The fit needs the whole mesh and target: every input is requested whole, and the outputs are
 * on piece 0 only (empty on the other pieces).
 *
 * Bad input gives an error and empty outputs: no generators (none usable), nothing to fit (every
 * Fit* off), a mesh without points or with a NaN or infinite point, a target without points (or,
 * POINT_TO_SURFACE, without cells), with a non-finite point or (POINT_TO_POINT) another number of
 * points than the mesh, a missing, wrongly shaped, negative, non-finite or all-zero point weight
 * array, bad Generators arrays or kinds, a non-finite Strength, NaN Falloff, Epsilon, tolerances
 * or bounds, an empty WeightRange, initial generators that send a point to infinity (or,
 * POINT_TO_SURFACE, beyond 1e75, as a target reaching beyond: the cell locator overflows there),
 * residuals whose squares overflow, a
 * problem larger than the memory budget (vtkBoostedMemoryBudget: the Jacobian holds residuals x
 * unknowns doubles), or a FitKinds search above MaximumKindSearchWork.
 */
#ifndef vtkPointPairFitFilter_h
#define vtkPointPairFitFilter_h

#include "BoostedSurfacesFiltersModule.h" // for export macro
#include "vtkPointPairFieldAlgorithm.h"

#include <string> // for the termination reason

class BOOSTEDSURFACESFILTERS_EXPORT vtkPointPairFitFilter : public vtkPointPairFieldAlgorithm
{
public:
  static vtkPointPairFitFilter* New();
  vtkTypeMacro(vtkPointPairFitFilter, vtkPointPairFieldAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // The initial generators (the list, AddGenerator ..., its selected row, SelectedGenerator ...,
  // and the Generators input, port 2, SetGeneratorsConnection, with its Generator*ArrayName
  // properties), the deformation's Strength, Falloff, Epsilon, ExponentialRule and
  // OutputPointsPrecision and the EXACT/PAPER and kind constants are vtkPointPairFieldAlgorithm's,
  // as the deformation filter's.

  /// What the residual of a point measures (see the class description).
  enum TargetModes
  {
    POINT_TO_POINT = 0,
    POINT_TO_SURFACE = 1
  };

  ///@{
  /// The target (input 1): a vtkPointSet (see TargetMode).
  void SetTargetConnection(vtkAlgorithmOutput* output);
  void SetTargetData(vtkDataObject* data);
  ///@}

  ///@{
  /// POINT_TO_POINT (default) or POINT_TO_SURFACE.
  vtkSetClampMacro(TargetMode, int, POINT_TO_POINT, POINT_TO_SURFACE);
  vtkGetMacro(TargetMode, int);
  void SetTargetModeToPointToPoint() { this->SetTargetMode(POINT_TO_POINT); }
  void SetTargetModeToPointToSurface() { this->SetTargetMode(POINT_TO_SURFACE); }
  ///@}

  ///@{
  /// The name of a 1-component point array of the mesh with each point's weight omega_p >= 0 in
  /// the cost (not all zero). Empty (default): every point weighs 1.
  vtkSetStringMacro(PointWeightArrayName);
  vtkGetStringMacro(PointWeightArrayName);
  ///@}

  ///@{
  /// The unknowns: the weights (default on), the locations, the directions and the pitches
  /// (default off) of every generator; a pitch is read by a TWIST only, so only twists' pitches
  /// move. At least one must be on. A direction's length multiplies its weight, so fitting both
  /// weights and directions leaves one scale per generator free: the RegularizationWeight (or the
  /// bounds) then picks one.
  vtkSetMacro(FitWeights, bool);
  vtkGetMacro(FitWeights, bool);
  vtkBooleanMacro(FitWeights, bool);
  vtkSetMacro(FitLocations, bool);
  vtkGetMacro(FitLocations, bool);
  vtkBooleanMacro(FitLocations, bool);
  vtkSetMacro(FitDirections, bool);
  vtkGetMacro(FitDirections, bool);
  vtkBooleanMacro(FitDirections, bool);
  vtkSetMacro(FitPitches, bool);
  vtkGetMacro(FitPitches, bool);
  vtkBooleanMacro(FitPitches, bool);
  ///@}

  ///@{
  /// Choose every generator's kind too (default off): the greedy search of the class description,
  /// over the unknowns above. KindSeparation (default 1e-6, in [0, 1]) is the margin, a fraction
  /// of the initial cost, by which one kind must fit better than another to be preferred and to
  /// count as identified.
  vtkSetMacro(FitKinds, bool);
  vtkGetMacro(FitKinds, bool);
  vtkBooleanMacro(FitKinds, bool);
  vtkSetClampMacro(KindSeparation, double, 0.0, 1.0);
  vtkGetMacro(KindSeparation, double);
  ///@}

  ///@{
  /// The most work the FitKinds search may take (default 1e8): its bound, (1 + 16 M) fits x
  /// (MaximumNumberOfIterations + 1) evaluations x points x M generators, is checked before the
  /// search, and a larger one is refused with an error naming it (each unit, one generator's
  /// part of one point's evaluation, took 1 to 2 microseconds in POINT_TO_POINT mode on the test
  /// machine, several times that in POINT_TO_SURFACE: the default bounds a search to minutes).
  vtkSetClampMacro(MaximumKindSearchWork, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumKindSearchWork, double);
  ///@}

  ///@{
  /// The Tikhonov term's weight lambda >= 0 (default 0: none): lambda |theta - theta_0|^2 is added
  /// to the squared RMS residual.
  vtkSetClampMacro(RegularizationWeight, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(RegularizationWeight, double);
  ///@}

  ///@{
  /// Bounds of the unknowns: every fitted weight within WeightRange (default [-1000, 1000], min <=
  /// max; min = max holds the weights, as a change of 0 holds the others); every location coordinate within MaximumLocationChange (default 0.25) times the mesh's
  /// bounding-box diagonal of its initial value; every direction component within
  /// MaximumDirectionChange (default 1) times the initial direction's length of its initial value;
  /// every twist's pitch (a length per radian) within MaximumPitchChange (default 1) times the
  /// diagonal of its initial value.
  vtkSetVector2Macro(WeightRange, double);
  vtkGetVector2Macro(WeightRange, double);
  vtkSetClampMacro(MaximumLocationChange, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumLocationChange, double);
  vtkSetClampMacro(MaximumDirectionChange, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumDirectionChange, double);
  vtkSetClampMacro(MaximumPitchChange, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(MaximumPitchChange, double);
  ///@}

  ///@{
  /// The solver's stops (Ceres's Solver::Options of the same names): at most
  /// MaximumNumberOfIterations iterations (default 100; 0 evaluates the start only), or when the
  /// cost changes by less than FunctionTolerance relative (default 1e-12), the gradient's largest
  /// component is below GradientTolerance (default 1e-14) or a step is below ParameterTolerance
  /// relative to the unknowns (default 1e-12).
  vtkSetClampMacro(MaximumNumberOfIterations, int, 0, 100000);
  vtkGetMacro(MaximumNumberOfIterations, int);
  vtkSetClampMacro(FunctionTolerance, double, 0.0, 1.0);
  vtkGetMacro(FunctionTolerance, double);
  vtkSetClampMacro(GradientTolerance, double, 0.0, 1.0);
  vtkGetMacro(GradientTolerance, double);
  vtkSetClampMacro(ParameterTolerance, double, 0.0, 1.0);
  vtkGetMacro(ParameterTolerance, double);
  ///@}

  ///@{
  /// The last fit's summary (also in the output's field data): iterations, the weighted RMS
  /// residual of the initial and of the fitted generators, whether the fit lowered the cost, and
  /// Ceres's termination type and message (of the best fit with FitKinds; the iterations are
  /// then those of every fit run, GetNumberOfFits() of them; 1 without FitKinds), and with
  /// FitKinds the number of generators whose kind could not be identified (-1 without). -1, NaN
  /// and empty before a fit or after an error.
  int GetNumberOfIterations() const { return this->NumberOfIterations; }
  int GetNumberOfFits() const { return this->NumberOfFits; }
  int GetNumberOfUnidentifiedKinds() const { return this->NumberOfUnidentifiedKinds; }
  double GetInitialRMS() const { return this->InitialRMS; }
  double GetFinalRMS() const { return this->FinalRMS; }
  bool GetImproved() const { return this->Improved; }
  const char* GetTerminationReason() const { return this->TerminationReason.c_str(); }
  ///@}

protected:
  vtkPointPairFitFilter();
  ~vtkPointPairFitFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int ComputeInputUpdateExtent(
    vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int TargetMode = POINT_TO_POINT;
  char* PointWeightArrayName = nullptr;
  bool FitWeights = true;
  bool FitLocations = false;
  bool FitDirections = false;
  bool FitPitches = false;
  bool FitKinds = false;
  double KindSeparation = 1e-6;
  double MaximumKindSearchWork = 1e8;
  double RegularizationWeight = 0.0;
  double WeightRange[2] = { -1000.0, 1000.0 };
  double MaximumLocationChange = 0.25;
  double MaximumDirectionChange = 1.0;
  double MaximumPitchChange = 1.0;
  int MaximumNumberOfIterations = 100;
  double FunctionTolerance = 1e-12;
  double GradientTolerance = 1e-14;
  double ParameterTolerance = 1e-12;

  int NumberOfIterations = -1;
  int NumberOfFits = -1;
  int NumberOfUnidentifiedKinds = -1;
  double InitialRMS;
  double FinalRMS;
  bool Improved = false;
  std::string TerminationReason;

private:
  vtkPointPairFitFilter(const vtkPointPairFitFilter&) = delete;
  void operator=(const vtkPointPairFitFilter&) = delete;
};

#endif
