#include "vtkBoostedSurfaceSource.h"

#include "vtkBoostedCurvatureArrays.h"
#include "vtkBoostedGridDriver.h"
#include "vtkBoostedTimeSweep.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include "cga/Conformal.h"
#include "cga/PointSandwich.h"
#include "cga/SurfaceCurvature.h"
#include "cga/surfaces/BoostedCircle.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

vtkStandardNewMacro(vtkBoostedSurfaceSource);

vtkBoostedSurfaceSource::vtkBoostedSurfaceSource()
{
  this->SetNumberOfInputPorts(0);
}

int vtkBoostedSurfaceSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkBoostedTimeSweep::ReportOnEveryPort(outputVector, this->NumberOfTimeSteps, true);
  return 1;
}

int vtkBoostedSurfaceSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);

  cga::BoostedCircle family;
  family.center = cga::toVec3(this->CircleCenter);
  family.normal = cga::toVec3(this->CircleNormal);
  family.radius = this->CircleRadius;
  family.boostDirection = cga::toVec3(this->BoostDirection);
  family.boostLocation =
    this->BoostAtCircleCenter ? family.center : cga::toVec3(this->BoostLocation);
  std::string problem = family.validate();
  if (problem.empty() && !(this->LambdaRange[0] <= this->LambdaRange[1]))
  {
    problem = "LambdaRange must be two finite numbers with minimum <= maximum";
  }
  if (problem.empty() && !(std::isfinite(this->LambdaRange[0]) && std::isfinite(this->LambdaRange[1])))
  {
    problem = "LambdaRange must be finite";
  }
  // The time sweep moves the range's upper end from its lower end to its value.
  const double lambdaRange[2] = { this->LambdaRange[0],
    vtkBoostedTimeSweep::Interpolate(this->LambdaRange[0], this->LambdaRange[1],
      vtkBoostedTimeSweep::Fraction(outInfo, this->NumberOfTimeSteps)) };
  // Computed about the circle's center (the grid adds it back): precision far from the origin.
  const cga::BoostedCircle centered = family.centered();
  if (problem.empty())
  {
    problem = centered.boostProblem(lambdaRange[0], lambdaRange[1]);
  }
  const long long rows = this->LambdaResolution + 1LL;
  const long long columns = this->ThetaResolution + 1LL; // the last column repeats the first (seam)
  vtkBoostedGridDriver driver(
    this, outInfo, this->CircleCenter, this->ClipRadius, this->OutputPointsPrecision);
  // The update's memory per grid sample, for the memory budget (vtkBoostedMemoryBudget): peak
  // resident memory of a 2000 x 2000 grid, double precision, measured once (156 and 80 bytes;
  // the surface's 156 with its exact normals, plus the curvature arrays' 160 with them).
  const bool surface = this->OutputType == SURFACE;
  const bool curvatures = surface && this->ComputeCurvatures;
  driver.SetBytesPerSample(
    surface ? 156 + (curvatures ? vtkBoostedCurvatureArrays::BytesPerSample : 0.0) : 80);
  driver.SetMergeSeam(this->MergeSeam);
  if (!driver.Prepare(problem, rows, columns, true, this->OutputType == SURFACE))
  {
    return 1; // an error, or an empty piece
  }

  std::vector<double> lambdas(rows), thetas(columns);
  for (int r = 0; r < rows; ++r)
  {
    const double t = rows > 1 ? static_cast<double>(r) / (rows - 1) : 0.0;
    lambdas[r] = (1.0 - t) * lambdaRange[0] + t * lambdaRange[1];
  }
  std::vector<cga::BoostedCircle::CircleSample> circleSamples(columns);
  for (int c = 0; c < columns; ++c)
  {
    thetas[c] = 2.0 * vtkMath::Pi() * c / this->ThetaResolution;
    circleSamples[c] = centered.circleSample(thetas[c]);
  }
  circleSamples[columns - 1] = circleSamples[0]; // exactly the same point (and normal) at the seam

  vtkBoostedGridBuilder& grid = driver.Grid();
  grid.SetOrigin(this->CircleCenter);
  // Surfaces: exact normals, and the curvature arrays when asked for.
  std::unique_ptr<vtkBoostedCurvatureArrays> exact;
  if (surface)
  {
    exact.reset(new vtkBoostedCurvatureArrays(grid, curvatures));
  }
  driver.SampleRows([&](int r) {
    // One 5x5 matrix per lambda row: the sandwich K up(p) ~K is linear in up(p).
    const cga::BoostedCircleRow row(centered, lambdas[r]);
    // The row's points about the circle's center (NaN where mapped to infinity), for its plane.
    std::vector<cga::Vec3> rowPoints(columns, cga::Vec3{ NAN, NAN, NAN });
    // Each branch leaves rowPoints NaN where the point went to infinity (dropped).
    if (exact && !curvatures)
    {
      // The points and normals eight samples at a time (the same bits as firstDerivatives and
      // cga::surfaceNormal, sample by sample).
      std::vector<cga::Vec3> normals(columns);
      std::vector<unsigned char> state(columns);
      row.pointsAndNormals(circleSamples.data(), static_cast<size_t>(columns), rowPoints.data(),
        normals.data(), state.data());
      for (int c = 0; c < columns; ++c)
      {
        if (state[c] > 1)
        {
          exact->SetNormal(r, c, normals[c]);
        }
      }
    }
    else if (exact)
    {
      // The points and curvatures eight samples at a time (the same bits as derivatives and
      // cga::surfaceCurvature, sample by sample).
      std::vector<cga::SurfaceCurvature> curvature(columns);
      std::unique_ptr<bool[]> mapped(new bool[columns]);
      row.curvatures(circleSamples.data(), static_cast<size_t>(columns), rowPoints.data(),
        curvature.data(), mapped.get());
      for (int c = 0; c < columns; ++c)
      {
        if (mapped[c])
        {
          exact->SetCurvature(r, c, curvature[c]);
        }
      }
    }
    else
    {
      for (int c = 0; c < columns; ++c)
      {
        row.point(circleSamples[c].point, rowPoints[c]);
      }
    }
    for (int c = 0; c < columns; ++c)
    {
      if (cga::isFinite(rowPoints[c])) // a mapped point is finite (normalizePoint)
      {
        const double point[3] = { rowPoints[c].x, rowPoints[c].y, rowPoints[c].z };
        grid.SetPoint(r, c, point);
      }
    }
    // The image circle's plane, for the normals where the surface's are degenerate: from the
    // row's points at any scale (the circle's blade holds radius^2, which underflows for a
    // circle below about 1e-154 across).
    const cga::Vec3 normal = cga::planeNormal(rowPoints.data(), rowPoints.size(), cga::Vec3{});
    const double fallback[3] = { normal.x, normal.y, normal.z };
    grid.SetRowFallbackNormal(r, fallback);
  });
  grid.AddRowParameter("lambda", lambdas);
  grid.AddColumnParameter("theta", thetas);
  driver.Build(vtkPolyData::GetData(outInfo));
  vtkBoostedTimeSweep::StampTime(outInfo, this->NumberOfTimeSteps, vtkPolyData::GetData(outInfo));
  return 1;
}

void vtkBoostedSurfaceSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "CircleCenter: (" << this->CircleCenter[0] << ", " << this->CircleCenter[1]
     << ", " << this->CircleCenter[2] << ")\n";
  os << indent << "CircleNormal: (" << this->CircleNormal[0] << ", " << this->CircleNormal[1]
     << ", " << this->CircleNormal[2] << ")\n";
  os << indent << "CircleRadius: " << this->CircleRadius << "\n";
  os << indent << "BoostDirection: (" << this->BoostDirection[0] << ", "
     << this->BoostDirection[1] << ", " << this->BoostDirection[2] << ")\n";
  os << indent << "BoostLocation: (" << this->BoostLocation[0] << ", " << this->BoostLocation[1]
     << ", " << this->BoostLocation[2] << ")\n";
  os << indent << "BoostAtCircleCenter: " << this->BoostAtCircleCenter << "\n";
  os << indent << "LambdaRange: [" << this->LambdaRange[0] << ", " << this->LambdaRange[1]
     << "]\n";
  os << indent << "LambdaResolution: " << this->LambdaResolution << "\n";
  os << indent << "ThetaResolution: " << this->ThetaResolution << "\n";
  os << indent << "ClipRadius: " << this->ClipRadius << "\n";
  os << indent << "OutputType: " << (this->OutputType == SURFACE ? "SURFACE" : "CIRCLES") << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "MergeSeam: " << this->MergeSeam << "\n";
  os << indent << "ComputeCurvatures: " << this->ComputeCurvatures << "\n";
  os << indent << "NumberOfTimeSteps: " << this->NumberOfTimeSteps << "\n";
}
