#include "vtkPointPairFitFilter.h"

#include "vtkBoostedExponentialRule.h"
#include "vtkBoostedGeneratorGlyphs.h"
#include "vtkBoostedGeneratorPort.h"
#include "vtkBoostedGeneratorRows.h"
#include "vtkBoostedMemoryBudget.h"
#include "vtkBoostedRowList.h"
#include "vtkBoostedSurfacesAbort.h"
#include "vtkBoostedWholeInput.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkGenericCell.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointPairDeformationFilter.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPThreadLocal.h"
#include "vtkSMPThreadLocalObject.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStaticCellLocator.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

#include "cga/GeneratorDerivatives.h"
#include "cga/PointPairField.h"

#include <ceres/ceres.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPointPairFitFilter);

namespace
{
// The unknowns of generator g start at theta[g * perGenerator]: its weight, location and direction
// as far as they are fitted (cga::FittedParameters' order).
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
  }
  return theta;
}

// The data term of the fit, evaluated once per point of the unknowns for every residual block
// (Ceres's EvaluationCallback): the field of the current generators maps every mesh point with its
// derivatives; the residuals (sqrt(omega_p / sum omega) times p' - t_p, or times the distance of p'
// to the target's cells) and their Jacobian rows are cached for the blocks to copy.
struct FitData
{
  vtkPointPairFitFilter* Filter = nullptr;
  std::vector<cga::GeneratorParameters> Start;
  cga::FittedParameters Fitted;
  std::vector<double> Theta; // the unknowns, which Ceres updates in place
  std::vector<double> Points; // the mesh, xyz interleaved
  std::vector<double> Targets; // POINT_TO_POINT: the target's points
  vtkStaticCellLocator* Locator = nullptr; // POINT_TO_SURFACE: over the target's cells
  std::vector<double> Scales; // sqrt(omega_p / sum omega)
  double Falloff = 1.0, Epsilon = 0.01, Strength = 1.0;
  cga::ExponentialRule Rule = cga::ExponentialRule::Exact;
  bool Surface = false;

  // The cache of the last evaluation.
  std::vector<double> Residuals; // per point 3 (POINT_TO_POINT) or 1
  std::vector<double> Jacobian;  // Residuals.size() rows of Theta.size() columns
  bool Valid = false;
  bool HasJacobian = false;

  vtkIdType count() const { return static_cast<vtkIdType>(this->Points.size() / 3); }
  int residualsPerPoint() const { return this->Surface ? 1 : 3; }
  int unknowns() const { return static_cast<int>(this->Theta.size()); }

  /// Fills the cache at Theta; false (Valid false) when a point's image is not finite or the
  /// generators are not usable (a direction fitted to zero), or after an abort.
  bool Evaluate(bool withJacobian)
  {
    this->Valid = false;
    this->HasJacobian = false;
    if (vtkBoostedSurfacesCheckAbort(this->Filter))
    {
      return false;
    }
    std::vector<cga::GeneratorParameters> generators;
    applyUnknowns(this->Start, this->Fitted, this->Theta.data(), generators);
    const cga::PointPairField field(
      generators.data(), generators.size(), this->Falloff, this->Epsilon);
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
        const double* p = this->Points.data() + 3 * i;
        cga::Vec3 image;
        const bool mapped = withJacobian
          ? cga::mapWithGeneratorDerivatives(field, generators.data(), generators.size(),
              this->Fitted, { p[0], p[1], p[2] }, this->Strength, this->Rule, image,
              derivatives.data())
          : field.map({ p[0], p[1], p[2] }, this->Strength, this->Rule, image);
        if (!mapped || !cga::isFinite(image))
        {
          failed = true;
          return;
        }
        const double scale = this->Scales[i];
        double* residual = this->Residuals.data() + rows * i;
        double* jacobian = withJacobian ? this->Jacobian.data() + rows * i * columns : nullptr;
        const double q[3] = { image.x, image.y, image.z };
        if (!this->Surface)
        {
          const double* t = this->Targets.data() + 3 * i;
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
        double closest[3], distance2 = 0.0;
        vtkIdType cellId;
        int subId;
        this->Locator->FindClosestPoint(q, closest, cell, cellId, subId, distance2);
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

// Progress per iteration, and the abort.
class FitProgress : public ceres::IterationCallback
{
public:
  FitProgress(vtkPointPairFitFilter* filter, int iterations)
    : Filter(filter)
    , Iterations(iterations)
  {
  }
  ceres::CallbackReturnType operator()(const ceres::IterationSummary& summary) override
  {
    this->Filter->UpdateProgress(
      std::min(1.0, (summary.iteration + 1.0) / (this->Iterations + 1.0)));
    return vtkBoostedSurfacesCheckAbort(this->Filter) ? ceres::SOLVER_ABORT
                                                      : ceres::SOLVER_CONTINUE;
  }

private:
  vtkPointPairFitFilter* Filter;
  int Iterations;
};

bool allFinite(vtkPoints* points)
{
  for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
  {
    double x[3];
    points->GetPoint(i, x);
    if (!std::isfinite(x[0]) || !std::isfinite(x[1]) || !std::isfinite(x[2]))
    {
      return false;
    }
  }
  return true;
}

// A generator the field keeps and the fit can differentiate (FieldGenerator::of gives one, with
// a finite location, weight and bivector).
bool usable(const cga::GeneratorParameters& g)
{
  cga::GeneratorDerivative derivative;
  if (!cga::isFinite(g.location) || !std::isfinite(g.weight) ||
    !cga::generatorDerivative(g, derivative))
  {
    return false;
  }
  const cga::Bivector b = g.field().bivector;
  return b.isFinite() && b.maxAbs() != 0.0;
}

// Records the first error of an internal algorithm, so that it becomes this filter's own.
struct ErrorCatcher
{
  std::string Message;
  static void Catch(vtkObject*, unsigned long, void* clientData, void* callData)
  {
    auto* self = static_cast<ErrorCatcher*>(clientData);
    if (self->Message.empty() && callData)
    {
      self->Message = static_cast<const char*>(callData);
    }
  }
};

vtkSmartPointer<vtkDoubleArray> scalarArray(const char* name, double value)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  return array.GetPointer();
}
} // namespace

vtkPointPairFitFilter::vtkPointPairFitFilter()
  : Generators(new vtkBoostedRowList(this, "Generator", vtkBoostedGeneratorRows::BlankRow()))
  , InitialRMS(std::nan(""))
  , FinalRMS(std::nan(""))
{
  static_assert(vtkBoostedGeneratorKinds<vtkPointPairFitFilter>(), "");
  this->SetNumberOfInputPorts(3);  // the mesh, the target, the generators
  this->SetNumberOfOutputPorts(3); // the fitted mesh, the generators as points and as a table
  this->SetGeneratorDirectionArrayName("Direction");
  this->SetGeneratorWeightArrayName("Weight");
  this->SetGeneratorKindArrayName("Kind");
  this->SetGeneratorPitchArrayName("Pitch");
}

vtkPointPairFitFilter::~vtkPointPairFitFilter()
{
  this->SetGeneratorDirectionArrayName(nullptr);
  this->SetGeneratorWeightArrayName(nullptr);
  this->SetGeneratorKindArrayName(nullptr);
  this->SetGeneratorPitchArrayName(nullptr);
  this->SetPointWeightArrayName(nullptr);
}

vtkBoostedGeneratorRowMethods(vtkPointPairFitFilter, Generators)

void vtkPointPairFitFilter::SetTargetConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkPointPairFitFilter::SetTargetData(vtkDataObject* data)
{
  this->SetInputData(1, data);
}

void vtkPointPairFitFilter::SetGeneratorsConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(2, output);
}

void vtkPointPairFitFilter::SetGeneratorsData(vtkDataObject* data)
{
  this->SetInputData(2, data);
}

int vtkPointPairFitFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  if (port == 2)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

int vtkPointPairFitFilter::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    vtkBoostedGeneratorGlyphs::FillOutputPortInformation(info);
    return 1;
  }
  if (port == 2)
  {
    info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkTable");
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

int vtkPointPairFitFilter::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Output 0 has the mesh's type, output 1 is a vtkPolyData, output 2 a vtkTable.
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  if (!input)
  {
    return 0;
  }
  vtkInformation* meshInfo = outputVector->GetInformationObject(0);
  vtkDataObject* mesh = meshInfo->Get(vtkDataObject::DATA_OBJECT());
  if (!mesh || !mesh->IsA(input->GetClassName()))
  {
    meshInfo->Set(vtkDataObject::DATA_OBJECT(), vtk::TakeSmartPointer(input->NewInstance()));
  }
  vtkInformation* generatorsInfo = outputVector->GetInformationObject(1);
  if (!vtkPolyData::SafeDownCast(generatorsInfo->Get(vtkDataObject::DATA_OBJECT())))
  {
    generatorsInfo->Set(vtkDataObject::DATA_OBJECT(), vtkNew<vtkPolyData>());
  }
  vtkInformation* tableInfo = outputVector->GetInformationObject(2);
  if (!vtkTable::SafeDownCast(tableInfo->Get(vtkDataObject::DATA_OBJECT())))
  {
    tableInfo->Set(vtkDataObject::DATA_OBJECT(), vtkNew<vtkTable>());
  }
  return 1;
}

int vtkPointPairFitFilter::ComputeInputUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The fit needs every point of the mesh and of the target, and every generator.
  for (int port = 0; port < 3; ++port)
  {
    vtkBoostedWholeInput::Request(inputVector[port]->GetInformationObject(0));
  }
  return 1;
}

int vtkPointPairFitFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  this->NumberOfIterations = -1;
  this->InitialRMS = this->FinalRMS = std::nan("");
  this->Improved = false;
  this->TerminationReason.clear();
  vtkPointSet* mesh = vtkPointSet::GetData(inputVector[0]);
  vtkPointSet* target = vtkPointSet::GetData(inputVector[1]);
  vtkPointSet* output = vtkPointSet::GetData(outputVector, 0);
  vtkPolyData* generatorsOutput = vtkPolyData::GetData(outputVector, 1);
  vtkTable* tableOutput = vtkTable::GetData(outputVector, 2);
  if (!mesh || !target || !output || !generatorsOutput || !tableOutput)
  {
    return 0;
  }
  if (!vtkBoostedGeneratorGlyphs::OnFirstPiece(outputVector))
  {
    return 1; // the whole fit is on piece 0
  }

  // Parameters (the clamp macros let NaN through).
  if (!std::isfinite(this->Strength) || std::isnan(this->Falloff) || std::isnan(this->Epsilon))
  {
    vtkErrorMacro(<< "Strength must be finite and Falloff and Epsilon numbers; they are "
                  << this->Strength << ", " << this->Falloff << " and " << this->Epsilon);
    return 1;
  }
  if (std::isnan(this->FunctionTolerance) || std::isnan(this->GradientTolerance) ||
    std::isnan(this->ParameterTolerance) || std::isnan(this->RegularizationWeight) ||
    std::isnan(this->MaximumLocationChange) || std::isnan(this->MaximumDirectionChange))
  {
    vtkErrorMacro(<< "the tolerances, RegularizationWeight, MaximumLocationChange and "
                     "MaximumDirectionChange must be numbers");
    return 1;
  }
  if (!(this->WeightRange[0] <= this->WeightRange[1]))
  {
    vtkErrorMacro(<< "WeightRange must be [min, max] with min <= max; it is ["
                  << this->WeightRange[0] << ", " << this->WeightRange[1] << "]");
    return 1;
  }
  if (!this->FitWeights && !this->FitLocations && !this->FitDirections)
  {
    vtkErrorMacro(<< "nothing to fit: turn on FitWeights, FitLocations or FitDirections");
    return 1;
  }

  // The initial generators: the list (the selected row at its line widget), then the Generators
  // input.
  if (!this->Generators->CheckForUpdate())
  {
    return 1;
  }
  std::vector<cga::GeneratorParameters> given(this->GetNumberOfGenerators());
  std::string problem;
  const vtkBoostedGeneratorRows::Selection selection{ this->SelectedGenerator,
    this->SelectedGeneratorLocation, this->AimSelectedGenerator, this->SelectedGeneratorTip };
  for (int i = 0; i < this->GetNumberOfGenerators(); ++i)
  {
    double used[vtkBoostedGeneratorRows::NumberOfValues];
    const double* row =
      vtkBoostedGeneratorRows::Selected(this->Generators->Row(i), i, selection, used);
    if (!vtkBoostedGeneratorRows::Read(row, row, i, given[i], problem))
    {
      vtkErrorMacro(<< problem);
      return 1;
    }
  }
  if (vtkPointSet* generatorSet = vtkPointSet::GetData(inputVector[2]))
  {
    const vtkBoostedGeneratorPort::ArrayNames names{ this->GeneratorDirectionArrayName,
      this->GeneratorWeightArrayName, this->UseGeneratorWeightArray, this->GeneratorKindArrayName,
      this->GeneratorPitchArrayName };
    if (!vtkBoostedGeneratorPort::Read(generatorSet, names, given, problem))
    {
      vtkErrorMacro(<< problem);
      return 1;
    }
  }
  FitData data;
  data.Filter = this;
  for (const cga::GeneratorParameters& g : given)
  {
    if (usable(g))
    {
      data.Start.push_back(g);
    }
  }
  if (data.Start.empty())
  {
    vtkErrorMacro(<< "no generators to fit: give initial generators (the list or the Generators "
                     "input) with a finite location and weight and a non-zero direction ("
                  << given.size() << " given)");
    return 1;
  }
  if (data.Start.size() < given.size())
  {
    vtkWarningMacro(<< given.size() - data.Start.size() << " of " << given.size()
                    << " generators were ignored: their direction is zero, or their location, "
                       "direction, weight or (a twist's) pitch is not finite");
  }
  for (std::size_t g = 0; g < data.Start.size(); ++g)
  {
    const double w = data.Start[g].weight;
    if (this->FitWeights && (w < this->WeightRange[0] || w > this->WeightRange[1]))
    {
      vtkErrorMacro(<< "the initial weight " << w << " of generator " << g
                    << " is outside WeightRange [" << this->WeightRange[0] << ", "
                    << this->WeightRange[1] << "]");
      return 1;
    }
  }

  // The mesh and the target.
  const vtkIdType count = mesh->GetNumberOfPoints();
  if (count == 0 || !mesh->GetPoints())
  {
    vtkErrorMacro(<< "the mesh (input 0) has no points");
    return 1;
  }
  if (!allFinite(mesh->GetPoints()))
  {
    vtkErrorMacro(<< "the mesh (input 0) has NaN or infinite points: the fit needs every point");
    return 1;
  }
  data.Surface = this->TargetMode == POINT_TO_SURFACE;
  const vtkIdType targetCount = target->GetNumberOfPoints();
  if (targetCount == 0 || !target->GetPoints())
  {
    vtkErrorMacro(<< "the target (input 1) is empty: it has no points");
    return 1;
  }
  if (!allFinite(target->GetPoints()))
  {
    vtkErrorMacro(<< "the target (input 1) has NaN or infinite points");
    return 1;
  }
  if (!data.Surface && targetCount != count)
  {
    vtkErrorMacro(<< "POINT_TO_POINT needs a target with the mesh's points in the same order: the "
                     "mesh has "
                  << count << " points, the target " << targetCount
                  << " (use POINT_TO_SURFACE for another mesh)");
    return 1;
  }
  if (data.Surface && target->GetNumberOfCells() == 0)
  {
    vtkErrorMacro(<< "POINT_TO_SURFACE needs a target with cells; the target has "
                  << targetCount << " points and no cells");
    return 1;
  }

  // The per-point weights: sqrt(omega_p / sum omega) scales each point's residuals.
  data.Scales.assign(count, 1.0);
  if (this->PointWeightArrayName && *this->PointWeightArrayName)
  {
    vtkDataArray* weights = mesh->GetPointData()->GetArray(this->PointWeightArrayName);
    if (!weights || weights->GetNumberOfComponents() != 1 ||
      weights->GetNumberOfTuples() != count)
    {
      vtkErrorMacro(<< "the mesh has no numeric point array '" << this->PointWeightArrayName
                    << "' of 1 component per point (PointWeightArrayName)");
      return 1;
    }
    for (vtkIdType i = 0; i < count; ++i)
    {
      data.Scales[i] = weights->GetComponent(i, 0);
      if (!(data.Scales[i] >= 0.0) || !std::isfinite(data.Scales[i]))
      {
        vtkErrorMacro(<< "the point weight " << data.Scales[i] << " of point " << i << " ('"
                      << this->PointWeightArrayName << "') is negative or not finite");
        return 1;
      }
    }
  }
  double total = 0.0;
  for (const double w : data.Scales)
  {
    total += w;
  }
  if (!(total > 0.0) || !std::isfinite(total))
  {
    vtkErrorMacro(<< "the point weights ('" << this->PointWeightArrayName
                  << "') must not all be zero, and their sum must be finite");
    return 1;
  }
  for (double& w : data.Scales)
  {
    w = std::sqrt(w / total);
  }

  // The unknowns and their bounds. A location or direction that may not change is not fitted.
  double bounds[6];
  mesh->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  const double locationChange = this->MaximumLocationChange * diagonal;
  data.Fitted.weight = this->FitWeights;
  data.Fitted.location = this->FitLocations && locationChange > 0.0;
  data.Fitted.direction = this->FitDirections && this->MaximumDirectionChange > 0.0;
  if (data.Fitted.perGenerator() == 0)
  {
    vtkErrorMacro(<< "nothing to fit: the locations and directions may not change "
                     "(MaximumLocationChange times the mesh's diagonal, MaximumDirectionChange)");
    return 1;
  }
  data.Theta = unknownsOf(data.Start, data.Fitted);
  const std::vector<double> start = data.Theta;
  const int per = data.Fitted.perGenerator();
  const int unknowns = data.unknowns();

  // The memory: the cache's Jacobian and Ceres's copies of it (its blocks and the dense QR
  // matrix), residuals x unknowns doubles each.
  const double residuals = static_cast<double>(count) * (data.Surface ? 1 : 3);
  const double bytes = 3.0 * 8.0 * residuals * unknowns + 8.0 * 12.0 * static_cast<double>(count);
  const std::string memoryProblem = vtkBoostedMemoryBudget::Problem(bytes,
    "fitting " + std::to_string(unknowns) + " unknowns to " + std::to_string(count) + " points");
  if (!memoryProblem.empty())
  {
    vtkErrorMacro(<< memoryProblem);
    return 1;
  }

  bool done = false;
  std::vector<cga::GeneratorParameters> fitted;
  vtkNew<vtkStaticCellLocator> locator;
  const bool run = vtkBoostedMemoryBudget::Run(this, [&] {
    data.Points.resize(3 * static_cast<std::size_t>(count));
    for (vtkIdType i = 0; i < count; ++i)
    {
      mesh->GetPoint(i, data.Points.data() + 3 * i);
    }
    if (data.Surface)
    {
      locator->SetDataSet(target);
      locator->BuildLocator();
      data.Locator = locator;
    }
    else
    {
      data.Targets.resize(3 * static_cast<std::size_t>(count));
      for (vtkIdType i = 0; i < count; ++i)
      {
        target->GetPoint(i, data.Targets.data() + 3 * i);
      }
    }
    data.Falloff = this->Falloff;
    data.Epsilon = this->Epsilon;
    data.Strength = this->Strength;
    data.Rule = vtkBoostedExponentialRule<vtkPointPairFitFilter>(this->ExponentialRule);

    // The start must be valid: Ceres needs a finite initial cost.
    if (!data.Evaluate(false))
    {
      if (!vtkBoostedSurfacesCheckAbort(this))
      {
        vtkErrorMacro(<< "the initial generators send a point of the mesh to infinity (or its "
                         "residual is not finite): the fit cannot start there");
      }
      return;
    }
    const double initialData = data.MeanSquare();
    this->InitialRMS = std::sqrt(initialData);

    ceres::Problem::Options problemOptions;
    FitEvaluation evaluation(data);
    problemOptions.evaluation_callback = &evaluation;
    ceres::Problem solverProblem(problemOptions);
    std::vector<double*> blocks;
    for (std::size_t g = 0; g < data.Start.size(); ++g)
    {
      double* block = data.Theta.data() + g * per;
      blocks.push_back(block);
      solverProblem.AddParameterBlock(block, per);
      int k = 0;
      const cga::GeneratorParameters& s = data.Start[g];
      if (data.Fitted.weight)
      {
        solverProblem.SetParameterLowerBound(block, k, this->WeightRange[0]);
        solverProblem.SetParameterUpperBound(block, k, this->WeightRange[1]);
        ++k;
      }
      if (data.Fitted.location)
      {
        for (int j = 0; j < 3; ++j, ++k)
        {
          solverProblem.SetParameterLowerBound(block, k, s.location[j] - locationChange);
          solverProblem.SetParameterUpperBound(block, k, s.location[j] + locationChange);
        }
      }
      if (data.Fitted.direction)
      {
        const double change = this->MaximumDirectionChange * cga::norm(s.direction);
        for (int j = 0; j < 3; ++j, ++k)
        {
          solverProblem.SetParameterLowerBound(block, k, s.direction[j] - change);
          solverProblem.SetParameterUpperBound(block, k, s.direction[j] + change);
        }
      }
      if (this->RegularizationWeight > 0.0)
      {
        solverProblem.AddResidualBlock(
          new RegularizationCost(start.data() + g * per, per, this->RegularizationWeight),
          nullptr, block);
      }
    }
    // Residual blocks of 64 points: few enough blocks for Ceres's bookkeeping, each a copy from
    // the cache.
    constexpr vtkIdType pointsPerBlock = 64;
    for (vtkIdType first = 0; first < count; first += pointsPerBlock)
    {
      solverProblem.AddResidualBlock(
        new PointBlockCost(data, first, std::min(count, first + pointsPerBlock)), nullptr, blocks);
    }

    ceres::Solver::Options options;
    options.linear_solver_type = ceres::DENSE_QR;
    options.max_num_iterations = this->MaximumNumberOfIterations;
    options.function_tolerance = this->FunctionTolerance;
    options.gradient_tolerance = this->GradientTolerance;
    options.parameter_tolerance = this->ParameterTolerance;
    options.logging_type = ceres::SILENT;
    options.minimizer_progress_to_stdout = false;
    options.num_threads = 1; // the points are mapped in parallel by vtkSMPTools (FitData)
    FitProgress progress(this, this->MaximumNumberOfIterations);
    options.callbacks.push_back(&progress);
    ceres::Solver::Summary summary;
    ceres::Solve(options, &solverProblem, &summary);
    if (vtkBoostedSurfacesCheckAbort(this) || summary.termination_type == ceres::USER_FAILURE)
    {
      return; // aborted: empty outputs
    }
    this->NumberOfIterations = static_cast<int>(summary.iterations.size()) - 1;
    this->TerminationReason =
      ceres::TerminationTypeToString(summary.termination_type) + std::string(": ") + summary.message;
    if (summary.termination_type == ceres::FAILURE)
    {
      vtkErrorMacro(<< "the solver failed: " << summary.message);
      return;
    }

    // The fitted unknowns (Ceres leaves the best point in the blocks), evaluated again for the
    // final RMS. A fit no better than its start keeps the start.
    const double regularization = [&] {
      double sum = 0.0;
      for (int u = 0; u < unknowns; ++u)
      {
        sum += (data.Theta[u] - start[u]) * (data.Theta[u] - start[u]);
      }
      return this->RegularizationWeight * sum;
    }();
    const bool finalValid = data.Evaluate(false);
    const double finalData = finalValid ? data.MeanSquare() : initialData;
    this->Improved = finalValid && finalData + regularization < initialData;
    if (!this->Improved)
    {
      data.Theta = start;
      this->FinalRMS = this->InitialRMS;
    }
    else
    {
      this->FinalRMS = std::sqrt(finalData);
    }
    if (!this->Improved && this->MaximumNumberOfIterations > 0) // 0: the start, evaluated
    {
      vtkWarningMacro(<< "the fit could not improve on the initial generators (RMS residual "
                      << this->InitialRMS << " after " << this->NumberOfIterations
                      << " iterations: " << this->TerminationReason
                      << "); the outputs are the initial generators and the mesh as they deform "
                         "it");
    }
    applyUnknowns(data.Start, data.Fitted, data.Theta.data(), fitted);
    done = true;
  });
  if (!run || !done)
  {
    output->Initialize();
    return 1;
  }

  // Output 0: the deformation filter's output for the fitted generators.
  vtkNew<vtkPointPairDeformationFilter> deformation;
  auto meshCopy = vtk::TakeSmartPointer(mesh->NewInstance());
  meshCopy->ShallowCopy(mesh);
  deformation->SetInputData(meshCopy);
  for (const cga::GeneratorParameters& g : fitted)
  {
    deformation->AddGenerator(g.location.x, g.location.y, g.location.z, g.direction.x,
      g.direction.y, g.direction.z, g.weight, static_cast<double>(g.kind), g.pitch);
  }
  deformation->SetStrength(this->Strength);
  deformation->SetFalloff(this->Falloff);
  deformation->SetEpsilon(this->Epsilon);
  deformation->SetExponentialRule(this->ExponentialRule);
  deformation->SetOutputPointsPrecision(this->OutputPointsPrecision);
  ErrorCatcher catcher;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(&ErrorCatcher::Catch);
  onError->SetClientData(&catcher);
  deformation->AddObserver(vtkCommand::ErrorEvent, onError);
  deformation->Update();
  vtkPointSet* deformed = vtkPointSet::SafeDownCast(deformation->GetOutputDataObject(0));
  if (!catcher.Message.empty() || !deformed || deformed->GetNumberOfPoints() != count)
  {
    vtkErrorMacro(<< "the fitted mesh could not be built: "
                  << (catcher.Message.empty() ? "the deformation gave no points" : catcher.Message));
    return 1;
  }
  output->ShallowCopy(deformed);

  // The per-point residual of the output's points.
  vtkNew<vtkDoubleArray> residual;
  residual->SetName("FitResidual");
  residual->SetNumberOfTuples(count);
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType i = 0; i < count; ++i)
  {
    double q[3], t[3], distance2 = 0.0;
    deformed->GetPoint(i, q);
    if (data.Surface)
    {
      vtkIdType cellId;
      int subId;
      locator->FindClosestPoint(q, t, cell, cellId, subId, distance2);
    }
    else
    {
      target->GetPoint(i, t);
      distance2 = vtkMath::Distance2BetweenPoints(q, t);
    }
    residual->SetValue(i, std::sqrt(distance2));
  }
  output->GetPointData()->AddArray(residual);

  // The summary in the field data.
  vtkFieldData* fieldData = output->GetFieldData();
  fieldData->AddArray(scalarArray("FitIterations", this->NumberOfIterations));
  fieldData->AddArray(scalarArray("FitInitialRMS", this->InitialRMS));
  fieldData->AddArray(scalarArray("FitFinalRMS", this->FinalRMS));
  fieldData->AddArray(scalarArray("FitImproved", this->Improved ? 1.0 : 0.0));
  vtkNew<vtkStringArray> termination;
  termination->SetName("FitTermination");
  termination->InsertNextValue(this->TerminationReason);
  fieldData->AddArray(termination);

  // Outputs 1 and 2: the fitted generators as points and as a table of generator rows.
  vtkBoostedGeneratorGlyphs glyphs(vtkBoostedGeneratorGlyphs::KindAndPitch);
  glyphs.Add(fitted);
  glyphs.Write(generatorsOutput);
  const char* columns[vtkBoostedGeneratorRows::NumberOfValues] = { "X", "Y", "Z", "DirectionX",
    "DirectionY", "DirectionZ", "Weight", "Kind", "Pitch" };
  for (int c = 0; c < vtkBoostedGeneratorRows::NumberOfValues; ++c)
  {
    vtkNew<vtkDoubleArray> column;
    column->SetName(columns[c]);
    for (const cga::GeneratorParameters& g : fitted)
    {
      const double row[vtkBoostedGeneratorRows::NumberOfValues] = { g.location.x, g.location.y,
        g.location.z, g.direction.x, g.direction.y, g.direction.z, g.weight,
        static_cast<double>(g.kind), g.pitch };
      column->InsertNextValue(row[c]);
    }
    tableOutput->AddColumn(column);
  }
  return 1;
}

void vtkPointPairFitFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->Generators->Print(os, indent);
  vtkBoostedGeneratorRows::PrintSelection(os, indent,
    { this->SelectedGenerator, this->SelectedGeneratorLocation, this->AimSelectedGenerator,
      this->SelectedGeneratorTip });
  const auto name = [](const char* s) { return s ? s : "(none)"; };
  os << indent << "GeneratorDirectionArrayName: " << name(this->GeneratorDirectionArrayName)
     << "\n";
  os << indent << "GeneratorWeightArrayName: " << name(this->GeneratorWeightArrayName) << "\n";
  os << indent << "GeneratorKindArrayName: " << name(this->GeneratorKindArrayName) << "\n";
  os << indent << "GeneratorPitchArrayName: " << name(this->GeneratorPitchArrayName) << "\n";
  os << indent << "UseGeneratorWeightArray: " << this->UseGeneratorWeightArray << "\n";
  os << indent << "TargetMode: "
     << (this->TargetMode == POINT_TO_SURFACE ? "POINT_TO_SURFACE" : "POINT_TO_POINT") << "\n";
  os << indent << "PointWeightArrayName: " << name(this->PointWeightArrayName) << "\n";
  os << indent << "FitWeights: " << this->FitWeights << "\n";
  os << indent << "FitLocations: " << this->FitLocations << "\n";
  os << indent << "FitDirections: " << this->FitDirections << "\n";
  os << indent << "RegularizationWeight: " << this->RegularizationWeight << "\n";
  os << indent << "WeightRange: [" << this->WeightRange[0] << ", " << this->WeightRange[1]
     << "]\n";
  os << indent << "MaximumLocationChange: " << this->MaximumLocationChange << "\n";
  os << indent << "MaximumDirectionChange: " << this->MaximumDirectionChange << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "FunctionTolerance: " << this->FunctionTolerance << "\n";
  os << indent << "GradientTolerance: " << this->GradientTolerance << "\n";
  os << indent << "ParameterTolerance: " << this->ParameterTolerance << "\n";
  os << indent << "Strength: " << this->Strength << "\n";
  os << indent << "Falloff: " << this->Falloff << "\n";
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  os << indent << "ExponentialRule: " << (this->ExponentialRule == PAPER ? "PAPER" : "EXACT")
     << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "Last fit: " << this->NumberOfIterations << " iterations, RMS residual "
     << this->InitialRMS << " -> " << this->FinalRMS << (this->Improved ? "" : " (not improved)")
     << ", " << (this->TerminationReason.empty() ? "(no fit)" : this->TerminationReason) << "\n";
}
