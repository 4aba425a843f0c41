/**
 * @class   vtkBoostedSurfaceSource
 * @brief   a circle swept by a family of boosts: the surfaces of Colapinto 2014, Fig 1-3
 *
 * A circle (center, normal, radius) is transformed by the boosts K(lambda) = exp(lambda tau) =
 * 1 + lambda tau, where tau = tau(BoostLocation, BoostDirection) is a null point pair: the tangent
 * no ^ BoostDirection translated to BoostLocation (docs/conventions.md section 1). The length of
 * BoostDirection is the generator's weight. Each lambda of LambdaRange gives one image circle;
 * together they make a surface.
 *
 * - Fig 1: circle in the xy plane, BoostDirection along x (in the circle's plane).
 * - Fig 2 (the defaults): circle in the yz plane, BoostDirection along x (the normal).
 * - Fig 3 (horn): BoostDirection along the circle's axis, BoostLocation on the axis.
 *
 * A boost sends one point, BoostLocation - BoostDirection / (lambda |BoostDirection|^2), to
 * infinity; a circle through that point becomes a line (Fig 1 at lambda = +-1). The output never
 * contains infinite or huge points: it is cut exactly at the clip sphere, radius ClipRadius about
 * the circle's center (vtkBoostedGridDriver), so the circles and the surface end on that sphere.
 *
 * Output (OutputType):
 * - SURFACE: quads, with point normals, texture coordinates (u along the circle, v along lambda)
 *   and the point arrays "lambda" and "theta". The normals are exact: the unit normal
 *   x_theta x x_lambda of the surface's closed-form derivatives (cga::BoostedCircleRow), except
 *   at degenerate samples (x_theta parallel to x_lambda), which get central differences of the
 *   grid. With ComputeCurvatures also "PrincipalCurvatures", "PrincipalDirections",
 *   "GaussianCurvature" and "MeanCurvature" (vtkBoostedCurvatureArrays).
 * - CIRCLES: one closed polyline per lambda (split where clipped), with "lambda" and "theta".
 *
 * Pieces: the lambda rows are divided among the requested pieces, so each MPI rank generates its
 * own band. Neighbouring bands repeat their shared row of points; cells are never repeated.
 *
 * Invalid parameters (a zero normal or direction, a radius <= 0, NaN or infinite values, or a
 * lambda range whose minimum exceeds its maximum) produce an error and an empty output.
 */
#ifndef vtkBoostedSurfaceSource_h
#define vtkBoostedSurfaceSource_h

#include "BoostedSurfacesSourcesModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"

class BOOSTEDSURFACESSOURCES_EXPORT vtkBoostedSurfaceSource : public vtkPolyDataAlgorithm
{
public:
  static vtkBoostedSurfaceSource* New();
  vtkTypeMacro(vtkBoostedSurfaceSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum OutputTypes
  {
    SURFACE = 0,
    CIRCLES = 1
  };

  ///@{
  /// The circle that is boosted. Default: center (0,0,0), normal (1,0,0) (the yz plane), radius 1.
  vtkSetVector3Macro(CircleCenter, double);
  vtkGetVector3Macro(CircleCenter, double);
  vtkSetVector3Macro(CircleNormal, double);
  vtkGetVector3Macro(CircleNormal, double);
  vtkSetMacro(CircleRadius, double);
  vtkGetMacro(CircleRadius, double);
  ///@}

  ///@{
  /// Direction of the tangent generator; its length is the weight. Default (1,0,0).
  vtkSetVector3Macro(BoostDirection, double);
  vtkGetVector3Macro(BoostDirection, double);
  ///@}

  ///@{
  /// Where the tangent is translated to (the boost's fixed point). Used only when
  /// BoostAtCircleCenter is off; otherwise the circle's center is used. Default (0,0,0).
  vtkSetVector3Macro(BoostLocation, double);
  vtkGetVector3Macro(BoostLocation, double);
  vtkSetMacro(BoostAtCircleCenter, bool);
  vtkGetMacro(BoostAtCircleCenter, bool);
  vtkBooleanMacro(BoostAtCircleCenter, bool);
  ///@}

  ///@{
  /// The range of the boost parameter lambda. Default [0, 2]. The minimum must not exceed the
  /// maximum; equal values give a single circle.
  vtkSetVector2Macro(LambdaRange, double);
  vtkGetVector2Macro(LambdaRange, double);
  ///@}

  ///@{
  /// Number of intervals along lambda (rows of quads) and around the circle. Defaults 64 and 64.
  /// More than vtkBoostedGridBuilder::MaximumSamples samples (both + 1, multiplied) is an error.
  vtkSetClampMacro(LambdaResolution, int, 1, 100000);
  vtkGetMacro(LambdaResolution, int);
  vtkSetClampMacro(ThetaResolution, int, 3, 100000);
  vtkGetMacro(ThetaResolution, int);
  ///@}

  ///@{
  /// The radius of the clip sphere about the circle's center, where the output is cut. Default 20.
  vtkSetClampMacro(ClipRadius, double, 1e-6, 1e12);
  vtkGetMacro(ClipRadius, double);
  ///@}

  ///@{
  /// SURFACE (default) or CIRCLES.
  vtkSetClampMacro(OutputType, int, SURFACE, CIRCLES);
  vtkGetMacro(OutputType, int);
  void SetOutputTypeToSurface() { this->SetOutputType(SURFACE); }
  void SetOutputTypeToCircles() { this->SetOutputType(CIRCLES); }
  ///@}

  ///@{
  /// SURFACE only: the seam column shares the points of the first column instead of repeating
  /// them, so the surface is closed around the circle and manifold (watertight exports); the
  /// TextureCoordinates are then left out (a seam point would need u = 0 and 1). Default off.
  vtkSetMacro(MergeSeam, bool);
  vtkGetMacro(MergeSeam, bool);
  vtkBooleanMacro(MergeSeam, bool);
  ///@}

  ///@{
  /// SURFACE only: add the point arrays PrincipalCurvatures (k1 >= k2), PrincipalDirections (two
  /// unit 3-vectors), GaussianCurvature and MeanCurvature, computed from the surface's exact first
  /// and second derivatives (not from the mesh). A curvature is positive where the surface bends
  /// away from Normals; degenerate samples have zeros (and zero directions). Default off.
  vtkSetMacro(ComputeCurvatures, bool);
  vtkGetMacro(ComputeCurvatures, bool);
  vtkBooleanMacro(ComputeCurvatures, bool);
  ///@}

  ///@{
  /// 0 (default): no time. N >= 1: N time steps t in [0, 1] (vtkBoostedTimeSweep); at time t the
  /// swept range is [LambdaRange[0], LambdaRange[0] + t (LambdaRange[1] - LambdaRange[0])], so the
  /// surface grows from its first circle to the whole LambdaRange as an animation plays.
  vtkSetClampMacro(NumberOfTimeSteps, int, 0, 100000);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

  ///@{
  /// vtkAlgorithm::SINGLE_PRECISION or DOUBLE_PRECISION (default) for the output points.
  vtkSetClampMacro(OutputPointsPrecision, int, SINGLE_PRECISION, DOUBLE_PRECISION);
  vtkGetMacro(OutputPointsPrecision, int);
  ///@}

protected:
  vtkBoostedSurfaceSource();
  ~vtkBoostedSurfaceSource() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double CircleCenter[3] = { 0.0, 0.0, 0.0 };
  double CircleNormal[3] = { 1.0, 0.0, 0.0 };
  double CircleRadius = 1.0;
  double BoostDirection[3] = { 1.0, 0.0, 0.0 };
  double BoostLocation[3] = { 0.0, 0.0, 0.0 };
  bool BoostAtCircleCenter = true;
  double LambdaRange[2] = { 0.0, 2.0 };
  int LambdaResolution = 64;
  int ThetaResolution = 64;
  double ClipRadius = 20.0;
  int OutputType = SURFACE;
  int OutputPointsPrecision = DOUBLE_PRECISION;
  bool MergeSeam = false;
  bool ComputeCurvatures = false;
  int NumberOfTimeSteps = 0;

private:
  vtkBoostedSurfaceSource(const vtkBoostedSurfaceSource&) = delete;
  void operator=(const vtkBoostedSurfaceSource&) = delete;
};

#endif
