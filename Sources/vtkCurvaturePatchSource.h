/**
 * @class   vtkCurvaturePatchSource
 * @brief   a plane patch bent by point-pair curvature operators (Colapinto 2014, eq 15-26, Fig 6-12)
 *
 * The patch p(a, b) = Origin + a u + b v, a in [-Size[0]/2, Size[0]/2], b in [-Size[1]/2,
 * Size[1]/2] (u, v the orthonormalized UDirection and VDirection, n = u x v) is sampled on a
 * (UResolution + 1) x (VResolution + 1) grid and every sample is moved by a boost
 * K = exp(E(a, b)): p' = fn(<K up(p) ~K>_1). E depends on the Method (docs/conventions.md section 3):
 *
 * - BENT_LINE (eq 15, Fig 6): each u row is bent with curvature KappaU at its point on the v axis,
 *   K = 1 - KappaU/2 tau(p, n). A row becomes the circle of radius 1/|KappaU| tangent at p, center
 *   p - n/KappaU. With Size[1] = 0 the output is one line.
 * - TRANSLATED_TANGENTS (eq 16, Fig 7): K = exp(-1/2 (KappaU tau(o + b v, n) + KappaV tau(o + a u, n))).
 *   The principal curvatures at Origin are KappaU along u and KappaV along v.
 * - OSCULATING_CIRCLES (eq 17-18, Fig 8): K = exp(-(KappaU/(d_u^2 + eps) + KappaV/(d_v^2 + eps)) tau(o, n)),
 *   d the eq 18 distance to the osculating circles at Origin.
 * - CONTROL_POINTS (eq 21-22, Fig 9-10): the same, summed over the control points, each weighted
 *   by 1/(Falloff |p - x_i|^2 + Epsilon).
 * - LINEAR (eq 24): generators 1 and 2 at the two ends of each u row, interpolated along the row.
 * - BILINEAR (eq 25-26, Fig 12): the four corner generators interpolated over the grid.
 *
 * A positive curvature puts the center of curvature on the -n side; zero curvature leaves the
 * patch flat. CurvaturePreset (other than CUSTOM) replaces KappaU, KappaV by the Fig 7 values.
 * ExponentialRule chooses the exact exponential (default) or the paper's eq 9-10.
 *
 * Output: quads (SURFACE) or one polyline per u row (LINES; also whenever Size[1] = 0), with the
 * point arrays "u" (a), "v" (b) and "GeneratorWeight" (sum of w_i in E = -sum_i w_i tau_i, tau_i
 * of unit direction), and for SURFACE point normals and texture coordinates. Samples whose image is at
 * infinity are dropped with their cells; the output is cut exactly at the clip sphere, radius
 * ClipRadius about Origin (vtkBoostedGridDriver). With ComputeCurvatures (SURFACE), the normals
 * are exact (from the derivatives of E(a, b) and p(a, b) through the exponential,
 * cga::CurvaturePatch::derivatives) and the point arrays "PrincipalCurvatures",
 * "PrincipalDirections", "GaussianCurvature" and "MeanCurvature" are added
 * (vtkBoostedCurvatureArrays).
 *
 * Output 1, "Generators" (vtkBoostedGeneratorGlyphs, for glyphs), on piece 0 only, empty after
 * an error: the Method's generators, one vertex each, with point arrays "Direction", "Weight"
 * and "Curvature" (kappa_u, kappa_v), at the curvatures of the requested time. CONTROL_POINTS:
 * each control point at its location (the selected one at SelectedControlPointLocation), its unit
 * normal, weight 1, its curvatures. LINEAR: corners 1 and 2 at the ends of the middle u row
 * (Origin -+ Size[0]/2 u); BILINEAR: the four corners (Origin -+ Size[0]/2 u -+ Size[1]/2 v);
 * each with its direction and weight, curvature (0, 0). BENT_LINE, TRANSLATED_TANGENTS and
 * OSCULATING_CIRCLES: one vertex at Origin along n = u x v, weight 1, curvature (KappaU, KappaV)
 * (or the preset's; (KappaU, 0) for BENT_LINE).
 *
 * Pieces: the rows are divided among the requested pieces (neighbouring bands repeat their shared
 * row of points; cells are never repeated; LINES partitions the points exactly).
 *
 * Invalid parameters (NaN or infinite values, Size[0] <= 0, Size[1] < 0, zero or parallel
 * directions, CONTROL_POINTS without control points, a control point whose normal is zero or
 * parallel to its u direction) produce an error and an empty output.
 */
#ifndef vtkCurvaturePatchSource_h
#define vtkCurvaturePatchSource_h

#include "BoostedSurfacesSourcesModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for the Generators output's cache

#include <memory> // for the control point list

class vtkBoostedRowList;
class vtkPolyData;

class BOOSTEDSURFACESSOURCES_EXPORT vtkCurvaturePatchSource : public vtkPolyDataAlgorithm
{
public:
  static vtkCurvaturePatchSource* New();
  vtkTypeMacro(vtkCurvaturePatchSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Methods
  {
    BENT_LINE = 0,
    TRANSLATED_TANGENTS = 1,
    OSCULATING_CIRCLES = 2,
    CONTROL_POINTS = 3,
    LINEAR = 4,
    BILINEAR = 5
  };
  enum Presets
  {
    CUSTOM = 0,
    PARABOLIC = 1,  ///< (0.5, 0)
    ELLIPTIC = 2,   ///< (0.5, 0.25)
    UMBILIC = 3,    ///< (0.5, 0.5)
    HYPERBOLIC = 4  ///< (-0.5, 0.5)
  };
  enum ExponentialRules
  {
    EXACT = 0,
    PAPER = 1
  };
  enum OutputTypes
  {
    SURFACE = 0,
    LINES = 1
  };

  ///@{
  /// The construction (default TRANSLATED_TANGENTS).
  vtkSetClampMacro(Method, int, BENT_LINE, BILINEAR);
  vtkGetMacro(Method, int);
  void SetMethodToBentLine() { this->SetMethod(BENT_LINE); }
  void SetMethodToTranslatedTangents() { this->SetMethod(TRANSLATED_TANGENTS); }
  void SetMethodToOsculatingCircles() { this->SetMethod(OSCULATING_CIRCLES); }
  void SetMethodToControlPoints() { this->SetMethod(CONTROL_POINTS); }
  void SetMethodToLinear() { this->SetMethod(LINEAR); }
  void SetMethodToBilinear() { this->SetMethod(BILINEAR); }
  ///@}

  ///@{
  /// EXACT (default): the true exponential; PAPER: eq 9-10 (not a versor for non-blade sums).
  vtkSetClampMacro(ExponentialRule, int, EXACT, PAPER);
  vtkGetMacro(ExponentialRule, int);
  void SetExponentialRuleToExact() { this->SetExponentialRule(EXACT); }
  void SetExponentialRuleToPaper() { this->SetExponentialRule(PAPER); }
  ///@}

  ///@{
  /// The patch: center (0,0,0), u direction (1,0,0), v direction (0,1,0) (made orthogonal to u),
  /// size (4, 4) along u and v. Size[1] = 0 gives a single line.
  vtkSetVector3Macro(Origin, double);
  vtkGetVector3Macro(Origin, double);
  vtkSetVector3Macro(UDirection, double);
  vtkGetVector3Macro(UDirection, double);
  vtkSetVector3Macro(VDirection, double);
  vtkGetVector3Macro(VDirection, double);
  vtkSetVector2Macro(Size, double);
  vtkGetVector2Macro(Size, double);
  ///@}

  ///@{
  /// Intervals along u and v (defaults 32, 32). More than vtkBoostedGridBuilder::MaximumSamples
  /// samples (UResolution + 1) x (VResolution + 1) is an error.
  vtkSetClampMacro(UResolution, int, 1, 100000);
  vtkGetMacro(UResolution, int);
  vtkSetClampMacro(VResolution, int, 1, 100000);
  vtkGetMacro(VResolution, int);
  ///@}

  ///@{
  /// Curvatures along u and v at Origin (defaults 0.5, 0.5); KappaU alone for BENT_LINE.
  vtkSetMacro(KappaU, double);
  vtkGetMacro(KappaU, double);
  vtkSetMacro(KappaV, double);
  vtkGetMacro(KappaV, double);
  /// CUSTOM (default) uses KappaU, KappaV; the others use the Fig 7 values instead.
  vtkSetClampMacro(CurvaturePreset, int, CUSTOM, HYPERBOLIC);
  vtkGetMacro(CurvaturePreset, int);
  void SetCurvaturePresetToCustom() { this->SetCurvaturePreset(CUSTOM); }
  void SetCurvaturePresetToParabolic() { this->SetCurvaturePreset(PARABOLIC); }
  void SetCurvaturePresetToElliptic() { this->SetCurvaturePreset(ELLIPTIC); }
  void SetCurvaturePresetToUmbilic() { this->SetCurvaturePreset(UMBILIC); }
  void SetCurvaturePresetToHyperbolic() { this->SetCurvaturePreset(HYPERBOLIC); }
  ///@}

  ///@{
  /// k of eq 21-22 (default 1) and the epsilon added to every squared distance (default 0.5:
  /// smooth bumps; small values give sharp pinches, as the weights grow like 1/d^2 near the
  /// osculating circles and control points).
  vtkSetClampMacro(Falloff, double, 0.0, 1e12);
  vtkGetMacro(Falloff, double);
  vtkSetClampMacro(Epsilon, double, 1e-12, 1e12);
  vtkGetMacro(Epsilon, double);
  ///@}

  ///@{
  /// The control point list of CONTROL_POINTS: rows of location (x, y, z), normal (nx, ny, nz),
  /// u direction (ux, uy, uz), kappa_u and kappa_v, with the list API and the cap of
  /// vtkBoostedRowList (Common/): AddControlPoint returns the new row's index,
  /// SetControlPoint(i, ...) changes row i < GetNumberOfControlPoints(), SetNumberOfControlPoints
  /// resizes (new rows: at the origin, normal z, u direction x, flat), GetControlPoint copies a
  /// row (false if there is none); at most 10^6 rows.
  int AddControlPoint(double x, double y, double z, double nx, double ny, double nz, double ux,
    double uy, double uz, double kappaU, double kappaV);
  void SetControlPoint(int index, double x, double y, double z, double nx, double ny, double nz,
    double ux, double uy, double uz, double kappaU, double kappaV);
  void SetNumberOfControlPoints(int count);
  bool GetControlPoint(int index, double values[11]) const;
  void RemoveAllControlPoints();
  int GetNumberOfControlPoints() const;
  ///@}

  ///@{
  /// For interactive editing: when SelectedControlPoint is a valid index (default -1: none), that
  /// control point's location is replaced by SelectedControlPointLocation.
  vtkSetClampMacro(SelectedControlPoint, int, -1, VTK_INT_MAX);
  vtkGetMacro(SelectedControlPoint, int);
  vtkSetVector3Macro(SelectedControlPointLocation, double);
  vtkGetVector3Macro(SelectedControlPointLocation, double);
  ///@}

  ///@{
  /// Corner generators of LINEAR (corners 1, 2) and BILINEAR (1: (-u,-v), 2: (+u,-v), 3: (-u,+v),
  /// 4: (+u,+v)): direction (default (0,0,1)) and weight (defaults 0.5, -0.5, -0.5, 0.5).
  vtkSetVector3Macro(Corner1Direction, double);
  vtkGetVector3Macro(Corner1Direction, double);
  vtkSetVector3Macro(Corner2Direction, double);
  vtkGetVector3Macro(Corner2Direction, double);
  vtkSetVector3Macro(Corner3Direction, double);
  vtkGetVector3Macro(Corner3Direction, double);
  vtkSetVector3Macro(Corner4Direction, double);
  vtkGetVector3Macro(Corner4Direction, double);
  vtkSetVector4Macro(CornerWeights, double);
  vtkGetVector4Macro(CornerWeights, double);
  ///@}

  ///@{
  /// The radius of the clip sphere about Origin, where the output is cut (default 100).
  vtkSetClampMacro(ClipRadius, double, 1e-6, 1e12);
  vtkGetMacro(ClipRadius, double);
  ///@}

  ///@{
  /// SURFACE (default) or LINES (one polyline per u row).
  vtkSetClampMacro(OutputType, int, SURFACE, LINES);
  vtkGetMacro(OutputType, int);
  void SetOutputTypeToSurface() { this->SetOutputType(SURFACE); }
  void SetOutputTypeToLines() { this->SetOutputType(LINES); }
  ///@}

  ///@{
  /// SURFACE only: add the point arrays PrincipalCurvatures (k1 >= k2), PrincipalDirections (two
  /// unit 3-vectors), GaussianCurvature and MeanCurvature, computed from the exact first and
  /// second derivatives of the construction (not from the mesh), and output the exact normals
  /// from the same derivatives (without it the normals are the grid's central differences: the
  /// second-order derivatives through the exponential make the update about 13 times slower).
  /// A curvature is positive where the surface bends away from Normals (n = u x v: KappaU > 0
  /// reads positive); degenerate samples have zeros (and zero directions). Default off.
  vtkSetMacro(ComputeCurvatures, bool);
  vtkGetMacro(ComputeCurvatures, bool);
  vtkBooleanMacro(ComputeCurvatures, bool);
  ///@}

  ///@{
  /// 0 (default): no time. N >= 1: N time steps t in [0, 1] (vtkBoostedTimeSweep); at time t
  /// every curvature (KappaU, KappaV or the preset's, each control point's, the CornerWeights) is
  /// multiplied by t, so the patch bends from the flat plane to its curvatures as an animation
  /// plays.
  vtkSetClampMacro(NumberOfTimeSteps, int, 0, 100000);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

  ///@{
  /// vtkAlgorithm::SINGLE_PRECISION or DOUBLE_PRECISION (default) for the output points.
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DOUBLE_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

protected:
  vtkCurvaturePatchSource();
  ~vtkCurvaturePatchSource() override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Method = TRANSLATED_TANGENTS;
  int ExponentialRule = EXACT;
  double Origin[3] = { 0.0, 0.0, 0.0 };
  double UDirection[3] = { 1.0, 0.0, 0.0 };
  double VDirection[3] = { 0.0, 1.0, 0.0 };
  double Size[2] = { 4.0, 4.0 };
  int UResolution = 32;
  int VResolution = 32;
  double KappaU = 0.5;
  double KappaV = 0.5;
  int CurvaturePreset = CUSTOM;
  double Falloff = 1.0;
  double Epsilon = 0.5;
  std::unique_ptr<vtkBoostedRowList> ControlPoints;
  int SelectedControlPoint = -1;
  double SelectedControlPointLocation[3] = { 0.0, 0.0, 0.0 };
  double Corner1Direction[3] = { 0.0, 0.0, 1.0 };
  double Corner2Direction[3] = { 0.0, 0.0, 1.0 };
  double Corner3Direction[3] = { 0.0, 0.0, 1.0 };
  double Corner4Direction[3] = { 0.0, 0.0, 1.0 };
  double CornerWeights[4] = { 0.5, -0.5, -0.5, 0.5 };
  double ClipRadius = 100.0;
  int OutputType = SURFACE;
  int OutputPointsPrecision = DOUBLE_PRECISION;
  bool ComputeCurvatures = false;
  int NumberOfTimeSteps = 0;

private:
  /// The "Generators" output of the last update, which the next one shares while the control
  /// points, corners or curvatures it holds stay the same to the bit
  /// (vtkBoostedGeneratorGlyphs::Write with a cache).
  vtkSmartPointer<vtkPolyData> GeneratorGlyphs;

  vtkCurvaturePatchSource(const vtkCurvaturePatchSource&) = delete;
  void operator=(const vtkCurvaturePatchSource&) = delete;
};

#endif
