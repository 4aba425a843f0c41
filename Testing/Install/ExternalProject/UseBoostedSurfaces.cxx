// Uses the installed library from outside: a VTK source (vtkBoostedSurfaceSource, Fig 2) and the
// core (cga::PointPairField), each checked against its closed form (docs/conventions.md section 3
// item 2, and section 2: one generator is a special conformal transformation about its location).
#include "vtkBoostedSurfaceSource.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include "cga/PointPairField.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

int main()
{
  int failures = 0;

  // Fig 2: the unit circle in the yz plane, boosted along x by lambda, lies in the plane
  // x = lambda / (1 + lambda^2) with radius 1 / (1 + lambda^2).
  vtkNew<vtkBoostedSurfaceSource> source;
  source->Update();
  vtkPolyData* surface = source->GetOutput();
  vtkDataArray* lambdas = surface->GetPointData()->GetArray("lambda");
  const vtkIdType count = surface->GetNumberOfPoints();
  double worst = 0.0;
  vtkIdType nonFinite = 0; // std::max drops a NaN distance: NaN points are counted instead
  for (vtkIdType i = 0; lambdas && i < count; ++i)
  {
    double p[3];
    surface->GetPoint(i, p);
    const double lambda = lambdas->GetTuple1(i);
    const double radius = std::hypot(p[1], p[2]);
    nonFinite += std::isfinite(p[0]) && std::isfinite(radius) && std::isfinite(lambda) ? 0 : 1;
    worst = std::max({ worst, std::abs(p[0] - lambda / (1 + lambda * lambda)),
      std::abs(radius - 1 / (1 + lambda * lambda)) });
  }
  std::printf("vtkBoostedSurfaceSource: %lld points (%lld not finite), largest distance from the "
    "closed form %.3g\n", static_cast<long long>(count), static_cast<long long>(nonFinite), worst);
  if (!lambdas || count != 65 * 65 || nonFinite != 0 || !(worst < 1e-12))
  {
    std::printf("FAILED: expected 4225 finite points on the closed-form circles\n");
    ++failures;
  }

  // One generator at x with direction v and weight w: K = exp(-c tau(x, v)), c = w / (k|r|^2 + eps),
  // r = p - x, maps p to x + (r + u|r|^2) / (1 + 2 u.r + |u|^2 |r|^2) with u = -c v.
  const cga::Vec3 x{ 0.5, -0.25, 1.0 };
  const cga::Vec3 v{ 0.0, 0.6, 0.8 };
  const double w = 0.75, k = 1.0, eps = 0.1;
  const cga::PointPairField field(std::vector<cga::PointPairGenerator>{ { x, v, w } }, k, eps);
  const cga::Vec3 p{ 1.0, 2.0, -0.5 };
  cga::Vec3 image{};
  const bool mapped = field.map(p, 1.0, cga::ExponentialRule::Exact, image);
  const double r[3] = { p.x - x.x, p.y - x.y, p.z - x.z };
  const double rr = r[0] * r[0] + r[1] * r[1] + r[2] * r[2];
  const double c = w / (k * rr + eps);
  const double u[3] = { -c * v.x, -c * v.y, -c * v.z };
  const double ur = u[0] * r[0] + u[1] * r[1] + u[2] * r[2];
  const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  const double denominator = 1 + 2 * ur + uu * rr;
  const double expected[3] = { x.x + (r[0] + u[0] * rr) / denominator,
    x.y + (r[1] + u[1] * rr) / denominator, x.z + (r[2] + u[2] * rr) / denominator };
  const double error = std::max({ std::abs(image.x - expected[0]),
    std::abs(image.y - expected[1]), std::abs(image.z - expected[2]) });
  std::printf("cga::PointPairField: (%g, %g, %g) -> (%.12g, %.12g, %.12g), closed form off by %.3g\n",
    p.x, p.y, p.z, image.x, image.y, image.z, error);
  // std::max drops a NaN coordinate's difference: the image must also be finite
  const bool finite = std::isfinite(image.x) && std::isfinite(image.y) && std::isfinite(image.z);
  if (!mapped || !finite || !(error < 1e-12))
  {
    std::printf("FAILED: expected (%.12g, %.12g, %.12g)\n", expected[0], expected[1], expected[2]);
    ++failures;
  }
  return failures == 0 ? 0 : 1;
}
