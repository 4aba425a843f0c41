#include "vtkPointPairFitSolver.h"

#include "vtkAlgorithm.h"
#include "vtkBoostedSurfacesAbort.h"
#include "vtkGenericCell.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkStaticCellLocator.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <sstream>

namespace
{
// The unknowns of generator g start at theta[g * perGenerator]: its weight, location, direction
// and pitch as far as they are fitted (cga::FittedParameters' order).
void applyUnknowns(const std::vector<cga::GeneratorParameters>& start, cga::FittedParameters fitted,
  const double* theta, std::vector<cga::GeneratorParameters>& out)
{
  out = start;
  const int per = fitted.perGenerator();
  for (std::size_t g = 0; g < start.size(); ++g)
  {
    const double* t = theta + g * per;
    if (fitted.weight)
    {
      out[g].weight = *t++;
    }
    if (fitted.location)
    {
      out[g].location = { t[0], t[1], t[2] };
      t += 3;
    }
    if (fitted.direction)
    {
      out[g].direction = { t[0], t[1], t[2] };
      t += 3;
    }
    if (fitted.pitch)
    {
      out[g].pitch = *t;
    }
  }
}

std::vector<double> unknownsOf(
  const std::vector<cga::GeneratorParameters>& generators, cga::FittedParameters fitted)
{
  std::vector<double> theta;
  for (const cga::GeneratorParameters& g : generators)
  {
    if (fitted.weight)
    {
      theta.push_back(g.weight);
    }
    if (fitted.location)
    {
      theta.insert(theta.end(), { g.location.x, g.location.y, g.location.z });
    }
    if (fitted.direction)
    {
      theta.insert(theta.end(), { g.direction.x, g.direction.y, g.direction.z });
    }
    if (fitted.pitch)
    {
      theta.push_back(g.pitch);
    }
  }
  return theta;
}

// The data term of one fit, evaluated once per point of the unknowns for every residual block
// (Ceres's EvaluationCallback): the field of the current generators maps every mesh point with its
// derivatives; the residuals (sqrt(omega_p / sum omega) times p' - t_p, or times the distance of p'
// to the target's cells) and their Jacobian rows are cached for the blocks to copy.
struct FitData
{
  const vtkPointPairFitProblem& Problem;
  std::vector<cga::GeneratorParameters> Start; // the kinds, and the parameters not fitted
  cga::FittedParameters Fitted;                // Problem.Fitted, or none (MeanSquare)
  std::vector<double> Theta; // the unknowns, which Ceres updates in place

  // The cache of the last evaluation.
  std::vector<double> Residuals; // per point 3 (POINT_TO_POINT) or 1
  std::vector<double> Jacobian;  // Residuals.size() rows of Theta.size() columns
  bool Valid = false;
  bool HasJacobian = false;

  FitData(const vtkPointPairFitProblem& problem, const std::vector<cga::GeneratorParameters>& start,
    cga::FittedParameters fitted)
    : Problem(problem)
    , Start(start)
    , Fitted(fitted)
    , Theta(unknownsOf(start, fitted))
  {
  }

  vtkIdType count() const { return this->Problem.count(); }
  int residualsPerPoint() const { return this->Problem.Surface ? 1 : 3; }
  int unknowns() const { return static_cast<int>(this->Theta.size()); }

  /// Fills the cache at Theta; false (Valid false) when a point's image is not finite or the
  /// generators are not usable (a direction fitted to zero), or after an abort.
  bool Evaluate(bool withJacobian)
  {
    this->Valid = false;
    this->HasJacobian = false;
    const vtkPointPairFitProblem& P = this->Problem;
    if (vtkBoostedSurfacesCheckAbort(P.Filter))
    {
      return false;
    }
    std::vector<cga::GeneratorParameters> generators;
    applyUnknowns(this->Start, this->Fitted, this->Theta.data(), generators);
    const cga::PointPairField field(generators.data(), generators.size(), P.Falloff, P.Epsilon);
    if (field.skippedGenerators() != 0)
    {
      return false;
    }
    const int rows = this->residualsPerPoint();
    const int columns = this->unknowns();
    this->Residuals.assign(static_cast<std::size_t>(rows * this->count()), 0.0);
    if (withJacobian)
    {
      this->Jacobian.assign(this->Residuals.size() * columns, 0.0);
    }
    std::atomic<bool> failed{ false };
    vtkSMPThreadLocalObject<vtkGenericCell> cells;
    vtkSMPThreadLocal<std::vector<double>> scratch;
    vtkSMPTools::For(0, this->count(), [&](vtkIdType begin, vtkIdType end) {
      std::vector<double>& derivatives = scratch.Local();
      derivatives.resize(3 * static_cast<std::size_t>(columns));
      vtkGenericCell* cell = cells.Local();
      for (vtkIdType i = begin; i < end && !failed; ++i)
      {
        const double* p = P.Points.data() + 3 * i;
        cga::Vec3 image;
        const bool mapped = withJacobian
          ? cga::mapWithGeneratorDerivatives(field, generators.data(), generators.size(),
              this->Fitted, { p[0], p[1], p[2] }, P.Strength, P.Rule, image, derivatives.data())
          : field.map({ p[0], p[1], p[2] }, P.Strength, P.Rule, image);
        if (!mapped || !cga::isFinite(image))
        {
          failed = true;
          return;
        }
        const double scale = P.Scales[i];
        double* residual = this->Residuals.data() + rows * i;
        double* jacobian = withJacobian ? this->Jacobian.data() + rows * i * columns : nullptr;
        const double q[3] = { image.x, image.y, image.z };
        if (!P.Surface)
        {
          const double* t = P.Targets.data() + 3 * i;
          for (int j = 0; j < 3; ++j)
          {
            residual[j] = scale * (q[j] - t[j]);
            for (int u = 0; jacobian && u < columns; ++u)
            {
              jacobian[j * columns + u] = scale * derivatives[3 * u + j];
            }
          }
          continue;
        }
        // The distance to the closest point c of the target's cells; its gradient is the unit
        // vector (p' - c) / |p' - c| (0 on the surface itself, where the distance has its kink).
        if (std::max({ std::fabs(q[0]), std::fabs(q[1]), std::fabs(q[2]) }) >
          vtkPointPairFitSolver::LargestSurfaceCoordinate)
        {
          failed = true; // beyond what the locator computes with
          return;
        }
        double closest[3], distance2 = 0.0;
        vtkIdType cellId;
        int subId;
        P.Locator->FindClosestPoint(q, closest, cell, cellId, subId, distance2);
        const double distance = std::sqrt(distance2);
        residual[0] = scale * distance;
        if (!std::isfinite(residual[0]))
        {
          failed = true;
          return;
        }
        for (int u = 0; jacobian && u < columns; ++u)
        {
          double sum = 0.0;
          for (int j = 0; distance > 0.0 && j < 3; ++j)
          {
            sum += (q[j] - closest[j]) / distance * derivatives[3 * u + j];
          }
          jacobian[u] = scale * sum;
        }
      }
    });
    if (failed)
    {
      return false;
    }
    if (withJacobian)
    {
      for (const double value : this->Jacobian)
      {
        if (!std::isfinite(value))
        {
          return false;
        }
      }
    }
    this->Valid = true;
    this->HasJacobian = withJacobian;
    return true;
  }

  /// The squared weighted RMS residual of the cache.
  double MeanSquare() const
  {
    double sum = 0.0;
    for (const double r : this->Residuals)
    {
      sum += r * r;
    }
    return sum;
  }
};

// Ceres writes some terminations through glog (LOG(ERROR), whatever Solver::Options::logging_type
// says; to stderr when the application has not set glog up), e.g. a solve stopped by invalid
// steps at a huge Strength. The filter reports them as its own error, so glog's threshold is
// raised to FATAL during the solve: saved by the first of concurrent solves, restored by the last.
std::mutex quietGlogMutex;
int quietSolves = 0;        // solves in progress, under quietGlogMutex
int savedMinimumLogLevel = 0; // glog's threshold before the first of them

class QuietGlog
{
public:
  QuietGlog()
  {
    std::lock_guard<std::mutex> lock(quietGlogMutex);
    if (quietSolves++ == 0)
    {
      savedMinimumLogLevel = FLAGS_minloglevel;
      FLAGS_minloglevel = google::GLOG_FATAL;
    }
  }
  ~QuietGlog()
  {
    std::lock_guard<std::mutex> lock(quietGlogMutex);
    if (--quietSolves == 0)
    {
      FLAGS_minloglevel = savedMinimumLogLevel;
    }
  }
  QuietGlog(const QuietGlog&) = delete;
  QuietGlog& operator=(const QuietGlog&) = delete;
};

// Ceres calls this once per new point of the unknowns, before any residual block's Evaluate.
class FitEvaluation : public ceres::EvaluationCallback
{
public:
  explicit FitEvaluation(FitData& data)
    : Data(data)
  {
  }
  void PrepareForEvaluation(bool evaluateJacobians, bool newEvaluationPoint) override
  {
    if (newEvaluationPoint || (evaluateJacobians && !this->Data.HasJacobian))
    {
      this->Data.Evaluate(evaluateJacobians);
    }
  }

private:
  FitData& Data;
};

// The residuals of the points [First, Last): copied from the cache, with their Jacobian blocks,
// one parameter block per generator.
class PointBlockCost : public ceres::CostFunction
{
public:
  PointBlockCost(const FitData& data, vtkIdType first, vtkIdType last)
    : Data(data)
    , First(first)
    , Last(last)
  {
    this->set_num_residuals(static_cast<int>((last - first) * data.residualsPerPoint()));
    for (std::size_t g = 0; g < data.Start.size(); ++g)
    {
      this->mutable_parameter_block_sizes()->push_back(data.Fitted.perGenerator());
    }
  }

  bool Evaluate(double const* const*, double* residuals, double** jacobians) const override
  {
    if (!this->Data.Valid || (jacobians && !this->Data.HasJacobian))
    {
      return false; // Ceres rejects the step
    }
    const int rows = this->num_residuals();
    const std::size_t first = static_cast<std::size_t>(this->First * this->Data.residualsPerPoint());
    std::copy_n(this->Data.Residuals.data() + first, rows, residuals);
    if (!jacobians)
    {
      return true;
    }
    const int per = this->Data.Fitted.perGenerator();
    const int columns = this->Data.unknowns();
    for (std::size_t g = 0; g < this->Data.Start.size(); ++g)
    {
      if (!jacobians[g])
      {
        continue;
      }
      for (int r = 0; r < rows; ++r)
      {
        const double* source = this->Data.Jacobian.data() + (first + r) * columns + g * per;
        std::copy_n(source, per, jacobians[g] + r * per);
      }
    }
    return true;
  }

private:
  const FitData& Data;
  vtkIdType First, Last;
};

// The Tikhonov term of one generator: sqrt(lambda) (theta_g - theta_g,0).
class RegularizationCost : public ceres::CostFunction
{
public:
  RegularizationCost(const double* start, int size, double lambda)
    : Start(start, start + size)
    , Root(std::sqrt(lambda))
  {
    this->set_num_residuals(size);
    this->mutable_parameter_block_sizes()->push_back(size);
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override
  {
    const int size = this->num_residuals();
    for (int k = 0; k < size; ++k)
    {
      residuals[k] = this->Root * (parameters[0][k] - this->Start[k]);
    }
    if (jacobians && jacobians[0])
    {
      std::fill_n(jacobians[0], size * size, 0.0);
      for (int k = 0; k < size; ++k)
      {
        jacobians[0][k * size + k] = this->Root;
      }
    }
    return true;
  }

private:
  std::vector<double> Start;
  double Root;
};

// Progress per iteration within [Begin, End] of the filter's, and the abort.
class FitProgress : public ceres::IterationCallback
{
public:
  FitProgress(vtkAlgorithm* filter, int iterations, double begin, double end)
    : Filter(filter)
    , Iterations(iterations)
    , Begin(begin)
    , End(end)
  {
  }
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override
  {
    const double fraction = std::min(1.0, (summary.iteration + 1.0) / (this->Iterations + 1.0));
    this->Filter->UpdateProgress(this->Begin + (this->End - this->Begin) * fraction);
    return vtkBoostedSurfacesCheckAbort(this->Filter) ? ceres::SOLVER_ABORT
                                                      : ceres::SOLVER_CONTINUE;
  }

private:
  vtkAlgorithm* Filter;
  int Iterations;
  double Begin, End;
};

// Sets the bounds of generator g's unknowns in `block` around the start `s`.
void setBounds(ceres::Problem& solverProblem, double* block, const vtkPointPairFitProblem& P,
  const cga::GeneratorParameters& s)
{
  int k = 0;
  const auto bound = [&](double low, double high) {
    solverProblem.SetParameterLowerBound(block, k, low);
    solverProblem.SetParameterUpperBound(block, k, high);
    ++k;
  };
  if (P.Fitted.weight)
  {
    bound(P.WeightRange[0], P.WeightRange[1]);
  }
  for (int j = 0; P.Fitted.location && j < 3; ++j)
  {
    bound(s.location[j] - P.LocationChange, s.location[j] + P.LocationChange);
  }
  const double change = P.DirectionChange * cga::norm(s.direction);
  for (int j = 0; P.Fitted.direction && j < 3; ++j)
  {
    bound(s.direction[j] - change, s.direction[j] + change);
  }
  if (P.Fitted.pitch)
  {
    bound(s.pitch - P.PitchChange, s.pitch + P.PitchChange);
  }
}
} // namespace

bool vtkPointPairFitSolver::Solve(const vtkPointPairFitProblem& problem,
  const std::vector<cga::GeneratorParameters>& start,
  const std::vector<cga::GeneratorParameters>& first, double progressBegin, double progressEnd,
  vtkPointPairFitResult& result, std::string& error)
{
  error.clear();
  const cga::FittedParameters fitted = problem.Fitted;
  const std::vector<double> theta0 = unknownsOf(start, fitted);
  FitData data(problem, first, fitted);
  // The start must be valid: Ceres needs a finite initial cost.
  if (!data.Evaluate(false))
  {
    if (!vtkBoostedSurfacesCheckAbort(problem.Filter))
    {
      error = "the initial generators send a point of the mesh to infinity (or its residual is "
              "not finite";
      if (problem.Surface)
      {
        std::ostringstream beyond;
        beyond << ", or its image is beyond " << vtkPointPairFitSolver::LargestSurfaceCoordinate
               << ", where the target's cell locator overflows";
        error += beyond.str();
      }
      error += "): the fit cannot start there";
    }
    return false;
  }
  if (!std::isfinite(data.MeanSquare()))
  {
    error = "the squared residuals of the initial generators overflow (coordinates of the mesh, "
            "its images or the target near the largest double): the fit cannot start there";
    return false;
  }
  const int per = fitted.perGenerator();
  const int unknowns = data.unknowns();
  const auto regularization = [&] {
    double sum = 0.0;
    for (int u = 0; u < unknowns; ++u)
    {
      sum += (data.Theta[u] - theta0[u]) * (data.Theta[u] - theta0[u]);
    }
    return problem.RegularizationWeight * sum;
  };
  result.InitialData = data.MeanSquare();
  const double initialCost = result.InitialData + regularization();
  const std::vector<double> firstTheta = data.Theta;

  ceres::Problem::Options problemOptions;
  FitEvaluation evaluation(data);
  problemOptions.evaluation_callback = &evaluation;
  ceres::Problem solverProblem(problemOptions);
  std::vector<double*> blocks;
  int free = 0;
  for (std::size_t g = 0; g < data.Start.size(); ++g)
  {
    double* block = data.Theta.data() + g * per;
    blocks.push_back(block);
    solverProblem.AddParameterBlock(block, per);
    setBounds(solverProblem, block, problem, start[g]);
    // Only a twist reads its pitch: for the other kinds that unknown is held (its column is 0).
    const bool heldPitch = fitted.pitch && data.Start[g].kind != cga::GeneratorKind::Twist;
    if (heldPitch && per == 1)
    {
      solverProblem.SetParameterBlockConstant(block);
      continue;
    }
    if (heldPitch)
    {
      solverProblem.SetManifold(block, new ceres::SubsetManifold(per, { per - 1 }));
    }
    free += heldPitch ? per - 1 : per;
    if (problem.RegularizationWeight > 0.0)
    {
      solverProblem.AddResidualBlock(
        new RegularizationCost(theta0.data() + g * per, per, problem.RegularizationWeight),
        nullptr, block);
    }
  }
  if (free == 0)
  {
    // Nothing can move (FitPitches alone, and no twist): the first point is the result.
    result.Generators = first;
    result.FinalData = result.InitialData;
    result.Cost = initialCost;
    result.Iterations = 0;
    result.Improved = false;
    result.Termination = "NO_CONVERGENCE: no unknown to fit (pitches of generators that are not twists)";
    return true;
  }
  // Residual blocks of 64 points: few enough blocks for Ceres's bookkeeping, each a copy from
  // the cache.
  constexpr vtkIdType pointsPerBlock = 64;
  const vtkIdType count = problem.count();
  for (vtkIdType begin = 0; begin < count; begin += pointsPerBlock)
  {
    solverProblem.AddResidualBlock(
      new PointBlockCost(data, begin, std::min(count, begin + pointsPerBlock)), nullptr, blocks);
  }

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = problem.MaximumNumberOfIterations;
  options.function_tolerance = problem.FunctionTolerance;
  options.gradient_tolerance = problem.GradientTolerance;
  options.parameter_tolerance = problem.ParameterTolerance;
  options.logging_type = ceres::SILENT;
  options.minimizer_progress_to_stdout = false;
  options.num_threads = 1; // the points are mapped in parallel by vtkSMPTools (FitData)
  FitProgress progress(
    problem.Filter, problem.MaximumNumberOfIterations, progressBegin, progressEnd);
  options.callbacks.push_back(&progress);
  ceres::Solver::Summary summary;
  {
    QuietGlog quiet;
    ceres::Solve(options, &solverProblem, &summary);
  }
  if (vtkBoostedSurfacesCheckAbort(problem.Filter) ||
    summary.termination_type == ceres::USER_FAILURE)
  {
    return false; // aborted
  }
  result.Iterations = static_cast<int>(summary.iterations.size()) - 1;
  result.Termination =
    ceres::TerminationTypeToString(summary.termination_type) + std::string(": ") + summary.message;
  if (summary.termination_type == ceres::FAILURE)
  {
    error = "the solver failed: " + summary.message;
    if (summary.message.find("invalid steps") != std::string::npos)
    {
      // An invalid step is one whose images are not finite (or whose direction became zero).
      error += " (every step tried sent a mesh point to infinity or beyond the doubles' range, or "
               "fitted a direction to zero: a huge Strength or weights do that)";
    }
    return false;
  }
  // The fitted unknowns (Ceres leaves the best point in the blocks), evaluated again. A fit no
  // better than its first point keeps the first point.
  const double finalRegularization = regularization();
  const bool finalValid = data.Evaluate(false);
  const double finalData = finalValid ? data.MeanSquare() : result.InitialData;
  result.Improved = finalValid && finalData + finalRegularization < initialCost;
  if (!result.Improved)
  {
    data.Theta = firstTheta;
  }
  result.FinalData = result.Improved ? finalData : result.InitialData;
  result.Cost = result.Improved ? finalData + finalRegularization : initialCost;
  applyUnknowns(data.Start, fitted, data.Theta.data(), result.Generators);
  return true;
}

bool vtkPointPairFitSolver::SearchKinds(const vtkPointPairFitProblem& problem,
  const std::vector<cga::GeneratorParameters>& start, double separation,
  vtkPointPairFitResult& result, std::vector<bool>& identified, int& fits, std::string& error)
{
  using Kind = cga::GeneratorKind;
  const Kind kinds[KindCount] = { Kind::PointPair, Kind::Rotation, Kind::Twist, Kind::Dilation,
    Kind::Translation };
  const std::size_t count = start.size();
  vtkPointPairFitResult best;
  if (!Solve(problem, start, start, 0.0, 0.2, best, error))
  {
    return false;
  }
  fits = 1;
  int iterations = best.Iterations;
  const double initialData = best.InitialData;
  const double margin = separation * initialData;
  std::vector<cga::GeneratorParameters> bestStart = start; // the initial values, the best kinds
  std::vector<std::array<double, KindCount>> costs(count);
  for (int sweep = 0; sweep < MaximumKindSweeps; ++sweep)
  {
    // Sweep s reports progress in [1 - 0.8 / 2^s, 1 - 0.8 / 2^(s+1)].
    const double sweepBegin = 1.0 - 0.8 * std::ldexp(1.0, -sweep);
    const double trialShare = 0.4 * std::ldexp(1.0, -sweep) / (count * (KindCount - 1));
    int trial = 0;
    bool changed = false;
    for (std::size_t g = 0; g < count; ++g)
    {
      // The kind g has when its turn begins is not fitted again after another replaced it in
      // this turn (the fits stay within MaximumKindFits): its cost is the best's before.
      const Kind original = bestStart[g].kind;
      const double originalCost = best.Cost;
      for (int k = 0; k < KindCount; ++k)
      {
        const Kind current = bestStart[g].kind;
        if (kinds[k] == original)
        {
          costs[g][k] = originalCost;
          continue;
        }
        std::vector<cga::GeneratorParameters> candidateStart = bestStart;
        candidateStart[g].kind = kinds[k];
        std::vector<cga::GeneratorParameters> first = best.Generators;
        first[g] = candidateStart[g];
        vtkPointPairFitResult candidate;
        const double begin = sweepBegin + trialShare * trial++;
        if (!Solve(problem, candidateStart, first, begin, begin + trialShare, candidate, error))
        {
          if (vtkBoostedSurfacesCheckAbort(problem.Filter))
          {
            return false;
          }
          error.clear();
          costs[g][k] = std::numeric_limits<double>::infinity();
          continue;
        }
        ++fits;
        iterations += candidate.Iterations;
        costs[g][k] = candidate.Cost;
        const bool lower = candidate.Cost < best.Cost - margin;
        const bool simpler = kinds[k] == Kind::Rotation && current == Kind::Twist &&
          candidate.Cost <= best.Cost + margin;
        if (lower || simpler)
        {
          best = candidate;
          bestStart = candidateStart;
          changed = true; // (the kinds tried before are compared again in the next sweep)
        }
      }
    }
    if (!changed)
    {
      break;
    }
  }
  identified.assign(count, true);
  for (std::size_t g = 0; g < count; ++g)
  {
    const Kind chosen = bestStart[g].kind;
    for (int k = 0; k < KindCount; ++k)
    {
      const bool contains = chosen == Kind::Rotation && kinds[k] == Kind::Twist;
      if (kinds[k] != chosen && !contains && !(costs[g][k] > best.Cost + margin))
      {
        identified[g] = false;
      }
    }
  }
  result = best;
  result.InitialData = initialData;
  result.Iterations = iterations;
  result.Improved = best.Cost < initialData;
  return true;
}
