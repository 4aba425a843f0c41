#include "vtkConformalOrbitSource.h"

#include "vtkBoostedGeneratorGlyphs.h"
#include "vtkBoostedGeneratorRows.h"
#include "vtkBoostedGridBuilder.h"
#include "vtkBoostedGridDriver.h"
#include "vtkBoostedRowList.h"
#include "vtkBoostedSinglePrecision.h"
#include "vtkBoostedSphereClip.h"
#include "vtkBoostedTimeSweep.h"
#include "vtkBoostedWholeInput.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "cga/Orbit.h"
#include "cga/PointSandwich.h"
#include "cga/PointPairField.h"
#include "cga/surfaces/TorusKnot.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <memory>
#include <numeric>
#include <optional>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkConformalOrbitSource);

namespace
{
bool finite(const double* values, int count)
{
  for (int i = 0; i < count; ++i)
  {
    if (!std::isfinite(values[i]))
    {
      return false;
    }
  }
  return true;
}

/// The identity's orbits: each seed of rows [first, last] as a vertex (double points).
void writeFixedSeeds(
  const std::vector<cga::Vec3>& seeds, int first, int last, double t, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataType(VTK_DOUBLE);
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkDoubleArray> ts;
  ts->SetName("t");
  vtkNew<vtkIntArray> ids;
  ids->SetName("OrbitId");
  for (int r = first; r <= last; ++r)
  {
    const vtkIdType id = points->InsertNextPoint(seeds[r].x, seeds[r].y, seeds[r].z);
    vertices->InsertNextCell(1, &id);
    ts->InsertNextValue(t);
    ids->InsertNextValue(r);
  }
  output->SetPoints(points);
  output->SetVerts(vertices);
  output->GetPointData()->AddArray(ts);
  output->GetPointData()->AddArray(ids);
}
} // namespace

vtkConformalOrbitSource::vtkConformalOrbitSource()
  : Generators(new vtkBoostedRowList(this, "Generator", vtkBoostedGeneratorRows::BlankRow()))
  , Seeds(new vtkBoostedRowList(this, "Seed", { 0, 0, 0 }))
{
  static_assert(vtkBoostedGeneratorKinds<vtkConformalOrbitSource>(), "");
  this->SetNumberOfInputPorts(1);  // optional seeds (INPUT_POINTS)
  this->SetNumberOfOutputPorts(3); // the orbits, the cores, the generators
}

vtkConformalOrbitSource::~vtkConformalOrbitSource() = default;

vtkBoostedGeneratorRowMethods(vtkConformalOrbitSource, Generators)

int vtkConformalOrbitSource::AddSeed(double x, double y, double z)
{
  return this->Seeds->Add({ x, y, z });
}

void vtkConformalOrbitSource::SetSeed(int index, double x, double y, double z)
{
  this->Seeds->Set(index, { x, y, z });
}

vtkBoostedRowListMethods(vtkConformalOrbitSource, Seed, Seeds)

int vtkConformalOrbitSource::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPointSet");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkConformalOrbitSource::FillOutputPortInformation(int port, vtkInformation* info)
{
  if (port == 2)
  {
    vtkBoostedGeneratorGlyphs::FillOutputPortInformation(info);
    return 1;
  }
  return this->Superclass::FillOutputPortInformation(port, info);
}

int vtkConformalOrbitSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkBoostedTimeSweep::ReportOnEveryPort(outputVector, this->NumberOfTimeSteps, true);
  return 1;
}

int vtkConformalOrbitSource::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Every rank reads all the seeds: the orbits, not the input, are divided among pieces.
  vtkBoostedWholeInput::Request(inputVector[0]->GetInformationObject(0));
  return 1;
}

int vtkConformalOrbitSource::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* orbits = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* cores = vtkPolyData::GetData(outputVector, 1);
  // The generators (output 2), written last, once every other output is built: after an error
  // every output stays empty.
  vtkBoostedGeneratorGlyphs glyphs(this->GeneratorType == TORUS_KNOT
      ? vtkBoostedGeneratorGlyphs::NoColumns
      : vtkBoostedGeneratorGlyphs::KindAndPitch);
  vtkPointSet* input = inputVector[0]->GetNumberOfInformationObjects() > 0
    ? vtkPointSet::GetData(inputVector[0]->GetInformationObject(0))
    : nullptr;

  // B, from the torus knot or the generator list, built about the center c (README, *Far from
  // the origin*): KnotCenter, or the mean location of the rows that count. The seeds are moved by
  // -c and the orbits and cores by +c, so moving everything by t moves the output by t to a few
  // eps |t| (B built in place would hold |c|^2 and round like eps |c|^2).
  std::string problem;
  cga::Bivector b;
  cga::TorusKnot knot;
  cga::Vec3 center{ 0, 0, 0 };
  const bool isKnot = this->GeneratorType == TORUS_KNOT;
  if (isKnot)
  {
    knot.center = cga::toVec3(this->KnotCenter);
    knot.normal = cga::toVec3(this->KnotNormal);
    knot.direction = cga::toVec3(this->KnotDirection);
    knot.radius = this->KnotRadius;
    knot.p = this->KnotP;
    knot.q = this->KnotQ;
    problem = knot.validate();
    center = knot.center;
    knot.center = { 0, 0, 0 };
  }
  else
  {
    problem = this->Generators->Problem();
    // Row i as used: the selected row's location and (aimed) direction are the line widget's.
    const vtkBoostedGeneratorRows::Selection selection{ this->SelectedGenerator,
      this->SelectedGeneratorLocation, this->AimSelectedGenerator, this->SelectedGeneratorTip };
    double used[vtkBoostedGeneratorRows::NumberOfValues];
    auto rowAsUsed = [this, &selection, &used](int i) {
      return vtkBoostedGeneratorRows::Selected(this->Generators->Row(i), i, selection, used);
    };
    std::vector<cga::GeneratorParameters> kept;
    int ignored = 0;
    for (int i = 0; problem.empty() && i < this->Generators->GetNumberOfRows(); ++i)
    {
      const double* row = rowAsUsed(i);
      cga::GeneratorParameters generator;
      if (!finite(row, vtkBoostedGeneratorRows::NumberOfValues))
      {
        problem = "generator " + std::to_string(i) + " has a NaN or infinite value";
        break;
      }
      if (!vtkBoostedGeneratorRows::Read(row, row, i, generator, problem))
      {
        break; // an unknown kind
      }
      const cga::FieldGenerator g = generator.field();
      if (row[6] == 0.0 || !(cga::norm(generator.direction) > 0.0) || !std::isfinite(g.weight))
      {
        ++ignored;
        continue;
      }
      kept.push_back(generator);
    }
    for (int i = 0; problem.empty() && i < this->Generators->GetNumberOfRows(); ++i)
    {
      cga::GeneratorParameters generator;
      const double* row = rowAsUsed(i);
      vtkBoostedGeneratorRows::Read(row, row, i, generator, problem);
      glyphs.Add(generator);
    }
    // The mean as a sum of x_i / n (as cga::PointPairField's center): no overflow, and a lone
    // row's location exactly.
    for (const cga::GeneratorParameters& generator : kept)
    {
      center = center + (1.0 / static_cast<double>(kept.size())) * generator.location;
    }
    for (cga::GeneratorParameters generator : kept)
    {
      generator.location = generator.location - center;
      const cga::FieldGenerator g = generator.field();
      // The filter's sign: exp(t B) is its exp(-Strength B(p)) at Strength t.
      b -= g.weight * g.bivector;
    }
    if (problem.empty() && ignored > 0)
    {
      vtkWarningMacro(<< ignored << " generator(s) with a zero direction or weight add nothing");
    }
  }
  const cga::Orbit orbit = problem.empty() && isKnot ? knot.orbit() : cga::Orbit(b);
  // TORUS_KNOT's generators: the two core circles, at their centers along their normals, with
  // their rates pi/P and pi/Q as weights.
  if (problem.empty() && isKnot)
  {
    const cga::TorusKnot::Circle circles[2] = { knot.coreA(), knot.coreC() };
    const double pi = std::acos(-1.0);
    const double rates[2] = { pi / knot.p, pi / knot.q };
    for (int i = 0; i < 2; ++i)
    {
      glyphs.Add(circles[i].center + center, circles[i].normal, rates[i]);
    }
  }
  // Output 2, on piece 0 only (as the cores), once the other outputs are built.
  auto writeGenerators = [&] {
    if (vtkBoostedGeneratorGlyphs::OnFirstPiece(outputVector))
    {
      glyphs.Write(vtkPolyData::GetData(outputVector, 2), this->GeneratorGlyphs);
    }
  };
  if (problem.empty())
  {
    problem = orbit.problem();
  }
  if (problem.empty() && !(finite(this->TRange, 2) && this->TRange[0] <= this->TRange[1]))
  {
    problem = "TRange must be finite with min <= max";
  }

  // The seeds, counted first: the size checks come before any copy of a huge input.
  const int columns = this->TResolution + 1;
  // Bytes per sample: the Hopf source's fibers, measured for the same builder and clip.
  const double bytesPerSample = 140;
  std::vector<cga::Vec3> seeds;
  if (problem.empty())
  {
    long long count = 1;
    if (this->SeedMode == SEED_LIST)
    {
      problem = this->Seeds->Problem();
      count = this->Seeds->GetNumberOfRows();
    }
    else if (this->SeedMode == INPUT_POINTS)
    {
      problem = input ? "" : "SeedMode is INPUT_POINTS but there is no input";
      count = input ? static_cast<long long>(input->GetNumberOfPoints()) : 0;
    }
    if (problem.empty())
    {
      problem = vtkBoostedGridDriver::GridProblem(count, columns, bytesPerSample, "the orbits");
    }
    for (long long i = 0; problem.empty() && i < count; ++i)
    {
      double p[3];
      if (this->SeedMode == SEED_POINT)
      {
        std::copy_n(this->SeedPoint, 3, p);
      }
      else if (this->SeedMode == SEED_LIST)
      {
        std::copy_n(this->Seeds->Row(static_cast<int>(i)), 3, p);
      }
      else
      {
        input->GetPoint(static_cast<vtkIdType>(i), p);
      }
      seeds.push_back(cga::toVec3(p));
      if (!cga::isFinite(seeds.back()))
      {
        problem = "seed " + std::to_string(i) + " is not finite";
      }
    }
  }

  // The samples of t: one period (closed orbits) or TRange, up to the animation's time (README,
  // *Time*: t's upper end grows). A periodic orbit closes only when the sweep reaches the period;
  // before, it is the open arc over [t0, tEnd].
  const double period = orbit.period();
  const bool periodic = this->ClosePeriodicOrbits && period > 0.0;
  const double t0 = this->TRange[0];
  const double fraction = vtkBoostedTimeSweep::Fraction(outInfo, this->NumberOfTimeSteps);
  const double tEnd =
    vtkBoostedTimeSweep::Interpolate(t0, periodic ? t0 + period : this->TRange[1], fraction);
  const bool closed = periodic && fraction == 1.0;
  const double span = closed ? period : tEnd - t0;
  std::vector<double> ts(columns);
  for (int c = 0; c < columns; ++c)
  {
    // span * c overflows for spans near the largest double; the fraction c / TResolution then.
    const double step = span * c;
    ts[c] = (closed && c == columns - 1)
      ? t0
      : t0 + (std::isfinite(step) ? step / this->TResolution : span * (c / double(this->TResolution)));
  }
  if (problem.empty() && !std::isfinite(span))
  {
    problem = "TRange's span must be finite";
  }

  if (problem.empty() && isKnot && knot.commonDivisor() > 1)
  {
    const int g = knot.commonDivisor();
    vtkWarningMacro(<< "KnotP = " << knot.p << " and KnotQ = " << knot.q
                    << " are not coprime (common divisor " << g << "): the orbit is the ("
                    << knot.p / g << ", " << knot.q / g << ") torus knot, period " << period
                    << "; over t in [0, P Q] it would be traced " << g << " times");
  }
  if (problem.empty() && orbit.isIdentity())
  {
    vtkWarningMacro(<< "B is zero: exp(t B) is the identity and every orbit is its seed");
    int first = 0, last = -1;
    const int piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
    const int pieces = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
    problem = vtkBoostedGridDriver::ClipSphereProblem(this->ClipCenter, this->ClipRadius);
    if (!problem.empty())
    {
      vtkErrorMacro(<< problem);
      return 1;
    }
    if (!seeds.empty() &&
      vtkBoostedGridBuilder::PieceRows(static_cast<int>(seeds.size()), false, piece, pieces, first, last))
    {
      writeFixedSeeds(seeds, first, last, t0, orbits);
      if (this->OutputPointsPrecision == SINGLE_PRECISION)
      {
        problem = vtkBoostedPointsToSinglePrecision(orbits->GetPoints(), "the orbits' points");
      }
      if (!problem.empty())
      {
        vtkErrorMacro(<< problem);
        orbits->Initialize();
        return 1;
      }
    }
    writeGenerators();
    this->StampTime(outputVector);
    return 1;
  }

  // The orbits: rows = seeds, columns = samples of t (vtkBoostedGridDriver: pieces, size and
  // memory checks, the block loop, the cut at the clip sphere).
  if (problem.empty())
  {
    problem = vtkBoostedGridDriver::ClipSphereProblem(this->ClipCenter, this->ClipRadius);
  }
  if (!problem.empty())
  {
    vtkErrorMacro(<< problem);
    return 1; // both outputs stay empty
  }
  vtkBoostedGridDriver driver(
    this, outInfo, this->ClipCenter, this->ClipRadius, this->OutputPointsPrecision);
  driver.SetBytesPerSample(bytesPerSample);
  // A closed orbit's last sample (t0 again) is its first: the grid leaves it out and closes its
  // rows instead, so that its points are the output's own (vtkBoostedGridBuilder::WritePoints).
  const int gridColumns = closed ? columns - 1 : columns;
  if (!seeds.empty() &&
    driver.Prepare(problem, static_cast<long long>(seeds.size()), gridColumns, false, false))
  {
    vtkBoostedGridBuilder& grid = driver.Grid();
    grid.SetClosedRows(closed);
    // exp(t B) is the same for every seed: its closed form once per t (eight times side by side,
    // cga::Orbit::versors), as a 5 x 5 point map (cga::PointMaps) that each seed then costs a
    // matrix-vector product.
    std::atomic<long long> overflowed{ 0 }; // samples whose exp(t B) is not finite
    // Samples whose image is at infinity or beyond the largest double, next to a sample inside
    // the clip sphere: the orbit is not cut on the sphere there (the cut needs a finite sample
    // outside it). Elsewhere such a sample is dropped without loss (an orbit through infinity).
    std::atomic<long long> uncut{ 0 };
    const cga::Vec3 clipCenter = cga::toVec3(this->ClipCenter);
    // A seed whose conformal point overflows (about 1e154 from the generators' center) has no
    // orbit to give: its samples stay NaN and are dropped, with a warning of their own.
    std::vector<char> farSeed(seeds.size());
    long long farSeeds = 0;
    for (size_t r = 0; r < seeds.size(); ++r)
    {
      farSeed[r] = !std::isfinite(cga::norm2(seeds[r] - center)); // up(p)'s |p|^2 / 2
      farSeeds += farSeed[r];
    }
    driver.SampleColumns([&](int firstColumn, int lastColumn, int firstRow, int lastRow) {
      // One map per column (their matrices side by side, eight columns at a time), then each
      // row's run of columns in order (the grid is row-major: a column at a time would store one
      // point per row, each in another cache line).
      std::vector<cga::Even> versors(static_cast<size_t>(lastColumn - firstColumn));
      orbit.versors(ts.data() + firstColumn, versors.size(), versors.data());
      const cga::PointMaps runMaps(versors.data(), versors.size());
      long long overflowedHere = 0;
      for (size_t k = 0; k < versors.size(); ++k)
      {
        if (!runMaps.isFinite(k))
        {
          overflowedHere += lastRow - firstRow + 1; // t B itself overflows: no image to give
        }
      }
      // Column c's map; the columns next to the run are made when a dropped sample asks.
      std::unique_ptr<cga::PointMap> before, after;
      auto mapAt = [&](int c) -> std::optional<cga::PointMap> {
        if (c < 0 || c >= columns)
        {
          return std::nullopt;
        }
        if (c >= firstColumn && c < lastColumn)
        {
          return runMaps.map(static_cast<size_t>(c - firstColumn));
        }
        std::unique_ptr<cga::PointMap>& made = c < firstColumn ? before : after;
        if (!made)
        {
          made.reset(new cga::PointMap(orbit.versor(ts[c])));
        }
        return *made;
      };
      // Whether seed r's image at column c is inside the clip sphere.
      auto insideAt = [&](int r, int c) {
        const std::optional<cga::PointMap> neighbour = mapAt(c);
        cga::Vec3 p;
        return neighbour && neighbour->apply(seeds[r] - center, p) &&
          cga::norm(p + center - clipCenter) <= this->ClipRadius;
      };
      long long lost = 0;
      // Each row's images of the run at once.
      cga::Vec3 images[vtkBoostedGridDriver::ColumnsPerRun];
      bool imaged[vtkBoostedGridDriver::ColumnsPerRun];
      // Every sample of the run is set or cleared here (SampleColumns clears none first).
      for (int r = firstRow; r <= lastRow; ++r)
      {
        if (farSeed[r])
        {
          grid.ClearSamples(r, firstColumn, lastColumn);
          continue;
        }
        const cga::Vec3 seed = seeds[r] - center;
        runMaps.apply(seed, images, imaged);
        for (int c = firstColumn; c < lastColumn; ++c)
        {
          const size_t k = static_cast<size_t>(c - firstColumn);
          if (runMaps.isFinite(k) && imaged[k])
          {
            const cga::Vec3 q = images[k] + center;
            const double xyz[3] = { q.x, q.y, q.z };
            grid.SetPoint(r, c, xyz);
            continue;
          }
          grid.ClearSamples(r, c, c + 1); // dropped: exp(t B) overflows, or the image is at infinity
          if (runMaps.isFinite(k) && (insideAt(r, c - 1) || insideAt(r, c + 1)))
          {
            ++lost;
          }
        }
      }
      // Shared atomics, touched only when needed (every run touching them kept the two threads
      // passing their cache line back and forth).
      if (lost > 0)
      {
        uncut += lost;
      }
      if (overflowedHere > 0)
      {
        overflowed += overflowedHere;
      }
    });
    std::vector<int> ids(seeds.size());
    std::iota(ids.begin(), ids.end(), 0);
    if (overflowed > 0)
    {
      vtkWarningMacro(<< overflowed << " samples dropped: t B overflows there (|t| up to "
                      << std::max(std::fabs(ts.front()), std::fabs(ts.back())) << ")");
    }
    if (farSeeds > 0)
    {
      vtkWarningMacro(<< farSeeds << " of " << seeds.size()
                      << " seeds are too far from the generators' center (about 1e154 or more; "
                         "their conformal points overflow): their orbits are dropped");
    }
    if (uncut > 0)
    {
      vtkWarningMacro(<< uncut
                      << " samples next to the clip sphere's inside dropped: their images are at "
                         "infinity or beyond the largest double (e.g. a growing dilation at large "
                         "t), so the orbits end there inside the sphere instead of on it; sample t "
                         "more finely to cross the sphere within the doubles' range");
    }
    grid.AddColumnParameter("t", ts);
    grid.AddRowIntegerParameter("OrbitId", ids);
    if (!driver.Build(orbits))
    {
      return 1; // aborted or refused (single precision): both outputs stay empty
    }
  }
  vtkNew<vtkDoubleArray> periodArray;
  periodArray->SetName("Period");
  periodArray->InsertNextValue(period);
  orbits->GetFieldData()->AddArray(periodArray);

  // The cores, on piece 0.
  // (Both ports' requests: a consumer of either output on another rank asks for its own piece.)
  vtkInformation* coreInfo = outputVector->GetInformationObject(1);
  if (coreInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) == 0 &&
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) == 0)
  {
    vtkNew<vtkPolyData> sampled;
    vtkNew<vtkPoints> points;
    points->SetDataType(VTK_DOUBLE); // floats last, after the cut (as the orbits)
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkIntArray> coreIds;
    coreIds->SetName("CoreId");
    for (int i = 0; i < 2; ++i)
    {
      cga::RoundInfo round;
      if (isKnot)
      {
        // The knot's circles as given (readCircle of the parts is accurate to about 1e-8 only).
        const cga::TorusKnot::Circle circle = i == 0 ? knot.coreA() : knot.coreC();
        round.center = circle.center + center;
        round.normal = circle.normal;
        round.radius = circle.radius;
      }
      else if (orbit.core(i, round))
      {
        round.center = round.center + center;
      }
      else
      {
        continue;
      }
      std::vector<cga::Vec3> samples;
      if (round.isLine)
      {
        // Long enough to cross the clip sphere on both sides.
        const double reach = cga::norm(round.center - cga::toVec3(this->ClipCenter)) + 2.0 * this->ClipRadius;
        for (int k = 0; k < this->CoreResolution; ++k)
        {
          samples.push_back(round.center + (reach * (2.0 * k / (this->CoreResolution - 1) - 1.0)) * round.direction);
        }
      }
      else
      {
        samples.resize(this->CoreResolution);
        cga::circlePoints({ round.center, round.normal, round.radius }, this->CoreResolution, samples.data());
      }
      std::vector<vtkIdType> cell;
      for (const cga::Vec3& s : samples)
      {
        cell.push_back(points->InsertNextPoint(s.x, s.y, s.z));
        coreIds->InsertNextValue(i);
      }
      if (!round.isLine)
      {
        cell.push_back(cell.front());
      }
      lines->InsertNextCell(static_cast<vtkIdType>(cell.size()), cell.data());
    }
    sampled->SetPoints(points);
    sampled->SetLines(lines);
    sampled->GetPointData()->AddArray(coreIds);
    vtkBoostedSphereClip::Clip(sampled, this->ClipCenter, this->ClipRadius, cores);
    if (this->OutputPointsPrecision == SINGLE_PRECISION)
    {
      problem = vtkBoostedPointsToSinglePrecision(cores->GetPoints(), "the cores' points");
    }
    if (!problem.empty())
    {
      vtkErrorMacro(<< problem);
      orbits->Initialize();
      cores->Initialize();
      return 1;
    }
  }
  writeGenerators();
  this->StampTime(outputVector);
  return 1;
}

void vtkConformalOrbitSource::StampTime(vtkInformationVector* outputVector)
{
  for (int port = 0; port < this->GetNumberOfOutputPorts(); ++port)
  {
    vtkInformation* info = outputVector->GetInformationObject(port);
    vtkBoostedTimeSweep::StampTime(info, this->NumberOfTimeSteps, vtkPolyData::GetData(info));
  }
}

void vtkConformalOrbitSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  auto vector3 = [&os](const double* v) { os << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")\n"; };
  os << indent << "GeneratorType: " << (this->GeneratorType == TORUS_KNOT ? "TORUS_KNOT" : "GENERATOR_LIST") << "\n";
  this->Generators->Print(os, indent);
  vtkBoostedGeneratorRows::PrintSelection(os, indent,
    { this->SelectedGenerator, this->SelectedGeneratorLocation, this->AimSelectedGenerator,
      this->SelectedGeneratorTip });
  os << indent << "KnotP: " << this->KnotP << "\n";
  os << indent << "KnotQ: " << this->KnotQ << "\n";
  os << indent << "KnotCenter: ";
  vector3(this->KnotCenter);
  os << indent << "KnotNormal: ";
  vector3(this->KnotNormal);
  os << indent << "KnotDirection: ";
  vector3(this->KnotDirection);
  os << indent << "KnotRadius: " << this->KnotRadius << "\n";
  const char* seedModes[] = { "SEED_POINT", "SEED_LIST", "INPUT_POINTS" };
  os << indent << "SeedMode: " << seedModes[this->SeedMode] << "\n";
  os << indent << "SeedPoint: ";
  vector3(this->SeedPoint);
  this->Seeds->Print(os, indent);
  os << indent << "TRange: [" << this->TRange[0] << ", " << this->TRange[1] << "]\n";
  os << indent << "TResolution: " << this->TResolution << "\n";
  os << indent << "ClosePeriodicOrbits: " << this->ClosePeriodicOrbits << "\n";
  os << indent << "CoreResolution: " << this->CoreResolution << "\n";
  os << indent << "ClipCenter: ";
  vector3(this->ClipCenter);
  os << indent << "ClipRadius: " << this->ClipRadius << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
  os << indent << "NumberOfTimeSteps: " << this->NumberOfTimeSteps << "\n";
}
