// Every source gives the same output, bit for bit, whatever vtkSMPTools runs it on: the Sequential
// backend, and the STDThread backend with one and with two threads. Each sample writes only its
// own slot and each output row its own range (vtkBoostedBlockLoop, vtkBoostedGridBuilder), so
// neither the blocks nor the threads may change a point, a value or a cell. The sizes span several
// blocks of vtkBoostedBlockLoop::SamplesPerBlock samples, and the grid sources cut some cells at
// their clip sphere.
#include "vtkBoostedSurfaceSource.h"
#include "vtkCellArray.h"
#include "vtkConformalOrbitSource.h"
#include "vtkCurvaturePatchSource.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkDipoleFieldSource.h"
#include "vtkCellData.h"
#include "vtkFieldData.h"
#include "vtkHopfFibrationSource.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cstring>
#include <functional>
#include <string>

namespace
{
// The bits of two doubles (NaN equal to the same NaN, -0 unequal to +0).
bool sameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

void expectSameArray(vtkDataArray* expected, vtkDataArray* actual, const std::string& what)
{
  ASSERT_NE(actual, nullptr) << what << ": missing";
  ASSERT_EQ(expected->GetDataType(), actual->GetDataType()) << what;
  ASSERT_EQ(expected->GetNumberOfComponents(), actual->GetNumberOfComponents()) << what;
  ASSERT_EQ(expected->GetNumberOfTuples(), actual->GetNumberOfTuples()) << what;
  const int components = expected->GetNumberOfComponents();
  for (vtkIdType i = 0; i < expected->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < components; ++c)
    {
      ASSERT_TRUE(sameBits(expected->GetComponent(i, c), actual->GetComponent(i, c)))
        << what << ": tuple " << i << " component " << c << ": " << expected->GetComponent(i, c)
        << " != " << actual->GetComponent(i, c);
    }
  }
}

void expectSameArrays(vtkFieldData* expected, vtkFieldData* actual, const std::string& what)
{
  ASSERT_EQ(expected->GetNumberOfArrays(), actual->GetNumberOfArrays()) << what;
  for (int a = 0; a < expected->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = expected->GetArray(a);
    ASSERT_NE(array, nullptr) << what << ": array " << a << " is not a data array";
    expectSameArray(array, actual->GetArray(array->GetName()), what + " " + array->GetName());
  }
}

void expectSameCells(vtkCellArray* expected, vtkCellArray* actual, const std::string& what)
{
  ASSERT_EQ(expected->GetNumberOfCells(), actual->GetNumberOfCells()) << what;
  expectSameArray(expected->GetOffsetsArray(), actual->GetOffsetsArray(), what + " offsets");
  expectSameArray(
    expected->GetConnectivityArray(), actual->GetConnectivityArray(), what + " connectivity");
}

// Points, point, cell and field data, and (poly data) every cell, to the bit.
void expectIdentical(vtkDataSet* expected, vtkDataSet* actual, const std::string& what)
{
  ASSERT_GT(expected->GetNumberOfPoints(), vtkIdType(65536)) << what << ": the case is too small";
  ASSERT_EQ(expected->GetNumberOfPoints(), actual->GetNumberOfPoints()) << what;
  ASSERT_EQ(expected->GetNumberOfCells(), actual->GetNumberOfCells()) << what;
  for (vtkIdType i = 0; i < expected->GetNumberOfPoints(); ++i)
  {
    double p[3], q[3];
    expected->GetPoint(i, p);
    actual->GetPoint(i, q);
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_TRUE(sameBits(p[c], q[c])) << what << ": point " << i << " coordinate " << c;
    }
  }
  expectSameArrays(expected->GetPointData(), actual->GetPointData(), what + ": point data");
  expectSameArrays(expected->GetCellData(), actual->GetCellData(), what + ": cell data");
  expectSameArrays(expected->GetFieldData(), actual->GetFieldData(), what + ": field data");
  auto* polyExpected = vtkPolyData::SafeDownCast(expected);
  auto* polyActual = vtkPolyData::SafeDownCast(actual);
  if (polyExpected)
  {
    ASSERT_NE(polyActual, nullptr) << what;
    expectSameCells(polyExpected->GetVerts(), polyActual->GetVerts(), what + ": verts");
    expectSameCells(polyExpected->GetLines(), polyActual->GetLines(), what + ": lines");
    expectSameCells(polyExpected->GetPolys(), polyActual->GetPolys(), what + ": polys");
    expectSameCells(polyExpected->GetStrips(), polyActual->GetStrips(), what + ": strips");
  }
}

// The source's output (port 0) updated under `backend` with `threads` threads.
vtkSmartPointer<vtkDataSet> run(vtkAlgorithm* source, const char* backend, int threads)
{
  vtkSmartPointer<vtkDataSet> output;
  vtkSMPTools::LocalScope(vtkSMPTools::Config{ threads, backend, false }, [&] {
    EXPECT_STREQ(vtkSMPTools::GetBackend(), backend);
    source->Modified();
    source->Update();
    output = vtkSmartPointer<vtkDataSet>::Take(
      vtkDataSet::SafeDownCast(source->GetOutputDataObject(0))->NewInstance());
    output->DeepCopy(source->GetOutputDataObject(0));
  });
  return output;
}

// Sequential is the reference; STDThread on 1 and 2 threads must give the same bits.
void expectTheSameOnEveryBackend(vtkAlgorithm* source, const std::string& what)
{
  const vtkSmartPointer<vtkDataSet> sequential = run(source, "Sequential", 1);
  for (const int threads : { 1, 2 })
  {
    const vtkSmartPointer<vtkDataSet> threaded = run(source, "STDThread", threads);
    expectIdentical(sequential, threaded,
      what + ", STDThread on " + std::to_string(threads) + " thread(s) against Sequential");
  }
}
} // namespace

TEST(SourceThreads, BoostedSurfaceIsTheSameOnEveryBackend)
{
  vtkNew<vtkBoostedSurfaceSource> source;
  source->SetLambdaRange(-3.0, 3.0);
  source->SetLambdaResolution(299);
  source->SetThetaResolution(299);
  source->SetClipRadius(4.0); // cuts the far rows
  expectTheSameOnEveryBackend(source, "surface");
  source->SetMergeSeam(true);
  expectTheSameOnEveryBackend(source, "merged surface");
  source->SetComputeCurvatures(true); // the exact normals and the curvature arrays
  expectTheSameOnEveryBackend(source, "merged surface with curvatures");
  source->SetOutputTypeToCircles();
  expectTheSameOnEveryBackend(source, "circles");
}

TEST(SourceThreads, HopfFibrationIsTheSameOnEveryBackend)
{
  vtkNew<vtkHopfFibrationSource> source;
  source->SetThetaResolution(12);
  source->SetPhiResolution(10);
  source->SetFiberResolution(699);
  source->SetClipRadius(3.0);
  for (const int mode : { vtkHopfFibrationSource::PAPER, vtkHopfFibrationSource::CLASSICAL })
  {
    source->SetMode(mode);
    const std::string name = mode == vtkHopfFibrationSource::PAPER ? "Paper" : "Classical";
    source->SetOutputTypeToFibers();
    expectTheSameOnEveryBackend(source, name + " fibers");
    source->SetOutputTypeToTwistorMesh();
    expectTheSameOnEveryBackend(source, name + " twistor mesh");
  }
}

TEST(SourceThreads, CurvaturePatchIsTheSameOnEveryBackendForEveryMethod)
{
  vtkNew<vtkCurvaturePatchSource> source;
  source->SetUResolution(299);
  source->SetVResolution(299);
  source->AddControlPoint(-1, -1, 0, 0, 0, 1, 1, 0, 0, 0.5, 0.5);
  source->AddControlPoint(1, 1, 0.2, 0, 0.3, 1, 1, 0, 0, -0.5, 0.25);
  for (int method = vtkCurvaturePatchSource::BENT_LINE; method <= vtkCurvaturePatchSource::BILINEAR;
       ++method)
  {
    source->SetMethod(method);
    for (const int rule : { vtkCurvaturePatchSource::EXACT, vtkCurvaturePatchSource::PAPER })
    {
      source->SetExponentialRule(rule);
      expectTheSameOnEveryBackend(source,
        "method " + std::to_string(method) + (rule == vtkCurvaturePatchSource::EXACT ? ", Exact" : ", Paper"));
    }
  }
  source->SetMethod(vtkCurvaturePatchSource::CONTROL_POINTS);
  source->SetComputeCurvatures(true);
  expectTheSameOnEveryBackend(source, "control points with curvatures");
  source->SetOutputTypeToLines();
  expectTheSameOnEveryBackend(source, "control points, lines");
}

TEST(SourceThreads, ConformalOrbitIsTheSameOnEveryBackend)
{
  vtkNew<vtkConformalOrbitSource> source;
  source->SetSeedModeToSeedList();
  for (int i = 0; i < 10; ++i)
  {
    source->AddSeed(0.1 + 0.03 * i, 0.02 * i, 0.01 * i);
  }
  source->SetTResolution(9999);
  source->SetClipRadius(2.0);
  expectTheSameOnEveryBackend(source, "torus knot orbits");
  source->SetGeneratorTypeToGeneratorList();
  source->AddGenerator(0.5, 0, 0, 0, 0, 1, 0.7);
  source->AddGenerator(-0.5, 0.2, 0, 1, 0, 0.5, 0.4);
  source->SetTRange(0.0, 3.0);
  expectTheSameOnEveryBackend(source, "generator orbits");
}

TEST(SourceThreads, DipoleFieldIsTheSameOnEveryBackend)
{
  vtkNew<vtkDipoleFieldSource> source;
  source->SetDimensions(50, 50, 30);
  source->SetOrigin(-2.0, -2.0, -0.5);
  source->SetSpacing(0.08, 0.08, 1.0 / 29);
  source->AddGenerator(0.5, 0, 0, 0, 0, 1, 0.7);
  source->AddGenerator(-0.5, 0.2, 0, 1, 0, 0.5, 0.4);
  source->AddGenerator(0.1, -0.7, 0.1, 0, 1, 1, 0.3);
  expectTheSameOnEveryBackend(source, "dipole field");
  // Method (b): the point pairs in closed form, a rotation by the kernel; a strong point pair
  // too; and one generator, whose method (b) is method (a)'s computation.
  source->AddGenerator(0.0, 0.0, 0.0, 0, 0, 1, 0.5, vtkDipoleFieldSource::ROTATION, 0.0);
  source->AddGenerator(-1.04, 0.0, 0.0, 1, 0, 0, 2.5);
  expectTheSameOnEveryBackend(source, "dipole field with a rotation");
  source->SetNumberOfGenerators(1);
  expectTheSameOnEveryBackend(source, "dipole field of one generator");
}
