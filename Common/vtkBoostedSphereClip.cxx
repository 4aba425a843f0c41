#include "vtkBoostedSphereClip.h"

#include "vtkBoostedBlockLoop.h"
#include "vtkBoostedCurvatureArrays.h"
#include "vtkBoostedPolylineRuns.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkIdList.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include "cga/SegmentSphere.h"
#include "cga/Vec3.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <memory>
#include <utility>
#include <vector>

void vtkBoostedSphereClip::Clip(
  vtkPolyData* input, const double center[3], double radius, vtkPolyData* output)
{
  const vtkIdType count = input->GetNumberOfPoints();
  vtkPoints* inPoints = input->GetPoints();
  const cga::Vec3 c{ center[0], center[1], center[2] };
  // The builders' points are doubles: read in place (GetPoint's virtual calls were a tenth of
  // an orbit update).
  vtkDoubleArray* doubles = inPoints ? vtkDoubleArray::FastDownCast(inPoints->GetData()) : nullptr;
  const double* values = doubles ? doubles->GetPointer(0) : nullptr;
  auto point = [inPoints, values](vtkIdType id) {
    if (values)
    {
      return cga::Vec3{ values[3 * id], values[3 * id + 1], values[3 * id + 2] };
    }
    double p[3];
    inPoints->GetPoint(id, p);
    return cga::Vec3{ p[0], p[1], p[2] };
  };
  // Written and counted on the threads (no serial pass over the points).
  std::unique_ptr<char[]> inside(new char[count]);
  std::atomic<vtkIdType> insideCount{ 0 };
  vtkBoostedBlockLoop::RunBlock(0, count, 1, [&](vtkIdType first, vtkIdType last) {
    vtkIdType chunkInside = 0;
    for (vtkIdType i = first; i < last; ++i)
    {
      const cga::Vec3 p = point(i);
      inside[i] = Inside(p.x, p.y, p.z, center, radius * radius);
      chunkInside += inside[i];
    }
    insideCount += chunkInside;
  });
  if (insideCount == count)
  {
    output->ShallowCopy(input); // nothing to cut
    return;
  }

  // The kept points first, in their order, with their point data.
  std::vector<vtkIdType> kept(count, -1);
  vtkNew<vtkIdList> from, to;
  from->Allocate(insideCount);
  to->Allocate(insideCount);
  for (vtkIdType i = 0; i < count; ++i)
  {
    if (inside[i])
    {
      kept[i] = to->GetNumberOfIds();
      from->InsertNextId(i);
      to->InsertNextId(kept[i]);
    }
  }
  vtkNew<vtkPoints> points;
  points->SetDataType(inPoints ? inPoints->GetDataType() : VTK_DOUBLE);
  points->Allocate(insideCount);
  if (insideCount > 0)
  {
    points->InsertPoints(to, from, inPoints);
  }
  vtkPointData* inPD = input->GetPointData();
  vtkPointData* outPD = output->GetPointData();
  outPD->InterpolateAllocate(inPD, count);
  outPD->CopyData(inPD, from, to);

  // The crossing on the edge from an inside to an outside point, made once per edge.
  std::map<std::pair<vtkIdType, vtkIdType>, vtkIdType> crossings;
  vtkDataArray* normals = outPD->GetNormals();
  auto crossing = [&](vtkIdType in, vtkIdType out) -> vtkIdType {
    const auto found = crossings.find({ in, out });
    if (found != crossings.end())
    {
      return found->second;
    }
    const cga::Vec3 a = point(in), b = point(out);
    vtkIdType id = kept[in];
    if (cga::isFinite(b))
    {
      const double s = cga::segmentSphereExit(a, b, c, radius);
      if (s > 0.0)
      {
        const cga::Vec3 p = cga::segmentSphereExitPoint(a, b, c, radius);
        id = points->InsertNextPoint(p.x, p.y, p.z);
        outPD->InterpolateEdge(inPD, id, in, out, s);
        if (normals && normals->GetNumberOfComponents() == 3)
        {
          double n[3];
          normals->GetTuple(id, n);
          if (vtkMath::Normalize(n) > 0.0)
          {
            normals->SetTuple(id, n);
          }
        }
        vtkBoostedCurvatureArrays::RenormalizeDirections(outPD, id);
      }
    }
    crossings.emplace(std::make_pair(in, out), id);
    return id;
  };
  // The edge a -> b: the crossing when exactly one end is inside, otherwise -1.
  auto edgeCrossing = [&](vtkIdType a, vtkIdType b) -> vtkIdType {
    if (inside[a] == inside[b])
    {
      return -1;
    }
    return inside[a] ? crossing(a, b) : crossing(b, a);
  };
  auto pushDistinct = [](std::vector<vtkIdType>& ids, vtkIdType id) {
    if (ids.empty() || ids.back() != id)
    {
      ids.push_back(id);
    }
  };

  vtkNew<vtkCellArray> lines;
  vtkBoostedPolylineRuns runs;
  vtkIdType npts;
  const vtkIdType* ids;
  vtkCellArray* inLines = input->GetLines();
  for (inLines->InitTraversal(); inLines->GetNextCell(npts, ids);)
  {
    runs.Walk(
      ids, npts, [&](vtkIdType v) { return inside[v] != 0; }, [&](vtkIdType v) { return kept[v]; },
      crossing, lines);
  }

  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> polygon;
  vtkCellArray* inPolys = input->GetPolys();
  for (inPolys->InitTraversal(); inPolys->GetNextCell(npts, ids);)
  {
    polygon.clear();
    for (vtkIdType k = 0; k < npts; ++k)
    {
      const vtkIdType a = ids[k], b = ids[(k + 1) % npts];
      if (inside[a])
      {
        pushDistinct(polygon, kept[a]);
      }
      const vtkIdType x = edgeCrossing(a, b);
      if (x >= 0)
      {
        pushDistinct(polygon, x);
      }
    }
    while (polygon.size() > 1 && polygon.front() == polygon.back())
    {
      polygon.pop_back();
    }
    if (polygon.size() >= 3)
    {
      polys->InsertNextCell(static_cast<vtkIdType>(polygon.size()), polygon.data());
    }
  }

  points->Squeeze();
  outPD->Squeeze();
  output->SetPoints(points);
  if (lines->GetNumberOfCells() > 0 || inLines->GetNumberOfCells() > 0)
  {
    output->SetLines(lines);
  }
  if (polys->GetNumberOfCells() > 0 || inPolys->GetNumberOfCells() > 0)
  {
    output->SetPolys(polys);
  }
}
