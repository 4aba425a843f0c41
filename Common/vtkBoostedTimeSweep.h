/**
 * @class   vtkBoostedTimeSweep
 * @brief   the one way the project's classes report time steps and read the requested time
 *
 * Every class that animates its natural sweep (the dipole's weights, the boosted surface's
 * lambda, the Hopf construction's phi, the curvature patch's curvatures, the deformation's
 * Strength) has the property NumberOfTimeSteps, 0 (no time) by default. With N >= 1 it reports
 * N time steps t_k = k / (N - 1) in [0, 1] (t = 1 for N = 1) as TIME_STEPS and TIME_RANGE, and
 * its RequestData reads the requested t as the fraction of the sweep to show: t = 0 is the
 * sweep's start, t = 1 the class's current parameter values, so the last frame equals the static
 * output. A requested time outside [0, 1] is clamped; without time steps, without a request, or
 * for a NaN request the fraction is 1 (the static output).
 */
#ifndef vtkBoostedTimeSweep_h
#define vtkBoostedTimeSweep_h

#include "BoostedSurfacesCommonModule.h" // for export macro

class vtkDataObject;
class vtkInformation;
class vtkInformationVector;

class BOOSTEDSURFACESCOMMON_EXPORT vtkBoostedTimeSweep
{
public:
  /// The largest NumberOfTimeSteps (the setters clamp to [0, MaximumNumberOfTimeSteps]).
  static constexpr int MaximumNumberOfTimeSteps = 100000;

  /// RequestInformation: sets TIME_STEPS and TIME_RANGE on `outInfo` for N >= 1, removes them
  /// for N = 0 (a class that stops animating forgets its steps).
  static void ReportTimeSteps(vtkInformation* outInfo, int numberOfTimeSteps);

  /// The sources' RequestInformation: ReportTimeSteps on every output port and, for a source
  /// that divides its output into pieces (`pieces`), CAN_HANDLE_PIECE_REQUEST on each.
  static void ReportOnEveryPort(
    vtkInformationVector* outputVector, int numberOfTimeSteps, bool pieces);

  /// RequestData: the fraction of the sweep in [0, 1] for the time requested on `outInfo`.
  static double Fraction(vtkInformation* outInfo, int numberOfTimeSteps);

  /// The end of RequestData: stamps the requested time on `output` as DATA_TIME_STEP when the
  /// class animates (after the output is built: a shallow copy would replace its information).
  static void StampTime(vtkInformation* outInfo, int numberOfTimeSteps, vtkDataObject* output);

  /// start + fraction (end - start), written so that fraction 0 gives exactly start and 1
  /// exactly end (the static output's parameter).
  static double Interpolate(double start, double end, double fraction)
  {
    return fraction == 1.0 ? end : (1.0 - fraction) * start + fraction * end;
  }
};

#endif
