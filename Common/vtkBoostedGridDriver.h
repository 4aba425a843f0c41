/**
 * @class   vtkBoostedGridDriver
 * @brief   the RequestData steps every grid source shares, around vtkBoostedGridBuilder
 *
 * A grid source (Boosted Surface, Curvature Patch, Hopf Fibration) validates its own parameters,
 * then hands the rest to this class:
 * 1. Prepare: reports the source's problem, a bad clip radius, a grid beyond
 *    vtkBoostedGridBuilder::MaximumSamples or an estimate beyond the memory budget
 *    (vtkBoostedMemoryBudget, from the source's SetBytesPerSample) as one error (the output stays
 *    empty), and finds the
 *    rows of the requested piece (an out-of-range piece is empty, as in VTK's sources). A surface
 *    also samples one halo row on each side, which the normals at the band's edge need.
 * 2. SampleRows, SampleGrid, SampleColumns or SampleRuns: the source computes its samples, in
 *    vtkBoostedBlockLoop's blocks (progress, abort, threads), each sample cleared first
 *    (vtkBoostedGridBuilder::ClearSamples) on the thread that computes it (SampleColumns: cleared
 *    or set by the source itself).
 * 3. Build: quads or polylines (vtkBoostedGridBuilder), cut exactly at the clip sphere
 *    (vtkBoostedSphereClip): every finite sample is kept until the cut, so the output ends on the
 *    sphere (to round-off), not at the last whole grid cell inside it. An aborted update stays
 *    empty, and so does one whose allocation fails (an error, not an abort). The grid is built
 *    and cut in double precision; single-precision output is converted last, and refused
 *    (vtkBoostedSinglePrecision) when a coordinate is beyond the largest float.
 *
 * The clip sphere has one meaning in every source: radius ClipRadius (an absolute length) about
 * the construction's center (the circle's center, the patch's origin).
 */
#ifndef vtkBoostedGridDriver_h
#define vtkBoostedGridDriver_h

#include "BoostedSurfacesCommonModule.h" // for export macro
#include "vtkBoostedGridBuilder.h"       // for the grid
#include "vtkType.h"                     // for vtkIdType

#include <functional> // for the sampling work
#include <memory>     // for the grid
#include <string>     // for the problem

class vtkAlgorithm;
class vtkInformation;
class vtkPolyData;

class BOOSTEDSURFACESCOMMON_EXPORT vtkBoostedGridDriver
{
public:
  /// `source` reports errors, progress and abort; `outputInformation` holds the piece request.
  vtkBoostedGridDriver(vtkAlgorithm* source, vtkInformation* outputInformation,
    const double clipCenter[3], double clipRadius, int outputPointsPrecision);
  ~vtkBoostedGridDriver();

  /// The update's memory per grid sample (all the rows, not only the piece's: the builder holds
  /// the whole grid), for Prepare's estimate; each source measures its own. 0: no estimate.
  void SetBytesPerSample(double bytesPerSample) { this->BytesPerSample = bytesPerSample; }

  /// Surfaces share the points of their closed directions (vtkBoostedGridBuilder::SetMergeSeam).
  void SetMergeSeam(bool mergeSeam) { this->MergeSeam = mergeSeam; }

  /// The size checks of Prepare, for a source that must know them before it can count its rows
  /// exactly (Hopf samples its base points first): a grid beyond
  /// vtkBoostedGridBuilder::MaximumSamples, or rows x columns x bytesPerSample beyond the memory
  /// budget (bytesPerSample 0: no estimate). `what` names the grid in the message. Empty when fine.
  static std::string GridProblem(long long rows, long long columns, double bytesPerSample,
    const std::string& what = "a grid");

  /// Step 1. `problem`: the source's own validation (empty when its parameters are valid). A
  /// surface makes quads between rows (and needs at least two); otherwise each row is a polyline.
  /// `rowsPerStrip` > 0 splits the rows into strips (vtkBoostedGridBuilder::SetRowsPerBlock).
  /// Returns false when there is nothing to compute: an error was reported, or the piece is empty.
  bool Prepare(const std::string& problem, long long rows, long long columns, bool periodicColumns,
    bool surface, int rowsPerStrip = 0);

  /// The grid, to set points, fallback normals and parameters (after Prepare).
  vtkBoostedGridBuilder& Grid() { return *this->Builder; }

  /// Step 2: sample(row) for every row this piece needs (its rows and halo), or sample(row,
  /// column) for every sample of those rows; called from several threads at once. False when
  /// aborted or out of memory (one error; the output stays empty).
  bool SampleRows(const std::function<void(int row)>& sample);
  bool SampleGrid(const std::function<void(int row, int column)>& sample);
  /// Step 2 for a map that is the same down a column (the orbits' exp(t B) at one t):
  /// sample(firstColumn, lastColumn, firstRow, lastRow) over runs of at most ColumnsPerRun
  /// columns [firstColumn, lastColumn) that together cover every column, each over the rows this
  /// piece needs, so that a source makes a run's maps once and then writes each row's run in
  /// order. Unlike the others, no sample is cleared first: sample sets or clears
  /// (vtkBoostedGridBuilder::ClearSamples) every sample of its run, which saves a pass of stores
  /// over the points when nearly all are set.
  bool SampleColumns(
    const std::function<void(int firstColumn, int lastColumn, int firstRow, int lastRow)>& sample);
  /// SampleColumns' largest run: its maps stay in the L1 cache (64 of the orbits' 5 x 5 maps,
  /// 12.8 KB).
  static constexpr int ColumnsPerRun = 64;
  /// Step 2 in batches: sample(row, firstColumn, lastColumn) over runs of one row's columns
  /// [firstColumn, lastColumn) that together cover the samples of the rows this piece needs, so
  /// that a source can hoist its per-row work and map a run at once.
  bool SampleRuns(const std::function<void(int row, int firstColumn, int lastColumn)>& sample);

  /// Step 3: this piece's cells, cut at the clip sphere, into `output`. False (`output` left
  /// empty) when aborted, out of memory or refused as single precision (an error was reported).
  bool Build(vtkPolyData* output);

  /// Empty when (center, radius) is a valid clip sphere, otherwise what is wrong with it.
  static std::string ClipSphereProblem(const double center[3], double radius);

private:
  vtkBoostedGridDriver(const vtkBoostedGridDriver&) = delete;
  void operator=(const vtkBoostedGridDriver&) = delete;
  bool Sample(vtkIdType begin, vtkIdType end, vtkIdType samplesPerItem,
    const std::function<void(vtkIdType, vtkIdType)>& work);

  vtkAlgorithm* Source;
  vtkInformation* OutputInformation;
  double ClipCenter[3];
  double ClipRadius;
  int OutputPointsPrecision;
  std::unique_ptr<vtkBoostedGridBuilder> Builder;
  bool Surface = false;
  int Columns = 0;
  int FirstRow = 0, LastRow = -1;     // this piece's rows
  int SampleFirst = 0, SampleLast = -1; // with the halo
  bool Aborted = false;
  double BytesPerSample = 0.0;
  bool MergeSeam = false;
};

#endif
