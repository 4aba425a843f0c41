/**
 * @class   vtkBoostedGridBuilder
 * @brief   turns a rows x columns grid of sampled surface points into a vtkPolyData
 *
 * Shared by the sources of this project: they sample a parametric surface on a grid (rows are the
 * sweep parameter, columns the curve parameter), mark which samples are usable, and let this class
 * emit either quads with point normals and texture coordinates, or one polyline per row.
 *
 * A sample is unusable when it is not finite (a point sent to infinity); cells touching an
 * unusable sample are left out, so the surface is cut there rather than stretched to infinity.
 * Only the points that are used are written. The cut at a clip sphere is vtkBoostedSphereClip's,
 * applied to this class's output (vtkBoostedGridDriver does both, and skips the cut when this
 * class counted no point outside the sphere: SetClipSphere). A grid built whole (all its rows),
 * in double precision, with every sample usable and nothing merged, is not copied: its points
 * and sample arrays become the output's (the first such build; a later one copies).
 *
 * Merged seams (SetMergeSeam): the grid's closed directions share their points instead of
 * repeating them, so that a closed surface comes out closed and manifold (watertight exports):
 * the repeated seam column of periodic columns is column 0; a row that repeats the row before it
 * in its block, or the block's first row (a strip closed over a full turn), is that row; a row
 * whose samples all coincide (a pole) is one point. Quads that then use a point twice become
 * triangles, those with fewer than three distinct points are left out, and so are the points
 * no cell then uses. "Repeats" and
 * "coincide" are geometric (within 1e-9 of the rows' size), so no source has to declare them.
 * Only the piece's own rows are merged: a piece boundary is not a seam (a strip's closing row
 * whose first row is on another piece keeps its points). Merged points have one texture
 * coordinate for two (u = 0 and 1), so TextureCoordinates are left out.
 *
 * Building runs on the block loop's threads (vtkBoostedBlockLoop::RunBlock): runs of one row's
 * columns each write their own range of the points, arrays and cells, numbered from per-run
 * counts, so the output is the same, bit for bit, whatever the backend and the number of threads.
 *
 * A sample's point, normal and values are undefined until ClearSamples makes it unset (NaN point
 * and normal, zero values): vtkBoostedGridDriver clears each sample on the thread that computes
 * it, right before (or the source clears what it does not set: SampleColumns), so that no pass
 * over the whole grid runs before the sampling and the grid's memory is first touched by the
 * threads that use it. Building reads only cleared samples: the
 * rows it builds, and their neighbours for the normals.
 */
#ifndef vtkBoostedGridBuilder_h
#define vtkBoostedGridBuilder_h

#include "BoostedSurfacesCommonModule.h" // for export macro
#include "vtkBoostedLargeArrays.h"       // for the sample buffers
#include "vtkBoostedSphereClip.h"        // for SetPoint's clip test
#include "vtkSmartPointer.h"             // for the arrays handed to an output
#include "vtkType.h"                     // for vtkIdType

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

class vtkDataArray;
class vtkPolyData;

class BOOSTEDSURFACESCOMMON_EXPORT vtkBoostedGridBuilder
{
public:
  /// `periodicColumns`: the last column repeats the first (a closed curve with a texture seam).
  vtkBoostedGridBuilder(int rows, int columns, bool periodicColumns);

  /// Makes the samples (row, [firstColumn, lastColumn)) unset (see the class description).
  void ClearSamples(int row, int firstColumn, int lastColumn);

  /// The points SetPoint takes are relative to `origin` (default 0); the output holds origin +
  /// point. A source far from the origin samples relative to its construction's center, so that
  /// its samples and their normals keep their precision (eps |origin| in the output).
  void SetOrigin(const double origin[3]);
  /// Sets a sample's point and notes whether it is usable and inside the clip sphere, so that
  /// building need not read every point again to count them (see BeginSampling).
  void SetPoint(int row, int column, const double point[3])
  {
    const size_t i = static_cast<size_t>(this->Index(row, column));
    double* p = &this->Points[3 * i];
    p[0] = point[0];
    p[1] = point[1];
    p[2] = point[2];
    this->States[i] = this->State(point);
  }
  /// Called once the origin and the clip sphere are set, before the first SetPoint (by
  /// vtkBoostedGridDriver): building then counts the usable points and those inside the clip
  /// sphere from what SetPoint noted. A later change of the origin or the sphere makes it read
  /// every point again instead, as without BeginSampling.
  void BeginSampling();
  /// Used where the grid gives no normal (a degenerate neighbourhood): e.g. the plane of the row's curve.
  void SetRowFallbackNormal(int row, const double normal[3]);

  /// Exact normals: a source that knows its surface's derivatives calls EnableSampleNormals once
  /// (before sampling), then SetSampleNormal for every sample where its normal is defined; those
  /// are written as they are, the other samples get the grid's central differences as without.
  void EnableSampleNormals();
  void SetSampleNormal(int row, int column, const double normal[3])
  {
    double* n = &this->SampleNormals[3 * static_cast<size_t>(this->Index(row, column))];
    n[0] = normal[0];
    n[1] = normal[1];
    n[2] = normal[2];
  }

  /// A named double point array of `components` values per grid sample, filled by the sampling
  /// through SampleValues (zeros where not written) and written with the points of a surface or
  /// of curves; returns its index. Call before sampling. The values of one row's samples are
  /// consecutive: SampleValues(array, row, c + 1) = SampleValues(array, row, c) + components.
  int AddSampleArray(const std::string& name, int components);
  double* SampleValues(int array, int row, int column)
  {
    SampleArray& values = this->SampleArrays[static_cast<size_t>(array)];
    return &values.Values[static_cast<size_t>(values.Components) * this->Index(row, column)];
  }
  /// A named per-point parameter, given per row and per column (value = row value or column value).
  void AddRowParameter(const std::string& name, const std::vector<double>& valuePerRow);
  void AddColumnParameter(const std::string& name, const std::vector<double>& valuePerColumn);

  /// Quads between point rows [firstRow, lastRow] (inclusive), with normals and texture coordinates.
  /// Both builds return how many of the points they write are outside the clip sphere
  /// (SetClipSphere; 0 without one).
  vtkIdType BuildSurface(
    vtkPolyData* output, int firstRow, int lastRow, int outputPointsPrecision) const;
  /// One polyline per row in [firstRow, lastRow], split where samples are unusable.
  vtkIdType BuildCurves(
    vtkPolyData* output, int firstRow, int lastRow, int outputPointsPrecision) const;

  /// vtkBoostedSphereClip's sphere: building counts the points outside it as it counts the points
  /// (vtkBoostedSphereClip's test on the doubles written, a point that is not finite outside), so
  /// that a caller whose points are all inside hands them on without the clip's own pass over
  /// them (a pass that reads every point back from memory: 9 % of an orbit update).
  void SetClipSphere(const double center[3], double radius);

  /// Curves only (BuildCurves): each row is a closed polyline, its last column joined to its
  /// first as with periodic columns, but without a repeated column (every column is distinct).
  /// Default off.
  void SetClosedRows(bool closedRows) { this->ClosedRows = closedRows; }

  /// Merge the seam, closed strips and poles (see the class description). Default off.
  void SetMergeSeam(bool mergeSeam) { this->MergeSeam = mergeSeam; }

  /// Splits the rows into consecutive blocks of `rowsPerBlock` rows, each its own strip: no quad
  /// and no normal difference crosses from one block to the next, and the texture coordinate v
  /// runs from 0 to 1 within each block. Default: one block of all rows.
  void SetRowsPerBlock(int rowsPerBlock);
  /// A named integer per-point parameter given per row (e.g. an id).
  void AddRowIntegerParameter(const std::string& name, const std::vector<int>& valuePerRow);
  /// The rows [firstRow, lastRow] of piece `piece` of `pieces`: for a surface whole rows of quads
  /// (neighbouring bands share their boundary row of points), otherwise whole rows of points.
  /// Returns false when the piece is empty: more pieces than rows, or a piece outside
  /// [0, pieces) (VTK's sources give an empty piece then; pieces < 1 counts as 1).
  static bool PieceRows(int rows, bool surface, int piece, int pieces, int& firstRow, int& lastRow);
  /// The most samples (rows x columns) a grid may hold: beyond it the builder's arrays and the
  /// output would need tens of gigabytes, and its int indices would overflow.
  static constexpr long long MaximumSamples = 100000000;
  /// An error message when rows x columns exceeds MaximumSamples (empty when it does not): the
  /// sources check it before building, so huge resolutions are an error rather than a crash.
  static std::string SizeProblem(long long rows, long long columns);

private:
  struct Parameter
  {
    std::string Name;
    bool PerRow;
    std::vector<double> Values;
  };

  struct SampleArray
  {
    std::string Name;
    int Components;
    double* Values; // Components x rows x columns: Memory's, or an output array's (AdoptedArrays)
    mutable vtkBoostedLargeArrays::Buffer<double> Memory; // empty once handed to an output
  };

  int Index(int row, int column) const { return row * this->Columns + column; }
  // Inline (not through the shared library's PLT): called several times for every sample.
  // Without branches, so that a loop counting usable samples stays branch-free.
  bool Usable(int row, int column) const
  {
    return Finite(&this->Points[3 * static_cast<size_t>(this->Index(row, column))]);
  }
  // Whether the three values are finite: x - x is 0 for a finite x and NaN for an infinite or
  // NaN one, so one comparison tests all three.
  static bool Finite(const double* p)
  {
    return (p[0] - p[0]) + (p[1] - p[1]) + (p[2] - p[2]) == 0.0;
  }
  // What SetPoint notes of a sample's point p (relative to Origin), and what building counts:
  // bit 0 usable, bit 1 inside the clip sphere (vtkBoostedSphereClip's test on origin + p).
  unsigned char State(const double* p) const
  {
    const bool inside = this->HasClipSphere &
      vtkBoostedSphereClip::Inside(this->Origin[0] + p[0], this->Origin[1] + p[1],
        this->Origin[2] + p[2], this->ClipCenter, this->ClipRadius2);
    return static_cast<unsigned char>(Finite(p) | (inside << 1));
  }
  /// The grid's normal at a sample from the differences of its usable neighbours (the row's
  /// fallback normal where they give none).
  void DifferenceNormal(int row, int column, double normal[3]) const;
  /// The normals of row `row`'s columns [firstColumn, lastColumn), at most NormalsPerRun of
  /// them, into normals (3 per column): a sample's given normal where finite (SetSampleNormal),
  /// DifferenceNormal's elsewhere, the inner samples many at a time.
  static constexpr int NormalsPerRun = 64;
  void ComputeNormals(int row, int firstColumn, int lastColumn, double* normals) const;
  /// Writes the usable points of rows [firstRow, lastRow] and returns the map grid index -> point
  /// id (-1: no point), defined for those rows' samples.
  /// `outside`: the points written outside the clip sphere (0 without one).
  /// `wholeRows` (when given; all -1 with MergeSeam's merged surfaces): for each of those rows
  /// the id of its first point where every sample of the row is a point of its own (the row's
  /// points are then consecutive and the map is not written for its samples), -1 elsewhere.
  vtkBoostedLargeArrays::Buffer<long long> WritePoints(vtkPolyData* output, int firstRow,
    int lastRow, int precision, bool withSurfaceAttributes, vtkIdType& outside,
    std::vector<vtkIdType>* wholeRows = nullptr) const;

  /// With MergeSeam: for each row of [firstRow, lastRow], the row whose points it reuses (itself
  /// when none), and whether the row is a pole (one point).
  void FindMergedRows(int firstRow, int lastRow, std::vector<int>& sameAs,
    std::vector<char>& pole) const;

  int Rows;
  int Columns;
  bool PeriodicColumns;
  bool ClosedRows = false;
  bool MergeSeam = false;
  // A zero origin is kept as -0, which adds nothing (+0 would turn -0 into +0): the copied
  // points are the samples' bits, as the handed-over ones (WritePoints).
  double Origin[3] = { -0.0, -0.0, -0.0 };
  bool HasClipSphere = false;
  double ClipCenter[3] = { 0.0, 0.0, 0.0 };
  double ClipRadius = 0.0;
  double ClipRadius2 = 0.0; // its square, for Inside
  // Rows x columns, what SetPoint noted of each sample: bit 0 usable, bit 1 inside the clip
  // sphere (0: unset). Counted instead of the points while StatesCurrent (BeginSampling).
  vtkBoostedLargeArrays::Buffer<unsigned char> States;
  bool SamplingBegun = false;
  bool StatesCurrent = false;
  // 3 x rows x columns, relative to Origin; NaN: not set. PointsMemory's, until a build hands
  // the memory to its output's points (WritePoints), then the output array's, which
  // AdoptedArrays keeps for the builder's later reads.
  double* Points = nullptr;
  mutable vtkBoostedLargeArrays::Buffer<double> PointsMemory;
  mutable std::vector<vtkSmartPointer<vtkDataArray>> AdoptedArrays;
  std::vector<double> FallbackNormals;
  // 3 x rows x columns when enabled; NaN: not given.
  vtkBoostedLargeArrays::Buffer<double> SampleNormals;
  std::vector<SampleArray> SampleArrays;
  std::vector<Parameter> Parameters;
  int RowsPerBlock = 0; // 0: one block of all rows
  std::vector<std::pair<std::string, std::vector<int>>> IntegerParameters;
  int BlockRows() const { return this->RowsPerBlock > 0 ? this->RowsPerBlock : this->Rows; }
  bool SameBlock(int rowA, int rowB) const
  {
    // One block (the default): no integer divisions in the per-sample normals.
    return this->RowsPerBlock <= 0 || rowA / this->BlockRows() == rowB / this->BlockRows();
  }
};

#endif
