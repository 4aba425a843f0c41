// NumberOfTimeSteps (vtkBoostedTimeSweep) on the grid sources: the time steps reported, and every
// frame equal, point for point and cell for cell, to the static output at the sweep's parameter
// (frame 0 the sweep's start, the last frame the current parameters, t = 0.5 half way).
#include "vtkBoostedSurfaceSource.h"
#include "vtkConformalOrbitSource.h"
#include "vtkCurvaturePatchSource.h"
#include "vtkHopfFibrationSource.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace
{
constexpr double kPi = 3.14159265358979323846;

// The same points (exactly) and the same cells.
void expectSameOutput(vtkPolyData* expected, vtkPolyData* actual, const std::string& what)
{
  ASSERT_GT(expected->GetNumberOfCells() + expected->GetNumberOfPoints(), 0) << what;
  ASSERT_EQ(actual->GetNumberOfPoints(), expected->GetNumberOfPoints()) << what;
  ASSERT_EQ(actual->GetNumberOfPolys(), expected->GetNumberOfPolys()) << what;
  ASSERT_EQ(actual->GetNumberOfLines(), expected->GetNumberOfLines()) << what;
  for (vtkIdType i = 0; i < expected->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    expected->GetPoint(i, p);
    actual->GetPoint(i, q);
    ASSERT_TRUE(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]) << what << ": point " << i;
  }
  vtkCellArray* cells[2][2] = { { expected->GetPolys(), actual->GetPolys() },
    { expected->GetLines(), actual->GetLines() } };
  for (auto& pair : cells)
  {
    ASSERT_EQ(pair[0]->GetConnectivityArray()->GetNumberOfValues(),
      pair[1]->GetConnectivityArray()->GetNumberOfValues()) << what;
    for (vtkIdType k = 0; k < pair[0]->GetConnectivityArray()->GetNumberOfValues(); ++k)
    {
      ASSERT_EQ(pair[0]->GetConnectivityArray()->GetComponent(k, 0),
        pair[1]->GetConnectivityArray()->GetComponent(k, 0)) << what;
    }
  }
}

// `setup` makes the static source; `atFraction(source, t)` changes a static source into the
// frame at sweep fraction t.
template <class Source>
void expectAnimation(const std::function<void(Source*)>& setup,
  const std::function<void(Source*, double)>& atFraction, const std::string& what)
{
  vtkNew<Source> timed;
  setup(timed);
  timed->UpdateInformation();
  vtkInformation* info = timed->GetOutputInformation(0);
  EXPECT_FALSE(info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS())) << what << ": off by default";

  timed->SetNumberOfTimeSteps(5);
  timed->UpdateInformation();
  info = timed->GetOutputInformation(0);
  ASSERT_TRUE(info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS())) << what;
  ASSERT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 5) << what;
  const double* times = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  for (int k = 0; k < 5; ++k)
  {
    EXPECT_DOUBLE_EQ(times[k], 0.25 * k) << what;
  }
  const double* range = info->Get(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  EXPECT_EQ(range[0], 0.0) << what;
  EXPECT_EQ(range[1], 1.0) << what;

  for (double t : { 0.0, 0.5, 1.0 })
  {
    timed->UpdateTimeStep(t);
    EXPECT_EQ(timed->GetOutput()->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP()), t)
      << what;
    vtkNew<Source> still;
    setup(still);
    atFraction(still, t);
    still->Update();
    expectSameOutput(still->GetOutput(), timed->GetOutput(), what + " at t = " + std::to_string(t));
  }
  // Outside [0, 1] the request is clamped: t = 2 is the static output.
  timed->UpdateTimeStep(2.0);
  vtkNew<Source> still;
  setup(still);
  still->Update();
  expectSameOutput(still->GetOutput(), timed->GetOutput(), what + " at t = 2");

  // Back to no time: the steps are gone and the output is the static one whatever is requested.
  timed->SetNumberOfTimeSteps(0);
  timed->UpdateInformation();
  EXPECT_FALSE(timed->GetOutputInformation(0)->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
    << what;
}
} // namespace

TEST(TimeSweeps, BoostedSurfaceGrowsLambdasUpperEnd)
{
  for (int type : { vtkBoostedSurfaceSource::SURFACE, vtkBoostedSurfaceSource::CIRCLES })
  {
    expectAnimation<vtkBoostedSurfaceSource>(
      [type](vtkBoostedSurfaceSource* s) {
        s->SetOutputType(type);
        s->SetLambdaRange(-0.5, 3.0);
        s->SetLambdaResolution(16);
        s->SetThetaResolution(24);
      },
      [](vtkBoostedSurfaceSource* s, double t) {
        s->SetLambdaRange(-0.5, -0.5 + t * 3.5);
      },
      "boosted surface, type " + std::to_string(type));
  }
}

TEST(TimeSweeps, HopfGrowsPhisUpperEndTheFiberStraightensIntoTheAxis)
{
  for (int type : { vtkHopfFibrationSource::FIBERS, vtkHopfFibrationSource::TWISTOR_MESH })
  {
    // Fig 4 d: one meridian from the circle C (phi = -pi/2) toward the axis line.
    expectAnimation<vtkHopfFibrationSource>(
      [type](vtkHopfFibrationSource* s) {
        s->SetOutputType(type);
        s->SetThetaRange(0.0, 0.0);
        s->SetThetaResolution(1);
        s->SetPhiRange(-kPi / 2, 1.25);
        s->SetPhiResolution(12);
        s->SetFiberResolution(32);
      },
      [](vtkHopfFibrationSource* s, double t) {
        s->SetPhiRange(-kPi / 2, (1.0 - t) * (-kPi / 2) + t * 1.25);
      },
      "hopf, type " + std::to_string(type));
  }
  // Base points have no sweep: every frame is the static output.
  expectAnimation<vtkHopfFibrationSource>(
    [](vtkHopfFibrationSource* s) {
      s->SetSamplingModeToBasePoints();
      s->AddBasePoint(0.5, 0.25);
      s->AddBasePoint(1.5, -0.75);
    },
    [](vtkHopfFibrationSource*, double) {}, "hopf base points");
}

TEST(TimeSweeps, CurvaturePatchScalesEveryCurvature)
{
  expectAnimation<vtkCurvaturePatchSource>(
    [](vtkCurvaturePatchSource* s) {
      s->SetKappaU(0.75);
      s->SetKappaV(-0.25);
      s->SetUResolution(12);
      s->SetVResolution(10);
    },
    [](vtkCurvaturePatchSource* s, double t) {
      s->SetKappaU(t * 0.75);
      s->SetKappaV(t * -0.25);
    },
    "translated tangents");
  expectAnimation<vtkCurvaturePatchSource>(
    [](vtkCurvaturePatchSource* s) { s->SetCurvaturePreset(vtkCurvaturePatchSource::HYPERBOLIC); },
    [](vtkCurvaturePatchSource* s, double t) {
      s->SetCurvaturePreset(vtkCurvaturePatchSource::CUSTOM);
      s->SetKappaU(t * -0.5);
      s->SetKappaV(t * 0.5);
    },
    "hyperbolic preset");
  expectAnimation<vtkCurvaturePatchSource>(
    [](vtkCurvaturePatchSource* s) {
      s->SetMethod(vtkCurvaturePatchSource::CONTROL_POINTS);
      s->AddControlPoint(1, 0, 0, 0, 0, 1, 1, 0, 0, 0.5, -0.5);
      s->AddControlPoint(-1, 1, 0, 0, 0.2, 1, 1, 0, 0, 0.25, 0.75);
    },
    [](vtkCurvaturePatchSource* s, double t) {
      s->SetControlPoint(0, 1, 0, 0, 0, 0, 1, 1, 0, 0, t * 0.5, t * -0.5);
      s->SetControlPoint(1, -1, 1, 0, 0, 0.2, 1, 1, 0, 0, t * 0.25, t * 0.75);
    },
    "control points");
  expectAnimation<vtkCurvaturePatchSource>(
    [](vtkCurvaturePatchSource* s) { s->SetMethod(vtkCurvaturePatchSource::BILINEAR); },
    [](vtkCurvaturePatchSource* s, double t) {
      s->SetCornerWeights(t * 0.5, t * -0.5, t * -0.5, t * 0.5);
    },
    "bilinear corners");
}

TEST(TimeSweeps, ConformalOrbitGrowsTsUpperEndAPeriodicOrbitClosesAtTheEnd)
{
  // The trefoil (period T): before the last frame the open arc over [0, s T], so the orbit is
  // closed only at s = 1 (t0 = 0: Interpolate(0, T, s) is s T exactly).
  expectAnimation<vtkConformalOrbitSource>(
    [](vtkConformalOrbitSource* s) { s->SetTResolution(64); },
    [](vtkConformalOrbitSource* s, double t) {
      if (t < 1.0)
      {
        vtkNew<vtkConformalOrbitSource> probe;
        probe->Update();
        const double period = probe->GetOutput()->GetFieldData()->GetArray("Period")->GetTuple1(0);
        s->SetClosePeriodicOrbits(false);
        s->SetTRange(0.0, t * period);
      }
    },
    "conformal orbit, torus knot");
  // A point pair (no period): TRange's upper end.
  expectAnimation<vtkConformalOrbitSource>(
    [](vtkConformalOrbitSource* s) {
      s->SetGeneratorTypeToGeneratorList();
      s->AddGenerator(0.5, 0, 0, 0, 0.3, 0.2, 0.7);
      s->SetSeedPoint(0.3, -0.4, 0.2);
      s->SetTRange(-0.5, 2.0);
      s->SetTResolution(32);
    },
    [](vtkConformalOrbitSource* s, double t) { s->SetTRange(-0.5, (1.0 - t) * -0.5 + t * 2.0); },
    "conformal orbit, generator list");
}
