#include "vtkDipoleFieldSource.h"

#include "vtkBoostedBlockLoop.h"
#include "vtkBoostedExponentialRule.h"
#include "vtkBoostedGeneratorGlyphs.h"
#include "vtkBoostedGeneratorRows.h"
#include "vtkBoostedLargeArrays.h"
#include "vtkBoostedMemoryBudget.h"
#include "vtkBoostedRowList.h"
#include "vtkBoostedSinglePrecision.h"
#include "vtkBoostedTimeSweep.h"
#include "vtkAOSDataArrayTemplate.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "cga/DipoleField.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

vtkStandardNewMacro(vtkDipoleFieldSource);

namespace
{
// The most points one update computes: a larger request is an error instead of a failed
// allocation; a larger grid can be streamed in pieces.
constexpr double MaximumPointsPerUpdate = 1e8;
// The update's memory per point for vtkBoostedMemoryBudget: its five arrays (11 values a point)
// and the work buffers of the blocks; measured once as the peak resident memory of a 2000 x 2000
// grid (90.0 and 46.0 bytes a point).
constexpr double BytesPerPointDouble = 90;
constexpr double BytesPerPointSingle = 46;

vtkSmartPointer<vtkDataArray> newArray(int precision, const char* name, int components, vtkIdType n)
{
  vtkSmartPointer<vtkDataArray> array;
  if (precision == vtkAlgorithm::SINGLE_PRECISION)
  {
    array = vtkSmartPointer<vtkFloatArray>::New();
  }
  else
  {
    array = vtkSmartPointer<vtkDoubleArray>::New();
  }
  array->SetName(name);
  array->SetNumberOfComponents(components);
  vtkBoostedLargeArrays::SetNumberOfTuples(array, n);
  return array;
}

// Points begin ... begin + n - 1 of the extent (ids from 0, x fastest), interleaved.
void gridPoints(const int extent[6], const double origin[3], const double spacing[3],
  vtkIdType begin, std::size_t n, double* points)
{
  const vtkIdType nx = extent[1] - extent[0] + 1;
  const vtkIdType ny = extent[3] - extent[2] + 1;
  // The first point's structured index (i, j, k) in the extent, then one step at a time.
  vtkIdType index[3] = { begin % nx, (begin / nx) % ny, begin / (nx * ny) };
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      points[3 * i + c] = origin[c] + (extent[2 * c] + index[c]) * spacing[c];
    }
    if (++index[0] == nx)
    {
      index[0] = 0;
      if (++index[1] == ny)
      {
        index[1] = 0;
        ++index[2];
      }
    }
  }
}

// The arrays of one extent (values of type T: float or double), filled by chunks of points from
// several threads.
template <typename T>
struct FieldFunctor
{
  const cga::DipoleField* Field;
  double WeightScale;
  int Extent[6];
  double Origin[3];
  double Spacing[3];
  T* SummedGenerators;
  T* SummedDisplacements;
  T* Difference;
  T* DifferenceMagnitude;
  T* Potential;
  std::atomic<std::size_t>* Failures;
  std::atomic<double>* Largest; // of the values written, for single precision's range

  // The points of a chunk go through sampleMany at most SubChunk at a time, in one scratch
  // buffer per chunk that is not cleared (sampleMany writes every value): the same doubles per
  // point of a whole chunk, zeroed, were 13 MB of memset and page faults per 10^6 points.
  static constexpr vtkIdType SubChunk = 4096;
  // Per point: the point, method (a)'s and (b)'s displacements, the potential, sampleMany's
  // scratch.
  static constexpr std::size_t DoublesPerPoint = 3 + 3 + 3 + 1 + 3;

  void operator()(vtkIdType begin, vtkIdType end)
  {
    const std::size_t most = static_cast<std::size_t>(std::min(end - begin, SubChunk));
    const std::unique_ptr<double[]> buffer(new double[DoublesPerPoint * most]);
    for (vtkIdType first = begin; first < end; first += SubChunk)
    {
      this->Sample(first, std::min(end, first + SubChunk), buffer.get());
    }
  }

  void Sample(vtkIdType begin, vtkIdType end, double* buffer)
  {
    const std::size_t n = static_cast<std::size_t>(end - begin);
    double* const points = buffer;
    double* const a = points + 3 * n;
    double* const b = a + 3 * n;
    double* const phi = b + 3 * n;
    double* const scratch = phi + n;
    gridPoints(this->Extent, this->Origin, this->Spacing, begin, n, points);
    *this->Failures +=
      this->Field->sampleMany(points, n, this->WeightScale, a, b, phi, scratch);
    // Huge weights of translations, twists or dilations move points by up to ~1e308, and sums of
    // such displacements overflow: every value saturates at the largest double (a float output
    // beyond the largest float is then the single-precision error, through `largest`).
    const double limit = std::numeric_limits<double>::max();
    const auto saturated = [limit](double value)
    { return std::isnan(value) ? 0.0 : std::max(-limit, std::min(limit, value)); };
    double largest = 0.0; // of the values written (all finite)
    for (std::size_t i = 0; i < n; ++i)
    {
      const vtkIdType id = begin + static_cast<vtkIdType>(i);
      double difference[3];
      for (int c = 0; c < 3; ++c)
      {
        const double summedGenerators = saturated(a[3 * i + c]);
        const double summedDisplacements = saturated(b[3 * i + c]);
        difference[c] = saturated(summedGenerators - summedDisplacements);
        this->SummedGenerators[3 * id + c] = static_cast<T>(summedGenerators);
        this->SummedDisplacements[3 * id + c] = static_cast<T>(summedDisplacements);
        this->Difference[3 * id + c] = static_cast<T>(difference[c]);
        // The magnitude of (a) - (b) is at least each of its components.
        largest = std::max({ largest, std::fabs(summedGenerators), std::fabs(summedDisplacements) });
      }
      // no spurious overflow
      const double magnitude =
        saturated(cga::norm({ difference[0], difference[1], difference[2] }));
      const double potential = saturated(phi[i]);
      this->DifferenceMagnitude[id] = static_cast<T>(magnitude);
      this->Potential[id] = static_cast<T>(potential);
      largest = std::max({ largest, magnitude, std::fabs(potential) });
    }
    double seen = this->Largest->load();
    while (largest > seen && !this->Largest->compare_exchange_weak(seen, largest))
    {
    }
  }
};

// Fills the five arrays of values of type T in the block loop; false when aborted.
template <typename T>
bool fillArrays(vtkAlgorithm* algorithm, FieldFunctor<T> functor,
  vtkDataArray* const arrays[5], vtkIdType n)
{
  T* pointers[5];
  for (int k = 0; k < 5; ++k)
  {
    pointers[k] = vtkAOSDataArrayTemplate<T>::FastDownCast(arrays[k])->GetPointer(0);
  }
  functor.SummedGenerators = pointers[0];
  functor.SummedDisplacements = pointers[1];
  functor.Difference = pointers[2];
  functor.DifferenceMagnitude = pointers[3];
  functor.Potential = pointers[4];
  return vtkBoostedBlockLoop::For(algorithm, 0, n, 1, functor);
}
} // namespace

vtkDipoleFieldSource::vtkDipoleFieldSource()
  : Generators(new vtkBoostedRowList(this, "Generator", vtkBoostedGeneratorRows::BlankRow()))
{
  static_assert(vtkBoostedGeneratorKinds<vtkDipoleFieldSource>(), "");
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2); // the field, the generators
  this->AddGenerator(0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.5);
}

vtkDipoleFieldSource::~vtkDipoleFieldSource() = default;

vtkBoostedGeneratorRowMethods(vtkDipoleFieldSource, Generators)

std::string vtkDipoleFieldSource::Validate() const
{
  if (!this->Generators->Problem().empty())
  {
    return this->Generators->Problem();
  }
  for (int c = 0; c < 3; ++c)
  {
    if (this->Dimensions[c] < 1)
    {
      return "Dimensions must be at least 1 in every direction";
    }
    if (!std::isfinite(this->Spacing[c]) || !(this->Spacing[c] > 0.0))
    {
      return "Spacing must be positive and finite in every direction";
    }
    if (!std::isfinite(this->Origin[c]))
    {
      return "Origin must be finite";
    }
    // The grid's last point, computed as RequestData computes every point.
    if (!std::isfinite(this->Origin[c] + (this->Dimensions[c] - 1) * this->Spacing[c]))
    {
      return "the grid overflows: Origin + (Dimensions - 1) Spacing is not finite in every direction";
    }
  }
  if (!std::isfinite(this->Falloff) || !std::isfinite(this->Epsilon))
  {
    return "Falloff and Epsilon must be finite";
  }
  if (!(this->Tolerance >= 0.0))
  {
    return "Tolerance must be 0 or positive";
  }
  for (double t : this->GeneratorsTranslation)
  {
    if (!std::isfinite(t))
    {
      return "GeneratorsTranslation must be finite";
    }
  }
  if (this->SelectedGenerator >= 0 && this->SelectedGenerator < this->GetNumberOfGenerators())
  {
    for (int c = 0; c < 3; ++c)
    {
      if (!std::isfinite(this->SelectedGeneratorLocation[c]) ||
        (this->AimSelectedGenerator && !std::isfinite(this->SelectedGeneratorTip[c])))
      {
        return "SelectedGeneratorLocation and SelectedGeneratorTip must be finite";
      }
    }
  }
  for (int i = 0; i < this->GetNumberOfGenerators(); ++i)
  {
    for (int c = 0; c < this->Generators->GetNumberOfValuesPerRow(); ++c)
    {
      if (!std::isfinite(this->Generators->Row(i)[c]))
      {
        std::ostringstream message;
        message << "generator " << i << " has a value that is not finite";
        return message.str();
      }
    }
    cga::GeneratorKind kind;
    std::string problem;
    if (!vtkBoostedGeneratorRows::ReadKind(this->Generators->Row(i)[vtkBoostedGeneratorRows::KindValue],
          "generator row " + std::to_string(i), kind, problem))
    {
      return problem;
    }
  }
  return {};
}

int vtkDipoleFieldSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int wholeExtent[6] = { 0, -1, 0, -1, 0, -1 }; // empty when the grid is invalid
  if (this->Validate().empty())
  {
    for (int c = 0; c < 3; ++c)
    {
      wholeExtent[2 * c + 1] = this->Dimensions[c] - 1;
    }
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), wholeExtent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), this->Origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), this->Spacing, 3);
  outInfo->Set(CAN_PRODUCE_SUB_EXTENT(), 1);
  vtkDataObject::SetPointDataActiveScalarInfo(
    outInfo, this->OutputPointsPrecision == SINGLE_PRECISION ? VTK_FLOAT : VTK_DOUBLE, 1);

  // Extents, not pieces (CAN_PRODUCE_SUB_EXTENT above).
  vtkBoostedTimeSweep::ReportOnEveryPort(outputVector, this->NumberOfTimeSteps, false);
  return 1;
}

int vtkDipoleFieldSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  output->Initialize();

  const std::string problem = this->Validate();
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return 1; // the output stays empty
  }

  // Only the requested extent, clipped to the whole grid.
  int extent[6] = { 0, this->Dimensions[0] - 1, 0, this->Dimensions[1] - 1, 0,
    this->Dimensions[2] - 1 }; // the whole grid when only the generators were requested
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  }
  for (int c = 0; c < 3; ++c)
  {
    extent[2 * c] = std::max(extent[2 * c], 0);
    extent[2 * c + 1] = std::min(extent[2 * c + 1], this->Dimensions[c] - 1);
    if (extent[2 * c] > extent[2 * c + 1])
    {
      this->WriteGenerators(outputVector);
      return 1; // an empty request
    }
  }
  // Counted in double: the product of three int dimensions may overflow vtkIdType.
  const double requested = (extent[1] - extent[0] + 1.0) * (extent[3] - extent[2] + 1.0) *
    (extent[5] - extent[4] + 1.0);
  if (requested > MaximumPointsPerUpdate)
  {
    vtkErrorMacro(<< "the requested extent holds " << requested << " points, more than the "
                  << MaximumPointsPerUpdate
                  << " one update computes: lower Dimensions or request smaller pieces");
    return 1; // the output stays empty
  }
  const double bytesPerPoint =
    this->OutputPointsPrecision == SINGLE_PRECISION ? BytesPerPointSingle : BytesPerPointDouble;
  const std::string memoryProblem = vtkBoostedMemoryBudget::Problem(requested * bytesPerPoint,
    "the dipole field's extent of " + std::to_string(static_cast<long long>(requested)) +
      " points");
  if (!memoryProblem.empty())
  {
    vtkErrorMacro(<< memoryProblem);
    return 1; // the output stays empty
  }
  output->SetExtent(extent);
  output->SetOrigin(this->Origin);
  output->SetSpacing(this->Spacing);

  // The time sweep grows the weights from 0 to their values.
  const double weightScale = vtkBoostedTimeSweep::Fraction(outInfo, this->NumberOfTimeSteps);
  vtkBoostedTimeSweep::StampTime(outInfo, this->NumberOfTimeSteps, output);

  // The rows were validated (finite values, known kinds) by Validate().
  std::vector<cga::GeneratorParameters> generators(this->GetNumberOfGenerators());
  for (int i = 0; i < this->GetNumberOfGenerators(); ++i)
  {
    generators[i] = this->GeneratorAsUsed(i);
  }
  cga::DipoleField field(generators.data(), generators.size(), this->Falloff,
    this->Epsilon, vtkBoostedExponentialRule<vtkDipoleFieldSource>(this->ExponentialRule));

  const vtkIdType n = output->GetNumberOfPoints();
  const int precision = this->OutputPointsPrecision;
  vtkSmartPointer<vtkDataArray> summedGenerators, summedDisplacements, difference,
    differenceMagnitude, potential;
  if (!vtkBoostedMemoryBudget::Run(this, [&] {
        field.setTolerance(this->Tolerance); // the tree: O(M), a few hundred bytes per generator
        field.planTreeCells(static_cast<std::size_t>(n), // its cells fitted to the grid's points
          [&](std::size_t first, std::size_t count, double* xyz) {
            gridPoints(extent, this->Origin, this->Spacing, static_cast<vtkIdType>(first), count,
              xyz);
          });
        summedGenerators = newArray(precision, "DisplacementSummedGenerators", 3, n);
        summedDisplacements = newArray(precision, "DisplacementSummedDisplacements", 3, n);
        difference = newArray(precision, "DisplacementDifference", 3, n);
        differenceMagnitude = newArray(precision, "DisplacementDifferenceMagnitude", 1, n);
        potential = newArray(precision, "DipolePotential", 1, n);
      }))
  {
    output->Initialize();
    return 1; // the output stays empty
  }

  std::atomic<std::size_t> failures{ 0 };
  std::atomic<double> largest{ 0.0 };
  vtkDataArray* const arrays[5] = { summedGenerators, summedDisplacements, difference,
    differenceMagnitude, potential };
  // The extent's point ids run from 0; each chunk writes its own range of every array.
  auto fill = [&](auto functor) {
    functor.Field = &field;
    functor.WeightScale = weightScale;
    std::copy_n(extent, 6, functor.Extent);
    std::copy_n(this->Origin, 3, functor.Origin);
    std::copy_n(this->Spacing, 3, functor.Spacing);
    functor.Failures = &failures;
    functor.Largest = &largest;
    return fillArrays(this, functor, arrays, n);
  };
  bool completed = false;
  if (!vtkBoostedMemoryBudget::Run(this,
        [&] {
          completed = precision == SINGLE_PRECISION ? fill(FieldFunctor<float>{})
                                                    : fill(FieldFunctor<double>{});
        }) ||
    !completed)
  {
    output->Initialize(); // aborted or out of memory: never hand on half-filled arrays
    return 1;
  }
  const std::string rangeProblem = precision == SINGLE_PRECISION
    ? vtkBoostedSinglePrecisionProblem(largest, "the displacements or the potential")
    : std::string();
  if (!rangeProblem.empty())
  {
    vtkErrorMacro(<< rangeProblem);
    output->Initialize();
    return 1;
  }
  if (failures > 0)
  {
    vtkWarningMacro(<< failures
                    << " boost(s) sent a grid point to infinity, or their B(p) overflowed (a "
                       "weight near 1e300 or above); their displacements are zero");
  }

  vtkPointData* pointData = output->GetPointData();
  pointData->AddArray(summedGenerators);
  pointData->AddArray(summedDisplacements);
  pointData->AddArray(difference);
  pointData->AddArray(differenceMagnitude);
  pointData->SetScalars(potential);
  pointData->SetVectors(summedGenerators);
  this->WriteGenerators(outputVector);
  return 1;
}

int vtkDipoleFieldSource::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    vtkBoostedGeneratorGlyphs::FillOutputPortInformation(info);
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

cga::GeneratorParameters vtkDipoleFieldSource::GeneratorAsUsed(int index) const
{
  double used[vtkBoostedGeneratorRows::NumberOfValues];
  const double* row = vtkBoostedGeneratorRows::Selected(this->Generators->Row(index), index,
    { this->SelectedGenerator, this->SelectedGeneratorLocation, this->AimSelectedGenerator,
      this->SelectedGeneratorTip },
    used);
  const double* t = this->GeneratorsTranslation;
  const double translated[3] = { row[0] + t[0], row[1] + t[1], row[2] + t[2] };
  cga::GeneratorParameters generator;
  std::string problem;
  // The selected row stays at the line's start: GeneratorsTranslation does not move it.
  const bool selected = row == used;
  vtkBoostedGeneratorRows::Read(row, selected ? row : translated, index, generator, problem);
  return generator; // the rows were validated
}

void vtkDipoleFieldSource::WriteGenerators(vtkInformationVector* outputVector)
{
  vtkInformation* info = outputVector->GetInformationObject(1);
  vtkPolyData* output = vtkPolyData::GetData(info);
  if (vtkBoostedGeneratorGlyphs::OnFirstPiece(outputVector))
  {
    // The rows as the field uses them, weights at this time.
    const double weightScale =
      vtkBoostedTimeSweep::Fraction(outputVector->GetInformationObject(0), this->NumberOfTimeSteps);
    vtkBoostedGeneratorGlyphs glyphs(vtkBoostedGeneratorGlyphs::KindAndPitch);
    for (int i = 0; i < this->GetNumberOfGenerators(); ++i)
    {
      cga::GeneratorParameters generator = this->GeneratorAsUsed(i);
      generator.weight *= weightScale;
      glyphs.Add(generator);
    }
    glyphs.Write(output, this->GeneratorGlyphs);
  }
  vtkBoostedTimeSweep::StampTime(info, this->NumberOfTimeSteps, output);
}

void vtkDipoleFieldSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Origin: (" << this->Origin[0] << ", " << this->Origin[1] << ", "
     << this->Origin[2] << ")\n";
  os << indent << "Spacing: (" << this->Spacing[0] << ", " << this->Spacing[1] << ", "
     << this->Spacing[2] << ")\n";
  os << indent << "Dimensions: (" << this->Dimensions[0] << ", " << this->Dimensions[1] << ", "
     << this->Dimensions[2] << ")\n";
  this->Generators->Print(os, indent);
  os << indent << "GeneratorsTranslation: (" << this->GeneratorsTranslation[0] << ", "
     << this->GeneratorsTranslation[1] << ", " << this->GeneratorsTranslation[2] << ")\n";
  vtkBoostedGeneratorRows::PrintSelection(os, indent,
    { this->SelectedGenerator, this->SelectedGeneratorLocation, this->AimSelectedGenerator,
      this->SelectedGeneratorTip });
  os << indent << "Falloff: " << this->Falloff << "\n";
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "ExponentialRule: " << (this->ExponentialRule == PAPER ? "PAPER" : "EXACT")
     << "\n";
  os << indent << "NumberOfTimeSteps: " << this->NumberOfTimeSteps << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
}
