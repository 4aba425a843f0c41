// ComputeCurvatures of the two grid sources through their VTK paths (the grid builder's sample
// arrays, the clip's interpolation, merged seams, pieces), in C++ so that the sanitizer build
// runs them: every value finite, directions unit (or zero at degenerate samples), the boosted
// surface's horn torus and Fig 7's elliptic preset at their closed forms (the full closed-form
// checks are in Python.BoostedSurfaceCurvatures and Python.CurvaturePatchCurvatures).
#include "vtkBoostedSurfaceSource.h"
#include "vtkCurvaturePatchSource.h"

#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
const char* const kArrays[] = { "PrincipalCurvatures", "PrincipalDirections", "GaussianCurvature",
  "MeanCurvature" };

// Every array present, finite, directions unit or both zero; returns the number of points.
vtkIdType expectWellFormed(vtkPolyData* output)
{
  vtkPointData* data = output->GetPointData();
  for (const char* name : kArrays)
  {
    vtkDataArray* array = data->GetArray(name);
    EXPECT_NE(array, nullptr) << name;
    if (!array)
    {
      return 0;
    }
    for (vtkIdType i = 0; i < array->GetNumberOfValues(); ++i)
    {
      EXPECT_TRUE(std::isfinite(array->GetComponent(i / array->GetNumberOfComponents(),
        static_cast<int>(i % array->GetNumberOfComponents()))))
        << name;
    }
  }
  vtkDataArray* directions = data->GetArray("PrincipalDirections");
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double d[6];
    directions->GetTuple(i, d);
    const double n1 = vtkMath::Norm(d), n2 = vtkMath::Norm(d + 3);
    EXPECT_TRUE((std::abs(n1 - 1.0) < 1e-9 && std::abs(n2 - 1.0) < 1e-9) || (n1 == 0 && n2 == 0))
      << i << " " << n1 << " " << n2;
  }
  return output->GetNumberOfPoints();
}

// The boosted circle boosted along its axis at its center: the horn torus r = radius / 2 about
// the axis (x) through the center (the origin). K at a point p: cos v / (r rho), rho its
// distance from the axis, cos v = (rho - r) / r.
double hornTorusGaussian(const double p[3], double r)
{
  const double rho = std::hypot(p[1], p[2]);
  return (rho - r) / r / (r * rho);
}

TEST(SourceCurvatures, BoostedSurfaceArraysThroughClipMergedSeamAndPieces)
{
  for (const bool merge : { false, true })
  {
    for (const int pieces : { 1, 2 })
    {
      for (int piece = 0; piece < pieces; ++piece)
      {
        vtkNew<vtkBoostedSurfaceSource> source;
        source->SetLambdaRange(-3.0, 3.0);
        source->SetClipRadius(0.9); // the horn torus reaches 1 from the center: cut
        source->SetMergeSeam(merge);
        source->ComputeCurvaturesOn();
        source->UpdatePiece(piece, pieces, 0);
        vtkPolyData* output = source->GetOutput();
        ASSERT_GT(expectWellFormed(output), 100);
        vtkDataArray* gaussian = output->GetPointData()->GetArray("GaussianCurvature");
        int kept = 0, cut = 0;
        for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
        {
          double p[3];
          output->GetPoint(i, p);
          if (std::abs(vtkMath::Norm(p) - 0.9) < 1e-9)
          {
            ++cut; // interpolated along its edge: second-order close
            EXPECT_NEAR(gaussian->GetTuple1(i), hornTorusGaussian(p, 0.5), 0.1);
            continue;
          }
          ++kept;
          EXPECT_NEAR(gaussian->GetTuple1(i), hornTorusGaussian(p, 0.5), 1e-9);
        }
        EXPECT_GT(kept, 0);
        EXPECT_GT(cut, 0);
      }
    }
  }
}

TEST(SourceCurvatures, CurvaturePatchArraysThroughClipAndPieces)
{
  for (const int pieces : { 1, 2 })
  {
    for (int piece = 0; piece < pieces; ++piece)
    {
      vtkNew<vtkCurvaturePatchSource> source;
      source->SetCurvaturePreset(vtkCurvaturePatchSource::ELLIPTIC);
      source->SetClipRadius(1.5);
      source->ComputeCurvaturesOn();
      source->UpdatePiece(piece, pieces, 0);
      vtkPolyData* output = source->GetOutput();
      ASSERT_GT(expectWellFormed(output), 100);
      vtkDataArray* u = output->GetPointData()->GetArray("u");
      vtkDataArray* v = output->GetPointData()->GetArray("v");
      for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
      {
        if (u->GetTuple1(i) == 0.0 && v->GetTuple1(i) == 0.0) // Fig 7 b's origin
        {
          double k[2];
          output->GetPointData()->GetArray("PrincipalCurvatures")->GetTuple(i, k);
          EXPECT_NEAR(k[0], 0.5, 1e-9);
          EXPECT_NEAR(k[1], 0.25, 1e-9);
        }
      }
    }
  }
}

TEST(SourceCurvatures, DegenerateSamplesHaveZerosAndUnitNormals)
{
  // A boost located on the circle fixes that point: x_lambda = 0 there.
  vtkNew<vtkBoostedSurfaceSource> probe;
  probe->SetLambdaRange(0.0, 0.0);
  probe->SetOutputTypeToCircles();
  probe->Update();
  double fixed[3];
  probe->GetOutput()->GetPoint(0, fixed); // theta = 0
  vtkNew<vtkBoostedSurfaceSource> source;
  source->BoostAtCircleCenterOff();
  source->SetBoostLocation(fixed);
  source->ComputeCurvaturesOn();
  source->Update();
  vtkPolyData* output = source->GetOutput();
  expectWellFormed(output);
  int degenerate = 0;
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double p[3], n[3], k[2];
    output->GetPoint(i, p);
    output->GetPointData()->GetNormals()->GetTuple(i, n);
    EXPECT_NEAR(vtkMath::Norm(n), 1.0, 1e-6);
    if (std::sqrt(vtkMath::Distance2BetweenPoints(p, fixed)) < 1e-12)
    {
      ++degenerate;
      output->GetPointData()->GetArray("PrincipalCurvatures")->GetTuple(i, k);
      EXPECT_EQ(k[0], 0.0);
      EXPECT_EQ(k[1], 0.0);
    }
  }
  EXPECT_EQ(degenerate, 2 * 65);
}
} // namespace
