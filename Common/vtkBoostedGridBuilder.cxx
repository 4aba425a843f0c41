#include "vtkBoostedGridBuilder.h"

#include "vtkBoostedBlockLoop.h"
#include "vtkBoostedPolylineRuns.h"
#include "vtkBoostedSphereClip.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include "cga/GridNormals.h"
#include "cga/Vec3.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>
#include <type_traits>
#include <vector>

namespace
{
// The builder's passes run on the block loop's threads (vtkBoostedBlockLoop::RunBlock), each over
// its own runs of columns of one row (segments) or its own rows: their points, array values and
// cells are numbered from per-item counts, so the output is the same, bit for bit, whatever the
// threads. No pass allocates in a worker thread.
struct Segment
{
  int Row, FirstColumn, LastColumn; // columns [FirstColumn, LastColumn)
};

// Long rows are cut into segments of at most this many columns, so that a grid of a few long rows
// (one orbit of a million samples) still spreads over the threads.
constexpr int ColumnsPerSegment = 16384;

// A normal whose two unit differences cross with a sine at most this is not taken from them (the
// row's fallback normal instead).
constexpr double MinimumNormalSine = 1e-12;

std::vector<Segment> Segments(int firstRow, int lastRow, int firstColumn, int lastColumn, int perSegment)
{
  perSegment = std::max(1, perSegment);
  std::vector<Segment> segments;
  for (int r = firstRow; r <= lastRow; ++r)
  {
    for (int c = firstColumn; c < lastColumn; c += perSegment)
    {
      segments.push_back({ r, c, std::min(lastColumn, c + perSegment) });
    }
  }
  return segments;
}

// The columns of the segments per segment, rounded up: the samples of one item of their passes.
vtkIdType ColumnsPerItem(const std::vector<Segment>& segments)
{
  vtkIdType columns = 0;
  for (const Segment& s : segments)
  {
    columns += s.LastColumn - s.FirstColumn;
  }
  return segments.empty() ? 1 : (columns + segments.size() - 1) / segments.size();
}

// work(i) for every i in [0, count), each item worth about samplesPerItem samples, on the block
// loop's threads (guided chunks on the project's kept threads: VTK 9.2's For starts new threads
// and splits into eight equal chunks, and a pass's last chunk kept one of two threads waiting).
template <typename Work>
void forEach(size_t count, vtkIdType samplesPerItem, const Work& work)
{
  vtkBoostedBlockLoop::RunBlock(vtkIdType(0), static_cast<vtkIdType>(count), samplesPerItem,
    [&work](vtkIdType first, vtkIdType last) {
      for (vtkIdType i = first; i < last; ++i)
      {
        work(static_cast<size_t>(i));
      }
    });
}

// offsets[i] = counts[0] + ... + counts[i - 1]; offsets[counts.size()] is the total.
std::vector<vtkIdType> PrefixSums(const std::vector<vtkIdType>& counts)
{
  std::vector<vtkIdType> offsets(counts.size() + 1, 0);
  for (size_t i = 0; i < counts.size(); ++i)
  {
    offsets[i + 1] = offsets[i] + counts[i];
  }
  return offsets;
}

// Writes the cells of one item (a segment or a row) into the shared arrays, from its first cell
// and its first connectivity index on.
struct CellWriter
{
  vtkIdType* Offsets;
  vtkIdType* Connectivity;
  vtkIdType Cell, At;
  void Start() { this->Offsets[this->Cell++] = this->At; }
  void Add(vtkIdType id) { this->Connectivity[this->At++] = id; }
};

// The cells that fill(i, writer) writes for every item i in [0, cellCounts.size()), in item order
// (item i: cellCounts[i] cells of sizes[i] ids in all, from about samplesPerItem samples),
// written on the block loop's threads.
template <typename Fill>
vtkSmartPointer<vtkCellArray> CellsInOrder(const std::vector<vtkIdType>& cellCounts,
  const std::vector<vtkIdType>& sizes, vtkIdType samplesPerItem, const Fill& fill)
{
  const std::vector<vtkIdType> firstCells = PrefixSums(cellCounts), firstIds = PrefixSums(sizes);
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  vtkBoostedLargeArrays::SetNumberOfTuples(offsets, firstCells.back() + 1);
  offsets->SetValue(firstCells.back(), firstIds.back());
  vtkBoostedLargeArrays::SetNumberOfTuples(connectivity, firstIds.back());
  forEach(cellCounts.size(), samplesPerItem, [&](size_t i) {
    CellWriter writer{ offsets->GetPointer(0), connectivity->GetPointer(0), firstCells[i],
      firstIds[i] };
    fill(i, writer);
  });
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}

// Merged rows can leave points no cell uses (a pole between two poles, a row that repeats its
// neighbour through infinity): they are dropped, so that an export (STL keeps only what its
// triangles use) keeps every point.
void dropUnusedPoints(vtkPolyData* mesh)
{
  const vtkIdType count = mesh->GetNumberOfPoints();
  vtkDataArray* connectivity = mesh->GetPolys()->GetConnectivityArray();
  std::vector<vtkIdType> newIds(count, -1);
  for (vtkIdType k = 0; k < connectivity->GetNumberOfValues(); ++k)
  {
    newIds[static_cast<vtkIdType>(connectivity->GetComponent(k, 0))] = 0;
  }
  vtkIdType used = 0;
  for (vtkIdType& id : newIds)
  {
    id = id < 0 ? -1 : used++;
  }
  if (used == count)
  {
    return;
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(mesh->GetPoints()->GetDataType());
  points->SetNumberOfPoints(used);
  vtkNew<vtkPointData> data;
  data->CopyAllocate(mesh->GetPointData(), used);
  for (vtkIdType i = 0; i < count; ++i)
  {
    if (newIds[i] >= 0)
    {
      points->SetPoint(newIds[i], mesh->GetPoint(i));
      data->CopyData(mesh->GetPointData(), i, newIds[i]);
    }
  }
  for (vtkIdType k = 0; k < connectivity->GetNumberOfValues(); ++k)
  {
    connectivity->SetComponent(
      k, 0, static_cast<double>(newIds[static_cast<vtkIdType>(connectivity->GetComponent(k, 0))]));
  }
  mesh->GetPolys()->Modified();
  mesh->SetPoints(points);
  mesh->GetPointData()->ShallowCopy(data);
}
} // namespace

// Points are cleared by ClearSamples.
vtkBoostedGridBuilder::vtkBoostedGridBuilder(int rows, int columns, bool periodicColumns)
  : Rows(rows)
  , Columns(columns)
  , PeriodicColumns(periodicColumns)
  , FallbackNormals(3 * static_cast<size_t>(rows), 0.0)
{
  this->PointsMemory = vtkBoostedLargeArrays::New<double>(3 * static_cast<size_t>(rows) * columns);
  this->Points = this->PointsMemory.get();
  this->States = vtkBoostedLargeArrays::New<unsigned char>(static_cast<size_t>(rows) * columns);
}

void vtkBoostedGridBuilder::BeginSampling()
{
  if (!this->SamplingBegun) // a second call (a source sampling twice) changes nothing
  {
    this->StatesCurrent = true;
    this->SamplingBegun = true;
  }
}

void vtkBoostedGridBuilder::ClearSamples(int row, int firstColumn, int lastColumn)
{
  const size_t first = static_cast<size_t>(this->Index(row, firstColumn));
  const size_t last = static_cast<size_t>(this->Index(row, lastColumn));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::fill(this->Points + 3 * first, this->Points + 3 * last, nan);
  std::fill(this->States.get() + first, this->States.get() + last, 0);
  if (this->SampleNormals)
  {
    std::fill(this->SampleNormals.get() + 3 * first, this->SampleNormals.get() + 3 * last, nan);
  }
  for (SampleArray& values : this->SampleArrays)
  {
    const size_t components = static_cast<size_t>(values.Components);
    std::fill(values.Values + components * first, values.Values + components * last, 0.0);
  }
}

void vtkBoostedGridBuilder::SetClipSphere(const double center[3], double radius)
{
  // The same sphere again (a caller setting it before the sampling and again before building)
  // leaves SetPoint's notes current.
  this->StatesCurrent &= this->HasClipSphere && std::equal(center, center + 3, this->ClipCenter) &&
    radius == this->ClipRadius;
  this->HasClipSphere = true;
  std::copy_n(center, 3, this->ClipCenter);
  this->ClipRadius = radius;
  this->ClipRadius2 = radius * radius;
}

void vtkBoostedGridBuilder::SetOrigin(const double origin[3])
{
  double kept[3];
  for (int i = 0; i < 3; ++i)
  {
    kept[i] = origin[i] == 0.0 ? -0.0 : origin[i]; // -0 adds nothing (see Origin)
  }
  // Compared bit for bit: -0 and +0 are the same origin, NaN another.
  this->StatesCurrent &= std::memcmp(kept, this->Origin, sizeof kept) == 0;
  std::copy_n(kept, 3, this->Origin);
}

void vtkBoostedGridBuilder::SetRowFallbackNormal(int row, const double normal[3])
{
  for (int i = 0; i < 3; ++i)
  {
    this->FallbackNormals[3 * row + i] = normal[i];
  }
}

void vtkBoostedGridBuilder::EnableSampleNormals()
{
  // Cleared by ClearSamples.
  this->SampleNormals =
    vtkBoostedLargeArrays::New<double>(3 * static_cast<size_t>(this->Rows) * this->Columns);
}

int vtkBoostedGridBuilder::AddSampleArray(const std::string& name, int components)
{
  // Cleared by ClearSamples.
  vtkBoostedLargeArrays::Buffer<double> memory = vtkBoostedLargeArrays::New<double>(
    static_cast<size_t>(components) * this->Rows * this->Columns);
  double* values = memory.get();
  this->SampleArrays.push_back({ name, components, values, std::move(memory) });
  return static_cast<int>(this->SampleArrays.size()) - 1;
}

void vtkBoostedGridBuilder::AddRowParameter(
  const std::string& name, const std::vector<double>& valuePerRow)
{
  this->Parameters.push_back({ name, true, valuePerRow });
}

void vtkBoostedGridBuilder::AddColumnParameter(
  const std::string& name, const std::vector<double>& valuePerColumn)
{
  this->Parameters.push_back({ name, false, valuePerColumn });
}

void vtkBoostedGridBuilder::DifferenceNormal(int row, int column, double normal[3]) const
{
  // Central differences where both neighbours are usable, one-sided otherwise. Periodic columns
  // skip the repeated seam column so that both copies of a seam point get the same normal.
  // Each difference as a unit vector (cga::normalized, scaled where its square would underflow
  // or overflow): a grid of size 1e-160 or 1e200 has normals too.
  auto difference = [this](int r0, int c0, int r1, int c1, double d[3]) {
    const double* a = &this->Points[3 * this->Index(r0, c0)];
    const double* b = &this->Points[3 * this->Index(r1, c1)];
    const cga::Vec3 unit = cga::normalized({ b[0] - a[0], b[1] - a[1], b[2] - a[2] });
    d[0] = unit.x;
    d[1] = unit.y;
    d[2] = unit.z;
  };
  auto neighbours = [](int i, int count, bool periodic, auto usable, int& lo, int& hi) {
    lo = i - 1;
    hi = i + 1;
    if (periodic)
    {
      // columns 0 and count-1 are the same point
      if (lo < 0)
      {
        lo = count - 2;
      }
      if (hi > count - 1)
      {
        hi = 1;
      }
    }
    if (lo < 0 || !usable(lo))
    {
      lo = i;
    }
    if (hi > count - 1 || !usable(hi))
    {
      hi = i;
    }
  };

  int c0, c1, r0, r1;
  neighbours(
    column, this->Columns, this->PeriodicColumns, [&](int c) { return this->Usable(row, c); }, c0, c1);
  neighbours(row, this->Rows, false,
    [&](int r) { return this->SameBlock(r, row) && this->Usable(r, column); }, r0, r1);

  double alongColumns[3] = { 0, 0, 0 };
  double alongRows[3] = { 0, 0, 0 };
  if (c0 != c1)
  {
    difference(row, c0, row, c1, alongColumns);
  }
  if (r0 != r1)
  {
    difference(r0, column, r1, column, alongRows);
  }
  vtkMath::Cross(alongColumns, alongRows, normal);
  const double length = vtkMath::Norm(normal); // the sine of the angle between the unit differences
  if (length > MinimumNormalSine)
  {
    vtkMath::MultiplyScalar(normal, 1.0 / length);
    return;
  }
  for (int i = 0; i < 3; ++i)
  {
    normal[i] = this->FallbackNormals[3 * row + i];
  }
}

void vtkBoostedGridBuilder::ComputeNormals(
  int row, int firstColumn, int lastColumn, double* normals) const
{
  if (this->SampleNormals)
  {
    // The given normals copied in one loop; DifferenceNormal for the samples without one.
    const double* given =
      &this->SampleNormals[3 * static_cast<size_t>(this->Index(row, firstColumn))];
    for (int c = firstColumn; c < lastColumn; ++c, given += 3)
    {
      double* normal = normals + 3 * (c - firstColumn);
      if (std::isfinite(given[0]) && std::isfinite(given[1]) && std::isfinite(given[2]))
      {
        std::copy_n(given, 3, normal);
      }
      else
      {
        this->DifferenceNormal(row, c, normal);
      }
    }
    return;
  }
  // The samples whose four neighbours exist in the row's block without a seam's wrap (columns 1
  // to Columns - 2 of an inner row) eight at a time, where DifferenceNormal would take the plain
  // central differences (cga::crossedDifferenceNormals: the same bits); the others one at a time.
  int first = lastColumn, last = lastColumn;
  if (row > 0 && row + 1 < this->Rows && this->SameBlock(row - 1, row) &&
    this->SameBlock(row + 1, row))
  {
    first = std::min(std::max(firstColumn, 1), lastColumn);
    last = std::max(first, std::min(lastColumn, this->Columns - 1));
  }
  bool plain[NormalsPerRun];
  if (last > first)
  {
    const double* p = this->Points;
    cga::crossedDifferenceNormals(p + 3 * static_cast<size_t>(this->Index(row, first - 1)),
      p + 3 * static_cast<size_t>(this->Index(row, first + 1)),
      p + 3 * static_cast<size_t>(this->Index(row - 1, first)),
      p + 3 * static_cast<size_t>(this->Index(row + 1, first)), static_cast<size_t>(last - first),
      MinimumNormalSine, normals + 3 * (first - firstColumn), plain);
  }
  for (int c = firstColumn; c < lastColumn; ++c)
  {
    if (c < first || c >= last || !plain[c - first])
    {
      this->DifferenceNormal(row, c, normals + 3 * (c - firstColumn));
    }
  }
}

vtkBoostedLargeArrays::Buffer<long long> vtkBoostedGridBuilder::WritePoints(vtkPolyData* output,
  int firstRow, int lastRow, int precision, bool withSurfaceAttributes, vtkIdType& outside,
  std::vector<vtkIdType>* wholeRows) const
{
  // Each sample's point id (-1: no point) for the samples of every segment, written by the
  // writing pass below.
  vtkBoostedLargeArrays::Buffer<long long> ids =
    vtkBoostedLargeArrays::New<long long>(static_cast<size_t>(this->Rows) * this->Columns);
  // Curves never repeat the seam (see below), so only surfaces merge.
  const bool merge = this->MergeSeam && withSurfaceAttributes;
  const bool withTCoords = withSurfaceAttributes && !merge;
  std::vector<int> sameAs;
  std::vector<char> pole;
  if (merge)
  {
    this->FindMergedRows(firstRow, lastRow, sameAs, pole);
  }
  const double uScale = this->Columns > 1 ? 1.0 / (this->Columns - 1) : 0.0;
  const double vScale = this->BlockRows() > 1 ? 1.0 / (this->BlockRows() - 1) : 0.0;
  // Curves need no texture seam: the repeated last column of periodic grids is left out.
  const int columns =
    (this->PeriodicColumns && !withSurfaceAttributes) ? this->Columns - 1 : this->Columns;

  // Which samples become points, in grid order: the points of a segment of a row are numbered
  // after those of the segments before it. With merging, a whole row is one segment (its seam
  // column and its pole refer back to its first points).
  const std::vector<Segment> segments =
    Segments(firstRow, lastRow, 0, columns, merge ? columns : ColumnsPerSegment);
  // walk(segment, newPoint, reuse): newPoint(c) (returning the new point's id) for each sample
  // of the segment that becomes a point of its own, reuse(c, id) for each usable sample that
  // shares the point `id` (the merged seam column, a pole's samples); unusable samples are skipped.
  auto walk = [&](const Segment& s, auto&& newPoint, auto&& reuse) {
    if (merge && sameAs[s.Row - firstRow] != s.Row)
    {
      return; // a repeated row: its ids are copied below
    }
    long long poleId = -1;
    for (int c = s.FirstColumn; c < s.LastColumn; ++c)
    {
      if (!this->Usable(s.Row, c))
      {
        continue;
      }
      if (merge && this->PeriodicColumns && c == this->Columns - 1)
      {
        reuse(c, ids[this->Index(s.Row, 0)]);
        continue;
      }
      if (poleId >= 0)
      {
        reuse(c, poleId);
        continue;
      }
      const long long id = newPoint(c);
      if (merge && pole[s.Row - firstRow])
      {
        poleId = id;
      }
    }
  };
  // Each segment's points, and those of them outside the clip sphere (vtkBoostedSphereClip's
  // test on the point written, before any cast to float), counted in one pass over the samples.
  const vtkIdType columnsPerSegment = ColumnsPerItem(segments);
  std::vector<vtkIdType> counts(segments.size(), 0), outsideCounts(segments.size(), 0);
  forEach(segments.size(), columnsPerSegment, [&](size_t i) {
    const Segment& s = segments[i];
    vtkIdType count = 0, insideHere = 0;
    if (!merge)
    {
      // Every usable sample is a point (walk's loop without its merging, branch-free); only a
      // finite point can be inside. Counted from SetPoint's notes where current: a read of the
      // points here, after the sampling wrote all of them, came from memory (a fifth of an
      // orbit's update).
      const auto tally = [&](unsigned char state) {
        count += state & 1;
        insideHere += state >> 1;
      };
      if (this->StatesCurrent)
      {
        const unsigned char* state = &this->States[this->Index(s.Row, s.FirstColumn)];
        for (int c = 0; c < s.LastColumn - s.FirstColumn; ++c)
        {
          tally(state[c]);
        }
      }
      else
      {
        const double* p = &this->Points[3 * static_cast<size_t>(this->Index(s.Row, s.FirstColumn))];
        const double* end = p + 3 * static_cast<size_t>(s.LastColumn - s.FirstColumn);
        for (const double* q = p; q < end; q += 3)
        {
          tally(this->State(q));
        }
      }
    }
    else
    {
      walk(
        s,
        [&](int c) {
          const size_t sample = static_cast<size_t>(this->Index(s.Row, c));
          insideHere += this->State(&this->Points[3 * sample]) >> 1;
          return count++;
        },
        [](int, long long) {});
    }
    counts[i] = count;
    outsideCounts[i] = this->HasClipSphere ? count - insideHere : 0;
  });
  const std::vector<vtkIdType> offsets = PrefixSums(counts);
  const vtkIdType total = offsets.back();
  // The whole rows' first ids (segments run row by row, each row's from its first column); none
  // with merged points, whose ids are not a row's consecutive ones.
  if (wholeRows)
  {
    wholeRows->assign(static_cast<size_t>(std::max(0, lastRow - firstRow + 1)), -1);
    for (size_t i = 0; i < (merge ? 0 : segments.size()); ++i)
    {
      const Segment& s = segments[i];
      vtkIdType& first = (*wholeRows)[static_cast<size_t>(s.Row - firstRow)];
      const bool full = counts[i] == s.LastColumn - s.FirstColumn;
      if (s.FirstColumn == 0)
      {
        first = full ? offsets[i] : -1;
      }
      else if (!full)
      {
        first = -1;
      }
    }
  }

  // The whole grid, every sample its own point in grid order, in double precision: the points
  // are the samples themselves (the origin adds nothing) and the sample arrays' values are the
  // grid's, so their buffers become the output's arrays instead of copies (a copy read and wrote
  // every point again: a fifth of an orbit update). Once: a later build copies them.
  const bool adopt = this->PointsMemory && !merge && firstRow == 0 && lastRow == this->Rows - 1 &&
    columns == this->Columns && total == static_cast<vtkIdType>(this->Rows) * this->Columns &&
    precision != vtkAlgorithm::SINGLE_PRECISION && this->Origin[0] == 0.0 &&
    this->Origin[1] == 0.0 && this->Origin[2] == 0.0;
  const auto adoptInto = [this, total](vtkDataArray* array, auto& memory) {
    vtkBoostedLargeArrays::Adopt(array, memory.release(), array->GetNumberOfComponents() * total);
    this->AdoptedArrays.emplace_back(array);
  };
  vtkNew<vtkPoints> points;
  points->SetDataType(precision == vtkAlgorithm::SINGLE_PRECISION ? VTK_FLOAT : VTK_DOUBLE);
  if (adopt)
  {
    adoptInto(points->GetData(), this->PointsMemory);
  }
  else
  {
    vtkBoostedLargeArrays::SetNumberOfTuples(points->GetData(), total);
  }
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkBoostedLargeArrays::SetNumberOfTuples(normals, withSurfaceAttributes ? total : 0);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TextureCoordinates");
  tcoords->SetNumberOfComponents(2);
  vtkBoostedLargeArrays::SetNumberOfTuples(tcoords, withTCoords ? total : 0);
  std::vector<vtkSmartPointer<vtkDoubleArray>> parameters;
  std::vector<vtkSmartPointer<vtkIntArray>> integerParameters;
  for (const auto& parameter : this->IntegerParameters)
  {
    auto array = vtkSmartPointer<vtkIntArray>::New();
    array->SetName(parameter.first.c_str());
    vtkBoostedLargeArrays::SetNumberOfTuples(array, total);
    integerParameters.push_back(array);
  }
  for (const Parameter& parameter : this->Parameters)
  {
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(parameter.Name.c_str());
    vtkBoostedLargeArrays::SetNumberOfTuples(array, total);
    parameters.push_back(array);
  }
  std::vector<vtkSmartPointer<vtkDoubleArray>> sampleArrays;
  for (const SampleArray& values : this->SampleArrays)
  {
    auto array = vtkSmartPointer<vtkDoubleArray>::New();
    array->SetName(values.Name.c_str());
    array->SetNumberOfComponents(values.Components);
    if (adopt)
    {
      adoptInto(array, values.Memory);
    }
    else
    {
      vtkBoostedLargeArrays::SetNumberOfTuples(array, total);
    }
    sampleArrays.push_back(array);
  }
  auto* doublePoints = vtkDoubleArray::FastDownCast(points->GetData());
  auto* floatPoints = vtkFloatArray::FastDownCast(points->GetData());

  // Each segment writes its own range of every array: first which columns become its points
  // (point offsets[i] + j is column columnOf(j)), then each array in a pass of its own (one
  // output stream at a time: writing every array's values point by point, six to ten streams at
  // once, was 21 % of a Hopf fibration update).
  // writeArrays(segment, first point, n, columnOf): the segment's n points' values.
  auto writeArrays = [&](const Segment& s, vtkIdType first, size_t n, auto columnOf) {
    const int r = s.Row;
    auto sample = [&](size_t j) { return static_cast<size_t>(this->Index(r, columnOf(j))); };
    auto writePoints = [&](auto* to) { // double or float
      using Value = std::remove_pointer_t<decltype(to)>;
      // A local copy: the stores through `to` could alias members and captured references.
      const cga::Vec3 at{ this->Origin[0], this->Origin[1], this->Origin[2] };
      const double* from = this->Points;
      for (size_t j = 0; j < n; ++j)
      {
        const double* relative = from + 3 * sample(j);
        to[3 * j] = static_cast<Value>(at.x + relative[0]);
        to[3 * j + 1] = static_cast<Value>(at.y + relative[1]);
        to[3 * j + 2] = static_cast<Value>(at.z + relative[2]);
      }
    };
    if (doublePoints && !adopt) // adopted points are in place
    {
      writePoints(doublePoints->GetPointer(3 * first));
    }
    else if (floatPoints)
    {
      writePoints(floatPoints->GetPointer(3 * first));
    }
    if (withSurfaceAttributes)
    {
      // The normals of columns [runFirst, runFirst + NormalsPerRun), made as the pass reaches them.
      double runNormals[3 * NormalsPerRun];
      int runFirst = -NormalsPerRun;
      float* to = normals->GetPointer(3 * first);
      for (size_t j = 0; j < n; ++j)
      {
        const int c = columnOf(j);
        if (c >= runFirst + NormalsPerRun)
        {
          runFirst = c;
          this->ComputeNormals(r, c, std::min(s.LastColumn, c + NormalsPerRun), runNormals);
        }
        for (int k = 0; k < 3; ++k)
        {
          to[3 * j + k] = static_cast<float>(runNormals[3 * (c - runFirst) + k]);
        }
      }
    }
    if (withTCoords)
    {
      const float v = static_cast<float>((r % this->BlockRows()) * vScale); // the row's
      float* to = tcoords->GetPointer(2 * first);
      for (size_t j = 0; j < n; ++j)
      {
        to[2 * j] = static_cast<float>(columnOf(j) * uScale);
        to[2 * j + 1] = v;
      }
    }
    for (size_t k = 0; k < parameters.size(); ++k)
    {
      const Parameter& parameter = this->Parameters[k];
      double* to = parameters[k]->GetPointer(first);
      if (parameter.PerRow)
      {
        std::fill_n(to, n, parameter.Values[r]);
        continue;
      }
      for (size_t j = 0; j < n; ++j)
      {
        to[j] = parameter.Values[columnOf(j)];
      }
    }
    for (size_t k = 0; k < integerParameters.size(); ++k)
    {
      std::fill_n(integerParameters[k]->GetPointer(first), n, this->IntegerParameters[k].second[r]);
    }
    for (size_t k = 0; k < (adopt ? 0 : sampleArrays.size()); ++k)
    {
      const SampleArray& values = this->SampleArrays[k];
      const size_t components = static_cast<size_t>(values.Components);
      double* to = sampleArrays[k]->GetPointer(static_cast<vtkIdType>(components) * first);
      for (size_t j = 0; j < n; ++j)
      {
        const double* from = &values.Values[components * sample(j)];
        for (size_t m = 0; m < components; ++m)
        {
          to[components * j + m] = from[m];
        }
      }
    }
  };
  forEach(segments.size(), columnsPerSegment, [&](size_t i) {
    const Segment& s = segments[i];
    const int r = s.Row;
    const vtkIdType first = offsets[i];
    const int length = s.LastColumn - s.FirstColumn;
    if (!merge && counts[i] == length)
    {
      // Every sample usable, each its own point (the common case): column FirstColumn + j is
      // point first + j, and the arrays' loops run over consecutive samples.
      if (!(wholeRows && (*wholeRows)[static_cast<size_t>(r - firstRow)] >= 0))
      {
        long long* segmentIds = ids.get() + this->Index(r, s.FirstColumn);
        for (int j = 0; j < length; ++j)
        {
          segmentIds[j] = first + j;
        }
      }
      const int firstColumn = s.FirstColumn;
      writeArrays(s, first, static_cast<size_t>(length),
        [firstColumn](size_t j) { return firstColumn + static_cast<int>(j); });
      return;
    }
    std::fill(ids.get() + this->Index(r, s.FirstColumn), ids.get() + this->Index(r, s.LastColumn), -1);
    std::vector<int> newColumns;
    newColumns.reserve(static_cast<size_t>(counts[i]));
    walk(
      s,
      [&](int c) {
        const long long id = first + static_cast<vtkIdType>(newColumns.size());
        newColumns.push_back(c);
        ids[this->Index(r, c)] = id;
        return id;
      },
      [&](int c, long long id) { ids[this->Index(r, c)] = id; });
    writeArrays(s, first, newColumns.size(), [&newColumns](size_t j) { return newColumns[j]; });
  });
  if (merge)
  {
    // A repeated row reuses the points of the row it repeats (an earlier row, numbered above).
    for (int r = firstRow; r <= lastRow; ++r)
    {
      const int same = sameAs[r - firstRow];
      if (same != r)
      {
        std::copy_n(&ids[this->Index(same, 0)], columns, &ids[this->Index(r, 0)]);
      }
    }
  }

  outside = std::accumulate(outsideCounts.begin(), outsideCounts.end(), vtkIdType(0));
  output->SetPoints(points);
  if (withSurfaceAttributes)
  {
    output->GetPointData()->SetNormals(normals);
  }
  if (withTCoords)
  {
    output->GetPointData()->SetTCoords(tcoords);
  }
  for (auto& array : parameters)
  {
    output->GetPointData()->AddArray(array);
  }
  for (auto& array : integerParameters)
  {
    output->GetPointData()->AddArray(array);
  }
  for (auto& array : sampleArrays)
  {
    output->GetPointData()->AddArray(array);
  }
  return ids;
}

vtkIdType vtkBoostedGridBuilder::BuildSurface(
  vtkPolyData* output, int firstRow, int lastRow, int outputPointsPrecision) const
{
  vtkIdType outside = 0;
  // The whole rows' first point ids (their points are consecutive and the map `ids` is not
  // written for them; none with merged points): idOf reads either.
  std::vector<vtkIdType> wholeFirst;
  const vtkBoostedLargeArrays::Buffer<long long> ids = this->WritePoints(
    output, firstRow, lastRow, outputPointsPrecision, true, outside, &wholeFirst);
  auto wholeRowFirst = [&](int r) { return wholeFirst[static_cast<size_t>(r - firstRow)]; };
  auto idOf = [&](int r, int c) {
    const vtkIdType first = wholeRowFirst(r);
    return first >= 0 ? first + c : static_cast<vtkIdType>(ids[this->Index(r, c)]);
  };
  // The cell of the quad between rows r, r + 1 and columns c, c + 1: its size (0: no cell).
  auto quadCell = [&](int r, int c, vtkIdType cell[4]) -> vtkIdType {
    const vtkIdType quad[4] = { idOf(r, c), idOf(r, c + 1), idOf(r + 1, c + 1), idOf(r + 1, c) };
    if (quad[0] < 0 || quad[1] < 0 || quad[2] < 0 || quad[3] < 0)
    {
      return 0;
    }
    // Merged points: a quad with a point twice is a triangle, one with fewer than three a
    // degenerate cell that is left out (without merging all four are distinct).
    vtkIdType size = 0;
    for (int k = 0; k < 4; ++k)
    {
      if (size == 0 || cell[size - 1] != quad[k])
      {
        cell[size++] = quad[k];
      }
    }
    while (size > 1 && cell[size - 1] == cell[0])
    {
      --size;
    }
    return (size == 4 && cell[0] != cell[2] && cell[1] != cell[3]) || size == 3 ? size : 0;
  };
  // The quads of row r start at column segments' first columns; blocks are separate strips.
  std::vector<Segment> segments = Segments(firstRow, lastRow - 1, 0, this->Columns - 1, ColumnsPerSegment);
  segments.erase(std::remove_if(segments.begin(), segments.end(),
                   [this](const Segment& s) { return !this->SameBlock(s.Row, s.Row + 1); }),
    segments.end());
  const vtkIdType columnsPerSegment = ColumnsPerItem(segments);
  // Between two whole rows every quad is a cell of four distinct consecutive ids.
  auto betweenWholeRows = [&](const Segment& s) {
    return wholeRowFirst(s.Row) >= 0 && wholeRowFirst(s.Row + 1) >= 0;
  };
  std::vector<vtkIdType> cellCounts(segments.size(), 0), sizes(segments.size(), 0);
  forEach(segments.size(), columnsPerSegment, [&](size_t i) {
    const Segment& s = segments[i];
    if (betweenWholeRows(s))
    {
      cellCounts[i] = s.LastColumn - s.FirstColumn;
      sizes[i] = 4 * cellCounts[i];
      return;
    }
    vtkIdType cell[4];
    for (int c = s.FirstColumn; c < s.LastColumn; ++c)
    {
      const vtkIdType size = quadCell(s.Row, c, cell);
      cellCounts[i] += size > 0;
      sizes[i] += size;
    }
  });
  output->SetPolys(CellsInOrder(cellCounts, sizes, columnsPerSegment, [&](size_t i, CellWriter& writer) {
    const Segment& s = segments[i];
    if (betweenWholeRows(s))
    {
      const vtkIdType below = wholeRowFirst(s.Row), above = wholeRowFirst(s.Row + 1);
      for (vtkIdType c = s.FirstColumn; c < s.LastColumn; ++c)
      {
        writer.Start();
        writer.Add(below + c);
        writer.Add(below + c + 1);
        writer.Add(above + c + 1);
        writer.Add(above + c);
      }
      return;
    }
    vtkIdType cell[4];
    for (int c = segments[i].FirstColumn; c < segments[i].LastColumn; ++c)
    {
      const vtkIdType size = quadCell(segments[i].Row, c, cell);
      if (size > 0)
      {
        writer.Start();
        for (vtkIdType k = 0; k < size; ++k)
        {
          writer.Add(cell[k]);
        }
      }
    }
  }));
  if (this->MergeSeam)
  {
    dropUnusedPoints(output); // an unused point outside is still counted: the clip then runs
  }
  return outside;
}

void vtkBoostedGridBuilder::FindMergedRows(
  int firstRow, int lastRow, std::vector<int>& sameAs, std::vector<char>& pole) const
{
  // Two samples coincide within 1e-9 of the rows' bounding box (and at least within the
  // round-off of their coordinates): far below any grid step (resolutions are at most 1e5), far
  // above the round-off by which a sweep's last sample misses its first (2 pi = 0 up to ulps).
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  double largest = 0.0;
  for (int r = firstRow; r <= lastRow; ++r)
  {
    for (int c = 0; c < this->Columns; ++c)
    {
      if (this->Usable(r, c))
      {
        const double* p = &this->Points[3 * this->Index(r, c)];
        for (int i = 0; i < 3; ++i)
        {
          lo[i] = std::min(lo[i], p[i]);
          hi[i] = std::max(hi[i], p[i]);
          largest = std::max(largest, std::abs(p[i]));
        }
      }
    }
  }
  double diagonal = 0.0;
  for (int i = 0; i < 3; ++i)
  {
    diagonal = std::max(diagonal, hi[i] - lo[i]);
  }
  const double tolerance = std::max(1e-9 * diagonal, 1e-13 * largest);
  auto coincide = [&](int r0, int c0, int r1, int c1) {
    const bool u0 = this->Usable(r0, c0), u1 = this->Usable(r1, c1);
    if (!u0 || !u1)
    {
      return !u0 && !u1;
    }
    const double* a = &this->Points[3 * this->Index(r0, c0)];
    const double* b = &this->Points[3 * this->Index(r1, c1)];
    for (int i = 0; i < 3; ++i)
    {
      if (!(std::abs(a[i] - b[i]) <= tolerance))
      {
        return false;
      }
    }
    return true;
  };
  auto sameRow = [&](int a, int b) {
    for (int c = 0; c < this->Columns; ++c)
    {
      if (!coincide(a, c, b, c))
      {
        return false;
      }
    }
    return true;
  };

  const int count = lastRow - firstRow + 1;
  sameAs.assign(count, 0);
  pole.assign(count, 0);
  for (int r = firstRow; r <= lastRow; ++r)
  {
    const int i = r - firstRow;
    sameAs[i] = r;
    const int blockFirst = r - r % this->BlockRows();
    const bool blockLast = r + 1 == this->Rows || !this->SameBlock(r, r + 1);
    if (r > firstRow && this->SameBlock(r - 1, r) && sameRow(r - 1, r))
    {
      sameAs[i] = sameAs[i - 1]; // a repeated row: its quads are degenerate and left out
      continue;
    }
    if (blockLast && blockFirst >= firstRow && blockFirst < r && sameRow(blockFirst, r))
    {
      sameAs[i] = sameAs[blockFirst - firstRow]; // the strip closes on its first row
      continue;
    }
    int first = -1;
    bool collapsed = true;
    for (int c = 0; c < this->Columns && collapsed; ++c)
    {
      if (this->Usable(r, c))
      {
        first = first < 0 ? c : first;
        collapsed = coincide(r, first, r, c);
      }
    }
    pole[i] = collapsed && first >= 0;
  }
}

vtkIdType vtkBoostedGridBuilder::BuildCurves(
  vtkPolyData* output, int firstRow, int lastRow, int outputPointsPrecision) const
{
  vtkIdType outside = 0;
  // With periodic columns the last column repeats the first: each row is a closed polyline of
  // grid indices (as with closed rows, whose columns are all distinct).
  const bool closed = this->PeriodicColumns || this->ClosedRows;
  const int distinct = this->PeriodicColumns ? this->Columns - 1 : this->Columns;
  // A row whose samples are all usable is one polyline (closed with periodic columns), written
  // in place below from its first point id (its points are consecutive; the map `ids` is not
  // written for it); the others are split into runs by the one walker first. Rows of fewer than
  // three distinct columns are all split.
  std::vector<vtkIdType> wholeFirst;
  const vtkBoostedLargeArrays::Buffer<long long> ids = this->WritePoints(output, firstRow,
    lastRow, outputPointsPrecision, false, outside, distinct >= 3 ? &wholeFirst : nullptr);
  wholeFirst.resize(static_cast<size_t>(std::max(0, lastRow - firstRow + 1)), -1); // none: -1
  const vtkIdType wholeSize = closed ? distinct + 1 : distinct;
  std::vector<vtkSmartPointer<vtkCellArray>> split(wholeFirst.size());
  std::vector<vtkIdType> cellCounts(wholeFirst.size()), sizes(wholeFirst.size());
  vtkBoostedPolylineRuns runs;
  std::vector<vtkIdType> row(closed ? distinct + 1 : distinct);
  for (size_t i = 0; i < wholeFirst.size(); ++i)
  {
    if (wholeFirst[i] >= 0)
    {
      cellCounts[i] = 1;
      sizes[i] = wholeSize;
      continue;
    }
    const int r = firstRow + static_cast<int>(i);
    for (int c = 0; c < distinct; ++c)
    {
      row[c] = this->Index(r, c);
    }
    if (closed)
    {
      row[distinct] = row[0];
    }
    split[i] = vtkSmartPointer<vtkCellArray>::New();
    runs.Walk(
      row.data(), static_cast<vtkIdType>(row.size()), [&ids](vtkIdType k) { return ids[k] >= 0; },
      [&ids](vtkIdType k) { return static_cast<vtkIdType>(ids[k]); },
      [](vtkIdType, vtkIdType) { return vtkIdType(-1); }, split[i]);
    cellCounts[i] = split[i]->GetNumberOfCells();
    sizes[i] = split[i]->GetNumberOfConnectivityIds();
  }
  output->SetLines(CellsInOrder(cellCounts, sizes, distinct, [&](size_t i, CellWriter& writer) {
    if (wholeFirst[i] >= 0)
    {
      const vtkIdType first = wholeFirst[i];
      writer.Start();
      for (vtkIdType c = 0; c < distinct; ++c)
      {
        writer.Add(first + c);
      }
      if (closed)
      {
        writer.Add(first);
      }
      return;
    }
    vtkIdType count;
    const vtkIdType* cell;
    for (split[i]->InitTraversal(); split[i]->GetNextCell(count, cell);)
    {
      writer.Start();
      for (vtkIdType k = 0; k < count; ++k)
      {
        writer.Add(cell[k]);
      }
    }
  }));
  return outside;
}

void vtkBoostedGridBuilder::SetRowsPerBlock(int rowsPerBlock)
{
  this->RowsPerBlock = rowsPerBlock;
}

void vtkBoostedGridBuilder::AddRowIntegerParameter(
  const std::string& name, const std::vector<int>& valuePerRow)
{
  this->IntegerParameters.emplace_back(name, valuePerRow);
}

bool vtkBoostedGridBuilder::PieceRows(
  int rows, bool surface, int piece, int pieces, int& firstRow, int& lastRow)
{
  pieces = pieces < 1 ? 1 : pieces;
  firstRow = 0;
  lastRow = -1;
  if (piece < 0 || piece >= pieces)
  {
    return false;
  }
  // In long long: piece + 1 and the products overflow an int.
  const long long begin = piece, end = static_cast<long long>(piece) + 1;
  if (surface)
  {
    const long long cellRows = rows - 1;
    firstRow = static_cast<int>(begin * cellRows / pieces);
    lastRow = static_cast<int>(end * cellRows / pieces);
    return firstRow < lastRow;
  }
  firstRow = static_cast<int>(begin * rows / pieces);
  lastRow = static_cast<int>(end * rows / pieces) - 1;
  return firstRow <= lastRow;
}

std::string vtkBoostedGridBuilder::SizeProblem(long long rows, long long columns)
{
  // Compared in double: rows x columns itself may overflow.
  if (static_cast<double>(rows) * static_cast<double>(columns) <= MaximumSamples)
  {
    return {};
  }
  return "the resolutions ask for " + std::to_string(rows) + " x " + std::to_string(columns) +
    " samples, more than the " + std::to_string(MaximumSamples) + " a grid may hold";
}
