// The meshes and generator rows of the fit filter's tests (TestPointPairFitFilter.cxx,
// TestPointPairFitKinds.cxx): a latitude-longitude sphere, generator rows, the deformation filter's
// image of a mesh (the targets), the largest FitResidual.
#ifndef FitTestSupport_h
#define FitTestSupport_h

#include "TestSupport.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPointPairDeformationFilter.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

namespace
{
// A latitude-longitude triangulated sphere of `radius(theta, phi)` about the origin: rings of
// `longitudes` points at `latitudes - 1` latitudes, and the two poles.
vtkSmartPointer<vtkPolyData> sphere(
  int longitudes, int latitudes, const std::function<double(double, double)>& radius)
{
  const double pi = std::acos(-1.0);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const auto add = [&](double theta, double phi) {
    const double r = radius(theta, phi);
    return points->InsertNextPoint(r * std::sin(phi) * std::cos(theta),
      r * std::sin(phi) * std::sin(theta), r * std::cos(phi));
  };
  const vtkIdType north = add(0.0, 0.0);
  for (int j = 1; j < latitudes; ++j)
  {
    for (int i = 0; i < longitudes; ++i)
    {
      add(2.0 * pi * i / longitudes, pi * j / latitudes);
    }
  }
  const vtkIdType south = add(0.0, pi);
  vtkNew<vtkCellArray> triangles;
  const auto ring = [&](int j, int i) { return 1 + (j - 1) * longitudes + (i % longitudes); };
  for (int i = 0; i < longitudes; ++i)
  {
    triangles->InsertNextCell({ north, ring(1, i), ring(1, i + 1) });
    triangles->InsertNextCell({ south, ring(latitudes - 1, i + 1), ring(latitudes - 1, i) });
    for (int j = 1; j + 1 < latitudes; ++j)
    {
      triangles->InsertNextCell({ ring(j, i), ring(j + 1, i), ring(j + 1, i + 1) });
      triangles->InsertNextCell({ ring(j, i), ring(j + 1, i + 1), ring(j, i + 1) });
    }
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(triangles);
  return mesh.GetPointer();
}

vtkSmartPointer<vtkPolyData> unitSphere(int longitudes = 24, int latitudes = 12)
{
  return sphere(longitudes, latitudes, [](double, double) { return 1.0; });
}

// A generator row: location, direction, weight, kind, pitch.
struct Row
{
  double values[9];
};

template <class Filter>
void addRows(Filter* filter, const std::vector<Row>& rows)
{
  for (const Row& r : rows)
  {
    const double* v = r.values;
    filter->AddGenerator(v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]);
  }
}

vtkSmartPointer<vtkPolyData> deformed(vtkPolyData* mesh, const std::vector<Row>& rows)
{
  vtkNew<vtkPointPairDeformationFilter> deformation;
  deformation->SetInputData(mesh);
  addRows(deformation.GetPointer(), rows);
  deformation->Update();
  vtkSmartPointer<vtkPolyData> out = vtkPolyData::SafeDownCast(deformation->GetOutput());
  return out;
}

double largestResidual(vtkPolyData* output)
{
  vtkDataArray* residual = output->GetPointData()->GetArray("FitResidual");
  double largest = -1.0;
  for (vtkIdType i = 0; residual && i < residual->GetNumberOfTuples(); ++i)
  {
    largest = cgatest::worseOf(largest, residual->GetComponent(i, 0));
  }
  return largest;
}

} // namespace

#endif
