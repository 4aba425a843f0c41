#include "vtkBoostedGeneratorGlyphs.h"

#include "vtkCellArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>

void vtkBoostedGeneratorGlyphs::Add(const cga::Vec3& location, const cga::Vec3& direction,
  double weight, int kind, double pitch, double kappaU, double kappaV)
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
  this->Points.push_back({ location, direction, weight, pitch, kappaU, kappaV, kind });
}

void vtkBoostedGeneratorGlyphs::Add(const cga::GeneratorParameters& generator)
{
  this->Add(generator.location, generator.direction, generator.weight,
    static_cast<int>(generator.kind), generator.pitch);
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
  vtkNew<vtkIntArray> kinds;
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
