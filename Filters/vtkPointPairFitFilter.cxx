#include "vtkPointPairFitFilter.h"

#include "vtkBoostedExponentialRule.h"
#include "vtkBoostedGeneratorGlyphs.h"
#include "vtkBoostedGeneratorRows.h"
#include "vtkBoostedLargeArrays.h"
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
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointPairDeformationFilter.h"
#include "vtkPointPairFitSolver.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStaticCellLocator.h"
#include "vtkStringArray.h"
#include "vtkTable.h"

#include "cga/GeneratorDerivatives.h"
#include "cga/PointPairField.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkPointPairFitFilter);

namespace
{
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
  // A pitch is read by twists only, but any generator may become a twist (FitKinds) and the
  // outputs hold every fitted generator's pitch: a non-finite one makes it unusable whatever its
  // kind (found by the property fuzz, seed 424242 trial 12186: a translation's infinite pitch
  // in the Generator Table).
  cga::GeneratorDerivative derivative;
  if (!cga::isFinite(g.location) || !std::isfinite(g.weight) || !std::isfinite(g.pitch) ||
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
  : vtkPointPairFieldAlgorithm(2) // the Generators input is port 2
  , InitialRMS(std::nan(""))
  , FinalRMS(std::nan(""))
{
  this->SetNumberOfInputPorts(3);  // the mesh, the target, the generators
  this->SetNumberOfOutputPorts(3); // the fitted mesh, the generators as points and as a table
}

vtkPointPairFitFilter::~vtkPointPairFitFilter()
{
  this->SetPointWeightArrayName(nullptr);
}

void vtkPointPairFitFilter::SetTargetConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkPointPairFitFilter::SetTargetData(vtkDataObject* data)
{
  this->SetInputData(1, data);
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
  this->NumberOfIterations = this->NumberOfFits = this->NumberOfUnidentifiedKinds = -1;
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
  if (!this->CheckFieldParameters() || !this->CheckMeshStructure(mesh, "the mesh (input 0)") ||
    !this->CheckMeshStructure(target, "the target (input 1)"))
  {
    return 1;
  }
  if (std::isnan(this->FunctionTolerance) || std::isnan(this->GradientTolerance) ||
    std::isnan(this->ParameterTolerance) || std::isnan(this->RegularizationWeight) ||
    std::isnan(this->MaximumLocationChange) || std::isnan(this->MaximumDirectionChange) ||
    std::isnan(this->MaximumPitchChange) || std::isnan(this->KindSeparation) ||
    std::isnan(this->MaximumKindSearchWork))
  {
    vtkErrorMacro(<< "the tolerances, RegularizationWeight, MaximumLocationChange, "
                     "MaximumDirectionChange, MaximumPitchChange, KindSeparation and "
                     "MaximumKindSearchWork must be numbers");
    return 1;
  }
  if (!(this->WeightRange[0] <= this->WeightRange[1]))
  {
    vtkErrorMacro(<< "WeightRange must be [min, max] with min <= max; it is ["
                  << this->WeightRange[0] << ", " << this->WeightRange[1] << "]");
    return 1;
  }
  if (!this->FitWeights && !this->FitLocations && !this->FitDirections && !this->FitPitches)
  {
    vtkErrorMacro(
      << "nothing to fit: turn on FitWeights, FitLocations, FitDirections or FitPitches");
    return 1;
  }

  // The initial generators: the list (the selected row at its line widget), then the Generators
  // input.
  std::vector<cga::GeneratorParameters> given;
  if (!this->ReadGenerators(inputVector, given))
  {
    return 1;
  }
  vtkPointPairFitProblem data;
  data.Filter = this;
  std::vector<cga::GeneratorParameters> start;
  for (const cga::GeneratorParameters& g : given)
  {
    if (usable(g))
    {
      start.push_back(g);
    }
  }
  if (start.empty())
  {
    vtkErrorMacro(<< "no generators to fit: give initial generators (the list or the Generators "
                     "input) with a finite location, weight and pitch and a non-zero direction ("
                  << given.size() << " given)");
    return 1;
  }
  if (start.size() < given.size())
  {
    vtkWarningMacro(<< given.size() - start.size() << " of " << given.size()
                    << " generators were ignored: their direction is zero, or their location, "
                       "direction, weight or pitch is not finite");
  }
  for (std::size_t g = 0; g < start.size(); ++g)
  {
    const double w = start[g].weight;
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
  if (data.Surface)
  {
    double targetBounds[6];
    target->GetBounds(targetBounds);
    const double largest = std::max(
      { std::fabs(targetBounds[0]), std::fabs(targetBounds[1]), std::fabs(targetBounds[2]),
        std::fabs(targetBounds[3]), std::fabs(targetBounds[4]), std::fabs(targetBounds[5]) });
    if (largest > vtkPointPairFitSolver::LargestSurfaceCoordinate)
    {
      vtkErrorMacro(<< "POINT_TO_SURFACE needs a target with coordinates of magnitude at most "
                    << vtkPointPairFitSolver::LargestSurfaceCoordinate << " (its cell locator "
                    << "overflows beyond); the target reaches " << largest);
      return 1;
    }
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

  // The unknowns and their bounds. A weight, location, direction or pitch that may not change is
  // not fitted (Ceres refuses a bound whose two ends are equal).
  double bounds[6];
  mesh->GetBounds(bounds);
  const double diagonal = std::sqrt((bounds[1] - bounds[0]) * (bounds[1] - bounds[0]) +
    (bounds[3] - bounds[2]) * (bounds[3] - bounds[2]) +
    (bounds[5] - bounds[4]) * (bounds[5] - bounds[4]));
  data.LocationChange = this->MaximumLocationChange * diagonal;
  data.DirectionChange = this->MaximumDirectionChange;
  data.PitchChange = this->MaximumPitchChange * diagonal;
  data.Fitted.weight = this->FitWeights && this->WeightRange[0] < this->WeightRange[1];
  data.Fitted.location = this->FitLocations && data.LocationChange > 0.0;
  data.Fitted.direction = this->FitDirections && data.DirectionChange > 0.0;
  data.Fitted.pitch = this->FitPitches && data.PitchChange > 0.0;
  if (data.Fitted.perGenerator() == 0)
  {
    vtkErrorMacro(<< "nothing to fit: the weights, locations, directions and pitches may not "
                     "change (WeightRange of one value, MaximumLocationChange and "
                     "MaximumPitchChange times the mesh's diagonal, MaximumDirectionChange)");
    return 1;
  }
  data.WeightRange[0] = this->WeightRange[0];
  data.WeightRange[1] = this->WeightRange[1];
  data.RegularizationWeight = this->RegularizationWeight;
  data.MaximumNumberOfIterations = this->MaximumNumberOfIterations;
  data.FunctionTolerance = this->FunctionTolerance;
  data.GradientTolerance = this->GradientTolerance;
  data.ParameterTolerance = this->ParameterTolerance;
  const int unknowns = data.Fitted.perGenerator() * static_cast<int>(start.size());

  // The kinds search's time, bounded before it starts: fits that do not converge run their
  // MaximumNumberOfIterations each, and the fits grow with the generators (found by the fuzz:
  // 38 generators on 4 points at 22,653 iterations, hours of work).
  if (this->FitKinds)
  {
    const double work = vtkPointPairFitSolver::KindSearchWork(static_cast<double>(start.size()),
      static_cast<double>(count), this->MaximumNumberOfIterations);
    if (work > this->MaximumKindSearchWork)
    {
      vtkErrorMacro(<< "the FitKinds search of " << start.size() << " generators on " << count
                    << " points may take up to "
                    << vtkPointPairFitSolver::MaximumKindFits(static_cast<double>(start.size()))
                    << " fits of " << this->MaximumNumberOfIterations
                    << " iterations: its work bound " << work << " (fits x (iterations + 1) x "
                    << "points x generators) exceeds MaximumKindSearchWork ("
                    << this->MaximumKindSearchWork
                    << "). Lower MaximumNumberOfIterations, fit fewer generators or points, or "
                       "raise MaximumKindSearchWork");
      return 1;
    }
  }

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
  vtkPointPairFitResult result;
  std::vector<bool> identified;
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

    std::string error;
    int fits = 1;
    const bool solved = this->FitKinds
      ? vtkPointPairFitSolver::SearchKinds(
          data, start, this->KindSeparation, result, identified, fits, error)
      : vtkPointPairFitSolver::Solve(data, start, start, 0.0, 1.0, result, error);
    if (!solved)
    {
      if (!error.empty())
      {
        vtkErrorMacro(<< error);
      }
      return; // an error, or aborted: empty outputs
    }
    this->NumberOfIterations = result.Iterations;
    this->NumberOfFits = fits;
    this->TerminationReason = result.Termination;
    this->Improved = result.Improved;
    this->InitialRMS = std::sqrt(result.InitialData);
    this->FinalRMS = this->Improved ? std::sqrt(result.FinalData) : this->InitialRMS;
    if (!this->Improved)
    {
      result.Generators = start; // a fit no better than its start keeps the start
    }
    if (!this->Improved && this->MaximumNumberOfIterations > 0) // 0: the start, evaluated
    {
      vtkWarningMacro(<< "the fit could not improve on the initial generators (RMS residual "
                      << this->InitialRMS << " after " << this->NumberOfIterations
                      << " iterations: " << this->TerminationReason
                      << "); the outputs are the initial generators and the mesh as they deform "
                         "it");
    }
    if (this->FitKinds)
    {
      if (!this->Improved)
      {
        identified.assign(start.size(), false); // the start's kinds were not chosen by the fit
      }
      std::string unidentified;
      this->NumberOfUnidentifiedKinds = 0;
      for (std::size_t g = 0; g < identified.size(); ++g)
      {
        if (!identified[g])
        {
          ++this->NumberOfUnidentifiedKinds;
          unidentified += (unidentified.empty() ? "" : ", ") + std::to_string(g);
        }
      }
      if (this->NumberOfUnidentifiedKinds > 0)
      {
        vtkWarningMacro(<< "the kinds of generators " << unidentified << " (of " << start.size()
                        << ") cannot be identified: another kind fits within KindSeparation ("
                        << this->KindSeparation
                        << ") times the initial cost (the target does not tell them apart); "
                           "their kinds are the best found, with KindIdentified 0");
      }
    }
    done = true;
  });
  if (!run || !done)
  {
    output->Initialize();
    return 1;
  }
  const std::vector<cga::GeneratorParameters>& fitted = result.Generators;

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
  vtkBoostedLargeArrays::SetNumberOfTuples(residual, count);
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType i = 0; i < count; ++i)
  {
    double q[3], t[3], distance = 0.0;
    deformed->GetPoint(i, q);
    if (data.Surface)
    {
      if (std::max({ std::fabs(q[0]), std::fabs(q[1]), std::fabs(q[2]) }) >
        vtkPointPairFitSolver::LargestSurfaceCoordinate)
      {
        // The fit kept its images within the range; a rounding of the final mapping must not
        // take one to the locator beyond it.
        vtkErrorMacro(<< "the image of point " << i << " lies beyond "
                      << vtkPointPairFitSolver::LargestSurfaceCoordinate
                      << ", where the target's cell locator overflows");
        output->Initialize();
        return 1;
      }
      vtkIdType cellId;
      int subId;
      double distance2 = 0.0;
      locator->FindClosestPoint(q, t, cell, cellId, subId, distance2);
      distance = std::sqrt(distance2);
    }
    else
    {
      target->GetPoint(i, t);
      distance = std::hypot(q[0] - t[0], q[1] - t[1], q[2] - t[2]); // no overflow of squares
    }
    if (!std::isfinite(distance))
    {
      // The fit's weighted cost was finite; a point of tiny weight may still be too far away.
      vtkErrorMacro(<< "the residual of point " << i << " overflows (its image and its target "
                    << "are near the largest double apart)");
      output->Initialize();
      return 1;
    }
    residual->SetValue(i, distance);
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

  // Outputs 1 and 2: the fitted generators as points and as a table of generator rows. The
  // points are written anew only when the fitted generators (and, with FitKinds, which kinds were
  // identified) differ from the last update's, to the bit: the cache compares what it would write.
  vtkBoostedGeneratorGlyphs glyphs(vtkBoostedGeneratorGlyphs::KindAndPitch |
    (this->FitKinds ? vtkBoostedGeneratorGlyphs::KindIdentified : 0));
  for (std::size_t g = 0; g < fitted.size(); ++g)
  {
    glyphs.Add(fitted[g], g < identified.size() && identified[g]);
  }
  glyphs.Write(generatorsOutput, this->GeneratorGlyphs);
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
  const auto name = [](const char* s) { return s ? s : "(none)"; };
  os << indent << "TargetMode: "
     << (this->TargetMode == POINT_TO_SURFACE ? "POINT_TO_SURFACE" : "POINT_TO_POINT") << "\n";
  os << indent << "PointWeightArrayName: " << name(this->PointWeightArrayName) << "\n";
  os << indent << "FitWeights: " << this->FitWeights << "\n";
  os << indent << "FitLocations: " << this->FitLocations << "\n";
  os << indent << "FitDirections: " << this->FitDirections << "\n";
  os << indent << "FitPitches: " << this->FitPitches << "\n";
  os << indent << "FitKinds: " << this->FitKinds << "\n";
  os << indent << "KindSeparation: " << this->KindSeparation << "\n";
  os << indent << "MaximumKindSearchWork: " << this->MaximumKindSearchWork << "\n";
  os << indent << "RegularizationWeight: " << this->RegularizationWeight << "\n";
  os << indent << "WeightRange: [" << this->WeightRange[0] << ", " << this->WeightRange[1]
     << "]\n";
  os << indent << "MaximumLocationChange: " << this->MaximumLocationChange << "\n";
  os << indent << "MaximumDirectionChange: " << this->MaximumDirectionChange << "\n";
  os << indent << "MaximumPitchChange: " << this->MaximumPitchChange << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "FunctionTolerance: " << this->FunctionTolerance << "\n";
  os << indent << "GradientTolerance: " << this->GradientTolerance << "\n";
  os << indent << "ParameterTolerance: " << this->ParameterTolerance << "\n";
  os << indent << "Last fit: " << this->NumberOfIterations << " iterations (" << this->NumberOfFits
     << " fits, " << this->NumberOfUnidentifiedKinds << " kinds unidentified), RMS residual "
     << this->InitialRMS << " -> " << this->FinalRMS << (this->Improved ? "" : " (not improved)")
     << ", " << (this->TerminationReason.empty() ? "(no fit)" : this->TerminationReason) << "\n";
}
