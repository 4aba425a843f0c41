#include "vtkPointPairDeformationFilter.h"

#include "vtkAOSDataArrayTemplate.h"
#include "vtkArrayDispatch.h"
#include "vtkBoostedBlockLoop.h"
#include "vtkBoostedExponentialRule.h"
#include "vtkBoostedGeneratorGlyphs.h"
#include "vtkBoostedGeneratorRows.h"
#include "vtkBoostedLargeArrays.h"
#include "vtkBoostedMemoryBudget.h"
#include "vtkBoostedTimeSweep.h"
#include "vtkBoostedRowList.h"
#include "vtkBoostedSinglePrecision.h"
#include "vtkBoostedSurfacesAbort.h"
#include "vtkBoostedWholeInput.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDoubleArray.h"
#include "vtkImageData.h"
#include "vtkImageDataToPointSet.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointPairJacobianArrays.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkPoints.h"
#include "vtkRectilinearGrid.h"
#include "vtkRectilinearGridToPointSet.h"
#include "vtkSOADataArrayTemplate.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStructuredData.h"
#include "vtkStructuredGrid.h"
#include "vtkStructuredGridAlgorithm.h"

#include "cga/PointPairField.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <string>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkPointPairDeformationFilter);

namespace
{
bool isFinite(double x, double y, double z)
{
  return std::isfinite(x) && std::isfinite(y) && std::isfinite(z);
}

// Points copied per pass through the local buffer of the copy path: a few kilobytes on the stack
// of each SMP thread.
constexpr vtkIdType BufferedPoints = 256;
// The progress text while the generator tree is built (the header's Tolerance).
constexpr const char* kBuildingTree = "Building the generator tree";

// Deforms every point of an input point array into the output points and their Displacement
// (out - in; 0 where a point is left in place because it is not finite). vtkArrayDispatch calls it
// with the array's concrete type (AOS or SOA, float or double), or with the vtkDataArray for any
// other array. AOS arrays are read in place by the kernel's batch map; any other array (SOA,
// implicit, integer values) is copied chunk by chunk into a small buffer of doubles. The kernel
// turns every coordinate into a double before computing, so both paths give the same bits.
template <typename Out>
struct DeformWorker
{
  vtkPointPairDeformationFilter* Filter;
  const cga::PointPairField* Field;
  double Strength;
  cga::ExponentialRule Rule;
  Out* OutPoints;
  Out* Displacement;
  // The arrays from J, or null: then mapPoints alone. With them mapPointsWithJacobians, whose
  // images are mapPoints' bit for bit (with the tree of Tolerance too: J is then the tree's).
  vtkPointPairJacobianArrays* Derivatives = nullptr;
  // Whether the field has a tree: then each chunk goes through the map with J in one call, whose
  // points share the tree's cells (their local expansions), not BufferedPoints at a time.
  bool TreeField = false;
  std::atomic<vtkIdType> Unchanged{ 0 };
  std::atomic<vtkIdType> NonFiniteInputs{ 0 };
  std::atomic<vtkIdType> BeyondOutputType{ 0 };

  template <typename InArray>
  void operator()(InArray* points)
  {
    // The project's one work loop: blocks with progress and abort between them, each block split
    // by vtkSMPTools. An aborted update is caught by the caller (CheckAbort).
    vtkBoostedBlockLoop::For(this->Filter, 0, points->GetNumberOfTuples(), 1,
      [this, points](vtkIdType first, vtkIdType last) { this->mapRange(points, first, last); });
  }

  template <typename InArray>
  void mapRange(InArray* points, vtkIdType begin, vtkIdType end)
  {
    using Value = vtk::GetAPIType<InArray>;
    if constexpr (std::is_base_of<vtkAOSDataArrayTemplate<Value>, InArray>::value)
    {
      this->mapChunk(points->GetPointer(3 * begin), begin, end - begin);
    }
    else
    {
      double buffer[3 * BufferedPoints];
      const auto tuples = vtk::DataArrayTupleRange<3>(points, begin, end);
      for (vtkIdType first = begin; first < end; first += BufferedPoints)
      {
        const vtkIdType count = std::min(BufferedPoints, end - first);
        double* value = buffer;
        for (const auto tuple : tuples.GetSubRange(first - begin, first - begin + count))
        {
          *value++ = static_cast<double>(tuple[0]);
          *value++ = static_cast<double>(tuple[1]);
          *value++ = static_cast<double>(tuple[2]);
        }
        this->mapChunk(buffer, first, count);
      }
    }
  }

  // Maps `count` points, xyz interleaved in `in`, to output points first, first + 1, ...
  template <typename In>
  void mapChunk(const In* in, vtkIdType first, vtkIdType count)
  {
    if (this->Derivatives)
    {
      this->mapChunkWithJacobians(in, first, count);
      return;
    }
    // The displacements and counts in the kernel's pass over the points (not a second one).
    const cga::PointPairField::DisplacementCounts counts =
      this->Field->mapPointsWithDisplacements(in, this->OutPoints + 3 * first,
        this->Displacement + 3 * first, static_cast<std::size_t>(count), this->Strength,
        this->Rule);
    this->Unchanged += static_cast<vtkIdType>(counts.unchanged);
    this->NonFiniteInputs += static_cast<vtkIdType>(counts.notFinite);
    this->BeyondOutputType += static_cast<vtkIdType>(counts.beyondRange);
  }

  // mapChunk with J: the batch map with Jacobians takes doubles, so float points are converted
  // (exactly) and the images rounded to Out as mapPoints rounds them, BufferedPoints at a time
  // (with a tree the whole chunk at once).
  // When the only output is one normals array, J along the normal's two tangents suffices
  // (mapPointsWithDirectionalDerivatives: two tangents through the map instead of three).
  template <typename In>
  void mapChunkWithJacobians(const In* in, vtkIdType first, vtkIdType count)
  {
    // Per point: its coordinates as doubles (3), its image (3), J or J along two tangents (9)
    // and the tangents (6).
    constexpr vtkIdType kPerPoint = 21;
    double onStack[kPerPoint * BufferedPoints];
    std::vector<double> onHeap;
    vtkIdType step = BufferedPoints;
    double* buffers = onStack;
    if (this->TreeField && count > BufferedPoints)
    {
      step = count;
      onHeap.resize(static_cast<std::size_t>(kPerPoint * count));
      buffers = onHeap.data();
    }
    double* points = buffers;
    double* images = points + 3 * step;
    double* jacobians = images + 3 * step;
    double* tangents = jacobians + 9 * step;
    const bool oneNormal = this->Derivatives->OnlyOneNormal();
    for (vtkIdType done = 0; done < count; done += step)
    {
      const vtkIdType n = std::min(step, count - done);
      const In* chunk = in + 3 * done;
      const double* asDoubles = points;
      if constexpr (std::is_same<In, double>::value)
      {
        asDoubles = chunk;
      }
      else
      {
        std::copy(chunk, chunk + 3 * n, points);
      }
      std::size_t withoutJacobian = 0;
      if (oneNormal)
      {
        this->Derivatives->Tangents(first + done, n, tangents);
        withoutJacobian = this->Field->mapPointsWithDirectionalDerivatives(asDoubles, tangents,
          images, jacobians, static_cast<std::size_t>(n), this->Strength, this->Rule);
      }
      else
      {
        withoutJacobian = this->Field->mapPointsWithJacobians(asDoubles, images, jacobians,
          static_cast<std::size_t>(n), this->Strength, this->Rule);
      }
      std::size_t unchanged = withoutJacobian;
      Out* out = this->OutPoints + 3 * (first + done);
      // A point whose J is not finite (huge weights) is left in place by the batch map with
      // Jacobians while mapPoints maps it: where there is such a point (or one not mapped at
      // all, which is rare) the chunk's images come from mapPoints.
      if (withoutJacobian > 0)
      {
        unchanged = this->Field->mapPoints(
          chunk, out, static_cast<std::size_t>(n), this->Strength, this->Rule);
        this->Derivatives->NonFiniteJacobians +=
          static_cast<vtkIdType>(withoutJacobian - std::min(withoutJacobian, unchanged));
      }
      else
      {
        std::transform(images, images + 3 * n, out, [](double x) { return static_cast<Out>(x); });
      }
      this->finishChunk(chunk, first + done, n, unchanged);
      if (oneNormal)
      {
        this->Derivatives->WriteNormal(first + done, n, tangents, jacobians);
      }
      else
      {
        this->Derivatives->Write(first + done, n, jacobians);
      }
    }
  }

  // The displacements of the points mapped into OutPoints, and the counts of the warnings.
  template <typename In>
  void finishChunk(const In* in, vtkIdType first, vtkIdType count, std::size_t unchanged)
  {
    const Out* out = this->OutPoints + 3 * first;
    Out* displacement = this->Displacement + 3 * first;
    vtkIdType nonFinite = 0, beyondOutputType = 0;
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
      // A finite point whose image or displacement is not: beyond the largest float (the
      // kernel keeps a double image finite).
      if (!isFinite(out[i], out[i + 1], out[i + 2]) ||
        !isFinite(displacement[i], displacement[i + 1], displacement[i + 2]))
      {
        ++beyondOutputType;
      }
    }
    this->Unchanged += static_cast<vtkIdType>(unchanged);
    this->NonFiniteInputs += nonFinite;
    this->BeyondOutputType += beyondOutputType;
  }
};

// An image or rectilinear grid whose extent is empty: VTK's empty extent (0, -1, ...) or any other
// with an upper index below the lower, whose point count VTK reports as a negative product.
bool hasEmptyExtent(vtkDataSet* input)
{
  int extent[6];
  if (auto* image = vtkImageData::SafeDownCast(input))
  {
    image->GetExtent(extent);
  }
  else if (auto* grid = vtkRectilinearGrid::SafeDownCast(input))
  {
    grid->GetExtent(extent);
  }
  else
  {
    return false;
  }
  return vtkStructuredData::GetDataDescriptionFromExtent(extent) == VTK_EMPTY;
}

// The input as a point set: images and rectilinear grids through VTK's converters, which make a
// vtkStructuredGrid with double points, the same extent and the same point and cell data (an
// empty one for an empty or inverted extent, which the converters would turn into a grid of a
// negative number of points).
vtkSmartPointer<vtkPointSet> asPointSet(vtkDataSet* input)
{
  vtkSmartPointer<vtkStructuredGridAlgorithm> converter;
  if (hasEmptyExtent(input))
  {
    return vtkSmartPointer<vtkStructuredGrid>::New();
  }
  if (vtkImageData::SafeDownCast(input))
  {
    converter = vtkSmartPointer<vtkImageDataToPointSet>::New();
  }
  else if (vtkRectilinearGrid::SafeDownCast(input))
  {
    converter = vtkSmartPointer<vtkRectilinearGridToPointSet>::New();
  }
  else
  {
    return vtkPointSet::SafeDownCast(input);
  }
  // A shallow copy keeps the converter's pipeline away from this filter's input.
  auto copy = vtk::TakeSmartPointer(input->NewInstance());
  copy->ShallowCopy(input);
  converter->SetInputData(copy);
  converter->Update();
  return converter->GetOutput();
}

// The memory one update allocates for `input`: the output points and the Displacement array
// (3 values each per point, in the output precision), and for an image or a rectilinear grid
// their explicit copy (double points; the point and cell data are shared, not copied). Measured
// once: the peak resident memory of a 2000 x 2000 image in double grows by 72.3 bytes a point,
// for the 72 counted here. The arrays from J add their own (vtkPointPairJacobianArrays::
// BytesPerPoint: 3 doubles per transformed array, an upper bound, and the scalars in the output
// precision); the Jacobians themselves live in a buffer per thread of 256 points. Measured on the
// bench's 10^6-point mesh (double points, float normals and vectors): peak 60.1 bytes a point
// with its normals transformed (72 estimated), 88.0 with the normals, a vector array and both
// scalars (112 estimated).
double estimatedBytes(
  vtkDataSet* input, int precision, const vtkPointPairJacobianArrays::Request& derivatives)
{
  const bool converted =
    vtkImageData::SafeDownCast(input) || vtkRectilinearGrid::SafeDownCast(input);
  int valueSize = 8;
  if (precision == vtkAlgorithm::SINGLE_PRECISION)
  {
    valueSize = 4;
  }
  else if (precision == vtkAlgorithm::DEFAULT_PRECISION && !converted)
  {
    vtkPointSet* points = vtkPointSet::SafeDownCast(input);
    const bool single =
      points && points->GetPoints() && points->GetPoints()->GetDataType() == VTK_FLOAT;
    valueSize = single ? 4 : 8;
  }
  const double perPoint = 2.0 * 3 * valueSize + (converted ? 3.0 * 8 : 0.0) +
    vtkPointPairJacobianArrays::BytesPerPoint(derivatives, input->GetPointData(), valueSize);
  return hasEmptyExtent(input) ? 0.0 : perPoint * static_cast<double>(input->GetNumberOfPoints());
}

// What the filter's properties ask of the map's derivative.
vtkPointPairJacobianArrays::Request derivativeRequest(vtkPointPairDeformationFilter* self)
{
  vtkPointPairJacobianArrays::Request request;
  request.TransformNormals = self->GetTransformNormals();
  request.VectorArrays = self->GetVectorArraySelection();
  request.NormalArrays = self->GetNormalArraySelection();
  request.ConformalScale = self->GetComputeConformalScale();
  request.ConformalityDefect = self->GetComputeConformalityDefect();
  return request;
}

// cga::PointPairField::planTreeCells for the input's points: float or double AOS arrays as they
// are, any other array (rare: SOA or integer points) through a copy in double.
void planTreeCells(cga::PointPairField& field, vtkDataArray* points)
{
  const auto count = static_cast<std::size_t>(points->GetNumberOfTuples());
  if (auto* doubles = vtkArrayDownCast<vtkAOSDataArrayTemplate<double>>(points))
  {
    field.planTreeCells(doubles->GetPointer(0), count);
  }
  else if (auto* floats = vtkArrayDownCast<vtkAOSDataArrayTemplate<float>>(points))
  {
    field.planTreeCells(floats->GetPointer(0), count);
  }
  else
  {
    vtkNew<vtkDoubleArray> copy;
    copy->DeepCopy(points);
    field.planTreeCells(copy->GetPointer(0), count);
  }
}

// Deforms `inPoints` into `outPoints` and `displacement` (AOS arrays of value type Out), and,
// when `derivatives` asks for any, the arrays from J.
template <typename Out>
void deformPoints(vtkPointPairDeformationFilter* self, const cga::PointPairField& field,
  vtkDataArray* inPoints, vtkDataArray* outPoints, vtkDataArray* displacement, double strength,
  cga::ExponentialRule rule, vtkPointPairJacobianArrays& derivatives, vtkIdType& unchanged,
  vtkIdType& nonFiniteInputs, vtkIdType& beyondOutputType)
{
  DeformWorker<Out> worker{ self, &field, strength, rule,
    vtkArrayDownCast<vtkAOSDataArrayTemplate<Out>>(outPoints)->GetPointer(0),
    vtkArrayDownCast<vtkAOSDataArrayTemplate<Out>>(displacement)->GetPointer(0),
    derivatives.Any() ? &derivatives : nullptr, field.treeBytes() > 0 };
  // VTK's dispatch list holds AOS arrays only; SOA arrays, VTK's other stored layout, are added so
  // that their copy is typed (through vtkDataArray's virtual API it costs several times more).
  using Arrays = vtkTypeList::Create<vtkAOSDataArrayTemplate<float>,
    vtkAOSDataArrayTemplate<double>, vtkSOADataArrayTemplate<float>,
    vtkSOADataArrayTemplate<double>>;
  using Dispatcher = vtkArrayDispatch::DispatchByArray<Arrays>;
  if (!Dispatcher::Execute(inPoints, worker))
  {
    worker(inPoints); // any other array, through vtkDataArray's API
  }
  unchanged = worker.Unchanged;
  nonFiniteInputs = worker.NonFiniteInputs;
  beyondOutputType = worker.BeyondOutputType;
}
} // namespace

vtkPointPairDeformationFilter::vtkPointPairDeformationFilter()
  : vtkPointPairFieldAlgorithm(1) // the Generators input is port 1
{
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(2); // the deformed input, the generators
}

vtkPointPairDeformationFilter::~vtkPointPairDeformationFilter() = default;

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

int vtkPointPairDeformationFilter::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    vtkBoostedGeneratorGlyphs::FillOutputPortInformation(info);
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

int vtkPointPairDeformationFilter::RequestDataObject(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  int result = 1;
  // Images and rectilinear grids cannot hold moved points: they become structured grids.
  if (vtkImageData::GetData(inputVector[0]) || vtkRectilinearGrid::GetData(inputVector[0]))
  {
    if (!vtkStructuredGrid::GetData(outputVector))
    {
      vtkNew<vtkStructuredGrid> output;
      outputVector->GetInformationObject(0)->Set(vtkDataObject::DATA_OBJECT(), output);
    }
  }
  else
  {
    // The output takes the input's type, as vtkPointSetAlgorithm's rule, but on port 0 only: that
    // rule gives every port the input's type, so each update of a mesh that is not a polydata
    // made a new data set of the mesh's type for the generators' port and the new polydata below
    // (0.14 ms of the calling thread per update, perf on the bench's 10^6-point grid).
    vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
    if (!input)
    {
      return 0;
    }
    vtkInformation* info = outputVector->GetInformationObject(0);
    vtkDataObject* output = info->Get(vtkDataObject::DATA_OBJECT());
    if (!output || !output->IsA(input->GetClassName()))
    {
      info->Set(vtkDataObject::DATA_OBJECT(), vtk::TakeSmartPointer(input->NewInstance()));
    }
  }
  vtkInformation* generatorsInfo = outputVector->GetInformationObject(1);
  vtkDataObject* existing = generatorsInfo->Get(vtkDataObject::DATA_OBJECT());
  if (!existing || std::string(existing->GetClassName()) != "vtkPolyData")
  {
    vtkNew<vtkPolyData> generators;
    generatorsInfo->Set(vtkDataObject::DATA_OBJECT(), generators);
  }
  return result;
}

int vtkPointPairDeformationFilter::ExecuteInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  // Without time steps of its own the filter keeps its input's (the executive copied them).
  if (this->NumberOfTimeSteps > 0)
  {
    for (int port = 0; port < this->GetNumberOfOutputPorts(); ++port)
    {
      vtkBoostedTimeSweep::ReportTimeSteps(
        outputVector->GetInformationObject(port), this->NumberOfTimeSteps);
    }
  }
  return 1;
}

int vtkPointPairDeformationFilter::ComputeInputUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The mesh (port 0) gets the downstream piece request unchanged; the generators are needed
  // whole on every rank, or the field would differ from piece to piece.
  vtkBoostedWholeInput::Request(inputVector[1]->GetInformationObject(0));
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

  if (!this->CheckFieldParameters() || !this->CheckMeshStructure(input, "the input"))
  {
    return 1; // the output stays empty
  }
  if (!(this->Tolerance >= 0.0))
  {
    vtkErrorMacro(<< "Tolerance must be 0 or positive; it is " << this->Tolerance);
    return 1; // the output stays empty
  }

  // The list, with the selected generator moved and aimed by its widget, then the second port.
  std::vector<cga::GeneratorParameters> generators;
  if (!this->ReadGenerators(inputVector, generators))
  {
    return 1; // the output stays empty
  }
  const auto field = std::make_shared<cga::PointPairField>(
    generators.data(), generators.size(), this->Falloff, this->Epsilon);
  if (field->skippedGenerators() > 0)
  {
    vtkWarningMacro(<< field->skippedGenerators() << " of " << generators.size()
                    << " generators were ignored: their direction is zero, or their location, "
                       "direction, weight or (a twist's) pitch is not finite");
  }

  // Before any allocation: an image's or a rectilinear grid's dimensions alone give its size,
  // however many points its explicit copy would need.
  const std::string memoryProblem = vtkBoostedMemoryBudget::Problem(
    estimatedBytes(input, this->OutputPointsPrecision, derivativeRequest(this)), "deforming " +
      std::to_string(input->GetNumberOfPoints()) + " points of a " + input->GetClassName());
  if (!memoryProblem.empty())
  {
    vtkErrorMacro(<< memoryProblem);
    return 1; // the output stays empty
  }
  // The time sweep grows Strength from 0 (the identity) to its value.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const double strength =
    this->Strength * vtkBoostedTimeSweep::Fraction(outInfo, this->NumberOfTimeSteps);
  vtkInformation* generatorsInfo = outputVector->GetInformationObject(1);
  vtkPolyData* generatorsOutput = vtkPolyData::GetData(generatorsInfo);
  bool deformed = false;
  // The tree (O(M), a few hundred bytes per generator) is built inside the budget's guard, unless
  // the last update's is the same one (only Strength, the time, the input or the arrays changed).
  // The last field is let go before a tree is built: one tree at a time.
  const bool shared =
    this->LastTreeField && field->shareTree(*this->LastTreeField, this->Tolerance);
  this->LastTreeField.reset();
  if (!vtkBoostedMemoryBudget::Run(this, [&] {
        if (!shared)
        {
          // O(M log M) before any point moves (README, Many generators): said as progress text.
          const bool building = cga::PointPairField::usesTree(this->Tolerance, field->size());
          if (building)
          {
            this->SetProgressText(kBuildingTree);
            this->UpdateProgress(0.0);
          }
          field->setTolerance(this->Tolerance);
          this->SetProgressText(nullptr);
        }
        deformed = this->Deform(input, *field, strength, output);
      }))
  {
    this->SetProgressText(nullptr); // the tree's build may have failed
    output->Initialize();           // no half-built output
  }
  else if (deformed && vtkBoostedGeneratorGlyphs::OnFirstPiece(outputVector))
  {
    // The generators as used (the selected row at the handle, then the Generators input's), once
    // under MPI.
    vtkBoostedGeneratorGlyphs glyphs(vtkBoostedGeneratorGlyphs::KindAndPitch);
    glyphs.Add(generators);
    glyphs.Write(generatorsOutput, this->GeneratorGlyphs);
  }
  if (field->treeBytes() > 0)
  {
    this->LastTreeField = field; // for the next update
  }
  vtkBoostedTimeSweep::StampTime(outInfo, this->NumberOfTimeSteps, output);
  vtkBoostedTimeSweep::StampTime(generatorsInfo, this->NumberOfTimeSteps, generatorsOutput);
  return 1;
}

vtkMTimeType vtkPointPairDeformationFilter::GetMTime()
{
  return std::max({ this->Superclass::GetMTime(), this->VectorArraySelection->GetMTime(),
    this->NormalArraySelection->GetMTime() });
}

bool vtkPointPairDeformationFilter::Deform(
  vtkDataSet* input, cga::PointPairField& field, double strength, vtkPointSet* output)
{
  // Same topology, cells and arrays; the normals are dropped here (cell normals would be wrong
  // after the warp) and the point normals come back transformed by J when asked for.
  vtkSmartPointer<vtkPointSet> source = asPointSet(input);
  output->CopyStructure(source);
  output->GetPointData()->CopyNormalsOff();
  output->GetPointData()->PassData(source->GetPointData());
  output->GetCellData()->CopyNormalsOff();
  output->GetCellData()->PassData(source->GetCellData());
  output->GetFieldData()->PassData(input->GetFieldData());

  vtkPoints* inPoints = source->GetPoints();
  const vtkIdType count = inPoints ? inPoints->GetNumberOfPoints() : 0;
  if (count == 0)
  {
    return true;
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
  vtkBoostedLargeArrays::SetNumberOfTuples(outPoints->GetData(), count);
  vtkSmartPointer<vtkDataArray> displacement =
    vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(outputType));
  displacement->SetName("Displacement");
  displacement->SetNumberOfComponents(3);
  vtkBoostedLargeArrays::SetNumberOfTuples(displacement, count);

  vtkPointPairJacobianArrays derivatives;
  std::string problem, missing;
  if (!derivatives.Prepare(derivativeRequest(this), source->GetPointData(), count, outputType,
        problem, missing))
  {
    vtkErrorMacro(<< problem << "; the output is empty");
    output->Initialize();
    return false;
  }
  if (!missing.empty())
  {
    vtkWarningMacro(<< "the input has no point array named " << missing
                    << " (VectorArrays, NormalArrays): not transformed");
  }

  const cga::ExponentialRule rule =
    vtkBoostedExponentialRule<vtkPointPairDeformationFilter>(this->ExponentialRule);
  if (field.treeBytes() > 0)
  {
    planTreeCells(field, inPoints->GetData()); // the tree's cells fitted to this input's points
  }
  vtkIdType unchanged = 0, nonFiniteInputs = 0, beyondOutputType = 0;
  (outputType == VTK_FLOAT ? deformPoints<float> : deformPoints<double>)(this, field,
    inPoints->GetData(), outPoints->GetData(), displacement, strength, rule, derivatives,
    unchanged, nonFiniteInputs, beyondOutputType);
  if (vtkBoostedSurfacesCheckAbort(this))
  {
    output->Initialize(); // aborted: no half-deformed mesh
    return false;
  }
  if (derivatives.ScaleBeyondFloat > 0)
  {
    vtkErrorMacro(<< vtkBoostedSinglePrecisionProblem("the ConformalScale of " +
                    std::to_string(derivatives.ScaleBeyondFloat) + " of " + std::to_string(count) +
                    " points is"));
    output->Initialize();
    return false;
  }
  if (beyondOutputType > 0)
  {
    vtkErrorMacro(<< vtkBoostedSinglePrecisionProblem("the images or displacements of " +
                    std::to_string(beyondOutputType) + " of " + std::to_string(count) +
                    " points are"));
    output->Initialize();
    return false;
  }
  if (unchanged > 0)
  {
    vtkWarningMacro(<< unchanged << " of " << count << " points were left in place: "
                    << nonFiniteInputs << " are NaN or infinite, " << unchanged - nonFiniteInputs
                    << " have an image that is not finite (at infinity, beyond the range of the "
                       "output points' precision, or the field overflowed for huge weights)");
  }
  if (derivatives.NonFinite + derivatives.Collapsed + derivatives.Overflowed > 0)
  {
    vtkWarningMacro(<< "normals and vectors left unchanged: " << derivatives.NonFinite
                    << " are NaN or infinite, " << derivatives.Collapsed
                    << " normals have no direction where the map's derivative J flattens the "
                       "tangent plane (cof(J) n = 0), "
                    << derivatives.Overflowed << " images J v or n' overflow their type");
  }
  if (derivatives.NonFiniteJacobians > 0)
  {
    vtkWarningMacro(<< "the map's derivative J overflows at " << derivatives.NonFiniteJacobians
                    << " of " << count
                    << " points (huge weights): J is taken as the identity there (normals and "
                       "vectors unchanged, ConformalScale 1, ConformalityDefect 0)");
  }
  output->SetPoints(outPoints);
  output->GetPointData()->AddArray(displacement);
  derivatives.AddTo(output->GetPointData());
  return true;
}

void vtkPointPairDeformationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfTimeSteps: " << this->NumberOfTimeSteps << "\n";
  os << indent << "Tolerance: " << this->Tolerance << "\n";
  os << indent << "TransformNormals: " << this->TransformNormals << "\n";
  for (auto selection : { std::make_pair("VectorArrays", this->VectorArraySelection.Get()),
         std::make_pair("NormalArrays", this->NormalArraySelection.Get()) })
  {
    os << indent << selection.first << ":";
    for (int i = 0; i < selection.second->GetNumberOfArrays(); ++i)
    {
      if (selection.second->GetArraySetting(i))
      {
        os << " '" << selection.second->GetArrayName(i) << "'";
      }
    }
    os << "\n";
  }
  os << indent << "ComputeConformalScale: " << this->ComputeConformalScale << "\n";
  os << indent << "ComputeConformalityDefect: " << this->ComputeConformalityDefect << "\n";
}
