#include "vtkCurvaturePatchSource.h"

#include "vtkBoostedCurvatureArrays.h"
#include "vtkBoostedExponentialRule.h"
#include "vtkBoostedGeneratorGlyphs.h"
#include "vtkBoostedGridDriver.h"
#include "vtkBoostedTimeSweep.h"
#include "vtkBoostedMemoryBudget.h"
#include "vtkBoostedRowList.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include "cga/surfaces/CurvaturePatch.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

vtkStandardNewMacro(vtkCurvaturePatchSource);

vtkCurvaturePatchSource::vtkCurvaturePatchSource()
  : ControlPoints(new vtkBoostedRowList(
      this, "ControlPoint", { 0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0 }))
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2); // the patch, its generators
}

vtkCurvaturePatchSource::~vtkCurvaturePatchSource() = default;

int vtkCurvaturePatchSource::AddControlPoint(double x, double y, double z, double nx, double ny,
  double nz, double ux, double uy, double uz, double kappaU, double kappaV)
{
  return this->ControlPoints->Add({ x, y, z, nx, ny, nz, ux, uy, uz, kappaU, kappaV });
}

void vtkCurvaturePatchSource::SetControlPoint(int index, double x, double y, double z, double nx,
  double ny, double nz, double ux, double uy, double uz, double kappaU, double kappaV)
{
  this->ControlPoints->Set(index, { x, y, z, nx, ny, nz, ux, uy, uz, kappaU, kappaV });
}

vtkBoostedRowListMethods(vtkCurvaturePatchSource, ControlPoint, ControlPoints)

int vtkCurvaturePatchSource::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    vtkBoostedGeneratorGlyphs::FillOutputPortInformation(info);
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

int vtkCurvaturePatchSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkBoostedTimeSweep::ReportOnEveryPort(outputVector, this->NumberOfTimeSteps, true);
  return 1;
}

int vtkCurvaturePatchSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);

  cga::CurvaturePatch patch;
  patch.method = static_cast<cga::CurvatureMethod>(this->Method);
  patch.rule = vtkBoostedExponentialRule<vtkCurvaturePatchSource>(this->ExponentialRule);
  patch.frame.origin = cga::toVec3(this->Origin);
  patch.frame.u = cga::toVec3(this->UDirection);
  patch.frame.v = cga::toVec3(this->VDirection);
  patch.sizeU = this->Size[0];
  patch.sizeV = this->Size[1];
  patch.kappaU = this->KappaU;
  patch.kappaV = this->KappaV;
  if (this->CurvaturePreset != CUSTOM)
  {
    cga::presetCurvatures(
      static_cast<cga::CurvaturePreset>(this->CurvaturePreset - 1), patch.kappaU, patch.kappaV);
  }
  // The time sweep scales every curvature from 0 (the flat plane) to its value.
  const double scale = vtkBoostedTimeSweep::Fraction(outInfo, this->NumberOfTimeSteps);
  patch.kappaU *= scale;
  patch.kappaV *= scale;
  patch.falloff = this->Falloff;
  patch.epsilon = this->Epsilon;
  for (int i = 0; i < this->GetNumberOfControlPoints(); ++i)
  {
    const double* c = this->ControlPoints->Row(i);
    const double* location = this->ControlPoints->Location(
      i, this->SelectedControlPoint, this->SelectedControlPointLocation);
    patch.controlPoints.push_back(
      { cga::toVec3(location), { c[3], c[4], c[5] }, { c[6], c[7], c[8] }, scale * c[9],
        scale * c[10] });
  }
  const double* directions[4] = { this->Corner1Direction, this->Corner2Direction,
    this->Corner3Direction, this->Corner4Direction };
  for (int i = 0; i < 4; ++i)
  {
    patch.corners[i] = { cga::toVec3(directions[i]), scale * this->CornerWeights[i] };
  }
  const long long rows = patch.sizeV > 0.0 ? this->VResolution + 1LL : 1LL;
  const long long columns = this->UResolution + 1LL;
  // A refused list first: its kept rows would give a misleading message.
  std::string problem = this->Method == CONTROL_POINTS ? this->ControlPoints->Problem() : "";
  if (problem.empty())
  {
    problem = patch.validate();
  }
  vtkBoostedGridDriver driver(
    this, outInfo, this->Origin, this->ClipRadius, this->OutputPointsPrecision);
  // The update's memory per grid sample, for the memory budget (vtkBoostedMemoryBudget): peak
  // resident memory of a 2000 x 2000 grid, double precision, measured once (156 and 104 bytes;
  // 15 GB at the 1e8-sample cap for the surface in issue 15; 340 with ComputeCurvatures: its
  // exact normals and arrays).
  const bool surface = this->OutputType == SURFACE && rows > 1;
  const bool curvatures = surface && this->ComputeCurvatures;
  const double normalsBytes = 24.0; // the exact normals, 3 doubles a sample in the grid
  driver.SetBytesPerSample(surface
      ? 156 + (curvatures ? normalsBytes + vtkBoostedCurvatureArrays::BytesPerSample : 0.0)
      : 104);
  if (!driver.Prepare(problem, rows, columns, false, surface))
  {
    return 1; // an error, or an empty piece
  }

  std::vector<double> us(columns), vs(rows);
  for (int c = 0; c < columns; ++c)
  {
    us[c] = patch.a(c, static_cast<int>(columns));
  }
  for (int r = 0; r < rows; ++r)
  {
    vs[r] = patch.b(r, static_cast<int>(rows));
  }
  vtkBoostedGridBuilder& grid = driver.Grid();
  int weights = -1; // the grid's GeneratorWeight values, written by the sampling
  if (!vtkBoostedMemoryBudget::Run(this, [&] { weights = grid.AddSampleArray("GeneratorWeight", 1); }))
  {
    return 1; // the output stays empty
  }
  const double fallback[3] = { patch.frame.normal.x, patch.frame.normal.y, patch.frame.normal.z };
  std::unique_ptr<vtkBoostedCurvatureArrays> exact;
  if (curvatures)
  {
    exact.reset(new vtkBoostedCurvatureArrays(grid, true));
  }
  // Runs of a row's samples mapped at once (the block kernel), each writing only its own grid
  // slots: the builder's points and weights (one row's values are consecutive).
  driver.SampleRuns([&](int r, int first, int last) {
    const size_t count = static_cast<size_t>(last - first);
    double* runWeights = grid.SampleValues(weights, r, first);
    std::unique_ptr<bool[]> mapped(new bool[count]);
    const auto setPoint = [&grid, r](int column, const cga::Vec3& image) {
      const double point[3] = { image.x, image.y, image.z };
      grid.SetPoint(r, column, point);
    };
    if (exact)
    {
      // The row's derivatives eight samples at a time; their points and weights are mapRow's (the
      // same bits), so the samples are not mapped again. Where derivativesRow fails (a sample at
      // infinity, a derivative not finite) the sample is mapped alone and keeps its
      // central-difference normal.
      std::vector<cga::SurfaceDerivatives> derivatives(count);
      patch.derivativesRow(vs[r], &us[first], count, derivatives.data(), mapped.get(), runWeights);
      for (size_t i = 0; i < count; ++i)
      {
        const int column = first + static_cast<int>(i);
        cga::Vec3 image = derivatives[i].point;
        if (mapped[i])
        {
          exact->Set(r, column, derivatives[i]);
        }
        else
        {
          mapped[i] = patch.map(us[column], vs[r], image, runWeights[i]);
        }
        if (mapped[i]) // false: at infinity; left NaN and dropped
        {
          setPoint(column, image);
        }
      }
    }
    else
    {
      std::vector<cga::Vec3> images(count);
      patch.mapRow(vs[r], &us[first], count, images.data(), runWeights, mapped.get());
      for (size_t i = 0; i < count; ++i)
      {
        if (mapped[i]) // false: at infinity; left NaN and dropped
        {
          setPoint(first + static_cast<int>(i), images[i]);
        }
      }
    }
    if (first == 0)
    {
      grid.SetRowFallbackNormal(r, fallback);
    }
  });
  grid.AddColumnParameter("u", us);
  grid.AddRowParameter("v", vs);
  if (driver.Build(vtkPolyData::GetData(outInfo)) &&
    vtkBoostedGeneratorGlyphs::OnFirstPiece(outputVector))
  {
    // Output 1, the generators of the Method as used (validated, at this time's curvatures).
    vtkBoostedGeneratorGlyphs glyphs(vtkBoostedGeneratorGlyphs::Curvature);
    const cga::PatchFrame& frame = patch.frame;
    const double hu = 0.5 * patch.sizeU;
    switch (this->Method)
    {
      case CONTROL_POINTS:
        for (const cga::CurvatureControlPoint& c : patch.controlPoints)
        {
          glyphs.Add(c.location, c.normal, 1.0, 0, 0.0, c.kappaU, c.kappaV);
        }
        break;
      case LINEAR:
        glyphs.Add(frame.at(-hu, 0.0), patch.corners[0].direction, patch.corners[0].weight);
        glyphs.Add(frame.at(hu, 0.0), patch.corners[1].direction, patch.corners[1].weight);
        break;
      case BILINEAR:
        for (int i = 0; i < 4; ++i)
        {
          glyphs.Add(patch.cornerLocations()[i], patch.corners[i].direction, patch.corners[i].weight);
        }
        break;
      default: // the curvatures at Origin (BENT_LINE: KappaU only)
        glyphs.Add(frame.origin, frame.normal, 1.0, 0, 0.0, patch.kappaU,
          this->Method == BENT_LINE ? 0.0 : patch.kappaV);
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

void vtkCurvaturePatchSource::PrintSelf(ostream& os, vtkIndent indent)
{
  static const char* methods[] = { "BENT_LINE", "TRANSLATED_TANGENTS", "OSCULATING_CIRCLES",
    "CONTROL_POINTS", "LINEAR", "BILINEAR" };
  static const char* presets[] = { "CUSTOM", "PARABOLIC", "ELLIPTIC", "UMBILIC", "HYPERBOLIC" };
  auto vector = [&os](const char* name, const double* v, int n) {
    os << name << ": (";
    for (int i = 0; i < n; ++i)
    {
      os << (i ? ", " : "") << v[i];
    }
    os << ")\n";
  };
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << methods[this->Method] << "\n";
  os << indent << "ExponentialRule: " << (this->ExponentialRule == PAPER ? "PAPER" : "EXACT") << "\n";
  vector((os << indent, "Origin"), this->Origin, 3);
  vector((os << indent, "UDirection"), this->UDirection, 3);
  vector((os << indent, "VDirection"), this->VDirection, 3);
  vector((os << indent, "Size"), this->Size, 2);
  os << indent << "UResolution: " << this->UResolution << "\n";
  os << indent << "VResolution: " << this->VResolution << "\n";
  os << indent << "KappaU: " << this->KappaU << "\n";
  os << indent << "KappaV: " << this->KappaV << "\n";
  os << indent << "CurvaturePreset: " << presets[this->CurvaturePreset] << "\n";
  os << indent << "Falloff: " << this->Falloff << "\n";
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  this->ControlPoints->Print(os, indent);
  os << indent << "SelectedControlPoint: " << this->SelectedControlPoint << "\n";
  vector((os << indent, "SelectedControlPointLocation"), this->SelectedControlPointLocation, 3);
  vector((os << indent, "Corner1Direction"), this->Corner1Direction, 3);
  vector((os << indent, "Corner2Direction"), this->Corner2Direction, 3);
  vector((os << indent, "Corner3Direction"), this->Corner3Direction, 3);
  vector((os << indent, "Corner4Direction"), this->Corner4Direction, 3);
  vector((os << indent, "CornerWeights"), this->CornerWeights, 4);
  os << indent << "ClipRadius: " << this->ClipRadius << "\n";
  os << indent << "OutputType: " << (this->OutputType == SURFACE ? "SURFACE" : "LINES") << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "ComputeCurvatures: " << this->ComputeCurvatures << "\n";
  os << indent << "NumberOfTimeSteps: " << this->NumberOfTimeSteps << "\n";
}
