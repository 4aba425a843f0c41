#include "vtkBoostedCurvatureArrays.h"

#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkPointData.h"

#include "cga/SurfaceCurvature.h"

vtkBoostedCurvatureArrays::vtkBoostedCurvatureArrays(vtkBoostedGridBuilder& grid, bool withArrays)
  : Grid(grid)
{
  grid.EnableSampleNormals();
  if (withArrays)
  {
    this->Curvatures = grid.AddSampleArray(PrincipalCurvaturesName, 2);
    this->Directions = grid.AddSampleArray(PrincipalDirectionsName, 6);
    this->Gaussian = grid.AddSampleArray(GaussianCurvatureName, 1);
    this->Mean = grid.AddSampleArray(MeanCurvatureName, 1);
  }
}

void vtkBoostedCurvatureArrays::Set(int row, int column, const cga::SurfaceDerivatives& derivatives)
{
  if (this->Curvatures < 0)
  {
    cga::Vec3 n;
    if (cga::surfaceNormal(derivatives.du, derivatives.dv, n))
    {
      this->SetNormal(row, column, n);
    }
    return;
  }
  this->SetCurvature(row, column, cga::surfaceCurvature(derivatives));
}

void vtkBoostedCurvatureArrays::SetCurvature(
  int row, int column, const cga::SurfaceCurvature& curvature)
{
  if (curvature.regular)
  {
    this->SetNormal(row, column, curvature.normal);
  }
  if (this->Curvatures < 0)
  {
    return;
  }
  // A degenerate sample's SurfaceCurvature is all zeros: written as it is.
  double* k = this->Grid.SampleValues(this->Curvatures, row, column);
  k[0] = curvature.k1;
  k[1] = curvature.k2;
  double* d = this->Grid.SampleValues(this->Directions, row, column);
  const cga::Vec3 directions[2] = { curvature.direction1, curvature.direction2 };
  for (int i = 0; i < 2; ++i)
  {
    d[3 * i] = directions[i].x;
    d[3 * i + 1] = directions[i].y;
    d[3 * i + 2] = directions[i].z;
  }
  *this->Grid.SampleValues(this->Gaussian, row, column) = curvature.gaussian;
  *this->Grid.SampleValues(this->Mean, row, column) = curvature.mean;
}

void vtkBoostedCurvatureArrays::SetNormal(int row, int column, const cga::Vec3& normal)
{
  const double n[3] = { normal.x, normal.y, normal.z };
  this->Grid.SetSampleNormal(row, column, n);
}

void vtkBoostedCurvatureArrays::RenormalizeDirections(vtkPointData* data, vtkIdType id)
{
  vtkDataArray* directions = data->GetArray(PrincipalDirectionsName);
  if (!directions || directions->GetNumberOfComponents() != 6)
  {
    return;
  }
  double d[6];
  directions->GetTuple(id, d);
  vtkMath::Normalize(d); // a zero vector stays zero
  vtkMath::Normalize(d + 3);
  directions->SetTuple(id, d);
}
