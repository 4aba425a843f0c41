// Regression image of the paper's Fig 11: a plane and a sphere warped by point-pair generators,
// coloured by the length of "Displacement".
// Usage: TestPointPairDeformationFilterImage -V <baseline.png> -T <output directory>
#include "vtkPointPairDeformationFilter.h"

#include "RegressionScene.h"
#include "vtkCellArray.h"
#include "vtkLookupTable.h"
#include "vtkMath.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <functional>

namespace
{
// A rows x columns grid of quads whose points come from `point(u, v)`, u and v in [0, 1].
vtkNew<vtkPolyData> grid(int rows, int columns, const std::function<void(double, double, double*)>& point)
{
  vtkNew<vtkPolyData> mesh;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (int r = 0; r <= rows; ++r)
  {
    for (int c = 0; c <= columns; ++c)
    {
      double p[3];
      point(static_cast<double>(c) / columns, static_cast<double>(r) / rows, p);
      points->InsertNextPoint(p);
    }
  }
  vtkNew<vtkCellArray> quads;
  for (int r = 0; r < rows; ++r)
  {
    for (int c = 0; c < columns; ++c)
    {
      const vtkIdType a = r * (columns + 1) + c;
      const vtkIdType ids[4] = { a, a + 1, a + columns + 2, a + columns + 1 };
      quads->InsertNextCell(4, ids);
    }
  }
  mesh->SetPoints(points);
  mesh->SetPolys(quads);
  return mesh;
}

vtkNew<vtkActor> deformedActor(vtkPolyData* mesh, const double (*generators)[7], int count)
{
  vtkNew<vtkPointPairDeformationFilter> deformation;
  deformation->SetInputData(mesh);
  for (int i = 0; i < count; ++i)
  {
    const double* g = generators[i];
    deformation->AddGenerator(g[0], g[1], g[2], g[3], g[4], g[5], g[6]);
  }
  deformation->SetFalloff(4.0);
  deformation->SetEpsilon(0.05);
  vtkNew<vtkLookupTable> lut;
  lut->SetVectorModeToMagnitude();
  lut->SetRange(0.0, 0.6);
  lut->SetHueRange(0.66, 0.0);
  lut->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(deformation->GetOutputPort());
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Displacement");
  mapper->SetLookupTable(lut);
  mapper->UseLookupTableScalarRangeOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  return actor;
}
}

int main(int argc, char* argv[])
{
  const double planeGenerators[][7] = { { -1.0, -0.8, 0.4, 0, 0, 1, 0.7 },
    { 1.0, -0.7, -0.4, 0, 0, 1, -0.7 }, { -0.3, 0.9, 0.3, 1, 0, 0, 0.6 },
    { 1.1, 1.0, 0.3, 0, 0, -1, 0.5 } };
  const double sphereGenerators[][7] = { { 5.0, 0.0, 1.4, 0, 0, 1, 0.6 },
    { 6.4, 0.0, 0.2, 1, 0, 0, -0.5 }, { 4.6, -1.4, -0.4, 0, 1, 0, 0.5 },
    { 4.3, 0.9, -1.0, -1, 1, -1, 0.4 } };

  auto plane = grid(60, 60, [](double u, double v, double* p) {
    p[0] = -2.0 + 4.0 * u;
    p[1] = -2.0 + 4.0 * v;
    p[2] = 0.0;
  });
  auto sphere = grid(48, 64, [](double u, double v, double* p) {
    const double theta = 2.0 * vtkMath::Pi() * u, phi = vtkMath::Pi() * v;
    p[0] = 5.0 + std::sin(phi) * std::cos(theta);
    p[1] = std::sin(phi) * std::sin(theta);
    p[2] = std::cos(phi);
  });

  RegressionScene scene(500, 300);
  scene.window->SetMultiSamples(0);
  scene.renderer->AddActor(deformedActor(plane, planeGenerators, 4));
  scene.renderer->AddActor(deformedActor(sphere, sphereGenerators, 4));
  scene.LookAtOriginFrom(0.15, -1.0, 0.6, 1.3);
  return scene.RenderAndCompare(argc, argv);
}
