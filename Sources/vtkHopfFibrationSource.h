/**
 * @class   vtkHopfFibrationSource
 * @brief   the Hopf fibration of Colapinto 2014 section 4.1 (eq 11-14, Fig 4-5): one circle fiber
 *          per point (theta, phi) of the base 2-sphere
 *
 * The fiber over (theta, phi) (theta the longitude, phi the latitude in [-pi/2, pi/2]) is the image
 * of the base circle C (CircleCenter, CircleNormal, CircleRadius) under a versor KH(theta, phi)
 * (cga/surfaces/HopfFibration.h). phi = -pi/2 gives C itself, phi = +pi/2 its axis line, for every
 * theta.
 * - Mode PAPER: the paper's boost K = 1 + k no v_theta, k = 1/2 + phi/pi, followed by the twist
 *   M = exp(k/2 log(L / L_theta)) that screws the boosted line L_theta into C's axis L. A topological
 *   Hopf fibration (circles, pairwise disjoint and linked once), not the round one.
 * - Mode CLASSICAL: the stereographic projection of the Hopf fibration of S^3 (great circles
 *   e^{it}(z1, z2)), whose antipodal fibers commute.
 *
 * Base points (SamplingMode; cga/surfaces/HopfSampling.h):
 * - GRID: ThetaResolution longitudes theta0 + i (theta1 - theta0)/ThetaResolution, i = 0 ..
 *   ThetaResolution-1 (half-open: theta is periodic), times PhiResolution latitudes
 *   phi0 + j (phi1 - phi0)/(PhiResolution - 1), j = 0 .. PhiResolution-1 (closed; one sample: phi0).
 *   One theta sample is a meridian, one phi sample a latitude, sub-ranges a band. Fibers are ordered
 *   theta-major.
 * - BASE_POINTS: the (theta, phi) pairs given with AddBasePoint / SetBasePoint.
 * - INPUT_POINTS: the points of the optional input (any vtkPointSet, port 0): the direction
 *   d = p - SphereCenter gives theta = atan2(d.y, d.x) and phi = atan2(d.z, sqrt(d.x^2 + d.y^2)),
 *   so the points need not lie exactly on a sphere. The whole input is used on every rank.
 *
 * Output (OutputType):
 * - FIBERS: one closed polyline of FiberResolution points per fiber (cut where clipped), point
 *   arrays "theta", "phi", "FiberId" (the index of the base point).
 * - TWISTOR_MESH: the surface swept by the fibers (Fig 4d, Fig 5): with GRID and MeshSweep
 *   MERIDIANS one strip per theta sample through its phi samples; with LATITUDES one strip per phi
 *   sample through theta0 .. theta1 inclusive (closed when the range is a full turn); with
 *   BASE_POINTS or INPUT_POINTS one strip through the points in their order. Quads with "Normals",
 *   "TextureCoordinates", "theta", "phi", "FiberId" and "StripId".
 *
 * Clipping: fibers near phi = +pi/2 are huge and the north-pole fiber is a line. The output is cut
 * exactly at the clip sphere, radius ClipRadius about CircleCenter (vtkBoostedGridDriver); cut
 * quads become polygons of 3 to 6 points. Only samples at infinity drop their cells before the
 * cut.
 *
 * Output 1, "Generators" (vtkBoostedGeneratorGlyphs, for glyphs): one vertex per base point, in
 * the order of FiberId, on the base sphere drawn about C: CircleCenter + CircleRadius (cos phi
 * cos theta a + cos phi sin theta b + sin phi n) in C's frame (a, b, n as in
 * cga/surfaces/HopfFibration.h), with "Direction" the paper's unit boost direction
 * v_theta = cos theta a + sin theta b and "Weight" its k = 1/2 + phi/pi (both modes); on piece 0
 * only, empty after an error.
 *
 * Pieces: fibers (FIBERS) or rows of quads (TWISTOR_MESH) are divided among the requested pieces.
 *
 * Invalid parameters (zero normal, radius <= 0, NaN or infinite values, a resolution of 0, a
 * FiberResolution below 3, inverted ranges, phi outside [-pi/2, pi/2], INPUT_POINTS without an
 * input or with a NaN input point, a NaN ClipRadius, more than
 * vtkBoostedGridBuilder::MaximumSamples fibers x (FiberResolution + 1) points) produce an error
 * and an empty output.
 */
#ifndef vtkHopfFibrationSource_h
#define vtkHopfFibrationSource_h

#include "BoostedSurfacesSourcesModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for the Generators output's cache

#include <memory> // for the base point list

class vtkBoostedRowList;
class vtkPolyData;

class vtkPointSet;
namespace cga
{
struct HopfSampling;
}

class BOOSTEDSURFACESSOURCES_EXPORT vtkHopfFibrationSource : public vtkPolyDataAlgorithm
{
public:
  static vtkHopfFibrationSource* New();
  vtkTypeMacro(vtkHopfFibrationSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    PAPER = 0,
    CLASSICAL = 1
  };
  enum SamplingModes
  {
    GRID = 0,
    BASE_POINTS = 1,
    INPUT_POINTS = 2
  };
  enum OutputTypes
  {
    FIBERS = 0,
    TWISTOR_MESH = 1
  };
  enum MeshSweeps
  {
    MERIDIANS = 0,
    LATITUDES = 1
  };

  ///@{
  /// PAPER (default, eq 11-14) or CLASSICAL (stereographic S^3 Hopf fibration).
  vtkSetClampMacro(Mode, int, PAPER, CLASSICAL);
  vtkGetMacro(Mode, int);
  void SetModeToPaper() { this->SetMode(PAPER); }
  void SetModeToClassical() { this->SetMode(CLASSICAL); }
  ///@}

  ///@{
  /// The base circle (fiber over the south pole). Default: center (0,0,0), normal (0,0,1), radius 1.
  vtkSetVector3Macro(CircleCenter, double);
  vtkGetVector3Macro(CircleCenter, double);
  vtkSetVector3Macro(CircleNormal, double);
  vtkGetVector3Macro(CircleNormal, double);
  vtkSetMacro(CircleRadius, double);
  vtkGetMacro(CircleRadius, double);
  ///@}

  ///@{
  /// GRID (default), BASE_POINTS or INPUT_POINTS.
  vtkSetClampMacro(SamplingMode, int, GRID, INPUT_POINTS);
  vtkGetMacro(SamplingMode, int);
  void SetSamplingModeToGrid() { this->SetSamplingMode(GRID); }
  void SetSamplingModeToBasePoints() { this->SetSamplingMode(BASE_POINTS); }
  void SetSamplingModeToInputPoints() { this->SetSamplingMode(INPUT_POINTS); }
  ///@}

  ///@{
  /// GRID sampling: theta range (radians, default [0, 2 pi]) with ThetaResolution samples
  /// (half-open, default 8), phi range (radians within [-pi/2, pi/2], default the whole
  /// [-pi/2, pi/2]) with PhiResolution samples (closed, default 9). 0 is an error.
  vtkSetVector2Macro(ThetaRange, double);
  vtkGetVector2Macro(ThetaRange, double);
  vtkSetVector2Macro(PhiRange, double);
  vtkGetVector2Macro(PhiRange, double);
  vtkSetClampMacro(ThetaResolution, int, 0, 100000);
  vtkGetMacro(ThetaResolution, int);
  vtkSetClampMacro(PhiResolution, int, 0, 100000);
  vtkGetMacro(PhiResolution, int);
  ///@}

  ///@{
  /// BASE_POINTS sampling: the base point list, rows of (theta, phi) in radians, with the list
  /// API and the cap of vtkBoostedRowList (Common/): AddBasePoint returns the new row's index,
  /// SetBasePoint(i, ...) changes row i < GetNumberOfBasePoints(), SetNumberOfBasePoints resizes
  /// (new rows are (0, 0)), GetBasePoint copies a row (false if there is none); at most 10^6 rows
  /// (more come through the input, INPUT_POINTS).
  int AddBasePoint(double theta, double phi);
  void SetBasePoint(int index, double theta, double phi);
  void SetNumberOfBasePoints(int count);
  bool GetBasePoint(int index, double values[2]) const;
  void RemoveAllBasePoints();
  int GetNumberOfBasePoints() const;
  ///@}

  ///@{
  /// INPUT_POINTS sampling: the center from which input point directions are taken. Default origin.
  vtkSetVector3Macro(SphereCenter, double);
  vtkGetVector3Macro(SphereCenter, double);
  ///@}

  ///@{
  /// Points per fiber (default 128, at least 3).
  vtkSetClampMacro(FiberResolution, int, 0, 1000000);
  vtkGetMacro(FiberResolution, int);
  ///@}

  ///@{
  /// The radius of the clip sphere about CircleCenter, where the output is cut. Default 10.
  vtkSetClampMacro(ClipRadius, double, 1e-6, 1e12);
  vtkGetMacro(ClipRadius, double);
  ///@}

  ///@{
  /// FIBERS (default) or TWISTOR_MESH; MeshSweep MERIDIANS (default) or LATITUDES.
  vtkSetClampMacro(OutputType, int, FIBERS, TWISTOR_MESH);
  vtkGetMacro(OutputType, int);
  void SetOutputTypeToFibers() { this->SetOutputType(FIBERS); }
  void SetOutputTypeToTwistorMesh() { this->SetOutputType(TWISTOR_MESH); }
  vtkSetClampMacro(MeshSweep, int, MERIDIANS, LATITUDES);
  vtkGetMacro(MeshSweep, int);
  void SetMeshSweepToMeridians() { this->SetMeshSweep(MERIDIANS); }
  void SetMeshSweepToLatitudes() { this->SetMeshSweep(LATITUDES); }
  ///@}

  ///@{
  /// TWISTOR_MESH only: the mesh shares the points of its closed directions instead of repeating
  /// them (vtkBoostedGridBuilder::SetMergeSeam): each fiber's seam, a latitude strip's closing
  /// fiber over a full turn of ThetaRange, and a strip's repeated fibers (a latitude strip at a
  /// pole, where every fiber is the same, has no area: no cells, no points), so Latitudes tori come out
  /// closed and manifold (watertight exports). TextureCoordinates are then left out. Default off.
  vtkSetMacro(MergeSeam, bool);
  vtkGetMacro(MergeSeam, bool);
  vtkBooleanMacro(MergeSeam, bool);
  ///@}

  ///@{
  /// 0 (default): no time. N >= 1: N time steps t in [0, 1] (vtkBoostedTimeSweep); with GRID
  /// sampling the latitudes at time t are [PhiRange[0], PhiRange[0] + t (PhiRange[1] -
  /// PhiRange[0])], so as an animation plays k = 1/2 + phi/pi grows and the last fiber
  /// straightens from the circle C into the axis line (Fig 4) while a Meridians mesh grows
  /// behind it. Base points and input points have no sweep: time leaves them unchanged.
  vtkSetClampMacro(NumberOfTimeSteps, int, 0, 100000);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

  ///@{
  /// vtkAlgorithm::SINGLE_PRECISION or DOUBLE_PRECISION (default) for the output points.
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DOUBLE_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

protected:
  vtkHopfFibrationSource();
  ~vtkHopfFibrationSource() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// The base points' parameters for the core (cga::HopfSampling); `input` may be null.
  cga::HopfSampling Sampling(vtkPointSet* input) const;

  int Mode = PAPER;
  double CircleCenter[3] = { 0.0, 0.0, 0.0 };
  double CircleNormal[3] = { 0.0, 0.0, 1.0 };
  double CircleRadius = 1.0;
  int SamplingMode = GRID;
  double ThetaRange[2] = { 0.0, 6.283185307179586 };
  double PhiRange[2] = { -1.5707963267948966, 1.5707963267948966 };
  int ThetaResolution = 8;
  int PhiResolution = 9;
  std::unique_ptr<vtkBoostedRowList> BasePoints;
  double SphereCenter[3] = { 0.0, 0.0, 0.0 };
  int FiberResolution = 128;
  double ClipRadius = 10.0;
  int OutputType = FIBERS;
  int MeshSweep = MERIDIANS;
  int OutputPointsPrecision = DOUBLE_PRECISION;
  bool MergeSeam = false;
  int NumberOfTimeSteps = 0;

private:
  /// The "Generators" output of the last update, which the next one shares while the base points it
  /// holds stay the same to the bit (vtkBoostedGeneratorGlyphs::Write with a cache).
  vtkSmartPointer<vtkPolyData> GeneratorGlyphs;

  vtkHopfFibrationSource(const vtkHopfFibrationSource&) = delete;
  void operator=(const vtkHopfFibrationSource&) = delete;
};

#endif
