#include "vtkCurvaturePatchSource.h"

#include "vtkBoostedExponentialRule.h"
#include "vtkBoostedGridBuilder.h"
#include "vtkBoostedRowList.h"
#include "vtkBoostedSurfacesAbort.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "cga/surfaces/CurvaturePatch.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkCurvaturePatchSource);

namespace
{
cga::Vec3 toVec3(const double v[3])
{
  return { v[0], v[1], v[2] };
}

// Rows mapped between two abort checks and progress updates.
constexpr int kRowsPerBlock = 16;
}

vtkCurvaturePatchSource::vtkCurvaturePatchSource()
  : ControlPoints(new vtkBoostedRowList(
      this, "ControlPoint", { 0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0 }))
{
  this->SetNumberOfInputPorts(0);
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

int vtkCurvaturePatchSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  outputVector->GetInformationObject(0)->Set(CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

int vtkCurvaturePatchSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);

  cga::CurvaturePatch patch;
  patch.method = static_cast<cga::CurvatureMethod>(this->Method);
  patch.rule = vtkBoostedExponentialRule<vtkCurvaturePatchSource>(this->ExponentialRule);
  patch.frame.origin = toVec3(this->Origin);
  patch.frame.u = toVec3(this->UDirection);
  patch.frame.v = toVec3(this->VDirection);
  patch.sizeU = this->Size[0];
  patch.sizeV = this->Size[1];
  patch.kappaU = this->KappaU;
  patch.kappaV = this->KappaV;
  if (this->CurvaturePreset != CUSTOM)
  {
    cga::presetCurvatures(
      static_cast<cga::CurvaturePreset>(this->CurvaturePreset - 1), patch.kappaU, patch.kappaV);
  }
  patch.falloff = this->Falloff;
  patch.epsilon = this->Epsilon;
  for (int i = 0; i < this->GetNumberOfControlPoints(); ++i)
  {
    const double* c = this->ControlPoints->Row(i);
    const double* location = this->ControlPoints->Location(
      i, this->SelectedControlPoint, this->SelectedControlPointLocation);
    patch.controlPoints.push_back(
      { toVec3(location), { c[3], c[4], c[5] }, { c[6], c[7], c[8] }, c[9], c[10] });
  }
  const double* directions[4] = { this->Corner1Direction, this->Corner2Direction,
    this->Corner3Direction, this->Corner4Direction };
  for (int i = 0; i < 4; ++i)
  {
    patch.corners[i] = { toVec3(directions[i]), this->CornerWeights[i] };
  }
  // A refused list first: its kept rows would give a misleading message.
  std::string problem = this->Method == CONTROL_POINTS ? this->ControlPoints->Problem() : "";
  if (problem.empty())
  {
    problem = patch.validate();
  }
  if (problem.empty() && std::isnan(this->ClipRadius)) // the clamp macro lets NaN through
  {
    problem = "ClipRadius must be a number";
  }
  if (problem.empty())
  {
    problem = vtkBoostedGridBuilder::SizeProblem(
      patch.sizeV > 0.0 ? this->VResolution + 1LL : 1LL, this->UResolution + 1LL);
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return 1; // the output stays empty
  }

  const int rows = patch.sizeV > 0.0 ? this->VResolution + 1 : 1;
  const int columns = this->UResolution + 1;
  const bool surface = this->OutputType == SURFACE && rows > 1;

  // This piece's rows: whole rows of quads (surface) or whole rows of points (lines).
  const int piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  const int pieces =
    std::max(1, outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
  int firstRow, lastRow;
  if (!vtkBoostedGridBuilder::PieceRows(rows, surface, piece, pieces, firstRow, lastRow))
  {
    return 1; // more pieces than rows: this one is empty
  }

  std::vector<double> us(columns), vs(rows);
  for (int c = 0; c < columns; ++c)
  {
    us[c] = patch.a(c, columns);
  }
  for (int r = 0; r < rows; ++r)
  {
    vs[r] = patch.b(r, rows);
  }

  vtkBoostedGridBuilder grid(rows, columns, false);
  grid.SetClipSphere(this->Origin, this->ClipRadius);
  std::vector<double> weights(static_cast<size_t>(rows) * columns, 0.0);
  const double fallback[3] = { patch.frame.normal.x, patch.frame.normal.y, patch.frame.normal.z };

  // Normals at a band's edge need the neighbouring rows, so sample one row more on each side.
  const int sampleFirst = std::max(0, firstRow - 1);
  const int sampleLast = std::min(rows - 1, lastRow + 1);
  for (int blockFirst = sampleFirst; blockFirst <= sampleLast; blockFirst += kRowsPerBlock)
  {
    if (vtkBoostedSurfacesCheckAbort(this))
    {
      break;
    }
    const int blockLast = std::min(sampleLast, blockFirst + kRowsPerBlock - 1);
    const vtkIdType begin = static_cast<vtkIdType>(blockFirst) * columns;
    const vtkIdType end = static_cast<vtkIdType>(blockLast + 1) * columns;
    // Every sample writes only its own grid slot: the builder's points and `weights`.
    vtkSMPTools::For(begin, end, [&](vtkIdType first, vtkIdType last) {
      for (vtkIdType i = first; i < last; ++i)
      {
        const int r = static_cast<int>(i / columns);
        const int c = static_cast<int>(i % columns);
        cga::Vec3 image;
        double weight = 0.0;
        if (patch.map(us[c], vs[r], image, weight)) // false: at infinity; left NaN and dropped
        {
          const double point[3] = { image.x, image.y, image.z };
          grid.SetPoint(r, c, point);
          weights[i] = weight;
        }
      }
    });
    for (int r = blockFirst; r <= blockLast; ++r)
    {
      grid.SetRowFallbackNormal(r, fallback);
    }
    this->UpdateProgress(static_cast<double>(blockLast - sampleFirst + 1) / (sampleLast - sampleFirst + 1));
  }
  grid.AddColumnParameter("u", us);
  grid.AddRowParameter("v", vs);
  grid.AddPointParameter("GeneratorWeight", weights);

  if (surface)
  {
    grid.BuildSurface(output, firstRow, lastRow, this->OutputPointsPrecision);
  }
  else
  {
    grid.BuildCurves(output, firstRow, lastRow, this->OutputPointsPrecision);
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
}
