#include "vtkBoostedGeneratorGlyphs.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>
#include <cstring>

void vtkBoostedGeneratorGlyphs::Add(const cga::Vec3& location, const cga::Vec3& direction,
  double weight, int kind, double pitch, double kappaU, double kappaV, bool identified)
{
  const double values[] = { location.x, location.y, location.z, direction.x, direction.y,
    direction.z, weight, pitch, kappaU, kappaV };
  for (double value : values)
  {
    if (!std::isfinite(value))
    {
      return;
    }
  }
  this->Points.push_back(
    { location, direction, weight, pitch, kappaU, kappaV, kind, identified ? 1 : 0 });
}

void vtkBoostedGeneratorGlyphs::Add(const cga::GeneratorParameters& generator, bool identified)
{
  this->Add(generator.location, generator.direction, generator.weight,
    static_cast<int>(generator.kind), generator.pitch, 0.0, 0.0, identified);
}

void vtkBoostedGeneratorGlyphs::Add(const std::vector<cga::GeneratorParameters>& generators)
{
  for (const cga::GeneratorParameters& generator : generators)
  {
    this->Add(generator);
  }
}

void vtkBoostedGeneratorGlyphs::Write(vtkPolyData* output) const
{
  output->Initialize();
  const vtkIdType count = static_cast<vtkIdType>(this->Points.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkDoubleArray> directions, weights, pitches, curvatures;
  vtkNew<vtkIntArray> kinds, identified;
  directions->SetName("Direction");
  directions->SetNumberOfComponents(3);
  directions->SetNumberOfTuples(count);
  weights->SetName("Weight");
  weights->SetNumberOfTuples(count);
  kinds->SetName("Kind");
  kinds->SetNumberOfTuples(count);
  pitches->SetName("Pitch");
  pitches->SetNumberOfTuples(count);
  curvatures->SetName("Curvature");
  curvatures->SetNumberOfComponents(2);
  curvatures->SetNumberOfTuples(count);
  identified->SetName("KindIdentified");
  identified->SetNumberOfTuples(count);
  for (vtkIdType i = 0; i < count; ++i)
  {
    const Point& p = this->Points[static_cast<std::size_t>(i)];
    points->SetPoint(i, p.location.x, p.location.y, p.location.z);
    vertices->InsertNextCell(1, &i);
    directions->SetTuple3(i, p.direction.x, p.direction.y, p.direction.z);
    weights->SetValue(i, p.weight);
    kinds->SetValue(i, p.kind);
    pitches->SetValue(i, p.pitch);
    curvatures->SetTuple2(i, p.kappaU, p.kappaV);
    identified->SetValue(i, p.identified);
  }
  output->SetPoints(points);
  output->SetVerts(vertices);
  vtkPointData* pointData = output->GetPointData();
  pointData->SetVectors(directions);
  pointData->SetScalars(weights);
  if (this->Columns & KindAndPitch)
  {
    pointData->AddArray(kinds);
    pointData->AddArray(pitches);
  }
  if (this->Columns & Curvature)
  {
    pointData->AddArray(curvatures);
  }
  if (this->Columns & KindIdentified)
  {
    pointData->AddArray(identified);
  }
}

void vtkBoostedGeneratorGlyphs::Write(
  vtkPolyData* output, vtkSmartPointer<vtkPolyData>& cache) const
{
  if (!this->IsWrittenIn(cache))
  {
    cache = vtkSmartPointer<vtkPolyData>::New();
    this->Write(cache);
  }
  output->ShallowCopy(cache);
}

namespace
{
// The value of component `c` of tuple `i` of `array` has the bits of `value` (-0 is not 0).
template <typename Array, typename Value>
bool sameBits(Array* array, vtkIdType i, int c, Value value)
{
  const Value stored = array->GetTypedComponent(i, c);
  return std::memcmp(&stored, &value, sizeof value) == 0;
}
} // namespace

bool vtkBoostedGeneratorGlyphs::IsWrittenIn(vtkPolyData* data) const
{
  // Compared with the arrays themselves, not with a copy of the points kept aside: a consumer
  // that changed the shared arrays in place gets them written anew.
  const vtkIdType count = static_cast<vtkIdType>(this->Points.size());
  if (!data || !data->GetPoints() || data->GetNumberOfPoints() != count ||
    data->GetNumberOfVerts() != count || data->GetNumberOfCells() != count)
  {
    return false;
  }
  vtkPointData* pointData = data->GetPointData();
  auto* points = vtkDoubleArray::SafeDownCast(data->GetPoints()->GetData());
  auto* directions = vtkDoubleArray::SafeDownCast(pointData->GetVectors());
  auto* weights = vtkDoubleArray::SafeDownCast(pointData->GetScalars());
  auto* kinds = vtkIntArray::SafeDownCast(pointData->GetAbstractArray("Kind"));
  auto* pitches = vtkDoubleArray::SafeDownCast(pointData->GetAbstractArray("Pitch"));
  auto* curvatures = vtkDoubleArray::SafeDownCast(pointData->GetAbstractArray("Curvature"));
  auto* identified = vtkIntArray::SafeDownCast(pointData->GetAbstractArray("KindIdentified"));
  const bool kindAndPitch = (this->Columns & KindAndPitch) != 0;
  const bool curvature = (this->Columns & Curvature) != 0;
  const bool kindIdentified = (this->Columns & KindIdentified) != 0;
  if (!points || !directions || !weights || (kindAndPitch && !(kinds && pitches)) ||
    (curvature && !curvatures) || (kindIdentified && !identified) ||
    pointData->GetNumberOfArrays() !=
      2 + (kindAndPitch ? 2 : 0) + (curvature ? 1 : 0) + (kindIdentified ? 1 : 0) ||
    data->GetCellData()->GetNumberOfArrays() != 0 || data->GetFieldData()->GetNumberOfArrays() != 0)
  {
    return false;
  }
  for (vtkIdType i = 0; i < count; ++i)
  {
    const Point& p = this->Points[static_cast<std::size_t>(i)];
    const double location[] = { p.location.x, p.location.y, p.location.z };
    const double direction[] = { p.direction.x, p.direction.y, p.direction.z };
    for (int c = 0; c < 3; ++c)
    {
      if (!sameBits(points, i, c, location[c]) || !sameBits(directions, i, c, direction[c]))
      {
        return false;
      }
    }
    if (!sameBits(weights, i, 0, p.weight) ||
      (kindAndPitch && !(sameBits(kinds, i, 0, p.kind) && sameBits(pitches, i, 0, p.pitch))) ||
      (curvature && !(sameBits(curvatures, i, 0, p.kappaU) && sameBits(curvatures, i, 1, p.kappaV))) ||
      (kindIdentified && !sameBits(identified, i, 0, p.identified)))
    {
      return false;
    }
  }
  return true;
}

void vtkBoostedGeneratorGlyphs::FillOutputPortInformation(vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkPolyData");
}

bool vtkBoostedGeneratorGlyphs::OnFirstPiece(vtkInformationVector* outputVector)
{
  for (int port = 0; port < outputVector->GetNumberOfInformationObjects(); ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) &&
      info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) != 0)
    {
      return false;
    }
  }
  return true;
}
