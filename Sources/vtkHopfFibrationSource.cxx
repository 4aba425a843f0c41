#include "vtkHopfFibrationSource.h"

#include "vtkBoostedGridBuilder.h"
#include "vtkBoostedRowList.h"
#include "vtkBoostedSphereClip.h"
#include "vtkBoostedSurfacesAbort.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "cga/surfaces/HopfFibration.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkHopfFibrationSource);

namespace
{
constexpr double kHalfPi = 1.5707963267948966;
constexpr double kTwoPi = 6.283185307179586;

bool finite2(const double v[2])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]);
}

/// The base points of the output's rows and how they group into strips.
struct BaseSampling
{
  std::vector<double> theta, phi;
  std::vector<int> stripId;
  int rowsPerStrip = 0; // 0: one strip of all rows
};
}

vtkHopfFibrationSource::vtkHopfFibrationSource()
  : BasePoints(new vtkBoostedRowList(this, "BasePoint", { 0.0, 0.0 }))
{
  this->SetNumberOfInputPorts(1); // optional points on a sphere (INPUT_POINTS)
}

int vtkHopfFibrationSource::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

vtkHopfFibrationSource::~vtkHopfFibrationSource() = default;

int vtkHopfFibrationSource::AddBasePoint(double theta, double phi)
{
  return this->BasePoints->Add({ theta, phi });
}

void vtkHopfFibrationSource::SetBasePoint(int index, double theta, double phi)
{
  this->BasePoints->Set(index, { theta, phi });
}

vtkBoostedRowListMethods(vtkHopfFibrationSource, BasePoint, BasePoints)

int vtkHopfFibrationSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

int vtkHopfFibrationSource::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Every rank needs all the base points: the fibers, not the input, are divided among pieces.
  if (inputVector[0]->GetNumberOfInformationObjects() > 0)
  {
    vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
  return 1;
}

long long vtkHopfFibrationSource::GridRows() const
{
  const bool latitudes = this->OutputType == TWISTOR_MESH && this->MeshSweep == LATITUDES;
  return static_cast<long long>(this->ThetaResolution + (latitudes ? 1 : 0)) * this->PhiResolution;
}

int vtkHopfFibrationSource::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  vtkPointSet* input = inputVector[0]->GetNumberOfInformationObjects() > 0
    ? vtkPointSet::GetData(inputVector[0]->GetInformationObject(0))
    : nullptr;

  cga::HopfFibration hopf;
  hopf.center = { this->CircleCenter[0], this->CircleCenter[1], this->CircleCenter[2] };
  hopf.normal = { this->CircleNormal[0], this->CircleNormal[1], this->CircleNormal[2] };
  hopf.radius = this->CircleRadius;
  hopf.mode = this->Mode == CLASSICAL ? cga::HopfMode::Classical : cga::HopfMode::Paper;
  std::string problem = hopf.validate();
  if (problem.empty() && this->FiberResolution < 3)
  {
    problem = "FiberResolution must be at least 3";
  }
  if (problem.empty() && std::isnan(this->ClipRadius)) // the clamp macro lets NaN through
  {
    problem = "ClipRadius must be a number";
  }
  const bool mesh = this->OutputType == TWISTOR_MESH;

  // ---- the base points of the rows ----
  BaseSampling base;
  auto addRow = [&base](double theta, double phi, int strip) {
    base.theta.push_back(theta);
    base.phi.push_back(phi);
    base.stripId.push_back(strip);
  };
  if (problem.empty() && this->SamplingMode == GRID)
  {
    if (this->ThetaResolution < 1 || this->PhiResolution < 1)
    {
      problem = "ThetaResolution and PhiResolution must be at least 1";
    }
    else if (!finite2(this->ThetaRange) || !finite2(this->PhiRange))
    {
      problem = "ThetaRange and PhiRange must be finite";
    }
    else if (this->ThetaRange[0] > this->ThetaRange[1] || this->PhiRange[0] > this->PhiRange[1])
    {
      problem = "ThetaRange and PhiRange must have minimum <= maximum";
    }
    else if (this->PhiRange[0] < -kHalfPi - 1e-12 || this->PhiRange[1] > kHalfPi + 1e-12)
    {
      problem = "PhiRange must lie within [-pi/2, pi/2]";
    }
    else if (!vtkBoostedGridBuilder::SizeProblem(this->GridRows(), this->FiberResolution + 1LL).empty())
    {
      // Checked before sampling: the base points alone could exhaust memory.
      problem = vtkBoostedGridBuilder::SizeProblem(this->GridRows(), this->FiberResolution + 1LL);
    }
    else
    {
      const int nTheta = this->ThetaResolution, nPhi = this->PhiResolution;
      auto thetaAt = [this, nTheta](int i) {
        return this->ThetaRange[0] + (this->ThetaRange[1] - this->ThetaRange[0]) * i / nTheta;
      };
      auto phiAt = [this, nPhi](int j) {
        const double phi = nPhi > 1
          ? this->PhiRange[0] + (this->PhiRange[1] - this->PhiRange[0]) * j / (nPhi - 1)
          : this->PhiRange[0];
        return std::max(-kHalfPi, std::min(kHalfPi, phi));
      };
      if (mesh && this->MeshSweep == LATITUDES)
      {
        base.rowsPerStrip = nTheta + 1; // theta0 .. theta1 inclusive
        for (int j = 0; j < nPhi; ++j)
        {
          for (int i = 0; i <= nTheta; ++i)
          {
            addRow(thetaAt(i), phiAt(j), j);
          }
        }
      }
      else
      {
        base.rowsPerStrip = nPhi;
        for (int i = 0; i < nTheta; ++i)
        {
          for (int j = 0; j < nPhi; ++j)
          {
            addRow(thetaAt(i), phiAt(j), i);
          }
        }
      }
    }
  }
  else if (problem.empty() && this->SamplingMode == BASE_POINTS)
  {
    problem = this->BasePoints->Problem();
    for (int k = 0; problem.empty() && k < this->GetNumberOfBasePoints(); ++k)
    {
      addRow(this->BasePoints->Row(k)[0], this->BasePoints->Row(k)[1], 0);
    }
  }
  else if (problem.empty() && this->SamplingMode == INPUT_POINTS)
  {
    if (!input)
    {
      problem = "SamplingMode INPUT_POINTS needs an input of points";
    }
    else if (!std::isfinite(this->SphereCenter[0]) || !std::isfinite(this->SphereCenter[1]) ||
      !std::isfinite(this->SphereCenter[2]))
    {
      problem = "SphereCenter must be finite";
    }
    else
    {
      int atCenter = 0;
      for (vtkIdType i = 0; i < input->GetNumberOfPoints() && problem.empty(); ++i)
      {
        double p[3];
        input->GetPoint(i, p);
        const double d[3] = { p[0] - this->SphereCenter[0], p[1] - this->SphereCenter[1],
          p[2] - this->SphereCenter[2] };
        if (!std::isfinite(d[0]) || !std::isfinite(d[1]) || !std::isfinite(d[2]))
        {
          problem = "the input points must be finite (a NaN or an infinity was given)";
        }
        else if (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0)
        {
          ++atCenter; // no direction: skipped
        }
        else
        {
          addRow(std::atan2(d[1], d[0]), std::atan2(d[2], std::hypot(d[0], d[1])), 0);
        }
      }
      if (problem.empty() && atCenter > 0)
      {
        vtkWarningMacro(<< atCenter << " input point(s) at SphereCenter have no direction and were skipped");
      }
    }
  }
  for (size_t r = 0; problem.empty() && r < base.theta.size(); ++r)
  {
    if (!std::isfinite(base.theta[r]) || !std::isfinite(base.phi[r]))
    {
      problem = "base points must be finite (a NaN or an infinity was given)";
    }
    else if (base.phi[r] < -kHalfPi - 1e-12 || base.phi[r] > kHalfPi + 1e-12)
    {
      problem = "the latitude phi of a base point must lie within [-pi/2, pi/2]";
    }
    else
    {
      base.phi[r] = std::max(-kHalfPi, std::min(kHalfPi, base.phi[r]));
    }
  }
  if (problem.empty())
  {
    problem = vtkBoostedGridBuilder::SizeProblem(
      static_cast<long long>(base.theta.size()), this->FiberResolution + 1LL);
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return 1; // the output stays empty
  }
  const int rows = static_cast<int>(base.theta.size());
  if (rows == 0)
  {
    return 1; // no base points: an empty output
  }
  if (mesh && (base.rowsPerStrip > 0 ? base.rowsPerStrip : rows) < 2)
  {
    // A strip of one fiber has no quads: say so rather than hand on points without cells.
    vtkWarningMacro(<< "TwistorMesh needs at least two base points per strip (PhiResolution >= 2 "
                       "with Meridians, or two base or input points): the output is empty");
    return 1;
  }

  // ---- this piece's rows ----
  const int piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  const int pieces =
    std::max(1, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
  int firstRow, lastRow;
  if (!vtkBoostedGridBuilder::PieceRows(rows, mesh, piece, pieces, firstRow, lastRow))
  {
    return 1; // more pieces than rows (of quads): nothing here
  }
  // Normals at a band's edge need the neighbouring rows.
  const int sampleFirst = mesh ? std::max(0, firstRow - 1) : firstRow;
  const int sampleLast = mesh ? std::min(rows - 1, lastRow + 1) : lastRow;

  // ---- the fibers ----
  const int columns = this->FiberResolution + 1; // the last column repeats the first (seam)
  vtkBoostedGridBuilder grid(rows, columns, true);
  // No clip sphere on the grid: it keeps every finite sample (however far) so that the cells
  // reaching beyond the clip sphere can be cut exactly on it below; only the samples at infinity
  // (NaN from the kernel) take their cells with them.
  const double clipRadius = this->ClipRadius * this->CircleRadius;
  if (mesh && base.rowsPerStrip > 0)
  {
    grid.SetRowsPerBlock(base.rowsPerStrip);
  }
  std::vector<unsigned char> failed(rows, 0);
  const int chunk = 64;
  for (int start = sampleFirst; start <= sampleLast; start += chunk)
  {
    if (vtkBoostedSurfacesCheckAbort(this))
    {
      break;
    }
    const int end = std::min(sampleLast + 1, start + chunk);
    vtkSMPTools::For(start, end, [&](int begin, int finish) {
      std::vector<cga::Vec3> points;
      for (int r = begin; r < finish; ++r)
      {
        if (!hopf.fiberPoints(base.theta[r], base.phi[r], this->FiberResolution, points))
        {
          failed[r] = 1;
          continue;
        }
        points.push_back(points.front()); // the seam column
        cga::Vec3 newell{ 0, 0, 0 };
        for (int c = 0; c < columns; ++c)
        {
          const double p[3] = { points[c].x, points[c].y, points[c].z };
          grid.SetPoint(r, c, p);
          if (c > 0 && cga::isFinite(points[c]) && cga::isFinite(points[c - 1]))
          {
            newell = newell + cga::cross(points[c - 1] - hopf.center, points[c] - hopf.center);
          }
        }
        const cga::Vec3 n = cga::normalized(newell);
        const double fallback[3] = { n.x, n.y, n.z };
        grid.SetRowFallbackNormal(r, fallback);
      }
    });
    this->UpdateProgress(static_cast<double>(end - sampleFirst) / (sampleLast - sampleFirst + 1));
  }
  const int failures = static_cast<int>(std::count(failed.begin(), failed.end(), 1));
  if (failures > 0)
  {
    vtkWarningMacro(<< failures << " fiber(s) could not be computed (motor logarithm failed) and were left out");
  }

  std::vector<int> fiberIds(rows);
  for (int r = 0; r < rows; ++r)
  {
    fiberIds[r] = r;
  }
  grid.AddRowParameter("theta", base.theta);
  grid.AddRowParameter("phi", base.phi);
  grid.AddRowIntegerParameter("FiberId", fiberIds);
  vtkNew<vtkPolyData> sampled;
  if (mesh)
  {
    grid.AddRowIntegerParameter("StripId", base.stripId);
    grid.BuildSurface(sampled, firstRow, lastRow, this->OutputPointsPrecision);
  }
  else
  {
    grid.BuildCurves(sampled, firstRow, lastRow, this->OutputPointsPrecision);
  }
  vtkBoostedSphereClip::Clip(sampled, this->CircleCenter, clipRadius, output);
  return 1;
}

void vtkHopfFibrationSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << (this->Mode == PAPER ? "PAPER" : "CLASSICAL") << "\n";
  os << indent << "CircleCenter: (" << this->CircleCenter[0] << ", " << this->CircleCenter[1]
     << ", " << this->CircleCenter[2] << ")\n";
  os << indent << "CircleNormal: (" << this->CircleNormal[0] << ", " << this->CircleNormal[1]
     << ", " << this->CircleNormal[2] << ")\n";
  os << indent << "CircleRadius: " << this->CircleRadius << "\n";
  const char* samplingNames[] = { "GRID", "BASE_POINTS", "INPUT_POINTS" };
  os << indent << "SamplingMode: " << samplingNames[this->SamplingMode] << "\n";
  os << indent << "ThetaRange: [" << this->ThetaRange[0] << ", " << this->ThetaRange[1] << "]\n";
  os << indent << "PhiRange: [" << this->PhiRange[0] << ", " << this->PhiRange[1] << "]\n";
  os << indent << "ThetaResolution: " << this->ThetaResolution << "\n";
  os << indent << "PhiResolution: " << this->PhiResolution << "\n";
  this->BasePoints->Print(os, indent);
  os << indent << "SphereCenter: (" << this->SphereCenter[0] << ", " << this->SphereCenter[1]
     << ", " << this->SphereCenter[2] << ")\n";
  os << indent << "FiberResolution: " << this->FiberResolution << "\n";
  os << indent << "ClipRadius: " << this->ClipRadius << "\n";
  os << indent << "OutputType: " << (this->OutputType == FIBERS ? "FIBERS" : "TWISTOR_MESH")
     << "\n";
  os << indent << "MeshSweep: " << (this->MeshSweep == MERIDIANS ? "MERIDIANS" : "LATITUDES")
     << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
}
