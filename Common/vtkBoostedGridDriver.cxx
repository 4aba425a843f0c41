#include "vtkBoostedGridDriver.h"

#include "vtkAlgorithm.h"
#include "vtkBoostedBlockLoop.h"
#include "vtkBoostedMemoryBudget.h"
#include "vtkBoostedSinglePrecision.h"
#include "vtkBoostedSphereClip.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>

vtkBoostedGridDriver::vtkBoostedGridDriver(vtkAlgorithm* source, vtkInformation* outputInformation,
  const double clipCenter[3], double clipRadius, int outputPointsPrecision)
  : Source(source)
  , OutputInformation(outputInformation)
  , ClipCenter{ clipCenter[0], clipCenter[1], clipCenter[2] }
  , ClipRadius(clipRadius)
  , OutputPointsPrecision(outputPointsPrecision)
{
}

vtkBoostedGridDriver::~vtkBoostedGridDriver() = default;

std::string vtkBoostedGridDriver::ClipSphereProblem(const double center[3], double radius)
{
  if (!(std::isfinite(center[0]) && std::isfinite(center[1]) && std::isfinite(center[2])))
  {
    return "the clip sphere's center must be finite";
  }
  if (!(radius > 0.0) || !std::isfinite(radius)) // the clamp macros let NaN through
  {
    return "ClipRadius must be a positive number";
  }
  return {};
}

std::string vtkBoostedGridDriver::GridProblem(
  long long rows, long long columns, double bytesPerSample, const std::string& what)
{
  std::string problem = vtkBoostedGridBuilder::SizeProblem(rows, columns);
  if (problem.empty() && bytesPerSample > 0.0)
  {
    problem = vtkBoostedMemoryBudget::Problem(
      static_cast<double>(rows) * static_cast<double>(columns) * bytesPerSample,
      what + " of " + std::to_string(rows) + " x " + std::to_string(columns) + " samples");
  }
  return problem;
}

bool vtkBoostedGridDriver::Prepare(const std::string& sourceProblem, long long rows,
  long long columns, bool periodicColumns, bool surface, int rowsPerStrip)
{
  std::string problem = sourceProblem;
  if (problem.empty())
  {
    problem = ClipSphereProblem(this->ClipCenter, this->ClipRadius);
  }
  if (problem.empty())
  {
    problem = GridProblem(rows, columns, this->BytesPerSample);
  }
  if (!problem.empty())
  {
    vtkErrorWithObjectMacro(this->Source, << problem);
    return false; // the output stays empty
  }
  // Within MaximumSamples, hence within int.
  const int rowCount = static_cast<int>(rows);
  const int piece =
    this->OutputInformation->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  const int pieces =
    this->OutputInformation->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
  if (rowCount < 1 || columns < 1 ||
    !vtkBoostedGridBuilder::PieceRows(
      rowCount, surface, piece, pieces, this->FirstRow, this->LastRow))
  {
    return false; // an empty piece
  }
  this->Surface = surface;
  this->Columns = static_cast<int>(columns);
  this->SampleFirst = surface ? std::max(0, this->FirstRow - 1) : this->FirstRow;
  this->SampleLast = surface ? std::min(rowCount - 1, this->LastRow + 1) : this->LastRow;
  if (!vtkBoostedMemoryBudget::Run(this->Source, [&] {
        this->Builder.reset(new vtkBoostedGridBuilder(rowCount, this->Columns, periodicColumns));
      }))
  {
    return false; // the output stays empty
  }
  if (rowsPerStrip > 0)
  {
    this->Builder->SetRowsPerBlock(rowsPerStrip);
  }
  this->Builder->SetMergeSeam(this->MergeSeam);
  // Before the sampling: SetPoint notes which samples are inside.
  this->Builder->SetClipSphere(this->ClipCenter, this->ClipRadius);
  return true;
}

// Each variant clears its samples (vtkBoostedGridBuilder::ClearSamples) on the thread that
// computes them, right before the source's sample function.
bool vtkBoostedGridDriver::SampleRows(const std::function<void(int)>& sample)
{
  vtkBoostedGridBuilder* grid = this->Builder.get();
  const int columns = this->Columns;
  return this->Sample(this->SampleFirst, this->SampleLast + 1, this->Columns,
    [&sample, grid, columns](vtkIdType first, vtkIdType last) {
      for (vtkIdType r = first; r < last; ++r)
      {
        grid->ClearSamples(static_cast<int>(r), 0, columns);
        sample(static_cast<int>(r));
      }
    });
}

bool vtkBoostedGridDriver::SampleGrid(const std::function<void(int, int)>& sample)
{
  return this->SampleRuns([&sample](int row, int firstColumn, int lastColumn) {
    for (int c = firstColumn; c < lastColumn; ++c)
    {
      sample(row, c);
    }
  });
}

bool vtkBoostedGridDriver::SampleColumns(const std::function<void(int, int, int, int)>& sample)
{
  const int firstRow = this->SampleFirst, lastRow = this->SampleLast;
  return this->Sample(0, this->Columns, lastRow - firstRow + 1,
    [&sample, firstRow, lastRow](vtkIdType first, vtkIdType last) {
      for (vtkIdType c = first; c < last; c += ColumnsPerRun)
      {
        sample(static_cast<int>(c), static_cast<int>(std::min<vtkIdType>(last, c + ColumnsPerRun)),
          firstRow, lastRow);
      }
    });
}

bool vtkBoostedGridDriver::SampleRuns(const std::function<void(int, int, int)>& sample)
{
  vtkBoostedGridBuilder* grid = this->Builder.get();
  const vtkIdType columns = this->Columns;
  return this->Sample(this->SampleFirst * columns, (this->SampleLast + 1) * columns, 1,
    [&sample, grid, columns](vtkIdType first, vtkIdType last) {
      // The chunk [first, last) of row-major sample indices, cut where rows end.
      for (vtkIdType i = first; i < last;)
      {
        const vtkIdType row = i / columns;
        const vtkIdType end = std::min(last, (row + 1) * columns);
        const int firstColumn = static_cast<int>(i - row * columns);
        const int lastColumn = static_cast<int>(end - row * columns);
        grid->ClearSamples(static_cast<int>(row), firstColumn, lastColumn);
        sample(static_cast<int>(row), firstColumn, lastColumn);
        i = end;
      }
    });
}

bool vtkBoostedGridDriver::Sample(vtkIdType begin, vtkIdType end, vtkIdType samplesPerItem,
  const std::function<void(vtkIdType, vtkIdType)>& work)
{
  bool completed = false;
  this->Builder->BeginSampling(); // the origin and the clip sphere are set by now
  // An allocation that fails in a worker is one error (Run) and an empty output, like an abort.
  const bool ran = vtkBoostedMemoryBudget::Run(this->Source,
    [&] { completed = vtkBoostedBlockLoop::For(this->Source, begin, end, samplesPerItem, work); });
  this->Aborted = !(ran && completed);
  return !this->Aborted;
}

bool vtkBoostedGridDriver::Build(vtkPolyData* output)
{
  if (this->Aborted || !this->Builder)
  {
    return false; // never hand on a half-computed grid
  }
  std::string problem;
  const bool built = vtkBoostedMemoryBudget::Run(this->Source, [&] {
    // In double precision; single precision is the last step (a cut computed from floats would
    // round twice).
    vtkNew<vtkPolyData> sampled;
    const vtkIdType outside = this->Surface
      ? this->Builder->BuildSurface(
          sampled, this->FirstRow, this->LastRow, vtkAlgorithm::DOUBLE_PRECISION)
      : this->Builder->BuildCurves(
          sampled, this->FirstRow, this->LastRow, vtkAlgorithm::DOUBLE_PRECISION);
    if (outside == 0)
    {
      output->ShallowCopy(sampled); // nothing to cut: what the clip would give
    }
    else
    {
      vtkBoostedSphereClip::Clip(sampled, this->ClipCenter, this->ClipRadius, output);
    }
    if (this->OutputPointsPrecision == vtkAlgorithm::SINGLE_PRECISION)
    {
      problem = vtkBoostedPointsToSinglePrecision(output->GetPoints()); // as built: doubles
    }
  });
  if (!problem.empty())
  {
    vtkErrorWithObjectMacro(this->Source, << problem);
  }
  if (!built || !problem.empty())
  {
    output->Initialize(); // never hand on a half-built output
    return false;
  }
  return true;
}
