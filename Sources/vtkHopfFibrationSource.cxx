#include "vtkHopfFibrationSource.h"

#include "vtkBoostedGeneratorGlyphs.h"
#include "vtkBoostedGridDriver.h"
#include "vtkBoostedMemoryBudget.h"
#include "vtkBoostedRowList.h"
#include "vtkBoostedTimeSweep.h"
#include "vtkBoostedWholeInput.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointSet.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "cga/SurfaceCurvature.h"
#include "cga/surfaces/HopfFibration.h"
#include "cga/surfaces/HopfSampling.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkHopfFibrationSource);

vtkHopfFibrationSource::vtkHopfFibrationSource()
  : BasePoints(new vtkBoostedRowList(this, "BasePoint", { 0.0, 0.0 }))
{
  this->SetNumberOfInputPorts(1); // optional points on a sphere (INPUT_POINTS)
  this->SetNumberOfOutputPorts(2); // the fibers or mesh, the base points
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

int vtkHopfFibrationSource::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    vtkBoostedGeneratorGlyphs::FillOutputPortInformation(info);
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

int vtkHopfFibrationSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkBoostedTimeSweep::ReportOnEveryPort(outputVector, this->NumberOfTimeSteps, true);
  return 1;
}

int vtkHopfFibrationSource::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Every rank needs all the base points: the fibers, not the input, are divided among pieces.
  vtkBoostedWholeInput::Request(inputVector[0]->GetInformationObject(0));
  return 1;
}

int vtkHopfFibrationSource::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPointSet* input = inputVector[0]->GetNumberOfInformationObjects() > 0
    ? vtkPointSet::GetData(inputVector[0]->GetInformationObject(0))
    : nullptr;
  const bool mesh = this->OutputType == TWISTOR_MESH;

  cga::HopfFibration hopf;
  hopf.center = cga::toVec3(this->CircleCenter);
  hopf.normal = cga::toVec3(this->CircleNormal);
  hopf.radius = this->CircleRadius;
  hopf.mode = this->Mode == CLASSICAL ? cga::HopfMode::Classical : cga::HopfMode::Paper;
  cga::HopfSampling sampling = this->Sampling(input);
  // The time sweep moves the latitudes' upper end from their lower end to its value (a range
  // in the wrong order stays as it is, for its error).
  if (sampling.phiRange[0] <= sampling.phiRange[1])
  {
    sampling.phiRange[1] = vtkBoostedTimeSweep::Interpolate(sampling.phiRange[0],
      sampling.phiRange[1], vtkBoostedTimeSweep::Fraction(outInfo, this->NumberOfTimeSteps));
  }
  const long long columns = this->FiberResolution + 1LL; // the last column repeats the first (seam)
  std::string problem = hopf.validate();
  if (problem.empty() && this->FiberResolution < 3)
  {
    problem = "FiberResolution must be at least 3";
  }
  if (problem.empty() && this->SamplingMode == BASE_POINTS)
  {
    problem = this->BasePoints->Problem(); // a refused list
  }
  // The update's memory per grid sample, for the memory budget (vtkBoostedMemoryBudget): the peak
  // resident memory, double precision, measured at the 1e8-sample cap for issue 15 (14 and 23 GB;
  // 84 and 138 bytes a sample at 4000 fibers of 1000 points, where the arrays' growth by
  // doubling overshoots less) and for the default 72 fibers of 500,000 and 1,000,000 points
  // (155.5 and 154.6 bytes a sample for the fibers, 258.7 for the mesh at 500,000: long fibers
  // cost more), with a few percent to spare.
  const double bytesPerSample = mesh ? 265 : 160;
  if (problem.empty()) // before sampling: the base points alone could exhaust memory
  {
    problem = vtkBoostedGridDriver::GridProblem(sampling.rowCount(), columns, bytesPerSample,
      mesh ? "the twistor mesh" : "the fibers");
  }
  cga::HopfRows base;
  if (problem.empty() &&
    !vtkBoostedMemoryBudget::Run(this, [&] { problem = sampling.sample(base); }))
  {
    return 1; // out of memory: the output stays empty
  }
  if (problem.empty() && base.skipped > 0)
  {
    vtkWarningMacro(<< base.skipped
                    << " input point(s) at SphereCenter have no direction and were skipped");
  }
  if (problem.empty() && base.size() == 0)
  {
    return 1; // no base points: an empty output
  }
  if (problem.empty() && mesh && base.stripLength() < 2)
  {
    // A strip of one fiber has no quads: say so rather than hand on points without cells.
    vtkWarningMacro(<< "TwistorMesh needs at least two base points per strip (PhiResolution >= 2 "
                       "with Meridians, or two base or input points): the output is empty");
    return 1;
  }
  vtkBoostedGridDriver driver(
    this, outInfo, this->CircleCenter, this->ClipRadius, this->OutputPointsPrecision);
  driver.SetMergeSeam(this->MergeSeam);
  if (!driver.Prepare(problem, static_cast<long long>(base.size()), columns, true, mesh,
        mesh ? base.rowsPerStrip : 0))
  {
    return 1; // an error, or an empty piece
  }

  vtkBoostedGridBuilder& grid = driver.Grid();
  std::atomic<int> failures{ 0 };
  const std::vector<cga::Vec3> circle = cga::HopfFibration::circleSamples(this->FiberResolution);
  driver.SampleRows([&](int r) {
    std::vector<cga::Vec3> points(columns);
    if (!hopf.fiberPoints(base.theta[r], base.phi[r], circle, points.data()))
    {
      ++failures;
      return;
    }
    points[columns - 1] = points.front(); // the seam column
    for (int c = 0; c < columns; ++c)
    {
      const double p[3] = { points[c].x, points[c].y, points[c].z };
      grid.SetPoint(r, c, p);
    }
    // The fiber's plane, for the normals where the mesh gives none.
    const cga::Vec3 n = cga::planeNormal(points.data(), points.size(), hopf.center);
    const double fallback[3] = { n.x, n.y, n.z };
    grid.SetRowFallbackNormal(r, fallback);
  });
  if (failures > 0)
  {
    vtkWarningMacro(<< failures << " fiber(s) could not be computed (motor logarithm failed) and were left out");
  }

  std::vector<int> fiberIds(base.size());
  std::iota(fiberIds.begin(), fiberIds.end(), 0);
  grid.AddRowParameter("theta", base.theta);
  grid.AddRowParameter("phi", base.phi);
  grid.AddRowIntegerParameter("FiberId", fiberIds);
  if (mesh)
  {
    grid.AddRowIntegerParameter("StripId", base.strip);
  }
  if (driver.Build(vtkPolyData::GetData(outInfo)) &&
    vtkBoostedGeneratorGlyphs::OnFirstPiece(outputVector))
  {
    // Output 1: each base point on the base sphere (C's center and radius, C's frame), along the
    // paper's boost direction v_theta, with the boost's k as its weight.
    vtkBoostedGeneratorGlyphs glyphs(vtkBoostedGeneratorGlyphs::NoColumns);
    const double pi = std::acos(-1.0);
    for (std::size_t i = 0; i < base.size(); ++i)
    {
      const double theta = base.theta[i], phi = base.phi[i];
      const cga::Vec3 onSphere{ std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta),
        std::sin(phi) };
      const cga::Vec3 boost =
        (1.0 / hopf.radius) * (hopf.toWorld({ std::cos(theta), std::sin(theta), 0.0 }) - hopf.center);
      glyphs.Add(hopf.toWorld(onSphere), boost, 0.5 + phi / pi);
    }
    glyphs.Write(vtkPolyData::GetData(outputVector, 1), this->GeneratorGlyphs);
  }
  for (int port = 0; port < this->GetNumberOfOutputPorts(); ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    vtkBoostedTimeSweep::StampTime(info, this->NumberOfTimeSteps, vtkPolyData::GetData(info));
  }
  return 1;
}

cga::HopfSampling vtkHopfFibrationSource::Sampling(vtkPointSet* input) const
{
  cga::HopfSampling sampling;
  sampling.mode = static_cast<cga::HopfSamplingMode>(this->SamplingMode);
  std::copy_n(this->ThetaRange, 2, sampling.thetaRange);
  std::copy_n(this->PhiRange, 2, sampling.phiRange);
  sampling.thetaResolution = this->ThetaResolution;
  sampling.phiResolution = this->PhiResolution;
  sampling.latitudeStrips = this->OutputType == TWISTOR_MESH && this->MeshSweep == LATITUDES;
  if (this->SamplingMode == BASE_POINTS)
  {
    sampling.basePoints = this->BasePoints->GetValues();
  }
  sampling.sphereCenter = cga::toVec3(this->SphereCenter);
  if (input)
  {
    sampling.inputCount = static_cast<std::size_t>(input->GetNumberOfPoints());
    sampling.point = [input](std::size_t i) {
      double p[3];
      input->GetPoint(static_cast<vtkIdType>(i), p);
      return cga::Vec3{ p[0], p[1], p[2] };
    };
  }
  return sampling;
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
  os << indent << "MergeSeam: " << this->MergeSeam << "\n";
  os << indent << "NumberOfTimeSteps: " << this->NumberOfTimeSteps << "\n";
}
