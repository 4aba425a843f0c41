#include "vtkBoostedSurfaceSource.h"

#include "vtkBoostedGridBuilder.h"
#include "vtkBoostedSurfacesAbort.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "cga/Conformal.h"
#include "cga/PointSandwich.h"
#include "cga/surfaces/BoostedCircle.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkBoostedSurfaceSource);

namespace
{
cga::Vec3 toVec3(const double v[3])
{
  return { v[0], v[1], v[2] };
}
}

vtkBoostedSurfaceSource::vtkBoostedSurfaceSource()
{
  this->SetNumberOfInputPorts(0);
}

int vtkBoostedSurfaceSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

int vtkBoostedSurfaceSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);

  cga::BoostedCircle family;
  family.center = toVec3(this->CircleCenter);
  family.normal = toVec3(this->CircleNormal);
  family.radius = this->CircleRadius;
  family.boostDirection = toVec3(this->BoostDirection);
  family.boostLocation =
    this->BoostAtCircleCenter ? family.center : toVec3(this->BoostLocation);
  std::string problem = family.validate();
  if (problem.empty() && !(this->LambdaRange[0] <= this->LambdaRange[1]))
  {
    problem = "LambdaRange must be two finite numbers with minimum <= maximum";
  }
  if (problem.empty() && !(std::isfinite(this->LambdaRange[0]) && std::isfinite(this->LambdaRange[1])))
  {
    problem = "LambdaRange must be finite";
  }
  if (problem.empty() && std::isnan(this->ClipRadius)) // the clamp macro lets NaN through
  {
    problem = "ClipRadius must be a number";
  }
  if (problem.empty())
  {
    problem = vtkBoostedGridBuilder::SizeProblem(
      this->LambdaResolution + 1LL, this->ThetaResolution + 1LL);
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return 1; // the output stays empty
  }

  const int rows = this->LambdaResolution + 1;
  const int columns = this->ThetaResolution + 1; // the last column repeats the first (seam)

  // This piece's rows: whole rows of quads (SURFACE) or whole circles (CIRCLES).
  const int piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  const int pieces =
    std::max(1, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
  int firstRow, lastRow;
  if (!vtkBoostedGridBuilder::PieceRows(
        rows, this->OutputType == SURFACE, piece, pieces, firstRow, lastRow))
  {
    return 1; // more pieces than rows: this one is empty
  }

  vtkBoostedGridBuilder grid(rows, columns, true);
  grid.SetClipSphere(this->CircleCenter, this->ClipRadius);
  std::vector<double> lambdas(rows), thetas(columns);
  for (int r = 0; r < rows; ++r)
  {
    const double t = rows > 1 ? static_cast<double>(r) / (rows - 1) : 0.0;
    lambdas[r] = (1.0 - t) * this->LambdaRange[0] + t * this->LambdaRange[1];
  }
  for (int c = 0; c < columns; ++c)
  {
    thetas[c] = 2.0 * vtkMath::Pi() * c / this->ThetaResolution;
  }
  std::vector<cga::Vec3> circlePoints(columns);
  for (int c = 0; c < columns; ++c)
  {
    circlePoints[c] = family.circlePoint(thetas[c]);
  }
  circlePoints[columns - 1] = circlePoints[0]; // exactly the same point at the seam

  // Normals at a band's edge need the neighbouring rows, so sample one row more on each side.
  const int sampleFirst = std::max(0, firstRow - 1);
  const int sampleLast = std::min(rows - 1, lastRow + 1);
  for (int r = sampleFirst; r <= sampleLast; ++r)
  {
    if (vtkBoostedSurfacesCheckAbort(this))
    {
      break;
    }
    // One 5x5 matrix per lambda row: the sandwich K up(p) ~K is linear in up(p).
    const cga::PointMap boost(family.boostCompact(lambdas[r]));
    for (int c = 0; c < columns; ++c)
    {
      cga::Vec3 p;
      if (boost.apply(circlePoints[c], p)) // false: the point went to infinity; left NaN and dropped
      {
        const double point[3] = { p.x, p.y, p.z };
        grid.SetPoint(r, c, point);
      }
    }
    const cga::RoundInfo image = cga::readCircle(family.imageBlade(lambdas[r]), 1e-12);
    const double fallback[3] = { image.normal.x, image.normal.y, image.normal.z };
    grid.SetRowFallbackNormal(r, fallback);
    this->UpdateProgress(static_cast<double>(r - sampleFirst + 1) / (sampleLast - sampleFirst + 1));
  }
  grid.AddRowParameter("lambda", lambdas);
  grid.AddColumnParameter("theta", thetas);

  if (this->OutputType == SURFACE)
  {
    grid.BuildSurface(output, firstRow, lastRow, this->OutputPointsPrecision);
  }
  else
  {
    grid.BuildCurves(output, firstRow, lastRow, this->OutputPointsPrecision);
  }
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
}
