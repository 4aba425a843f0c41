// Every (verified) fact of docs/conventions.md sections 1-3, checked with the kernel's own paths.
#include "TestSupport.h"

#include "cga/CompactAlgebra.h"
#include "cga/Conformal.h"
#include "cga/Exponential.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"

#include <vector>

namespace
{
using namespace cga;
using cgatest::signedArea;
using cgatest::pointsNear;
using cgatest::Random;
using cgatest::relativeDifference;
using cgatest::boost;
using cgatest::mapPoint;
using cgatest::specialConformal;

// ---- section 1 ----

TEST(SpecSection1, NullPointPairSquaresToZeroAndIsATranslatedTangent)
{
  Random random(61);
  for (int n = 0; n < 500; ++n)
  {
    const Vec3 x = random.vec3(3.0), v = random.uniform(0.1, 2.0) * random.unit();
    const Multivector tau = nullPointPair(x, v);
    EXPECT_LE((tau * tau).maxAbs(), 1e-14 * tau.coefficientNorm() * tau.coefficientNorm());
    const Multivector t = translator(x);
    EXPECT_LE(relativeDifference(t * tangent(v) * t.reverse(), tau), 1e-14);
    // The tangent at the origin is no ^ v = no v.
    EXPECT_LE(relativeDifference(tangent(v), no() * vector(v)), 0.0);
  }
}

TEST(SpecSection1, TranslatorAndRotorConventions)
{
  Random random(62);
  for (int n = 0; n < 200; ++n)
  {
    const Vec3 x = random.vec3(3.0), d = random.vec3(3.0);
    EXPECT_TRUE(pointsNear(transformPoint(translator(d), x), x + d, 1e-14));
    EXPECT_TRUE(pointsNear(mapPoint(toEven(translator(d)), x), x + d, 1e-14));
    // T(d) = 1 - d ni/2 is a unit versor.
    EXPECT_LE(relativeDifference(translator(d) * translator(d).reverse(), Multivector::scalar(1.0)),
              1e-14);
  }
  // Right-hand rule about +z: e1 -> e2 by a quarter turn.
  EXPECT_TRUE(
    pointsNear(transformPoint(rotor({ 0, 0, 1 }, M_PI / 2), { 1, 0, 0 }), { 0, 1, 0 }, 1e-15));
  EXPECT_TRUE(
    pointsNear(mapPoint(toEven(rotor({ 1, 0, 0 }, M_PI / 2)), { 0, 1, 0 }), { 0, 0, 1 }, 1e-15));
  // fn and up are inverse; in the orthonormal basis the weight e- + e+ of up(x) cancels terms of
  // size |x|^2/2, so the reference path loses about |x|^2 ulps (the compact types do not).
  for (int n = 0; n < 100; ++n)
  {
    const Vec3 x = random.vec3(10.0);
    EXPECT_TRUE(pointsNear(down(3.5 * up(x)), x, 1e-15 * (1.0 + norm2(x))));
    Vec3 compact;
    ASSERT_TRUE(normalizePoint(3.5 * ConformalVector::point(x), compact));
    EXPECT_TRUE(pointsNear(compact, x, 2e-16));
  }
}

// ---- section 2 ----

TEST(SpecSection2, OriginBoostIsTheClosedFormTransversion)
{
  Random random(63);
  for (double scale : { 0.1, 0.5, 1.0, 2.0 })
  {
    for (int n = 0; n < 250; ++n)
    {
      const Vec3 v = scale * random.vec3(1.0), x = random.vec3(2.0);
      // K = exp(no v) = 1 + no v: tau(0, v) = no ^ v.
      const Even k = boost(1.0, {}, v);
      EXPECT_LE(relativeDifference(toMultivector(k), Multivector::scalar(1.0) + no() * vector(v)),
                0.0);
      const double denominator = 1.0 + 2.0 * dot(v, x) + norm2(v) * norm2(x);
      if (denominator > 1e-3)
      {
        EXPECT_TRUE(pointsNear(mapPoint(k, x), specialConformal(v, x), 1e-12 / denominator));
        EXPECT_TRUE(pointsNear(
          transformPoint(toMultivector(k), x), specialConformal(v, x), 1e-12 / denominator));
      }
    }
    // The point -v/|v|^2 goes to infinity.
    const Vec3 v = scale * random.unit();
    const ConformalVector image =
      sandwichGrade1(boost(1.0, {}, v), ConformalVector::point(-v / norm2(v)));
    // The image is a multiple of ni: the weight 1 + 2 v.x + |v|^2 |x|^2 = 1 - 2 + 1 and the
    // Euclidean part x + v |x|^2 vanish up to the rounding of their terms.
    EXPECT_LE(std::fabs(image.weight()), 1e-15);
    EXPECT_LE(cgatest::maxNorm(image.euclidean()), 1e-15 * std::fabs(image[ConformalVector::NI]));
    EXPECT_GT(std::fabs(image[ConformalVector::NI]), 0.1);
  }
}

TEST(SpecSection2, HomogeneousBoostIsATransversionAboutItsLocation)
{
  Random random(64);
  for (int n = 0; n < 1000; ++n)
  {
    const Vec3 x = random.vec3(2.0), u = random.uniform(0.05, 2.0) * random.unit();
    const Vec3 p = random.vec3(2.0);
    const Even k = boost(1.0, x, u);
    // Exact exponential of a null pair: exp(tau) = 1 + tau.
    EXPECT_LE(relativeDifference(expExact(nullPointPairCompact(x, u)), k), 4e-15);
    EXPECT_TRUE(pointsNear(mapPoint(k, x), x, 1e-14));
    const Vec3 y = p - x;
    const double denominator = 1.0 + 2.0 * dot(u, y) + norm2(u) * norm2(y);
    if (denominator > 1e-3)
    {
      EXPECT_TRUE(pointsNear(mapPoint(k, p), x + specialConformal(u, y), 1e-12 / denominator));
    }
  }
}

// ---- section 3 ----

TEST(SpecSection3, Fig1UnitCircleBoostedAlongItsPlane)
{
  const Multivector sigma = circle({ 0, 0, 0 }, { 0, 0, 1 }, 1.0);
  for (double lambda :
       { -100.0, -3.0, -1.5, -1.0, -0.5, 0.0, 0.25, 0.9, 0.99, 1.0, 1.01, 1.1, 2.0, 10.0, 1e3 })
  {
    const Even k = boost(lambda, {}, { 1, 0, 0 }); // 1 + lambda no e1
    const Multivector image = sandwich(toMultivector(k), sigma);
    const RoundInfo info = readCircle(image);
    std::vector<Vec3> points;
    for (int i = 0; i < 64; ++i)
    {
      const double theta = 2.0 * M_PI * (i + 0.5) / 64.0;
      points.push_back(mapPoint(k, { std::cos(theta), std::sin(theta), 0.0 }));
      EXPECT_EQ(points.back().z, 0.0);
    }
    if (std::fabs(lambda) == 1.0)
    {
      // The line x = 1/(2 lambda).
      EXPECT_TRUE(info.isLine) << lambda;
      EXPECT_TRUE(pointsNear(info.center, { 0.5 * lambda, 0, 0 }, 1e-14));
      EXPECT_NEAR(std::fabs(info.direction.y), 1.0, 1e-15);
      for (const Vec3& p : points)
      {
        EXPECT_NEAR(p.x, 0.5 * lambda, 1e-14);
      }
      continue;
    }
    const double radius = 1.0 / std::fabs(lambda * lambda - 1.0);
    const Vec3 center{ lambda / (lambda * lambda - 1.0), 0, 0 };
    EXPECT_FALSE(info.isLine) << lambda;
    EXPECT_NEAR(info.radius, radius, 1e-12 * radius) << lambda;
    EXPECT_TRUE(pointsNear(info.center, center, 1e-12)) << lambda;
    for (const Vec3& p : points)
    {
      EXPECT_NEAR(norm(p - center), radius, 1e-11 * std::max(radius, cgatest::maxNorm(center)))
        << lambda;
    }
    // Orientation: reversed for |lambda| > 1, in the blade and in the order of the points.
    const double expectedSign = std::fabs(lambda) < 1.0 ? 1.0 : -1.0;
    EXPECT_NEAR(info.normal.z, expectedSign, 1e-12) << lambda;
    EXPECT_GT(expectedSign * signedArea(points), 0.0) << lambda;
    if (std::fabs(lambda) >= 1e3)
    {
      // Shrinking onto the original center.
      EXPECT_LT(info.radius, 2.0 / (lambda * lambda));
      EXPECT_LT(norm(info.center), 2.0 / std::fabs(lambda));
    }
  }
}

TEST(SpecSection3, Fig1ShrinksOntoTheCenterForLargeLambda)
{
  // Points only: the compact path stays accurate where the orthonormal blade reader cancels.
  for (double lambda : { 1e3, 1e6, -1e6 })
  {
    const Even k = boost(lambda, {}, { 1, 0, 0 });
    const Vec3 center{ lambda / (lambda * lambda - 1.0), 0, 0 };
    const double radius = 1.0 / (lambda * lambda - 1.0);
    for (int i = 0; i < 64; ++i)
    {
      const double theta = 2.0 * M_PI * (i + 0.5) / 64.0;
      const Vec3 p = mapPoint(k, { std::cos(theta), std::sin(theta), 0.0 });
      EXPECT_NEAR(norm(p - center), radius, 1e-14 * radius * lambda * lambda);
      EXPECT_LT(norm(p), 1.01 / std::fabs(lambda));
    }
  }
}

TEST(SpecSection3, Fig2UnitCircleBoostedAcrossItsPlane)
{
  const Multivector sigma = circle({ 0, 0, 0 }, { 1, 0, 0 }, 1.0);
  for (double lambda : { 0.0, 0.25, 0.5, 1.0, 2.0, 4.0, -3.0 })
  {
    const Even k = boost(lambda, {}, { 1, 0, 0 });
    const double planeX = lambda / (1.0 + lambda * lambda);
    const double radius = 1.0 / (1.0 + lambda * lambda);
    for (int i = 0; i < 32; ++i)
    {
      const double theta = 2.0 * M_PI * i / 32.0;
      const Vec3 p = mapPoint(k, { 0.0, std::cos(theta), std::sin(theta) });
      EXPECT_NEAR(p.x, planeX, 1e-15);
      EXPECT_NEAR(std::hypot(p.y, p.z), radius, 1e-15);
    }
    const RoundInfo info = readCircle(sandwich(toMultivector(k), sigma));
    EXPECT_FALSE(info.isLine);
    EXPECT_TRUE(pointsNear(info.center, { planeX, 0, 0 }, 1e-14));
    EXPECT_NEAR(info.radius, radius, 1e-14);
    EXPECT_NEAR(std::fabs(info.normal.x), 1.0, 1e-14);
  }
}

TEST(SpecSection3, Eq15BendingALineIntoACircle)
{
  Random random(65);
  for (int n = 0; n < 100; ++n)
  {
    const Vec3 p = random.vec3(2.0), d = random.unit();
    const Vec3 n0 = normalized(cross(d, random.unit()));
    for (double kappa : { 0.1, 0.5, 1.0, 2.0, -1.0, -0.3 })
    {
      const Bivector tau = nullPointPairCompact(p, n0);
      const Even k = Even::identity() + Even::fromBivector(-0.5 * kappa * tau);
      const Vec3 center = p - n0 / kappa;
      const double radius = 1.0 / std::fabs(kappa);
      EXPECT_TRUE(pointsNear(mapPoint(k, p), p, 1e-14));
      std::vector<Vec3> images;
      for (int i = -20; i <= 20; ++i)
      {
        const Vec3 q = mapPoint(k, p + (0.25 * i) * d);
        images.push_back(q);
        EXPECT_NEAR(norm(q - center), radius, 1e-12 * std::max(radius, 1.0 + cgatest::maxNorm(p)));
        // In the plane of the line and n.
        EXPECT_NEAR(dot(q - p, cross(d, n0)), 0.0, 1e-12 * std::max(radius, 1.0));
      }
      // The line blade goes to the same circle.
      const RoundInfo info = readCircle(sandwich(toMultivector(k), line(p, p + d)));
      EXPECT_FALSE(info.isLine);
      EXPECT_NEAR(info.radius, radius, 1e-11 * radius);
      EXPECT_TRUE(pointsNear(info.center, center, 1e-11 * std::max(1.0, radius)));
      EXPECT_NEAR(std::fabs(dot(info.normal, cross(d, n0))), 1.0, 1e-12);
      // Rotating n by 180 degrees straightens the circle back into the line.
      const Even straighten =
        Even::identity() + Even::fromBivector(-0.5 * kappa * nullPointPairCompact(p, -n0));
      for (int i = 0; i < static_cast<int>(images.size()); ++i)
      {
        EXPECT_TRUE(pointsNear(mapPoint(straighten, images[i]), p + (0.25 * (i - 20)) * d, 1e-11));
      }
      for (int i = 0; i < 12; ++i)
      {
        // Any circle point except the one opposite p (which goes to infinity) lands on the line.
        const double phi = 2.0 * M_PI * (i + 0.5) / 12.0;
        const Vec3 onCircle =
          center + radius * (std::cos(phi) * normalized(p - center) + std::sin(phi) * d);
        const Vec3 q = mapPoint(straighten, onCircle);
        const Vec3 offLine = (q - p) - dot(q - p, d) * d;
        EXPECT_LE(norm(offLine), 1e-11 * std::max(1.0, norm(q - p)));
      }
      // K = 1 - kappa tau gives curvature 2 kappa.
      const Even twice = Even::identity() + Even::fromBivector(-kappa * tau);
      for (int i = -10; i <= 10; ++i)
      {
        const Vec3 q = mapPoint(twice, p + (0.3 * i) * d);
        EXPECT_NEAR(norm(q - (p - n0 / (2.0 * kappa))),
                    0.5 * radius,
                    1e-12 * std::max(radius, 1.0 + cgatest::maxNorm(p)));
      }
    }
  }
}

TEST(SpecSection3, ReadCircleRoundTrips)
{
  Random random(66);
  for (int n = 0; n < 500; ++n)
  {
    const Vec3 center = random.vec3(1.0), normal = random.unit();
    const double radius = random.uniform(0.5, 5.0);
    const RoundInfo info = readCircle(circle(center, normal, radius));
    EXPECT_FALSE(info.isLine);
    EXPECT_TRUE(pointsNear(info.center, center, 1e-12));
    EXPECT_NEAR(info.radius, radius, 1e-12 * radius);
    EXPECT_TRUE(pointsNear(info.normal, normal, 1e-12));
    // Small circles far from the origin: the orthonormal blade itself is built with cancellation
    // of order |c|^4 / r^2 ulps, which bounds what any reader can recover.
    const Vec3 farCenter = random.vec3(5.0);
    const double smallRadius = random.uniform(0.1, 0.5);
    const double conditioning = std::pow(1.0 + norm2(farCenter), 2.0) / (smallRadius * smallRadius);
    const RoundInfo far = readCircle(circle(farCenter, normal, smallRadius));
    EXPECT_TRUE(pointsNear(far.center, farCenter, 1e-14 * conditioning));
    EXPECT_NEAR(far.radius, smallRadius, 1e-14 * conditioning * smallRadius);
    EXPECT_TRUE(pointsNear(far.normal, normal, 1e-14 * conditioning));
    // Through three points: the normal follows the orientation a -> b -> c.
    const Vec3 a = random.vec3(2.0), b = random.vec3(2.0), c = random.vec3(2.0);
    const Vec3 ab = b - a, ac = c - a;
    const Vec3 expectedNormal = normalized(cross(ab, ac));
    const Vec3 circumcenter = a +
      (norm2(ac) * cross(cross(ab, ac), ab) + norm2(ab) * cross(ac, cross(ab, ac))) /
        (2.0 * norm2(cross(ab, ac)));
    const RoundInfo through = readCircle(circleThroughPoints(a, b, c));
    EXPECT_TRUE(pointsNear(through.normal, expectedNormal, 1e-10));
    EXPECT_TRUE(pointsNear(
      through.center, circumcenter, 1e-9 * std::max(1.0, cgatest::maxNorm(circumcenter))));
    EXPECT_NEAR(through.radius, norm(a - circumcenter), 1e-9 * std::max(1.0, through.radius));
    // Lines: direction a -> b, center = the point closest to the origin.
    const Vec3 direction = normalized(b - a);
    const RoundInfo flat = readCircle(line(a, b));
    EXPECT_TRUE(flat.isLine);
    EXPECT_TRUE(pointsNear(flat.direction, direction, 1e-12));
    EXPECT_TRUE(pointsNear(flat.center, a - dot(a, direction) * direction, 1e-12));
  }
}
} // namespace
