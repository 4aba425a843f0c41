#include "vtkPointPairDeformationFilter.h"

#include "vtkBoostedExponentialRule.h"
#include "vtkBoostedRowList.h"
#include "vtkBoostedSurfacesAbort.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkRectilinearGrid.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStructuredGrid.h"

#include "cga/PointPairField.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>

vtkStandardNewMacro(vtkPointPairDeformationFilter);

namespace
{
// Points handed to vtkSMPTools per progress step: large enough that the scheduling cost vanishes,
// small enough that progress and abort are seen often on big meshes.
constexpr vtkIdType PointsPerStep = 1 << 16;

bool isFinite(double x, double y, double z)
{
  return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

// Maps points [begin, end) of `in` to `out` with the kernel's batch map and writes the
// Displacement out - in (0 where the point was left in place because it is not finite).
template <typename In, typename Out>
struct DeformChunk
{
  const cga::PointPairField* Field;
  const In* InPoints;
  Out* OutPoints;
  Out* Displacement;
  double Strength;
  cga::ExponentialRule Rule;
  std::atomic<vtkIdType>* Unchanged;
  std::atomic<vtkIdType>* NonFiniteInputs;

  void operator()(vtkIdType begin, vtkIdType end) const
  {
    const In* in = this->InPoints + 3 * begin;
    Out* out = this->OutPoints + 3 * begin;
    Out* displacement = this->Displacement + 3 * begin;
    const vtkIdType count = end - begin;
    const std::size_t unchanged = this->Field->mapPoints(
      in, out, static_cast<std::size_t>(count), this->Strength, this->Rule);
    vtkIdType nonFinite = 0;
    for (vtkIdType i = 0; i < 3 * count; i += 3)
    {
      const double x = in[i], y = in[i + 1], z = in[i + 2];
      if (!isFinite(x, y, z))
      {
        ++nonFinite;
        displacement[i] = displacement[i + 1] = displacement[i + 2] = Out(0);
        continue;
      }
      displacement[i] = static_cast<Out>(out[i] - x);
      displacement[i + 1] = static_cast<Out>(out[i + 1] - y);
      displacement[i + 2] = static_cast<Out>(out[i + 2] - z);
    }
    *this->Unchanged += static_cast<vtkIdType>(unchanged);
    *this->NonFiniteInputs += nonFinite;
  }
};

// Reads the generators of the second input port; false with `problem` set on bad arrays.
bool readGeneratorPort(vtkPointSet* generators, const char* directionName, const char* weightName,
  bool useWeights, std::vector<cga::PointPairGenerator>& out, std::string& problem)
{
  const vtkIdType count = generators->GetNumberOfPoints();
  if (count == 0)
  {
    return true;
  }
  vtkPointData* pointData = generators->GetPointData();
  const std::string direction = directionName ? directionName : "";
  vtkAbstractArray* directionArray = pointData->GetAbstractArray(direction.c_str());
  if (direction.empty() || !directionArray)
  {
    problem = "the Generators input has no point array named '" + direction +
      "' (GeneratorDirectionArrayName)";
    return false;
  }
  vtkDataArray* directions = vtkDataArray::SafeDownCast(directionArray);
  if (!directions || directions->GetNumberOfComponents() != 3)
  {
    problem = "the Generators point array '" + direction +
      "' must be a numeric array of 3 components (directions), it is a " +
      directionArray->GetClassName() + " of " +
      std::to_string(directionArray->GetNumberOfComponents()) + " components";
    return false;
  }
  vtkDataArray* weights = nullptr;
  if (useWeights)
  {
    const std::string weight = weightName ? weightName : "";
    vtkAbstractArray* weightArray = pointData->GetAbstractArray(weight.c_str());
    if (weight.empty() || !weightArray)
    {
      problem = "the Generators input has no point array named '" + weight +
        "' (GeneratorWeightArrayName; turn UseGeneratorWeightArray off for unit weights)";
      return false;
    }
    weights = vtkDataArray::SafeDownCast(weightArray);
    if (!weights || weights->GetNumberOfComponents() != 1)
    {
      problem = "the Generators point array '" + weight +
        "' must be a numeric array of 1 component (weights), it is a " +
        weightArray->GetClassName() + " of " +
        std::to_string(weightArray->GetNumberOfComponents()) + " components";
      return false;
    }
  }
  out.reserve(out.size() + static_cast<std::size_t>(count));
  for (vtkIdType i = 0; i < count; ++i)
  {
    double x[3], v[3];
    generators->GetPoint(i, x);
    directions->GetTuple(i, v);
    out.push_back({ { x[0], x[1], x[2] }, { v[0], v[1], v[2] },
      weights ? weights->GetComponent(i, 0) : 1.0 });
  }
  return true;
}

// A vtkStructuredGrid with the points, extent and attributes of an image or rectilinear grid.
vtkSmartPointer<vtkStructuredGrid> toStructuredGrid(vtkDataSet* input, const int extent[6])
{
  auto grid = vtkSmartPointer<vtkStructuredGrid>::New();
  grid->SetExtent(const_cast<int*>(extent));
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(input->GetNumberOfPoints());
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    points->SetPoint(i, input->GetPoint(i));
  }
  grid->SetPoints(points);
  grid->GetPointData()->ShallowCopy(input->GetPointData());
  grid->GetCellData()->ShallowCopy(input->GetCellData());
  grid->GetFieldData()->ShallowCopy(input->GetFieldData());
  return grid;
}

template <typename In, typename Out>
void deformAll(vtkPointPairDeformationFilter* self, const cga::PointPairField& field,
  const In* in, Out* out, Out* displacement, vtkIdType count, double strength,
  cga::ExponentialRule rule, vtkIdType& unchanged, vtkIdType& nonFiniteInputs)
{
  std::atomic<vtkIdType> unchangedTotal(0), nonFiniteTotal(0);
  DeformChunk<In, Out> chunk{ &field, in, out, displacement, strength, rule, &unchangedTotal,
    &nonFiniteTotal };
  // Progress and abort are checked on this thread between steps; vtkSMPTools splits each step.
  for (vtkIdType begin = 0; begin < count; begin += PointsPerStep)
  {
    if (vtkBoostedSurfacesCheckAbort(self))
    {
      break;
    }
    const vtkIdType end = std::min(count, begin + PointsPerStep);
    vtkSMPTools::For(begin, end, 1024, chunk);
    self->UpdateProgress(static_cast<double>(end) / count);
  }
  unchanged = unchangedTotal;
  nonFiniteInputs = nonFiniteTotal;
}

template <typename In>
void deformTo(vtkPointPairDeformationFilter* self, const cga::PointPairField& field, const In* in,
  vtkDataArray* outPoints, vtkDataArray* displacement, vtkIdType count, double strength,
  cga::ExponentialRule rule, vtkIdType& unchanged, vtkIdType& nonFiniteInputs)
{
  if (auto* outDouble = vtkDoubleArray::SafeDownCast(outPoints))
  {
    deformAll(self, field, in, outDouble->GetPointer(0),
      vtkDoubleArray::SafeDownCast(displacement)->GetPointer(0), count, strength, rule, unchanged,
      nonFiniteInputs);
  }
  else
  {
    deformAll(self, field, in, vtkFloatArray::SafeDownCast(outPoints)->GetPointer(0),
      vtkFloatArray::SafeDownCast(displacement)->GetPointer(0), count, strength, rule, unchanged,
      nonFiniteInputs);
  }
}
} // namespace

vtkPointPairDeformationFilter::vtkPointPairDeformationFilter()
  : Generators(new vtkBoostedRowList(this, "Generator", std::vector<double>(7, 0.0)))
{
  this->SetNumberOfInputPorts(2);
  this->SetGeneratorDirectionArrayName("Direction");
  this->SetGeneratorWeightArrayName("Weight");
}

vtkPointPairDeformationFilter::~vtkPointPairDeformationFilter()
{
  this->SetGeneratorDirectionArrayName(nullptr);
  this->SetGeneratorWeightArrayName(nullptr);
}

int vtkPointPairDeformationFilter::AddGenerator(
  double x, double y, double z, double vx, double vy, double vz, double weight)
{
  return this->Generators->Add({ x, y, z, vx, vy, vz, weight });
}

void vtkPointPairDeformationFilter::SetGenerator(
  int index, double x, double y, double z, double vx, double vy, double vz, double weight)
{
  this->Generators->Set(index, { x, y, z, vx, vy, vz, weight });
}

vtkBoostedRowListMethods(vtkPointPairDeformationFilter, Generator, Generators)

void vtkPointPairDeformationFilter::SetGeneratorsConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkPointPairDeformationFilter::SetGeneratorsData(vtkDataObject* data)
{
  this->SetInputData(1, data);
}

int vtkPointPairDeformationFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Remove(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE());
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkRectilinearGrid");
    return 1;
  }
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkPointPairDeformationFilter::RequestDataObject(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  // Images and rectilinear grids cannot hold moved points: they become structured grids.
  if (vtkImageData::GetData(inputVector[0]) || vtkRectilinearGrid::GetData(inputVector[0]))
  {
    if (!vtkStructuredGrid::GetData(outputVector))
    {
      vtkNew<vtkStructuredGrid> output;
      outputVector->GetInformationObject(0)->Set(vtkDataObject::DATA_OBJECT(), output);
    }
    return 1;
  }
  return this->Superclass::RequestDataObject(request, inputVector, outputVector);
}

int vtkPointPairDeformationFilter::ComputeInputUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The mesh (port 0) gets the downstream piece request unchanged; the generators are needed
  // whole on every rank, or the field would differ from piece to piece.
  vtkInformation* generatorsInfo = inputVector[1]->GetInformationObject(0);
  if (generatorsInfo)
  {
    generatorsInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    generatorsInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    generatorsInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    if (generatorsInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
    {
      generatorsInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(),
        generatorsInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()), 6);
    }
  }
  return 1;
}

int vtkPointPairDeformationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkDataSet* input = vtkDataSet::GetData(inputVector[0]);
  vtkPointSet* output = vtkPointSet::GetData(outputVector);
  if (!input || !output)
  {
    return 0;
  }

  vtkSmartPointer<vtkPointSet> source = vtkPointSet::SafeDownCast(input);
  if (auto* image = vtkImageData::SafeDownCast(input))
  {
    source = toStructuredGrid(image, image->GetExtent());
  }
  else if (auto* grid = vtkRectilinearGrid::SafeDownCast(input))
  {
    source = toStructuredGrid(grid, grid->GetExtent());
  }

  // The clamp macros let NaN through.
  if (!std::isfinite(this->Strength) || std::isnan(this->Falloff) || std::isnan(this->Epsilon))
  {
    vtkErrorMacro(<< "Strength must be finite and Falloff and Epsilon numbers; they are "
                  << this->Strength << ", " << this->Falloff << " and " << this->Epsilon);
    return 1; // the output stays empty
  }

  // The list, with the selected generator moved to the handle's location, then the second port.
  if (!this->Generators->CheckForUpdate())
  {
    return 1; // the output stays empty
  }
  std::vector<cga::PointPairGenerator> generators;
  for (int i = 0; i < this->GetNumberOfGenerators(); ++i)
  {
    const double* g = this->Generators->Row(i);
    const double* location =
      this->Generators->Location(i, this->SelectedGenerator, this->SelectedGeneratorLocation);
    generators.push_back(
      { { location[0], location[1], location[2] }, { g[3], g[4], g[5] }, g[6] });
  }
  if (vtkPointSet* generatorSet = vtkPointSet::GetData(inputVector[1]))
  {
    std::string problem;
    if (!readGeneratorPort(generatorSet, this->GeneratorDirectionArrayName,
          this->GeneratorWeightArrayName, this->UseGeneratorWeightArray, generators, problem))
    {
      vtkErrorMacro(<< problem);
      return 1;
    }
  }
  const cga::PointPairField field(generators, this->Falloff, this->Epsilon);
  if (field.skippedGenerators() > 0)
  {
    vtkWarningMacro(<< field.skippedGenerators() << " of " << generators.size()
                    << " generators were ignored: their direction is zero, or their location, "
                       "direction or weight is not finite");
  }

  // Same topology, cells and arrays; normals would be wrong after the warp, so they are dropped.
  output->CopyStructure(source);
  output->GetPointData()->CopyNormalsOff();
  output->GetPointData()->PassData(source->GetPointData());
  output->GetCellData()->CopyNormalsOff();
  output->GetCellData()->PassData(source->GetCellData());
  output->GetFieldData()->PassData(source->GetFieldData());

  vtkPoints* inPoints = source->GetPoints();
  const vtkIdType count = inPoints ? inPoints->GetNumberOfPoints() : 0;
  if (count == 0)
  {
    return 1;
  }
  int outputType = inPoints->GetDataType() == VTK_FLOAT ? VTK_FLOAT : VTK_DOUBLE;
  if (this->OutputPointsPrecision == SINGLE_PRECISION)
  {
    outputType = VTK_FLOAT;
  }
  else if (this->OutputPointsPrecision == DOUBLE_PRECISION)
  {
    outputType = VTK_DOUBLE;
  }
  vtkNew<vtkPoints> outPoints;
  outPoints->SetDataType(outputType);
  outPoints->SetNumberOfPoints(count);
  vtkSmartPointer<vtkDataArray> displacement =
    vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(outputType));
  displacement->SetName("Displacement");
  displacement->SetNumberOfComponents(3);
  displacement->SetNumberOfTuples(count);

  // The kernel reads float or double; other point types are read through a double copy.
  vtkSmartPointer<vtkDataArray> inData = inPoints->GetData();
  if (inPoints->GetDataType() != VTK_FLOAT && inPoints->GetDataType() != VTK_DOUBLE)
  {
    vtkNew<vtkDoubleArray> copy;
    copy->DeepCopy(inPoints->GetData());
    inData = copy;
  }

  const cga::ExponentialRule rule =
    vtkBoostedExponentialRule<vtkPointPairDeformationFilter>(this->ExponentialRule);
  vtkIdType unchanged = 0, nonFiniteInputs = 0;
  if (auto* inFloat = vtkFloatArray::SafeDownCast(inData))
  {
    deformTo(this, field, inFloat->GetPointer(0), outPoints->GetData(), displacement, count,
      this->Strength, rule, unchanged, nonFiniteInputs);
  }
  else
  {
    deformTo(this, field, vtkDoubleArray::SafeDownCast(inData)->GetPointer(0),
      outPoints->GetData(), displacement, count, this->Strength, rule, unchanged,
      nonFiniteInputs);
  }
  if (vtkBoostedSurfacesCheckAbort(this))
  {
    output->Initialize(); // aborted: no half-deformed mesh
    return 1;
  }
  if (unchanged > 0)
  {
    vtkWarningMacro(<< unchanged << " of " << count << " points were left in place: "
                    << nonFiniteInputs << " are NaN or infinite, " << unchanged - nonFiniteInputs
                    << " have an image that is not finite (at infinity, or the field overflowed "
                       "for huge weights)");
  }
  output->SetPoints(outPoints);
  output->GetPointData()->AddArray(displacement);
  return 1;
}

void vtkPointPairDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->Generators->Print(os, indent);
  os << indent << "SelectedGenerator: " << this->SelectedGenerator << "\n";
  os << indent << "SelectedGeneratorLocation: (" << this->SelectedGeneratorLocation[0] << ", "
     << this->SelectedGeneratorLocation[1] << ", " << this->SelectedGeneratorLocation[2] << ")\n";
  os << indent << "GeneratorDirectionArrayName: "
     << (this->GeneratorDirectionArrayName ? this->GeneratorDirectionArrayName : "(none)") << "\n";
  os << indent << "GeneratorWeightArrayName: "
     << (this->GeneratorWeightArrayName ? this->GeneratorWeightArrayName : "(none)") << "\n";
  os << indent << "UseGeneratorWeightArray: " << this->UseGeneratorWeightArray << "\n";
  os << indent << "Strength: " << this->Strength << "\n";
  os << indent << "Falloff: " << this->Falloff << "\n";
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  os << indent << "ExponentialRule: " << (this->ExponentialRule == PAPER ? "PAPER" : "EXACT")
     << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
}
