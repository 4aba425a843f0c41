/**
 * @class   vtkBoostedPolylineRuns
 * @brief   splits a polyline into the runs of its vertices that are kept
 *
 * The one walker of the project's polylines: vtkBoostedGridBuilder splits its rows where samples
 * are unusable, vtkBoostedSphereClip splits polylines where they leave the clip sphere (and adds
 * the crossing points). A closed polyline (its last vertex repeats its first) that is partly
 * dropped is walked from its first dropped vertex, so that a kept arc is not split at the seam; a
 * closed polyline that is kept whole stays closed.
 */
#ifndef vtkBoostedPolylineRuns_h
#define vtkBoostedPolylineRuns_h

#include "vtkCellArray.h"
#include "vtkType.h"

#include <vector>

class vtkBoostedPolylineRuns
{
public:
  /// Appends to `lines` the runs of the polyline `vertices` (`count` handles, closed when the last
  /// equals the first, more than 2). `kept(v)`: whether vertex v is kept; `outputId(v)`: its point
  /// id in the output; `crossing(in, out)`: the id of the point that ends a run on the edge from
  /// the kept vertex `in` to the dropped `out`, or -1 for none. Runs of fewer than 2 points are
  /// left out.
  template <typename Kept, typename OutputId, typename Crossing>
  void Walk(const vtkIdType* vertices, vtkIdType count, Kept kept, OutputId outputId,
    Crossing crossing, vtkCellArray* lines)
  {
    this->Order.assign(vertices, vertices + count);
    if (count > 2 && vertices[0] == vertices[count - 1])
    {
      for (vtkIdType start = 0; start + 1 < count; ++start)
      {
        if (!kept(vertices[start]))
        {
          for (vtkIdType k = 0; k < count; ++k)
          {
            this->Order[k] = vertices[(start + k) % (count - 1)];
          }
          break;
        }
      }
    }
    this->Run.clear();
    for (size_t k = 0; k < this->Order.size(); ++k)
    {
      const vtkIdType v = this->Order[k];
      if (k > 0)
      {
        const vtkIdType previous = this->Order[k - 1];
        const bool previousKept = kept(previous);
        if (previousKept != kept(v))
        {
          const vtkIdType x = previousKept ? crossing(previous, v) : crossing(v, previous);
          if (x >= 0)
          {
            this->Push(x);
          }
          if (previousKept)
          {
            this->Flush(lines); // leaving the kept part
          }
        }
      }
      if (kept(v))
      {
        this->Push(outputId(v));
      }
    }
    this->Flush(lines);
  }

private:
  void Push(vtkIdType id)
  {
    if (this->Run.empty() || this->Run.back() != id)
    {
      this->Run.push_back(id);
    }
  }
  void Flush(vtkCellArray* lines)
  {
    if (this->Run.size() >= 2)
    {
      lines->InsertNextCell(static_cast<vtkIdType>(this->Run.size()), this->Run.data());
    }
    this->Run.clear();
  }

  std::vector<vtkIdType> Order, Run;
};

#endif
