// SurfaceCurvature.h against the closed forms of the sphere, the cylinder, the torus, the saddle
// z = (x^2 - y^2)/2 and an ellipsoid at its vertices, with the derivatives of their textbook
// parametrizations written out by hand.
#include "TestSupport.h"

#include "cga/SurfaceCurvature.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace
{
using namespace cga;
using cgatest::distance;

constexpr double kTolerance = 1e-12;

// (R cos u cos v, R sin u cos v, R sin v): u the longitude, v the latitude; x_u x x_v points out.
SurfaceDerivatives sphere(double r, double u, double v)
{
  const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
  SurfaceDerivatives x;
  x.point = r * Vec3{ cu * cv, su * cv, sv };
  x.du = r * Vec3{ -su * cv, cu * cv, 0.0 };
  x.dv = r * Vec3{ -cu * sv, -su * sv, cv };
  x.duu = r * Vec3{ -cu * cv, -su * cv, 0.0 };
  x.duv = r * Vec3{ su * sv, -cu * sv, 0.0 };
  x.dvv = r * Vec3{ -cu * cv, -su * cv, -sv };
  return x;
}

// ((R + r cos v) cos u, (R + r cos v) sin u, r sin v): x_u x x_v points out of the tube.
SurfaceDerivatives torus(double big, double small, double u, double v)
{
  const double cu = std::cos(u), su = std::sin(u), cv = std::cos(v), sv = std::sin(v);
  const double rho = big + small * cv;
  SurfaceDerivatives x;
  x.point = { rho * cu, rho * su, small * sv };
  x.du = { -rho * su, rho * cu, 0.0 };
  x.dv = { -small * sv * cu, -small * sv * su, small * cv };
  x.duu = { -rho * cu, -rho * su, 0.0 };
  x.duv = { small * sv * su, -small * sv * cu, 0.0 };
  x.dvv = { -small * cv * cu, -small * cv * su, -small * sv };
  return x;
}

// The graph (u, v, f(u, v)) with f's derivatives.
SurfaceDerivatives graph(double u, double v, double f, double fu, double fv, double fuu,
  double fuv, double fvv)
{
  SurfaceDerivatives x;
  x.point = { u, v, f };
  x.du = { 1.0, 0.0, fu };
  x.dv = { 0.0, 1.0, fv };
  x.duu = { 0.0, 0.0, fuu };
  x.duv = { 0.0, 0.0, fuv };
  x.dvv = { 0.0, 0.0, fvv };
  return x;
}

// x(a s + b t, c s + d t): the same surface in other parameters.
SurfaceDerivatives reparametrized(const SurfaceDerivatives& x, double a, double b, double c, double d)
{
  SurfaceDerivatives y;
  y.point = x.point;
  y.du = a * x.du + c * x.dv;
  y.dv = b * x.du + d * x.dv;
  y.duu = a * a * x.duu + 2.0 * a * c * x.duv + c * c * x.dvv;
  y.duv = a * b * x.duu + (a * d + b * c) * x.duv + c * d * x.dvv;
  y.dvv = b * b * x.duu + 2.0 * b * d * x.duv + d * d * x.dvv;
  return y;
}

// The normal curvature along a unit tangent t (bending away from n positive), from the
// parametrization directly: t = p x_u + q x_v solved by least squares (Gram matrix), then
// -II(p, q) / I(p, q).
double normalCurvature(const SurfaceDerivatives& x, Vec3 n, Vec3 t)
{
  const double e = dot(x.du, x.du), f = dot(x.du, x.dv), g = dot(x.dv, x.dv);
  const double bu = dot(t, x.du), bv = dot(t, x.dv);
  const double det = e * g - f * f;
  const double p = (g * bu - f * bv) / det, q = (e * bv - f * bu) / det;
  const Vec3 tangent = p * x.du + q * x.dv;
  const Vec3 second = p * p * x.duu + 2.0 * p * q * x.duv + q * q * x.dvv;
  return -dot(second, n) / dot(tangent, tangent);
}

// What every regular result satisfies: unit normal, orthonormal right-handed frame, directions
// that are principal (their normal curvatures are k1 and k2), K and H from k1 and k2.
void expectConsistent(const SurfaceDerivatives& x, const SurfaceCurvature& k, double tolerance)
{
  ASSERT_TRUE(k.regular);
  const double scale = std::max(1.0, std::max(std::fabs(k.k1), std::fabs(k.k2)));
  EXPECT_NEAR(norm(k.normal), 1.0, kTolerance);
  EXPECT_NEAR(norm(k.direction1), 1.0, kTolerance);
  EXPECT_NEAR(norm(k.direction2), 1.0, kTolerance);
  EXPECT_NEAR(dot(k.direction1, k.normal), 0.0, kTolerance);
  EXPECT_NEAR(dot(k.direction1, k.direction2), 0.0, kTolerance);
  EXPECT_LE(distance(cross(k.normal, k.direction1), k.direction2), kTolerance);
  EXPECT_GE(k.k1, k.k2);
  // The sign: positive along the nearer of e1 = x_u / |x_u| and e2 = n x e1.
  const Vec3 e1 = normalized(x.du), e2 = cross(k.normal, e1);
  const double along1 = dot(k.direction1, e1), along2 = dot(k.direction1, e2);
  EXPECT_GT(std::fabs(along1) >= std::fabs(along2) ? along1 : along2, 0.0);
  EXPECT_NEAR(normalCurvature(x, k.normal, k.direction1), k.k1, tolerance * scale);
  EXPECT_NEAR(normalCurvature(x, k.normal, k.direction2), k.k2, tolerance * scale);
  EXPECT_NEAR(k.gaussian, k.k1 * k.k2, kTolerance * scale * scale);
  EXPECT_NEAR(k.mean, 0.5 * (k.k1 + k.k2), kTolerance * scale);
}

TEST(SurfaceCurvature, SphereHasOneOverRadiusEverywhereWithTheOutwardNormal)
{
  for (const double r : { 0.5, 1.0, 3.0 })
  {
    for (const double u : { 0.0, 0.7, 2.5, -1.9 })
    {
      for (const double v : { -1.2, 0.0, 0.4, 1.5 })
      {
        const SurfaceDerivatives x = sphere(r, u, v);
        const SurfaceCurvature k = surfaceCurvature(x);
        expectConsistent(x, k, 1e-12);
        EXPECT_LE(distance(k.normal, x.point / r), kTolerance);
        EXPECT_NEAR(k.k1, 1.0 / r, kTolerance / r);
        EXPECT_NEAR(k.k2, 1.0 / r, kTolerance / r);
        EXPECT_NEAR(k.gaussian, 1.0 / (r * r), kTolerance / (r * r));
        EXPECT_NEAR(k.mean, 1.0 / r, kTolerance / r);
        // An umbilic: the first direction is x_u's.
        EXPECT_LE(distance(k.direction1, normalized(x.du)), kTolerance);
      }
    }
  }
}

TEST(SurfaceCurvature, SphereAtExtremeScalesKeepsItsCurvature)
{
  // The squares of the derivatives would underflow (1e-160^2) or overflow (1e300^2) unscaled.
  for (const double r : { 1e-150, 1e150, 1e300 })
  {
    const SurfaceDerivatives x = sphere(r, 0.3, 0.2);
    const SurfaceCurvature k = surfaceCurvature(x);
    ASSERT_TRUE(k.regular) << r;
    EXPECT_NEAR(k.k1 * r, 1.0, kTolerance) << r;
    EXPECT_NEAR(k.k2 * r, 1.0, kTolerance) << r;
    EXPECT_NEAR(k.mean * r, 1.0, kTolerance) << r;
    if (r < 1e200) // 1e-600 underflows to 0
    {
      EXPECT_NEAR(k.gaussian * r * r, 1.0, kTolerance) << r;
    }
    EXPECT_LE(distance(k.normal, normalized(x.point)), kTolerance) << r;
  }
  // K = 1/r^2 = 1e320 is beyond the doubles: degenerate, all zeros (not inf).
  const SurfaceCurvature tiny = surfaceCurvature(sphere(1e-160, 0.3, 0.2));
  EXPECT_FALSE(tiny.regular);
  EXPECT_EQ(tiny.gaussian, 0.0);
}

TEST(SurfaceCurvature, CylinderHasOneOverRadiusAroundAndZeroAlong)
{
  const double r = 2.0;
  for (const double u : { 0.0, 1.0, -2.0 })
  {
    const double cu = std::cos(u), su = std::sin(u);
    SurfaceDerivatives x;
    x.point = { r * cu, r * su, 0.5 };
    x.du = { -r * su, r * cu, 0.0 };
    x.dv = { 0.0, 0.0, 1.0 };
    x.duu = { -r * cu, -r * su, 0.0 };
    const SurfaceCurvature k = surfaceCurvature(x);
    expectConsistent(x, k, 1e-12);
    EXPECT_NEAR(k.k1, 1.0 / r, kTolerance);
    EXPECT_NEAR(k.k2, 0.0, kTolerance);
    EXPECT_NEAR(k.gaussian, 0.0, kTolerance);
    EXPECT_NEAR(k.mean, 0.5 / r, kTolerance);
    EXPECT_LE(distance(k.direction1, Vec3{ -su, cu, 0.0 }), kTolerance); // around
    EXPECT_LE(distance(k.direction2, Vec3{ 0.0, 0.0, 1.0 }), kTolerance); // n x around: the axis
  }
}

TEST(SurfaceCurvature, TorusHasItsClosedFormInAnyParametrization)
{
  const double big = 3.0, small = 1.0;
  for (const double u : { 0.0, 0.9, -2.2 })
  {
    for (const double v : { 0.0, 0.6, 1.7, 3.0, -2.4 })
    {
      const double cv = std::cos(v), rho = big + small * cv;
      const double meridian = 1.0 / small, parallel = cv / rho;
      // Sheared, stretched and orientation-preserving (det = 1.54 > 0): the same curvatures.
      for (const auto& shear : { std::array<double, 4>{ 1.0, 0.0, 0.0, 1.0 },
             std::array<double, 4>{ 0.8, 0.7, -0.6, 1.4 }, std::array<double, 4>{ 5.0, 0.0, 0.0, 0.01 } })
      {
        const SurfaceDerivatives x =
          reparametrized(torus(big, small, u, v), shear[0], shear[1], shear[2], shear[3]);
        const SurfaceCurvature k = surfaceCurvature(x);
        expectConsistent(x, k, 1e-11);
        const Vec3 tubeCenter = big * Vec3{ std::cos(u), std::sin(u), 0.0 };
        EXPECT_LE(distance(k.normal, (x.point - tubeCenter) / small), kTolerance);
        EXPECT_NEAR(k.k1, meridian, kTolerance);
        EXPECT_NEAR(k.k2, parallel, kTolerance);
        EXPECT_NEAR(k.gaussian, cv / (small * rho), kTolerance);
        EXPECT_NEAR(k.mean, (big + 2.0 * small * cv) / (2.0 * small * rho), kTolerance);
        // k1 along the meridian (up to sign), k2 along the parallel.
        const Vec3 meridianTangent = { -std::sin(v) * std::cos(u), -std::sin(v) * std::sin(u), cv };
        EXPECT_NEAR(std::fabs(dot(k.direction1, meridianTangent)), 1.0, 1e-10);
        EXPECT_NEAR(std::fabs(dot(k.direction2, Vec3{ -std::sin(u), std::cos(u), 0.0 })), 1.0, 1e-10);
      }
    }
  }
}

TEST(SurfaceCurvature, SaddleHasOppositeCurvaturesAtTheOriginAndMongeFormulasElsewhere)
{
  const SurfaceDerivatives origin = graph(0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -1.0);
  const SurfaceCurvature k0 = surfaceCurvature(origin);
  expectConsistent(origin, k0, 1e-12);
  // n = +z; the surface bends toward +z along x (k = -1) and away along y (k = +1).
  EXPECT_LE(distance(k0.normal, Vec3{ 0.0, 0.0, 1.0 }), kTolerance);
  EXPECT_NEAR(k0.k1, 1.0, kTolerance);
  EXPECT_NEAR(k0.k2, -1.0, kTolerance);
  EXPECT_NEAR(k0.gaussian, -1.0, kTolerance);
  EXPECT_NEAR(k0.mean, 0.0, kTolerance);
  EXPECT_NEAR(std::fabs(k0.direction1.y), 1.0, kTolerance);
  EXPECT_NEAR(std::fabs(k0.direction2.x), 1.0, kTolerance);
  // Away from the origin (x_u . x_v != 0): K = -1/W^4, H = (x^2 - y^2) / (2 W^3) in this sign
  // convention, W^2 = 1 + x^2 + y^2.
  for (const auto& p : { std::array<double, 2>{ 0.3, 0.7 }, std::array<double, 2>{ -1.5, 0.2 },
         std::array<double, 2>{ 2.0, -3.0 } })
  {
    const double u = p[0], v = p[1];
    const SurfaceDerivatives x = graph(u, v, 0.5 * (u * u - v * v), u, -v, 1.0, 0.0, -1.0);
    const SurfaceCurvature k = surfaceCurvature(x);
    expectConsistent(x, k, 1e-12);
    const double w2 = 1.0 + u * u + v * v, w = std::sqrt(w2);
    EXPECT_NEAR(k.gaussian, -1.0 / (w2 * w2), kTolerance);
    EXPECT_NEAR(k.mean, (u * u - v * v) / (2.0 * w2 * w), kTolerance);
    EXPECT_LE(distance(k.normal, Vec3{ -u, v, 1.0 } / w), kTolerance);
  }
}

TEST(SurfaceCurvature, EllipsoidAtItsVerticesHasTheSemiAxisRatios)
{
  const double a = 3.0, b = 2.0, c = 1.0;
  // (a cos u cos v, b sin u cos v, c sin v) at u = v = 0, the vertex (a, 0, 0): k = a/b^2 along y,
  // a/c^2 along z.
  {
    SurfaceDerivatives x;
    x.point = { a, 0.0, 0.0 };
    x.du = { 0.0, b, 0.0 };
    x.dv = { 0.0, 0.0, c };
    x.duu = { -a, 0.0, 0.0 };
    x.dvv = { -a, 0.0, 0.0 };
    const SurfaceCurvature k = surfaceCurvature(x);
    expectConsistent(x, k, 1e-12);
    EXPECT_NEAR(k.k1, a / (c * c), kTolerance);
    EXPECT_NEAR(k.k2, a / (b * b), kTolerance);
    EXPECT_NEAR(std::fabs(k.direction1.z), 1.0, kTolerance);
  }
  // At u = pi/2, v = 0, the vertex (0, b, 0): b/a^2 along x, b/c^2 along z.
  {
    SurfaceDerivatives x;
    x.point = { 0.0, b, 0.0 };
    x.du = { -a, 0.0, 0.0 };
    x.dv = { 0.0, 0.0, c };
    x.duu = { 0.0, -b, 0.0 };
    x.dvv = { 0.0, -b, 0.0 };
    const SurfaceCurvature k = surfaceCurvature(x);
    expectConsistent(x, k, 1e-12);
    EXPECT_LE(distance(k.normal, Vec3{ 0.0, 1.0, 0.0 }), kTolerance);
    EXPECT_NEAR(k.k1, b / (c * c), kTolerance);
    EXPECT_NEAR(k.k2, b / (a * a), kTolerance);
  }
  // The vertex (0, 0, c) as the graph z = c sqrt(1 - x^2/a^2 - y^2/b^2): c/b^2 along y, c/a^2 along x.
  {
    const SurfaceDerivatives x = graph(0.0, 0.0, c, 0.0, 0.0, -c / (a * a), 0.0, -c / (b * b));
    const SurfaceCurvature k = surfaceCurvature(x);
    expectConsistent(x, k, 1e-12);
    EXPECT_NEAR(k.k1, c / (b * b), kTolerance);
    EXPECT_NEAR(k.k2, c / (a * a), kTolerance);
    EXPECT_NEAR(k.gaussian, c * c / (a * a * b * b), kTolerance);
  }
}

TEST(SurfaceCurvature, ReversedOrientationFlipsTheNormalAndTheCurvaturesButNotK)
{
  const SurfaceDerivatives x = torus(3.0, 1.0, 0.4, 1.1);
  const SurfaceCurvature k = surfaceCurvature(x);
  const SurfaceCurvature flipped = surfaceCurvature(reparametrized(x, 0.0, 1.0, 1.0, 0.0)); // u <-> v
  ASSERT_TRUE(flipped.regular);
  EXPECT_LE(distance(flipped.normal, -k.normal), kTolerance);
  EXPECT_NEAR(flipped.k1, -k.k2, kTolerance);
  EXPECT_NEAR(flipped.k2, -k.k1, kTolerance);
  EXPECT_NEAR(flipped.gaussian, k.gaussian, kTolerance);
  EXPECT_NEAR(flipped.mean, -k.mean, kTolerance);
}

TEST(SurfaceCurvature, DegeneratePointsAreFlaggedWithZerosNeverNaN)
{
  auto expectDegenerate = [](const SurfaceDerivatives& x, const char* what) {
    const SurfaceCurvature k = surfaceCurvature(x);
    EXPECT_FALSE(k.regular) << what;
    for (const double value : { k.k1, k.k2, k.gaussian, k.mean, k.normal.x, k.normal.y,
           k.normal.z, k.direction1.x, k.direction1.y, k.direction1.z, k.direction2.x,
           k.direction2.y, k.direction2.z })
    {
      EXPECT_EQ(value, 0.0) << what;
    }
  };
  // The pole of the latitude-longitude sphere: x_u = 0.
  expectDegenerate(sphere(1.0, 0.3, 0.5 * 3.141592653589793238), "pole"); // x_u ~ 6e-17 x_v
  SurfaceDerivatives x = sphere(1.0, 0.3, 0.2);
  x.du = Vec3{};
  expectDegenerate(x, "x_u = 0");
  x = sphere(1.0, 0.3, 0.2);
  x.dv = 2.0 * x.du;
  expectDegenerate(x, "parallel");
  x = sphere(1.0, 0.3, 0.2);
  x.duv.y = std::numeric_limits<double>::quiet_NaN();
  expectDegenerate(x, "NaN");
  x = sphere(1.0, 0.3, 0.2);
  x.dv.z = std::numeric_limits<double>::infinity();
  expectDegenerate(x, "inf");
  // A sphere of radius 1e-310 (subnormal derivatives) has curvature 1e310: beyond the doubles.
  expectDegenerate(sphere(1e-310, 0.3, 0.2), "overflow");
  // Nearly parallel but not within 1e-12: regular.
  x = sphere(1.0, 0.3, 0.2);
  x.dv = x.du + 1e-9 * x.dv;
  EXPECT_TRUE(surfaceCurvature(x).regular);
}

TEST(SurfaceCurvature, PlaneHasZeroCurvature)
{
  SurfaceDerivatives x;
  x.du = { 1.0, 2.0, 0.0 };
  x.dv = { -0.5, 3.0, 0.0 };
  x.duu = { 4.0, -1.0, 0.0 }; // tangential second derivatives: a curved parametrization of a plane
  x.duv = { 0.3, 0.2, 0.0 };
  const SurfaceCurvature k = surfaceCurvature(x);
  ASSERT_TRUE(k.regular);
  EXPECT_LE(distance(k.normal, Vec3{ 0.0, 0.0, 1.0 }), kTolerance);
  EXPECT_EQ(k.k1, 0.0);
  EXPECT_EQ(k.k2, 0.0);
  EXPECT_EQ(k.gaussian, 0.0);
}

// planeNormal: a closed polygon of a circle in a tilted plane, at every scale and far from the
// origin, gives the plane's normal (oriented as the polygon turns) to rounding; its non-finite
// points are skipped; points spanning no plane give 0.
TEST(SurfaceCurvature, PlaneNormalOfAClosedPolylineAtAnyScale)
{
  const Vec3 n = normalized(Vec3{ 1.0, -2.0, 2.0 });
  const Vec3 a = normalized(cross(n, Vec3{ 0.0, 0.0, 1.0 }));
  const Vec3 b = cross(n, a); // a x b = n
  // 1e-310 and 1e308 take the scaling by ldexp (2^-e not a normal double); the others multiply by
  // 2^-e. Subnormal coordinates keep about 13 digits.
  for (double radius : { 1e-310, 1e-300, 1e-200, 1e-160, 1.0, 1e150, 1e300, 1e308 })
  {
    const double tolerance = radius < 1e-307 ? 1e-11 : 1e-14;
    for (Vec3 center : { Vec3{}, Vec3{ 3.0, -1.0, 2.0 } })
    {
      const Vec3 c = radius * 1e-3 * center; // a center close to the points, at their scale
      std::vector<Vec3> points;
      for (int i = 0; i <= 12; ++i)
      {
        const double t = 2.0 * M_PI * (i % 12) / 12.0;
        points.push_back(c + radius * (std::cos(t) * a + std::sin(t) * b));
      }
      EXPECT_LE(distance(planeNormal(points.data(), points.size(), c), n), tolerance) << radius;
      std::reverse(points.begin(), points.end());
      EXPECT_LE(distance(planeNormal(points.data(), points.size(), c), -1.0 * n), tolerance) << radius;
      points[3] = Vec3{ NAN, 0.0, 0.0 }; // a point at infinity: its two segments left out
      EXPECT_LE(distance(planeNormal(points.data(), points.size(), c), -1.0 * n), tolerance) << radius;
    }
  }
  const Vec3 line[3] = { { 1.0, 1.0, 1.0 }, { 2.0, 2.0, 2.0 }, { 1.0, 1.0, 1.0 } };
  EXPECT_EQ(norm(planeNormal(line, 3, Vec3{})), 0.0);
  const Vec3 lone[1] = { { 1.0, 0.0, 0.0 } };
  EXPECT_EQ(norm(planeNormal(lone, 1, Vec3{})), 0.0);
  EXPECT_EQ(norm(planeNormal(nullptr, 0, Vec3{})), 0.0);
}

TEST(SurfaceCurvature, TinyCurvaturesUnderLargeTangentialSecondDerivativesKeepTheirSize)
{
  // z = c u v (the u, v plane bent by c) with a large tangential second derivative: the second
  // derivatives are scaled by their largest component (1), so the shape operator's entries are
  // c itself, down to 1e-300, where c^2 underflows: the eigenvalues' radius must still be |c|.
  for (const double c : { 1.0, 1e-100, 1e-160, 1e-200, 1e-300 })
  {
    SurfaceDerivatives x;
    x.du = { 1.0, 0.0, 0.0 };
    x.dv = { 0.0, 1.0, 0.0 };
    x.duu = { 1.0, 0.0, 0.0 };
    x.duv = { 0.0, 0.0, c };
    const SurfaceCurvature k = surfaceCurvature(x);
    ASSERT_TRUE(k.regular) << c;
    // The normal is +z: curvatures c along (1, -1) and -c along (1, 1).
    EXPECT_NEAR(k.k1, c, 1e-15 * c) << c;
    EXPECT_NEAR(k.k2, -c, 1e-15 * c) << c;
    EXPECT_EQ(k.mean, 0.0) << c;
    // z = c u^2 / 2 bends toward the normal along u: curvatures 0 and -c.
    x.duu = { 1.0, 0.0, c };
    x.duv = { 0.0, 0.0, 0.0 };
    const SurfaceCurvature along = surfaceCurvature(x);
    ASSERT_TRUE(along.regular) << c;
    EXPECT_EQ(along.k1, 0.0) << c;
    EXPECT_NEAR(along.k2, -c, 1e-15 * c) << c;
    EXPECT_NEAR(along.mean, -0.5 * c, 1e-15 * c) << c;
  }
}
} // namespace
