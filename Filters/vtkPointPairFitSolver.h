// One least-squares fit of vtkPointPairFitFilter (internal, not wrapped): the generators' unknowns
// that bring a mesh closest to a target, by Ceres Solver's Levenberg-Marquardt with the analytic
// Jacobian (cga::mapWithGeneratorDerivatives). The filter validates its inputs, fills a
// vtkPointPairFitProblem once and calls Solve once, or once per kind it tries (FitKinds).
#ifndef vtkPointPairFitSolver_h
#define vtkPointPairFitSolver_h

#include "vtkType.h"

#include "cga/GeneratorDerivatives.h"
#include "cga/PointPairField.h"

#include <string>
#include <vector>

class vtkAlgorithm;
class vtkStaticCellLocator;

/// What stays the same for every fit of one update: the mesh, the target, the deformation, the
/// unknowns, their bounds and the solver's stops (the filter's properties; see its header).
struct vtkPointPairFitProblem
{
  vtkAlgorithm* Filter = nullptr; // progress and abort
  std::vector<double> Points;     // the mesh, xyz interleaved
  std::vector<double> Targets;    // POINT_TO_POINT: the target's points, in the mesh's order
  vtkStaticCellLocator* Locator = nullptr; // POINT_TO_SURFACE: over the target's cells
  std::vector<double> Scales;     // sqrt(omega_p / sum omega)
  bool Surface = false;
  double Falloff = 1.0, Epsilon = 0.01, Strength = 1.0;
  cga::ExponentialRule Rule = cga::ExponentialRule::Exact;
  cga::FittedParameters Fitted;
  double WeightRange[2] = { -1000.0, 1000.0 };
  double LocationChange = 0.0;  // a length: MaximumLocationChange times the mesh's diagonal
  double DirectionChange = 0.0; // a fraction of each initial direction's length
  double PitchChange = 0.0;     // a length per radian: MaximumPitchChange times the diagonal
  double RegularizationWeight = 0.0;
  int MaximumNumberOfIterations = 100;
  double FunctionTolerance = 1e-12, GradientTolerance = 1e-14, ParameterTolerance = 1e-12;

  vtkIdType count() const { return static_cast<vtkIdType>(this->Points.size() / 3); }
};

/// The outcome of one fit.
struct vtkPointPairFitResult
{
  std::vector<cga::GeneratorParameters> Generators; // the fitted ones (the first point if none better)
  double InitialData = 0.0; // the squared weighted RMS residual at the first point
  double FinalData = 0.0;   // ... at the fitted generators
  double Cost = 0.0;        // FinalData plus the regularization: what the fit minimized
  int Iterations = 0;
  std::string Termination;  // Ceres's termination type and message
  bool Improved = false;    // Cost below InitialData (then Generators are the fit's)
};

namespace vtkPointPairFitSolver
{
/// The largest coordinate magnitude of the target and of the images in POINT_TO_SURFACE mode:
/// VTK's closest-point queries evaluate each cell with products of up to four coordinate
/// differences (a triangle's normal normalized, a tetrahedron's or hexahedron's determinants),
/// which overflow beyond about 1e76 and then reach branches VTK asserts are dead (the fuzz: a
/// tetrahedron with a vertex at 1e150 aborted in vtkTriangle::EvaluatePosition).
constexpr double LargestSurfaceCoordinate = 1e75;

/// Fits the unknowns of `start` (their bounds and the regularization's theta_0), beginning at
/// `first` (the same kinds and count; within the bounds), reporting progress in [progressBegin,
/// progressEnd] of the filter's. False with `problem` empty after an abort, with `problem` set
/// when the first point is not valid (a point sent to infinity) or Ceres fails.
bool Solve(const vtkPointPairFitProblem& problem,
  const std::vector<cga::GeneratorParameters>& start,
  const std::vector<cga::GeneratorParameters>& first, double progressBegin, double progressEnd,
  vtkPointPairFitResult& result, std::string& error);

constexpr int MaximumKindSweeps = 4;
constexpr int KindCount = 5;

/// The most fits SearchKinds runs for `generators` generators (MaximumKindSweeps sweeps of
/// KindCount - 1 kinds each, after the first fit).
constexpr double MaximumKindFits(double generators)
{
  return 1.0 + MaximumKindSweeps * (KindCount - 1) * generators;
}

/// The bound of SearchKinds' work that MaximumKindSearchWork limits: every fit at its most
/// iterations (each an evaluation, plus the start's) of every point by every generator.
inline double KindSearchWork(double generators, double points, int maximumIterations)
{
  return MaximumKindFits(generators) * (maximumIterations + 1.0) * points * generators;
}

/// The kinds search of FitKinds, a greedy coordinate search over the discrete kinds: fit `start`
/// as it is; then, generator by generator, fit every kind other than the one it has when its turn
/// begins in its place (that generator's unknowns restarted from its initial values, the others
/// from the best fit so far) and keep a kind whose converged cost is lower than the best by more
/// than `separation` times the initial data cost (a Rotation also replaces a Twist whose cost it
/// matches within that margin: the twist with its pitch contains it); sweep again until a sweep changes no kind, at most
/// MaximumKindSweeps sweeps. `identified[g]` is true when in the last sweep every other kind of
/// generator g cost more than the best by more than the margin (the Twist's cost is not counted
/// against a Rotation). `result` is the best fit (Improved: below the initial data cost), its
/// Iterations the sum over every fit run, `fits` their number. False as Solve is, for the first
/// fit; a candidate kind that cannot be evaluated (a point sent to infinity) counts as
/// infinitely costly.
bool SearchKinds(const vtkPointPairFitProblem& problem,
  const std::vector<cga::GeneratorParameters>& start, double separation,
  vtkPointPairFitResult& result, std::vector<bool>& identified, int& fits, std::string& error);
}

#endif
