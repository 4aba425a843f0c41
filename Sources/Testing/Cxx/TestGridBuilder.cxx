// vtkBoostedGridBuilder's writing pass, checked from its output alone: every usable sample
// becomes one point with its own values whether its run of columns is whole (the pass's copy of
// consecutive samples) or has unusable samples (the walk over them), and the count of points
// outside the clip sphere that the builds return is the one counted here from the written points,
// whether the builder counts them from the points or from what SetPoint noted (BeginSampling).
#include "vtkBoostedGridBuilder.h"

#include "vtkCellArray.h"
#include "vtkDoubleArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace
{
constexpr int kRows = 6, kColumns = 11;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

// The sample (r, c): unusable at a few places (whole rows 0, 2 and 5, the others cut once or
// twice), otherwise a point that names its sample.
bool usable(int r, int c)
{
  return !((r == 1 && c == 4) || (r == 3 && (c == 0 || c == 7 || c == 8)) ||
    (r == 4 && c == kColumns - 1));
}

void samplePoint(int r, int c, double p[3])
{
  p[0] = usable(r, c) ? 10.0 * r + c : kNaN;
  p[1] = 0.5 * c;
  p[2] = -1.0 * r;
}

// A grid of those samples with a row parameter, a column parameter, an integer row parameter
// and a sample array of two components.
void fill(vtkBoostedGridBuilder& grid)
{
  std::vector<double> rowValues, columnValues;
  std::vector<int> rowIds;
  for (int r = 0; r < kRows; ++r)
  {
    rowValues.push_back(100.0 + r);
    rowIds.push_back(7 * r);
  }
  for (int c = 0; c < kColumns; ++c)
  {
    columnValues.push_back(0.25 * c);
  }
  grid.AddRowParameter("row", rowValues);
  grid.AddColumnParameter("column", columnValues);
  grid.AddRowIntegerParameter("rowId", rowIds);
  const int values = grid.AddSampleArray("pair", 2);
  for (int r = 0; r < kRows; ++r)
  {
    grid.ClearSamples(r, 0, kColumns);
    for (int c = 0; c < kColumns; ++c)
    {
      double p[3];
      samplePoint(r, c, p);
      grid.SetPoint(r, c, p);
      double* pair = grid.SampleValues(values, r, c);
      pair[0] = r + 0.5;
      pair[1] = c - 0.5;
    }
  }
}

// Every point is a usable sample of rows [firstRow, lastRow], each once, in row-major order,
// with that sample's values.
void expectEveryUsableSampleOnce(vtkPolyData* output, int firstRow, int lastRow)
{
  vtkDataArray* row = output->GetPointData()->GetArray("row");
  vtkDataArray* column = output->GetPointData()->GetArray("column");
  vtkDataArray* rowId = output->GetPointData()->GetArray("rowId");
  vtkDataArray* pair = output->GetPointData()->GetArray("pair");
  ASSERT_TRUE(row && column && rowId && pair);
  vtkIdType id = 0;
  for (int r = firstRow; r <= lastRow; ++r)
  {
    for (int c = 0; c < kColumns; ++c)
    {
      if (!usable(r, c))
      {
        continue;
      }
      ASSERT_LT(id, output->GetNumberOfPoints());
      double expected[3], p[3];
      samplePoint(r, c, expected);
      output->GetPoint(id, p);
      EXPECT_EQ(p[0], expected[0]) << r << " " << c;
      EXPECT_EQ(p[1], expected[1]) << r << " " << c;
      EXPECT_EQ(p[2], expected[2]) << r << " " << c;
      EXPECT_EQ(row->GetComponent(id, 0), 100.0 + r);
      EXPECT_EQ(column->GetComponent(id, 0), 0.25 * c);
      EXPECT_EQ(rowId->GetComponent(id, 0), 7.0 * r);
      EXPECT_EQ(pair->GetComponent(id, 0), r + 0.5);
      EXPECT_EQ(pair->GetComponent(id, 1), c - 0.5);
      ++id;
    }
  }
  EXPECT_EQ(id, output->GetNumberOfPoints());
}

// The (row, column) of point `id`, from its parameters.
std::pair<int, int> sampleOf(vtkPolyData* output, vtkIdType id)
{
  return { static_cast<int>(output->GetPointData()->GetArray("row")->GetComponent(id, 0)) - 100,
    static_cast<int>(std::lround(
      4.0 * output->GetPointData()->GetArray("column")->GetComponent(id, 0))) };
}

TEST(GridBuilder, WholeAndCutRunsWriteEveryUsableSampleOnce)
{
  vtkBoostedGridBuilder grid(kRows, kColumns, false);
  fill(grid);
  vtkNew<vtkPolyData> curves;
  EXPECT_EQ(grid.BuildCurves(curves, 0, kRows - 1, 1), 0); // no clip sphere: none outside
  expectEveryUsableSampleOnce(curves, 0, kRows - 1);
  // Each polyline runs over consecutive usable columns of one row: one per run of them.
  vtkCellArray* lines = curves->GetLines();
  vtkIdType count;
  const vtkIdType* ids;
  int polylines = 0;
  for (lines->InitTraversal(); lines->GetNextCell(count, ids); ++polylines)
  {
    for (vtkIdType k = 1; k < count; ++k)
    {
      const auto a = sampleOf(curves, ids[k - 1]), b = sampleOf(curves, ids[k]);
      EXPECT_EQ(a.first, b.first);
      EXPECT_EQ(a.second + 1, b.second);
    }
  }
  // Rows 0, 2, 5 whole, row 1 cut once, row 3 at its first column and in the middle, row 4 at
  // its last column.
  EXPECT_EQ(polylines, 3 + 2 + 2 + 1);

  vtkNew<vtkPolyData> surface;
  EXPECT_EQ(grid.BuildSurface(surface, 1, 4, 1), 0);
  expectEveryUsableSampleOnce(surface, 1, 4);
  // Each quad's corners are the samples of one grid cell.
  vtkCellArray* quads = surface->GetPolys();
  int cells = 0;
  for (quads->InitTraversal(); quads->GetNextCell(count, ids); ++cells)
  {
    ASSERT_EQ(count, 4);
    const auto corner = sampleOf(surface, ids[0]);
    const std::pair<int, int> expected[4] = { corner, { corner.first, corner.second + 1 },
      { corner.first + 1, corner.second + 1 }, { corner.first + 1, corner.second } };
    for (int k = 0; k < 4; ++k)
    {
      EXPECT_EQ(sampleOf(surface, ids[k]), expected[k]);
    }
  }
  int usableCells = 0;
  for (int r = 1; r < 4; ++r)
  {
    for (int c = 0; c + 1 < kColumns; ++c)
    {
      usableCells += usable(r, c) && usable(r, c + 1) && usable(r + 1, c) && usable(r + 1, c + 1);
    }
  }
  EXPECT_EQ(cells, usableCells);
}

// Rows longer than one of the pass's segments (16,384 columns): a whole row is one polyline of
// consecutive points (closed with periodic columns), and a row with one unusable sample in its
// second segment or its first is cut there, in rows before and after whole ones. The test below
// runs it at 40,001 columns and at 32,769 (a periodic row of exactly two segments), on one thread
// and on two (the rows' segments shared among the threads).
void expectLongRowsAreOnePolylineOrCutWhereASampleIsUnusable(int columns)
{
  constexpr int rows = 4;
  // Unusable: row 1 at column 20000 (its second segment), row 2 at column 5 (its first).
  auto usableHere = [](int r, int c) { return !((r == 1 && c == 20000) || (r == 2 && c == 5)); };
  for (const bool periodic : { false, true })
  {
    vtkBoostedGridBuilder grid(rows, columns, periodic);
    for (int r = 0; r < rows; ++r)
    {
      grid.ClearSamples(r, 0, columns);
      for (int c = 0; c < columns; ++c)
      {
        // Periodic: the last column repeats the first (the builds leave it out of curves).
        const int sample = periodic && c == columns - 1 ? 0 : c;
        const double p[3] = { static_cast<double>(sample), static_cast<double>(r), 0.0 };
        if (usableHere(r, sample))
        {
          grid.SetPoint(r, c, p);
        }
      }
    }
    vtkNew<vtkPolyData> curves;
    EXPECT_EQ(grid.BuildCurves(curves, 0, rows - 1, 1), 0);
    const int distinct = periodic ? columns - 1 : columns;
    ASSERT_EQ(curves->GetNumberOfPoints(), static_cast<vtkIdType>(rows) * distinct - 2);
    // The polylines in order, each as the (row, column) of its points.
    std::vector<std::vector<std::pair<int, int>>> lines;
    vtkCellArray* cells = curves->GetLines();
    vtkIdType count;
    const vtkIdType* ids;
    for (cells->InitTraversal(); cells->GetNextCell(count, ids);)
    {
      lines.emplace_back();
      for (vtkIdType k = 0; k < count; ++k)
      {
        double p[3];
        curves->GetPoint(ids[k], p);
        lines.back().emplace_back(static_cast<int>(p[1]), static_cast<int>(p[0]));
      }
    }
    // The expected polylines: whole rows 0 and 3 (closed when periodic); row 1 cut at 20000 and
    // row 2 at 5 (a periodic row's run through the seam joins its last and first runs).
    std::vector<std::vector<std::pair<int, int>>> expected;
    auto run = [&](int r, int from, int to) { // columns [from, to) of row r, mod distinct
      std::vector<std::pair<int, int>> line;
      for (int c = from; c < to; ++c)
      {
        line.emplace_back(r, c % distinct);
      }
      return line;
    };
    for (int r = 0; r < rows; ++r)
    {
      const int cut = r == 1 ? 20000 : r == 2 ? 5 : -1;
      if (cut < 0)
      {
        expected.push_back(run(r, 0, periodic ? distinct + 1 : distinct));
      }
      else if (periodic)
      {
        expected.push_back(run(r, cut + 1, distinct + cut));
      }
      else
      {
        expected.push_back(run(r, 0, cut));
        expected.push_back(run(r, cut + 1, distinct));
      }
    }
    ASSERT_EQ(lines.size(), expected.size()) << (periodic ? "periodic" : "open");
    for (size_t i = 0; i < lines.size(); ++i)
    {
      EXPECT_EQ(lines[i], expected[i]) << "polyline " << i << (periodic ? " periodic" : " open");
    }
    if (periodic)
    {
      continue;
    }
    // The surface: one quad per grid cell whose four samples are usable, its corners those
    // samples in order, between whole rows and next to cut ones.
    vtkNew<vtkPolyData> surface;
    EXPECT_EQ(grid.BuildSurface(surface, 0, rows - 1, 1), 0);
    ASSERT_EQ(surface->GetNumberOfPoints(), static_cast<vtkIdType>(rows) * columns - 2);
    vtkIdType quads = 0;
    cells = surface->GetPolys();
    for (cells->InitTraversal(); cells->GetNextCell(count, ids); ++quads)
    {
      ASSERT_EQ(count, 4);
      std::pair<int, int> corners[4];
      for (int k = 0; k < 4; ++k)
      {
        double p[3];
        surface->GetPoint(ids[k], p);
        corners[k] = { static_cast<int>(p[1]), static_cast<int>(p[0]) };
      }
      const auto [r, c] = corners[0];
      const std::pair<int, int> expectedCorners[4] = { { r, c }, { r, c + 1 }, { r + 1, c + 1 },
        { r + 1, c } };
      for (int k = 0; k < 4; ++k)
      {
        EXPECT_EQ(corners[k], expectedCorners[k]) << "quad " << quads;
      }
    }
    // Each unusable sample removes the four cells around it (row 1's at column 20,000, row 2's
    // at column 5).
    EXPECT_EQ(quads, static_cast<vtkIdType>(rows - 1) * (columns - 1) - 2 * 2 - 2 * 2);
  }
}

TEST(GridBuilder, LongRowsAreOnePolylineOrCutWhereASampleIsUnusable)
{
  for (const int threads : { 1, 2 })
  {
    // As TestSourceThreads' run: the backend and thread count for this scope only.
    vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, "STDThread", false }, [&] {
      EXPECT_STREQ(vtkSMPTools::GetBackend(), "STDThread");
      for (const int columns : { 40001, 32769 })
      {
        SCOPED_TRACE(std::to_string(threads) + " threads, " + std::to_string(columns) + " columns");
        expectLongRowsAreOnePolylineOrCutWhereASampleIsUnusable(columns);
      }
    });
  }
}

TEST(GridBuilder, BuildsCountThePointsOutsideTheClipSphere)
{
  // Counted here as vtkBoostedSphereClip decides: |p - center|^2 <= radius^2 is inside.
  auto outside = [](vtkPolyData* output, const double center[3], double radius) {
    vtkIdType count = 0;
    for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
    {
      double p[3];
      output->GetPoint(i, p);
      const double d2 = (p[0] - center[0]) * (p[0] - center[0]) +
        (p[1] - center[1]) * (p[1] - center[1]) + (p[2] - center[2]) * (p[2] - center[2]);
      count += !(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) &&
        d2 <= radius * radius);
    }
    return count;
  };
  const double center[3] = { 20.0, 2.0, -2.0 };
  // The sphere set after the sampling (the builds read the points), before it (they count
  // SetPoint's notes), and another sphere before it, changed after (the notes are stale: read).
  enum Order
  {
    After,
    Before,
    Changed
  };
  for (Order order : { After, Before, Changed })
  {
    for (double radius : { 1e-3, 5.0, 12.5, 30.0, 1e300 })
    {
      vtkBoostedGridBuilder grid(kRows, kColumns, false);
      if (order != After)
      {
        const double elsewhere[3] = { -50.0, 0.0, 0.0 };
        grid.SetClipSphere(order == Before ? center : elsewhere, order == Before ? radius : 1.0);
        grid.BeginSampling();
      }
      fill(grid);
      grid.SetClipSphere(center, radius);
      vtkNew<vtkPolyData> curves, surface;
      const vtkIdType curvesOutside = grid.BuildCurves(curves, 0, kRows - 1, 1);
      EXPECT_EQ(curvesOutside, outside(curves, center, radius)) << radius << " " << order;
      const vtkIdType surfaceOutside = grid.BuildSurface(surface, 0, kRows - 1, 1);
      EXPECT_EQ(surfaceOutside, outside(surface, center, radius)) << radius << " " << order;
      expectEveryUsableSampleOnce(curves, 0, kRows - 1);
      if (radius == 12.5)
      {
        EXPECT_GT(curvesOutside, 0);
        EXPECT_LT(curvesOutside, curves->GetNumberOfPoints());
      }
    }
  }
  // A point exactly on the sphere is inside: row 2's samples (20 + c, c / 2, -2) are at squared
  // distance c^2 + (c / 2 - 2)^2 from the center, exactly 16 at c = 4, so that with radius 4 the
  // columns 5 to 10 are outside.
  {
    vtkBoostedGridBuilder grid(kRows, kColumns, false);
    fill(grid);
    grid.SetClipSphere(center, 4.0);
    vtkNew<vtkPolyData> curves;
    const vtkIdType count = grid.BuildCurves(curves, 2, 2, 1);
    EXPECT_EQ(count, 6);
    EXPECT_EQ(count, outside(curves, center, 4.0));
  }
  // Points that overflow when the origin is added are not finite: outside whatever the radius.
  // The origin set after the sampling, before it, and changed after it (the notes of SetPoint,
  // made with a zero origin, would count none outside).
  for (Order order : { After, Before, Changed })
  {
    vtkBoostedGridBuilder grid(1, 3, false);
    const double origin[3] = { 1e308, 0.0, 0.0 }, zero[3] = { 0.0, 0.0, 0.0 };
    if (order != After)
    {
      grid.SetOrigin(order == Before ? origin : zero);
      grid.SetClipSphere(zero, std::numeric_limits<double>::max());
      grid.BeginSampling();
    }
    grid.ClearSamples(0, 0, 3);
    const double near[3] = { 1.0, 0.0, 0.0 }, far[3] = { 1e308, 0.0, 0.0 };
    grid.SetPoint(0, 0, near);
    grid.SetPoint(0, 1, far);
    grid.SetPoint(0, 2, near);
    grid.SetOrigin(origin);
    grid.SetClipSphere(zero, std::numeric_limits<double>::max());
    vtkNew<vtkPolyData> curves;
    EXPECT_EQ(grid.BuildCurves(curves, 0, 0, 1), 1) << order;
    EXPECT_EQ(curves->GetNumberOfPoints(), 3) << order;
  }
}

// A grid whose samples are all usable, built whole in double precision, hands its own samples
// and sample arrays to the output instead of copying them: the output holds the samples' bits
// (a zero origin adds nothing: -0 stays -0), as the copies of a piece, of single precision and
// of a grid with an unusable sample do, and a later build of the same grid still reads them
// after the first output is gone.
TEST(GridBuilder, WholeGridsGiveTheSamplesBitsAndStayReadableAfterTheirFirstOutput)
{
  constexpr int rows = 3, columns = 7;
  // Sample (r, c); -0 coordinates in row 1, (12, 0, 0) outside the clip sphere below.
  auto sampleAt = [](int r, int c, double p[3]) {
    p[0] = r == 1 ? -0.0 : 2.0 * c;
    p[1] = r == 1 ? 0.5 * c : -0.0;
    p[2] = 0.1 * r;
  };
  auto sameBits = [](double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
  };
  const double center[3] = { 0.0, 0.0, 0.0 };
  for (const bool dropOne : { false, true })
  {
    for (const int precision : { 1, 0 }) // vtkAlgorithm's DOUBLE_PRECISION, SINGLE_PRECISION
    {
      vtkBoostedGridBuilder grid(rows, columns, false);
      const int pair = grid.AddSampleArray("pair", 2);
      grid.SetClipSphere(center, 11.0);
      for (int r = 0; r < rows; ++r)
      {
        grid.ClearSamples(r, 0, columns);
        for (int c = 0; c < columns; ++c)
        {
          double p[3];
          sampleAt(r, c, p);
          if (!(dropOne && r == 2 && c == 3))
          {
            grid.SetPoint(r, c, p);
          }
          double* values = grid.SampleValues(pair, r, c);
          values[0] = r - 0.0;
          values[1] = -0.25 * c;
        }
      }
      // The points of rows [firstRow, lastRow] in order, their values, and the count outside.
      auto expectSamples = [&](vtkPolyData* output, int firstRow, int lastRow, vtkIdType outside,
                             const char* what) {
        SCOPED_TRACE(std::string(what) + (dropOne ? ", one dropped" : ", whole") +
          (precision ? ", double" : ", float"));
        vtkDataArray* values = output->GetPointData()->GetArray("pair");
        ASSERT_TRUE(values);
        vtkIdType id = 0, expectedOutside = 0;
        for (int r = firstRow; r <= lastRow; ++r)
        {
          for (int c = 0; c < columns; ++c)
          {
            if (dropOne && r == 2 && c == 3)
            {
              continue;
            }
            ASSERT_LT(id, output->GetNumberOfPoints());
            double expected[3], p[3];
            sampleAt(r, c, expected);
            output->GetPoint(id, p);
            for (int k = 0; k < 3; ++k)
            {
              const double written = precision ? expected[k] : static_cast<float>(expected[k]);
              EXPECT_TRUE(sameBits(p[k], written)) << r << " " << c << " " << k << ": " << p[k];
            }
            expectedOutside += expected[0] * expected[0] + expected[1] * expected[1] +
                expected[2] * expected[2] > 121.0;
            EXPECT_EQ(values->GetComponent(id, 0), r);
            EXPECT_EQ(values->GetComponent(id, 1), -0.25 * c);
            ++id;
          }
        }
        EXPECT_EQ(id, output->GetNumberOfPoints());
        EXPECT_EQ(outside, expectedOutside);
        EXPECT_GT(outside, 0);
      };
      {
        vtkNew<vtkPolyData> first;
        expectSamples(first, 0, rows - 1, grid.BuildSurface(first, 0, rows - 1, precision),
          "surface");
      } // the first output, and the arrays it was given, are gone
      vtkNew<vtkPolyData> curves;
      expectSamples(curves, 0, rows - 1, grid.BuildCurves(curves, 0, rows - 1, precision),
        "curves after the surface");
      vtkNew<vtkPolyData> piece;
      expectSamples(piece, 1, 2, grid.BuildCurves(piece, 1, 2, precision), "a piece");
    }
  }
}

// Closed rows (SetClosedRows) give the curves of periodic columns without the repeated column:
// the same points and polylines, whole or cut.
TEST(GridBuilder, ClosedRowsAreThePeriodicCurvesWithoutTheRepeatedColumn)
{
  constexpr int rows = 3, distinct = 9;
  vtkBoostedGridBuilder periodic(rows, distinct + 1, true), closed(rows, distinct, false);
  closed.SetClosedRows(true);
  for (int r = 0; r < rows; ++r)
  {
    periodic.ClearSamples(r, 0, distinct + 1);
    closed.ClearSamples(r, 0, distinct);
    for (int c = 0; c <= distinct; ++c)
    {
      const int sample = c % distinct;
      const double angle = 2.0 * 3.141592653589793 * sample / distinct;
      const double p[3] = { std::cos(angle), std::sin(angle), static_cast<double>(r) };
      // Row 1 is cut at column 4.
      if (r == 1 && sample == 4)
      {
        continue;
      }
      periodic.SetPoint(r, c, p);
      if (c < distinct)
      {
        closed.SetPoint(r, c, p);
      }
    }
  }
  vtkNew<vtkPolyData> fromPeriodic, fromClosed;
  periodic.BuildCurves(fromPeriodic, 0, rows - 1, 1);
  closed.BuildCurves(fromClosed, 0, rows - 1, 1);
  ASSERT_EQ(fromClosed->GetNumberOfPoints(), rows * distinct - 1);
  ASSERT_EQ(fromClosed->GetNumberOfPoints(), fromPeriodic->GetNumberOfPoints());
  for (vtkIdType i = 0; i < fromClosed->GetNumberOfPoints(); ++i)
  {
    double a[3], b[3];
    fromPeriodic->GetPoint(i, a);
    fromClosed->GetPoint(i, b);
    EXPECT_TRUE(a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) << i;
  }
  auto cells = [](vtkPolyData* output) {
    std::vector<std::vector<vtkIdType>> lines;
    vtkCellArray* array = output->GetLines();
    vtkIdType count;
    const vtkIdType* ids;
    for (array->InitTraversal(); array->GetNextCell(count, ids);)
    {
      lines.emplace_back(ids, ids + count);
    }
    return lines;
  };
  const auto lines = cells(fromClosed);
  EXPECT_EQ(lines, cells(fromPeriodic));
  // Rows 0 and 2 closed (their first point again at the end), row 1 one open run through the
  // seam.
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0].size(), static_cast<size_t>(distinct + 1));
  EXPECT_EQ(lines[0].front(), lines[0].back());
  EXPECT_EQ(lines[1].size(), static_cast<size_t>(distinct - 1));
  EXPECT_EQ(lines[2].front(), lines[2].back());
}
} // namespace
