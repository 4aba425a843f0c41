// MergeSeam (vtkBoostedGridBuilder): closed surfaces come out closed and manifold, open ones keep
// exactly their true boundary, pieces stay a partition, and STL / OBJ / PLY round trips keep the
// point and cell counts. Edges are counted here from the cells (an edge used once is a boundary
// edge, more than twice a non-manifold one), independently of the builder; vtkFeatureEdges, what
// a user would run, is checked against the same counts.
#include "vtkBoostedGridBuilder.h"
#include "vtkBoostedSurfaceSource.h"
#include "vtkHopfFibrationSource.h"

#include "vtkAppendPolyData.h"
#include "vtkCellArray.h"
#include "vtkCleanPolyData.h"
#include "vtkFeatureEdges.h"
#include "vtkNew.h"
#include "vtkOBJReader.h"
#include "vtkOBJWriter.h"
#include "vtkPLYReader.h"
#include "vtkPLYWriter.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSTLReader.h"
#include "vtkSTLWriter.h"
#include "vtkTriangleFilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <utility>

namespace
{
constexpr double kPi = 3.14159265358979323846;

struct EdgeCounts
{
  long long edges = 0, boundary = 0, nonManifold = 0;
};

EdgeCounts countEdges(vtkPolyData* mesh)
{
  std::map<std::pair<vtkIdType, vtkIdType>, int> uses;
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType npts;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    for (vtkIdType k = 0; k < npts; ++k)
    {
      vtkIdType a = ids[k], b = ids[(k + 1) % npts];
      EXPECT_NE(a, b) << "a cell uses a point twice in a row";
      ++uses[{ std::min(a, b), std::max(a, b) }];
    }
  }
  EdgeCounts counts;
  for (const auto& use : uses)
  {
    ++counts.edges;
    counts.boundary += use.second == 1;
    counts.nonManifold += use.second > 2;
  }
  return counts;
}

// vtkFeatureEdges with boundary (or non-manifold) edges only.
vtkIdType featureEdges(vtkPolyData* mesh, bool boundary)
{
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(mesh);
  edges->SetBoundaryEdges(boundary);
  edges->SetNonManifoldEdges(!boundary);
  edges->SetFeatureEdges(false);
  edges->SetManifoldEdges(false);
  edges->Update();
  return edges->GetOutput()->GetNumberOfLines();
}

// Euler characteristic V - E + F of the cells' points (unused points do not count).
long long euler(vtkPolyData* mesh)
{
  vtkNew<vtkCleanPolyData> clean; // drops unused points only: no tolerance merging
  clean->SetInputData(mesh);
  clean->PointMergingOff();
  clean->Update();
  return clean->GetOutput()->GetNumberOfPoints() - countEdges(clean->GetOutput()).edges +
    clean->GetOutput()->GetNumberOfPolys();
}

// A torus of Latitudes strips: every phi sample's fibers over a full turn of theta.
void setHopfTori(vtkHopfFibrationSource* source, int mode)
{
  source->SetMode(mode);
  source->SetOutputTypeToTwistorMesh();
  source->SetMeshSweepToLatitudes();
  source->SetThetaResolution(24);
  source->SetPhiRange(-1.2, 0.9);
  source->SetPhiResolution(3);
  source->SetFiberResolution(32);
  source->SetClipRadius(1e6); // nothing is cut
  source->MergeSeamOn();
}

std::string temporaryFile(const std::string& name)
{
  return std::string(BOOSTEDSURFACES_TEST_OUTPUT_DIR) + "/MergedSeams_" + name;
}
} // namespace

TEST(MergedSeams, BoostedSurfaceKeepsOnlyItsTwoEndCircles)
{
  vtkNew<vtkBoostedSurfaceSource> repeated; // Fig 2, 64 x 64: the 256 boundary edges
  repeated->Update();
  EdgeCounts counts = countEdges(repeated->GetOutput());
  EXPECT_EQ(counts.boundary, 2 * 64 + 2 * 64); // the end circles and both sides of the seam
  EXPECT_EQ(featureEdges(repeated->GetOutput(), true), counts.boundary);
  EXPECT_NE(repeated->GetOutput()->GetPointData()->GetTCoords(), nullptr);

  vtkNew<vtkBoostedSurfaceSource> merged;
  merged->MergeSeamOn();
  merged->Update();
  vtkPolyData* output = merged->GetOutput();
  EXPECT_EQ(output->GetNumberOfPoints(), 65 * 64);
  EXPECT_EQ(output->GetNumberOfPolys(), 64 * 64);
  counts = countEdges(output);
  EXPECT_EQ(counts.boundary, 2 * 64); // only the circles at lambda 0 and 2: an open tube
  EXPECT_EQ(counts.nonManifold, 0);
  EXPECT_EQ(featureEdges(output, true), 2 * 64);
  EXPECT_EQ(featureEdges(output, false), 0);
  EXPECT_EQ(euler(output), 0); // an annulus
  EXPECT_EQ(output->GetPointData()->GetTCoords(), nullptr); // documented: one u for two
  ASSERT_NE(output->GetPointData()->GetNormals(), nullptr);
  ASSERT_NE(output->GetPointData()->GetArray("theta"), nullptr);

  // The merged points are the repeated output's without its seam column, in the same order.
  vtkPolyData* all = repeated->GetOutput();
  for (vtkIdType r = 0, i = 0; r < 65; ++r)
  {
    for (vtkIdType c = 0; c < 64; ++c, ++i)
    {
      double p[3], q[3];
      all->GetPoint(r * 65 + c, p);
      output->GetPoint(i, q);
      ASSERT_EQ(p[0], q[0]);
      ASSERT_EQ(p[1], q[1]);
      ASSERT_EQ(p[2], q[2]);
    }
  }

  // Circles have no seam to merge: the option changes nothing there.
  repeated->SetOutputTypeToCircles();
  merged->SetOutputTypeToCircles();
  repeated->Update();
  merged->Update();
  EXPECT_EQ(merged->GetOutput()->GetNumberOfPoints(), repeated->GetOutput()->GetNumberOfPoints());
  EXPECT_EQ(merged->GetOutput()->GetNumberOfLines(), repeated->GetOutput()->GetNumberOfLines());
}

TEST(MergedSeams, ABoostedSurfaceWhoseEndCirclesShrinkToPointsIsClosed)
{
  // Fig 2 boosted far both ways: the circles shrink to radius ~1/lambda^2, below the merge
  // tolerance (1e-9 of the size) at |lambda| = 1e5, so both ends are poles: a closed surface of a
  // sphere's topology, with triangles at its poles.
  vtkNew<vtkBoostedSurfaceSource> source;
  source->SetLambdaRange(-1e5, 1e5);
  source->SetLambdaResolution(64);
  source->SetThetaResolution(32);
  source->Update();
  EXPECT_EQ(countEdges(source->GetOutput()).boundary, 2 * 32 + 2 * 64);
  source->MergeSeamOn();
  source->Update();
  vtkPolyData* output = source->GetOutput();
  const EdgeCounts counts = countEdges(output);
  EXPECT_EQ(counts.boundary, 0);
  EXPECT_EQ(counts.nonManifold, 0);
  EXPECT_EQ(euler(output), 2);
  vtkNew<vtkCleanPolyData> clean; // every point is used by a cell
  clean->SetInputData(output);
  clean->PointMergingOff();
  clean->Update();
  EXPECT_EQ(clean->GetOutput()->GetNumberOfPoints(), output->GetNumberOfPoints());
  vtkIdType triangles = 0;
  vtkCellArray* polys = output->GetPolys();
  vtkIdType npts;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    triangles += npts == 3;
  }
  EXPECT_EQ(triangles, 2 * 32);
}

TEST(MergedSeams, PolesCollapseToOnePointWithTriangles)
{
  // A unit sphere sampled by latitude rows (both poles) and periodic longitude columns: closed,
  // manifold, a sphere's Euler characteristic, one point and a fan of triangles at each pole.
  const int rows = 9, columns = 17; // 16 longitudes and the seam column
  vtkBoostedGridBuilder grid(rows, columns, true);
  for (int r = 0; r < rows; ++r)
  {
    const double phi = -kPi / 2 + kPi * r / (rows - 1);
    for (int c = 0; c < columns; ++c)
    {
      const double theta = 2 * kPi * (c % (columns - 1)) / (columns - 1);
      double p[3] = { std::cos(phi) * std::cos(theta), std::cos(phi) * std::sin(theta),
        std::sin(phi) };
      if (r == 0 || r == rows - 1)
      {
        p[0] = p[1] = 0.0; // the poles exactly
      }
      grid.SetPoint(r, c, p);
    }
  }
  vtkNew<vtkPolyData> repeated;
  grid.BuildSurface(repeated, 0, rows - 1, 1);
  EXPECT_GT(countEdges(repeated).boundary, 0);

  grid.SetMergeSeam(true);
  vtkNew<vtkPolyData> merged;
  grid.BuildSurface(merged, 0, rows - 1, 1);
  EXPECT_EQ(merged->GetNumberOfPoints(), 2 + (rows - 2) * 16);
  const EdgeCounts counts = countEdges(merged);
  EXPECT_EQ(counts.boundary, 0);
  EXPECT_EQ(counts.nonManifold, 0);
  EXPECT_EQ(euler(merged), 2);
  int triangles = 0, quads = 0;
  vtkCellArray* polys = merged->GetPolys();
  vtkIdType npts;
  const vtkIdType* ids;
  for (polys->InitTraversal(); polys->GetNextCell(npts, ids);)
  {
    triangles += npts == 3;
    quads += npts == 4;
  }
  EXPECT_EQ(triangles, 2 * 16);
  EXPECT_EQ(quads, (rows - 3) * 16);
}

TEST(MergedSeams, HopfLatitudeToriAreClosedAndManifold)
{
  for (int mode : { vtkHopfFibrationSource::PAPER, vtkHopfFibrationSource::CLASSICAL })
  {
    vtkNew<vtkHopfFibrationSource> source;
    setHopfTori(source, mode);
    source->Update();
    vtkPolyData* output = source->GetOutput();
    // Three tori of 24 fibers of 32 points, each with 24 x 32 quads.
    EXPECT_EQ(output->GetNumberOfPoints(), 3 * 24 * 32) << "mode " << mode;
    EXPECT_EQ(output->GetNumberOfPolys(), 3 * 24 * 32) << "mode " << mode;
    const EdgeCounts counts = countEdges(output);
    EXPECT_EQ(counts.boundary, 0) << "mode " << mode;
    EXPECT_EQ(counts.nonManifold, 0) << "mode " << mode;
    EXPECT_EQ(featureEdges(output, true), 0) << "mode " << mode;
    EXPECT_EQ(featureEdges(output, false), 0) << "mode " << mode;
    EXPECT_EQ(euler(output), 0) << "mode " << mode; // tori

    // Without merging: every fiber's seam and every strip's closing fiber are open.
    source->MergeSeamOff();
    source->Update();
    EXPECT_EQ(countEdges(source->GetOutput()).boundary, 3 * (2 * 24 + 2 * 32)) << "mode " << mode;
  }
}

TEST(MergedSeams, APaperLatitudeStripAtThePoleHasNoCells)
{
  // At phi = -pi/2 every fiber is the circle C itself (Paper: the same points): that strip has no
  // area, so merged it has no cells (and its points, used by none, are dropped); the tori beside
  // it stay closed.
  vtkNew<vtkHopfFibrationSource> source;
  setHopfTori(source, vtkHopfFibrationSource::PAPER);
  source->SetPhiRange(-kPi / 2, 0.9);
  source->Update();
  vtkPolyData* output = source->GetOutput();
  EXPECT_EQ(output->GetNumberOfPolys(), 2 * 24 * 32);
  EXPECT_EQ(output->GetNumberOfPoints(), 2 * 24 * 32);
  const EdgeCounts counts = countEdges(output);
  EXPECT_EQ(counts.boundary, 0);
  EXPECT_EQ(counts.nonManifold, 0);
}

TEST(MergedSeams, PiecesStayAPartitionAndTheirUnionIsTheWhole)
{
  vtkNew<vtkHopfFibrationSource> whole;
  setHopfTori(whole, vtkHopfFibrationSource::PAPER);
  whole->Update();
  const vtkIdType wholeCells = whole->GetOutput()->GetNumberOfPolys();
  const vtkIdType wholePoints = whole->GetOutput()->GetNumberOfPoints();
  for (int pieces : { 2, 3, 7, 100 })
  {
    vtkNew<vtkAppendPolyData> append;
    vtkIdType cells = 0;
    for (int piece = 0; piece < pieces; ++piece)
    {
      vtkNew<vtkHopfFibrationSource> part;
      setHopfTori(part, vtkHopfFibrationSource::PAPER);
      part->UpdatePiece(piece, pieces, 0);
      vtkNew<vtkPolyData> copy;
      copy->DeepCopy(part->GetOutput());
      EXPECT_EQ(countEdges(copy).nonManifold, 0) << piece << " of " << pieces;
      cells += copy->GetNumberOfPolys();
      append->AddInputData(copy);
    }
    EXPECT_EQ(cells, wholeCells) << pieces << " pieces"; // cells are never repeated
    // Pieces repeat the rows they share (a piece boundary is not a seam), and a strip's closing
    // fiber on another piece than its first one keeps its points (theta0 + 2 pi: equal to
    // round-off, not bit for bit): merging points within the builder's 1e-9 gives back the whole
    // merged mesh, closed.
    vtkNew<vtkCleanPolyData> clean;
    clean->SetInputConnection(append->GetOutputPort());
    clean->ToleranceIsAbsoluteOn();
    clean->SetAbsoluteTolerance(1e-9);
    clean->Update();
    EXPECT_EQ(clean->GetOutput()->GetNumberOfPoints(), wholePoints) << pieces << " pieces";
    EXPECT_EQ(clean->GetOutput()->GetNumberOfPolys(), wholeCells) << pieces << " pieces";
    EXPECT_EQ(countEdges(clean->GetOutput()).boundary, 0) << pieces << " pieces";
  }

  vtkNew<vtkBoostedSurfaceSource> surface;
  surface->MergeSeamOn();
  surface->SetLambdaResolution(13);
  surface->Update();
  for (int pieces : { 2, 5, 20 })
  {
    vtkIdType cells = 0;
    for (int piece = 0; piece < pieces; ++piece)
    {
      vtkNew<vtkBoostedSurfaceSource> part;
      part->MergeSeamOn();
      part->SetLambdaResolution(13);
      part->UpdatePiece(piece, pieces, 0);
      cells += part->GetOutput()->GetNumberOfPolys();
      EXPECT_EQ(countEdges(part->GetOutput()).boundary,
        part->GetOutput()->GetNumberOfPolys() > 0 ? 2 * 64 : 0); // each band: a tube
    }
    EXPECT_EQ(cells, surface->GetOutput()->GetNumberOfPolys()) << pieces << " pieces";
  }
}

TEST(MergedSeams, StlObjAndPlyRoundTripsKeepThePointsAndCells)
{
  vtkNew<vtkHopfFibrationSource> tori;
  setHopfTori(tori, vtkHopfFibrationSource::CLASSICAL);
  vtkNew<vtkBoostedSurfaceSource> tube;
  tube->MergeSeamOn();
  tube->SetThetaResolution(40);
  tube->SetLambdaResolution(20);
  vtkNew<vtkBoostedSurfaceSource> closed; // poles and triangles
  closed->MergeSeamOn();
  closed->SetLambdaRange(-1e5, 1e5);
  closed->SetThetaResolution(24);
  vtkPolyDataAlgorithm* sources[] = { tori, tube, closed };
  for (vtkPolyDataAlgorithm* source : sources)
  {
    source->Update();
    vtkPolyData* mesh = source->GetOutput();
    const std::string name = source->GetClassName() + std::to_string(mesh->GetNumberOfPoints());
    const EdgeCounts edges = countEdges(mesh);

    // PLY and OBJ keep indexed faces: the same points and the same quads.
    auto roundTrip = [&](auto* writer, auto* reader, const std::string& file) {
      writer->SetInputData(mesh);
      writer->SetFileName(temporaryFile(file).c_str());
      ASSERT_EQ(writer->Write(), 1) << file;
      reader->SetFileName(temporaryFile(file).c_str());
      reader->Update();
      vtkPolyData* read = reader->GetOutput();
      EXPECT_EQ(read->GetNumberOfPoints(), mesh->GetNumberOfPoints()) << file;
      EXPECT_EQ(read->GetNumberOfPolys(), mesh->GetNumberOfPolys()) << file;
      EXPECT_EQ(countEdges(read).boundary, edges.boundary) << file;
      std::remove(temporaryFile(file).c_str());
    };
    vtkNew<vtkPLYWriter> plyWriter;
    plyWriter->SetFileTypeToBinary();
    vtkNew<vtkPLYReader> plyReader;
    roundTrip(plyWriter.Get(), plyReader.Get(), name + ".ply");
    vtkNew<vtkOBJWriter> objWriter;
    vtkNew<vtkOBJReader> objReader;
    roundTrip(objWriter.Get(), objReader.Get(), name + ".obj");

    if (source == closed.Get())
    {
      continue; // STL stores floats: its rings of radius ~1e-9 next to the poles fold together
    }
    // STL stores unconnected triangles; its reader merges equal points back. The quads become
    // two triangles each, and the points are the mesh's (none lost, none repeated) only because
    // the seam is merged: with a repeated seam the reader would fold it into fewer points.
    vtkNew<vtkTriangleFilter> triangles;
    triangles->SetInputData(mesh);
    triangles->Update();
    vtkNew<vtkSTLWriter> stlWriter;
    stlWriter->SetInputData(mesh);
    stlWriter->SetFileName(temporaryFile(name + ".stl").c_str());
    stlWriter->SetFileTypeToBinary();
    ASSERT_EQ(stlWriter->Write(), 1);
    vtkNew<vtkSTLReader> stlReader;
    stlReader->SetFileName(temporaryFile(name + ".stl").c_str());
    stlReader->Update(); // merging on by default
    EXPECT_EQ(stlReader->GetOutput()->GetNumberOfPoints(), mesh->GetNumberOfPoints()) << name;
    EXPECT_EQ(stlReader->GetOutput()->GetNumberOfPolys(),
      triangles->GetOutput()->GetNumberOfPolys()) << name;
    EXPECT_EQ(countEdges(stlReader->GetOutput()).boundary, edges.boundary) << name;
    EXPECT_EQ(countEdges(stlReader->GetOutput()).nonManifold, 0) << name;
    std::remove(temporaryFile(name + ".stl").c_str());
  }
}
