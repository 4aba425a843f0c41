// Translation covariance, shared by the sources' and the filter's GoogleTests: moving a whole
// configuration by t (its center, generators, control points, grid origin, input mesh) moves its
// output points by t and leaves its displacement arrays as they are.
//
// The bound. Every class computes relative to its construction's center c (c moves with t), so
// an output coordinate is the centered result plus c: on the way each input coordinate and each
// result is rounded a few times at size |t| (c subtracted, the result added back, a generator's
// relative location), each rounding at most eps |t| / 2, and the map carries an input error
// through its derivative D (the caller states a bound for it; of order one for the shapes, up to
// sum_i |w_i v_i| / eps for a field of generators). Together with the result's own rounding
// (eps S, S the size of the output) every coordinate is within
//   TranslationTolerance(t, S, D) = 64 eps (|t| + S) D
// of out(0) + t, 64 covering the handful of roundings. Computed in space
// instead, up(p) = no + p + |p|^2/2 ni holds |t|^2 and the error grows like eps |t|^2 (3e-4 for
// a unit shape at |t| = 1e4): beyond this bound from |t| = 1e2 on.
#ifndef TranslationChecks_h
#define TranslationChecks_h

#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

inline double TranslationTolerance(double t, double size, double derivative)
{
  return 64.0 * std::numeric_limits<double>::epsilon() * (t + size) * std::max(1.0, derivative);
}

// The largest |coordinate| of a data set's points, and of an array's values.
inline double LargestCoordinate(vtkDataSet* data)
{
  double largest = 0.0;
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    double p[3];
    data->GetPoint(i, p);
    largest = std::max({ largest, std::fabs(p[0]), std::fabs(p[1]), std::fabs(p[2]) });
  }
  return largest;
}

inline double LargestValue(vtkDataArray* array)
{
  double largest = 0.0;
  for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
  {
    largest = std::max(largest, std::fabs(array->GetVariantValue(i).ToDouble()));
  }
  return largest;
}

// build(t) updates the configuration moved by t and returns its output. At |t| = 1e2, 1e4 and
// 1e6 (along a fixed unit direction) the output equals build(0)'s, its points moved by t and the
// named point arrays unchanged, within TranslationTolerance (the largest error is reported), and
// every coordinate and value of both is finite.
// A copy of `mesh` with every point moved by t (in double).
inline vtkSmartPointer<vtkPolyData> TranslatedCopy(vtkPolyData* mesh, const double t[3])
{
  auto moved = vtkSmartPointer<vtkPolyData>::New();
  moved->DeepCopy(mesh);
  for (vtkIdType i = 0; i < moved->GetNumberOfPoints(); ++i)
  {
    double p[3];
    moved->GetPoint(i, p);
    moved->GetPoints()->SetPoint(i, p[0] + t[0], p[1] + t[1], p[2] + t[2]);
  }
  return moved;
}

inline void ExpectTranslationCovariant(
  const std::function<vtkSmartPointer<vtkDataSet>(const double t[3])>& build,
  const std::vector<std::string>& invariantArrays = {}, double derivative = 1.0)
{
  const double zero[3] = { 0.0, 0.0, 0.0 };
  const vtkSmartPointer<vtkDataSet> original = build(zero);
  ASSERT_GT(original->GetNumberOfPoints(), 0);
  const double size = LargestCoordinate(original);
  for (const double length : { 1e2, 1e4, 1e6 })
  {
    const double t[3] = { 0.6 * length, -0.48 * length, 0.64 * length }; // |t| = length
    const vtkSmartPointer<vtkDataSet> moved = build(t);
    ASSERT_EQ(moved->GetNumberOfPoints(), original->GetNumberOfPoints()) << "|t| = " << length;
    ASSERT_EQ(moved->GetNumberOfCells(), original->GetNumberOfCells()) << "|t| = " << length;
    // std::max drops a NaN difference: the non-finite coordinates are counted as well, so that a
    // NaN or infinite output fails instead of vanishing from the largest error.
    double worst = 0.0;
    vtkIdType nonFinite = 0;
    for (vtkIdType i = 0; i < original->GetNumberOfPoints(); ++i)
    {
      double p[3], q[3];
      original->GetPoint(i, p);
      moved->GetPoint(i, q);
      for (int c = 0; c < 3; ++c)
      {
        nonFinite += std::isfinite(p[c]) && std::isfinite(q[c]) ? 0 : 1;
        worst = std::max(worst, std::fabs(q[c] - t[c] - p[c]));
      }
    }
    EXPECT_EQ(nonFinite, 0) << "non-finite point coordinates at |t| = 0 or " << length;
    EXPECT_LE(worst, TranslationTolerance(length, size, derivative))
      << "points at |t| = " << length << " (shape size " << size << ")";
    for (const std::string& name : invariantArrays)
    {
      vtkDataArray* a = original->GetPointData()->GetArray(name.c_str());
      vtkDataArray* b = moved->GetPointData()->GetArray(name.c_str());
      ASSERT_TRUE(a && b) << name;
      ASSERT_EQ(a->GetNumberOfValues(), b->GetNumberOfValues()) << name;
      double worstValue = 0.0;
      vtkIdType nonFiniteValues = 0;
      for (vtkIdType i = 0; i < a->GetNumberOfValues(); ++i)
      {
        const double before = a->GetVariantValue(i).ToDouble();
        const double after = b->GetVariantValue(i).ToDouble();
        nonFiniteValues += std::isfinite(before) && std::isfinite(after) ? 0 : 1;
        worstValue = std::max(worstValue, std::fabs(before - after));
      }
      EXPECT_EQ(nonFiniteValues, 0) << name << " non-finite at |t| = 0 or " << length;
      EXPECT_LE(worstValue, TranslationTolerance(length, size + LargestValue(a), derivative))
        << name << " at |t| = " << length;
    }
  }
}

#endif
