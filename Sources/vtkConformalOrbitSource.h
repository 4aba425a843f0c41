/**
 * @class   vtkConformalOrbitSource
 * @brief   orbits of points under the one-parameter group exp(t B) of a conformal bivector B, and
 *          torus knots (docs/conventions.md section 3 item 13)
 *
 * Every seed point p gives one polyline, its orbit fn(exp(t B) up(p) exp(-t B)) sampled at
 * TResolution + 1 values of t. exp(t B) is evaluated in closed form at every t through the
 * invariant decomposition B = B1 + B2 into commuting 2-blades (cga::Orbit), never by steps.
 *
 * B (GeneratorType):
 * - GENERATOR_LIST: B = -sum_i w_i G_i over the rows of the generator list, the deformation
 *   filter's rows (location, direction, weight, kind, pitch: a point pair, rotation, twist,
 *   dilation or translation; the direction's length multiplies the weight), so that exp(t B) is
 *   the filter's K = exp(-Strength B(p)) at Strength t without falloff (Falloff 0, Epsilon 1): a
 *   ROTATION row of weight w turns by the angle t w |v|, right-handed. Rows with a zero direction
 *   or weight add nothing (one warning).
 * - TORUS_KNOT (default): B = (pi/KnotP) A* + (pi/KnotQ) C*, A* and C* the unit duals of two
 *   round circles A and C of radius KnotRadius that are orthogonal and linked once (cga::TorusKnot:
 *   A's center KnotCenter - (r/sqrt 2) u with normal KnotNormal, C's center
 *   KnotCenter + (r/sqrt 2) u in the plane of u and KnotNormal, u = KnotDirection made orthogonal
 *   to KnotNormal). The orbit of a generic point is the (P, Q) torus knot: period lcm(P, Q),
 *   linking number Q with A and P with C. P and Q with a common divisor g give a warning: the
 *   orbit is the (P/g, Q/g) knot, and over t in [0, P Q] it would be traced g times.
 *
 * Seeds (SeedMode): SEED_POINT, the one point SeedPoint (default; (0.15, 0, 0), on a torus about
 * the default knot's circle A); SEED_LIST, the rows of the seed list (AddSeed, the list API of
 * vtkBoostedRowList); INPUT_POINTS, the points of the optional input (any vtkPointSet, read whole
 * on every rank).
 *
 * t: when ClosePeriodicOrbits is on (default) and exp(t B) has a period T (cga::Orbit::period:
 * every part a rotation, rates in a rational ratio), t runs over [TRange[0], TRange[0] + T) and
 * every orbit is a closed polyline; otherwise over TRange, both ends included.
 *
 * Time (NumberOfTimeSteps, vtkBoostedTimeSweep): at time s the upper end of t grows to
 * t0 + s (t1 - t0), t1 = TRange[1] or t0 + T: a periodic orbit is the open arc over that range and
 * closes only at s = 1, the static output.
 *
 * Far from the origin: B is built about a center c (KnotCenter, or the mean location of the rows
 * that count), the seeds are moved by -c and the orbits and cores by +c, so moving the whole
 * configuration (seeds, rows, KnotCenter, ClipCenter) by t moves the outputs by t to a few eps |t|.
 *
 * Output 0: the orbits, one polyline per seed, cut exactly at the clip sphere (ClipRadius about
 * ClipCenter) and where samples go to infinity; point arrays "t" and "OrbitId" (the seed's index),
 * field array "Period" (T, or 0 when exp(t B) is not periodic). The seeds are divided among the
 * requested pieces (each orbit whole on one rank). B = 0 is the identity: a warning, and each
 * orbit is its seed as a vertex.
 * Output 1: the cores, the circle (or line, cut at the clip sphere) about which each rotating part
 * of B turns, CoreResolution points each, point array "CoreId" (the part: 0 for A, 1 for C with
 * TORUS_KNOT); on piece 0 only.
 * Output 2: the generators (vtkBoostedGeneratorGlyphs), on piece 0 only: with GENERATOR_LIST one
 * vertex per row at its location, point arrays "Direction", "Weight", "Kind" and "Pitch" (the
 * row's values); with TORUS_KNOT the two core circles A and C, each a vertex at its center with
 * its unit normal as "Direction" and its rate pi/P or pi/Q as "Weight".
 *
 * Invalid parameters (non-finite values, a zero or parallel knot direction, KnotRadius <= 0,
 * KnotP or KnotQ 0, min t > max t, a non-finite or too large B, a refused list, INPUT_POINTS
 * without an input, a non-finite seed, more than vtkBoostedGridBuilder::MaximumSamples samples or
 * more memory than the budget, single-precision points of either output beyond the largest float,
 * vtkBoostedSinglePrecision.h) give a vtkErrorMacro message and empty outputs.
 */
#ifndef vtkConformalOrbitSource_h
#define vtkConformalOrbitSource_h

#include "BoostedSurfacesSourcesModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for the Generators output's cache

#include <memory> // for the lists

class vtkBoostedRowList;
class vtkPolyData;
class vtkPointSet;

class BOOSTEDSURFACESSOURCES_EXPORT vtkConformalOrbitSource : public vtkPolyDataAlgorithm
{
public:
  static vtkConformalOrbitSource* New();
  vtkTypeMacro(vtkConformalOrbitSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum GeneratorTypes
  {
    GENERATOR_LIST = 0,
    TORUS_KNOT = 1
  };
  enum SeedModes
  {
    SEED_POINT = 0,
    SEED_LIST = 1,
    INPUT_POINTS = 2
  };

  ///@{
  /// GENERATOR_LIST or TORUS_KNOT (default).
  vtkSetClampMacro(GeneratorType, int, GENERATOR_LIST, TORUS_KNOT);
  vtkGetMacro(GeneratorType, int);
  void SetGeneratorTypeToGeneratorList() { this->SetGeneratorType(GENERATOR_LIST); }
  void SetGeneratorTypeToTorusKnot() { this->SetGeneratorType(TORUS_KNOT); }
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
  /// GENERATOR_LIST: rows of location, direction, weight, kind (GeneratorKinds) and pitch (TWIST
  /// only), as the deformation filter's (vtkBoostedGeneratorRows); the forms without kind and
  /// pitch give a POINT_PAIR. The list API of vtkBoostedRowList (at most 10^6 rows); GetGenerator
  /// copies 9 values. Empty by default.
  int AddGenerator(double x, double y, double z, double dx, double dy, double dz, double weight);
  int AddGenerator(double x, double y, double z, double dx, double dy, double dz, double weight,
    double kind, double pitch);
  void SetGenerator(
    int index, double x, double y, double z, double dx, double dy, double dz, double weight);
  void SetGenerator(int index, double x, double y, double z, double dx, double dy, double dz,
    double weight, double kind, double pitch);
  void SetNumberOfGenerators(int count);
  bool GetGenerator(int index, double values[9]) const;
  void RemoveAllGenerators();
  int GetNumberOfGenerators() const;
  ///@}

  ///@{
  /// GENERATOR_LIST: one row aimed and moved by itself (ParaView's line widget from its location to
  /// its tip), as the deformation filter's: when SelectedGenerator is a valid row index, that row
  /// is at SelectedGeneratorLocation and, when AimSelectedGenerator is on, its direction is
  /// SelectedGeneratorTip - SelectedGeneratorLocation (its length multiplies the weight). -1 (the
  /// default) selects none; defaults location (0, 0, 0), aim off, tip (0, 0, 1). A non-finite
  /// location or (aimed) tip of the selected row is an error, as a non-finite row value.
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
  /// TORUS_KNOT: the integers P and Q (1 to 1000; 0 is an error), default (2, 3).
  vtkSetClampMacro(KnotP, int, 0, 1000);
  vtkGetMacro(KnotP, int);
  vtkSetClampMacro(KnotQ, int, 0, 1000);
  vtkGetMacro(KnotQ, int);
  ///@}

  ///@{
  /// TORUS_KNOT: the two core circles' midpoint (default origin), the normal of A's plane
  /// (default z), the direction from A's center to C's (default x; not parallel to the normal)
  /// and their radius (default 1).
  vtkSetVector3Macro(KnotCenter, double);
  vtkGetVector3Macro(KnotCenter, double);
  vtkSetVector3Macro(KnotNormal, double);
  vtkGetVector3Macro(KnotNormal, double);
  vtkSetVector3Macro(KnotDirection, double);
  vtkGetVector3Macro(KnotDirection, double);
  vtkSetMacro(KnotRadius, double);
  vtkGetMacro(KnotRadius, double);
  ///@}

  ///@{
  /// SEED_POINT (default), SEED_LIST or INPUT_POINTS.
  vtkSetClampMacro(SeedMode, int, SEED_POINT, INPUT_POINTS);
  vtkGetMacro(SeedMode, int);
  void SetSeedModeToSeedPoint() { this->SetSeedMode(SEED_POINT); }
  void SetSeedModeToSeedList() { this->SetSeedMode(SEED_LIST); }
  void SetSeedModeToInputPoints() { this->SetSeedMode(INPUT_POINTS); }
  ///@}

  ///@{
  /// SEED_POINT: the one seed (default (0.15, 0, 0)).
  vtkSetVector3Macro(SeedPoint, double);
  vtkGetVector3Macro(SeedPoint, double);
  ///@}

  ///@{
  /// SEED_LIST: rows (x, y, z), the list API of vtkBoostedRowList (at most 10^6 rows; more come
  /// through the input).
  int AddSeed(double x, double y, double z);
  void SetSeed(int index, double x, double y, double z);
  void SetNumberOfSeeds(int count);
  bool GetSeed(int index, double values[3]) const;
  void RemoveAllSeeds();
  int GetNumberOfSeeds() const;
  ///@}

  ///@{
  /// The range of t (default [0, 1]; min <= max) and the number of intervals along it (default
  /// 512, 1 ... 1000000). With a period and ClosePeriodicOrbits, only TRange[0] is used.
  vtkSetVector2Macro(TRange, double);
  vtkGetVector2Macro(TRange, double);
  vtkSetClampMacro(TResolution, int, 1, 1000000);
  vtkGetMacro(TResolution, int);
  vtkSetMacro(ClosePeriodicOrbits, vtkTypeBool);
  vtkGetMacro(ClosePeriodicOrbits, vtkTypeBool);
  vtkBooleanMacro(ClosePeriodicOrbits, vtkTypeBool);
  ///@}

  ///@{
  /// Points per core circle on output 1 (default 256, 3 ... 100000).
  vtkSetClampMacro(CoreResolution, int, 3, 100000);
  vtkGetMacro(CoreResolution, int);
  ///@}

  ///@{
  /// The clip sphere (default radius 100 about the origin): the orbits and cores are cut exactly
  /// on it.
  vtkSetVector3Macro(ClipCenter, double);
  vtkGetVector3Macro(ClipCenter, double);
  vtkSetClampMacro(ClipRadius, double, 1e-6, 1e12);
  vtkGetMacro(ClipRadius, double);
  ///@}

  ///@{
  /// vtkAlgorithm::SINGLE_PRECISION or DOUBLE_PRECISION (default) for the output points.
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DOUBLE_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

  ///@{
  /// 0 (default): no time. N >= 1: N time steps s in [0, 1] (vtkBoostedTimeSweep); at time s
  /// t runs over [t0, t0 + s (t1 - t0)] (see the class description), the last frame the static
  /// output.
  vtkSetClampMacro(NumberOfTimeSteps, int, 0, 100000);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

protected:
  vtkConformalOrbitSource();
  ~vtkConformalOrbitSource() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int GeneratorType = TORUS_KNOT;
  std::unique_ptr<vtkBoostedRowList> Generators;
  int SelectedGenerator = -1;
  double SelectedGeneratorLocation[3] = { 0.0, 0.0, 0.0 };
  bool AimSelectedGenerator = false;
  double SelectedGeneratorTip[3] = { 0.0, 0.0, 1.0 };
  int KnotP = 2;
  int KnotQ = 3;
  double KnotCenter[3] = { 0.0, 0.0, 0.0 };
  double KnotNormal[3] = { 0.0, 0.0, 1.0 };
  double KnotDirection[3] = { 1.0, 0.0, 0.0 };
  double KnotRadius = 1.0;
  int SeedMode = SEED_POINT;
  double SeedPoint[3] = { 0.15, 0.0, 0.0 };
  std::unique_ptr<vtkBoostedRowList> Seeds;
  double TRange[2] = { 0.0, 1.0 };
  int TResolution = 512;
  vtkTypeBool ClosePeriodicOrbits = 1;
  int CoreResolution = 256;
  double ClipCenter[3] = { 0.0, 0.0, 0.0 };
  double ClipRadius = 100.0;
  int OutputPointsPrecision = DOUBLE_PRECISION;
  int NumberOfTimeSteps = 0;

private:
  /// Both outputs get the requested time (vtkBoostedTimeSweep::StampTime).
  void StampTime(vtkInformationVector* outputVector);

  /// The "Generators" output of the last update, which the next one shares while the generators
  /// (rows or core circles) it holds stay the same to the bit (vtkBoostedGeneratorGlyphs::Write
  /// with a cache).
  vtkSmartPointer<vtkPolyData> GeneratorGlyphs;

  vtkConformalOrbitSource(const vtkConformalOrbitSource&) = delete;
  void operator=(const vtkConformalOrbitSource&) = delete;
};

#endif
