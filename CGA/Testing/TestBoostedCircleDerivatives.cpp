// The closed-form derivatives of the boosted circle's surface (BoostedCircleRow) and the
// commutator map they are built from: against the full geometric product, central finite
// differences of the point map, and the closed-form curvatures of the surfaces of revolution the
// family makes when the boost is along the circle's axis (horn tori) and of the plane it sweeps
// when the boost lies in the circle's plane.
#include "TestSupport.h"

#include "cga/CompactConversion.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"
#include "cga/SurfaceCurvature.h"
#include "cga/surfaces/BoostedCircle.h"

#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

namespace
{
using namespace cga;
using cgatest::distance;

TEST(BoostedCircleDerivatives, CommutatorMatrixIsTheFullProductsBXMinusXB)
{
  cgatest::Random random(1301);
  for (int trial = 0; trial < 50; ++trial)
  {
    const Bivector b = random.bivector(2.0);
    ConformalVector x;
    for (double& c : x.c)
    {
      c = random.uniform(-2.0, 2.0);
    }
    const Multivector mb = toMultivector(b), mx = toMultivector(x);
    const Multivector reference = mb * mx - mx * mb;
    const ConformalVector image = applyMatrix(commutatorMatrix(b), x);
    // The whole product is a vector: nothing is lost by comparing grade 1 only.
    EXPECT_LE(cgatest::relativeDifference(toMultivector(image), reference), 1e-14);
  }
}

// The surface point at (theta, lambda) through the source's own path (PointMap of K(lambda)).
Vec3 surfacePoint(const BoostedCircle& family, double theta, double lambda)
{
  Vec3 p;
  EXPECT_TRUE(PointMap(family.boostCompact(lambda)).apply(family.circlePoint(theta), p));
  return p;
}

TEST(BoostedCircleDerivatives, AgreeWithCentralFiniteDifferencesOfThePointMap)
{
  cgatest::Random random(1302);
  for (int trial = 0; trial < 20; ++trial)
  {
    BoostedCircle family;
    family.center = random.vec3(1.0);
    family.normal = random.unit();
    family.radius = random.uniform(0.5, 2.0);
    family.boostLocation = family.center + random.vec3(1.0);
    family.boostDirection = random.uniform(0.2, 1.0) * random.unit();
    const double theta = random.uniform(0.0, 6.283), lambda = random.uniform(-0.5, 0.5);
    SurfaceDerivatives x, first;
    const BoostedCircleRow row(family, lambda);
    ASSERT_TRUE(row.derivatives(family.circleSample(theta), x));
    ASSERT_TRUE(row.firstDerivatives(family.circleSample(theta), first));
    const double h = 1e-4;
    auto at = [&](double dt, double dl) { return surfacePoint(family, theta + dt, lambda + dl); };
    const Vec3 p = at(0, 0);
    const Vec3 du = (at(h, 0) - at(-h, 0)) / (2 * h), dv = (at(0, h) - at(0, -h)) / (2 * h);
    const Vec3 duu = (at(h, 0) - 2.0 * p + at(-h, 0)) / (h * h);
    const Vec3 dvv = (at(0, h) - 2.0 * p + at(0, -h)) / (h * h);
    const Vec3 duv = (at(h, h) - at(h, -h) - at(-h, h) + at(-h, -h)) / (4 * h * h);
    // The point is the source's, to the bit; the first derivatives alone are the same.
    EXPECT_EQ(x.point.x, p.x);
    EXPECT_EQ(x.point.y, p.y);
    EXPECT_EQ(x.point.z, p.z);
    EXPECT_EQ(distance(first.du, x.du), 0.0);
    EXPECT_EQ(distance(first.dv, x.dv), 0.0);
    // Central differences: O(h^2) = 1e-8 truncation, eps / h^2 = 1e-8 rounding in the second ones.
    const double scale = std::max({ 1.0, cgatest::maxNorm(x.duu), cgatest::maxNorm(x.dvv) });
    EXPECT_LE(distance(x.du, du), 1e-7 * scale) << trial;
    EXPECT_LE(distance(x.dv, dv), 1e-7 * scale) << trial;
    EXPECT_LE(distance(x.duu, duu), 1e-6 * scale) << trial;
    EXPECT_LE(distance(x.duv, duv), 1e-6 * scale) << trial;
    EXPECT_LE(distance(x.dvv, dvv), 1e-6 * scale) << trial;
  }
}

// The horn torus (tube radius = distance of the tube's center from the axis = r) about the axis
// through `center` along the unit `axis`, at the surface point p with the normal n computed
// there: expects n along the tube's radius and the closed-form curvatures, with the sign of n
// (outward: positive).
void expectHornTorus(Vec3 center, Vec3 axis, double r, const SurfaceCurvature& k, Vec3 p)
{
  ASSERT_TRUE(k.regular);
  const Vec3 offset = p - center;
  const Vec3 radial = offset - dot(offset, axis) * axis;
  const double rho = norm(radial); // distance from the axis
  const Vec3 tubeCenter = center + (r / rho) * radial;
  const Vec3 outward = (p - tubeCenter) / r;
  EXPECT_NEAR(norm(p - tubeCenter), r, 1e-12 * r); // p is on the torus
  const double side = dot(k.normal, outward);
  EXPECT_NEAR(std::fabs(side), 1.0, 1e-12);
  const double s = side > 0 ? 1.0 : -1.0;
  const double cosV = (rho - r) / r;
  const double meridian = s / r, parallel = s * cosV / rho;
  const double tolerance = 1e-9 / r;
  EXPECT_NEAR(k.k1, std::max(meridian, parallel), tolerance);
  EXPECT_NEAR(k.k2, std::min(meridian, parallel), tolerance);
  EXPECT_NEAR(k.gaussian, cosV / (r * rho), tolerance / r);
  EXPECT_NEAR(k.mean, 0.5 * (meridian + parallel), tolerance);
  // The meridian's curvature (1/r) along the profile circle, in the plane of the axis.
  const Vec3 alongMeridian = meridian > parallel ? k.direction1 : k.direction2;
  EXPECT_NEAR(dot(alongMeridian, normalized(cross(axis, radial))), 0.0, 1e-9);
}

TEST(BoostedCircleDerivatives, BoostAlongTheAxisAtTheCenterSweepsAHornTorus)
{
  // Fig 2: every circle point moves on a circle through the center, tangent to the axis, of
  // diameter the circle's radius: a horn torus R = r = radius/2 about the circle's axis.
  BoostedCircle family;
  family.center = { 0.3, -1.0, 2.0 };
  family.normal = normalized(Vec3{ 1.0, 2.0, -0.5 });
  family.radius = 1.7;
  family.boostLocation = family.center;
  family.boostDirection = 0.8 * family.normal;
  for (const double lambda : { -1.5, -0.4, 0.0, 0.3, 1.2 })
  {
    const BoostedCircleRow row(family, lambda);
    for (const double theta : { 0.0, 1.0, 2.5, 4.0, 5.9 })
    {
      SurfaceDerivatives x;
      ASSERT_TRUE(row.derivatives(family.circleSample(theta), x));
      expectHornTorus(family.center, family.normal, 0.5 * family.radius, surfaceCurvature(x), x.point);
    }
  }
}

TEST(BoostedCircleDerivatives, BoostAlongTheAxisOffTheCenterSweepsAHornTorusAboutTheBoost)
{
  // Fig 3 (the horn): the orbits of q = p - x0 are circles through x0 tangent to the axis, of
  // diameter |q|^2 / |q_perp|: a horn torus about x0 with r = |q|^2 / (2 |q_perp|).
  BoostedCircle family;
  family.normal = { 1.0, 0.0, 0.0 };
  family.radius = 1.0;
  family.boostLocation = { -1.5, 0.0, 0.0 };
  family.boostDirection = { 0.7, 0.0, 0.0 };
  const double r = (1.5 * 1.5 + 1.0) / 2.0;
  for (const double lambda : { -0.8, 0.0, 0.5, 2.0 })
  {
    const BoostedCircleRow row(family, lambda);
    for (const double theta : { 0.0, 0.8, 3.0, 5.0 })
    {
      SurfaceDerivatives x;
      ASSERT_TRUE(row.derivatives(family.circleSample(theta), x));
      expectHornTorus(family.boostLocation, family.normal, r, surfaceCurvature(x), x.point);
    }
  }
}

TEST(BoostedCircleDerivatives, BoostInTheCirclesPlaneSweepsThatPlane)
{
  // Fig 1: a transversion along a direction of the plane through its center keeps the plane.
  BoostedCircle family;
  family.normal = { 0.0, 0.0, 1.0 };
  family.boostDirection = { 1.0, 0.0, 0.0 };
  int regular = 0;
  for (const double lambda : { -0.7, -0.2, 0.1, 0.5 })
  {
    const BoostedCircleRow row(family, lambda);
    for (const double theta : { 0.3, 1.3, 2.0, 4.4 })
    {
      SurfaceDerivatives x;
      ASSERT_TRUE(row.derivatives(family.circleSample(theta), x));
      const SurfaceCurvature k = surfaceCurvature(x);
      EXPECT_NEAR(x.point.z, 0.0, 1e-15);
      if (k.regular)
      {
        ++regular;
        EXPECT_NEAR(std::fabs(k.normal.z), 1.0, 1e-12);
        EXPECT_NEAR(k.k1, 0.0, 1e-9);
        EXPECT_NEAR(k.k2, 0.0, 1e-9);
      }
    }
  }
  EXPECT_GE(regular, 12);
}

// A family for the eight-sample tests at `scale`: the boost anywhere (kind 0), along the
// circle's axis (1: a surface of revolution) or in its plane through its center (2: Fig 1's plane).
BoostedCircle trialFamily(cgatest::Random& random, double scale, int kind)
{
  BoostedCircle family;
  family.center = scale * random.vec3(1.0);
  family.normal = random.unit();
  family.radius = scale * random.uniform(0.5, 2.0);
  family.boostLocation = family.center + (kind == 0 ? scale * random.vec3(1.0) : Vec3{});
  const Vec3 inPlane = normalized(cross(family.normal, random.unit()));
  family.boostDirection = (random.uniform(0.2, 1.0) / scale) *
    (kind == 0 ? random.unit() : kind == 1 ? family.normal : inPlane);
  return family;
}

// 19 samples of the family's circle; 2 and 11 not finite, 5 with a zero tangent (degenerate).
std::vector<BoostedCircle::CircleSample> trialSamples(
  cgatest::Random& random, const BoostedCircle& family)
{
  std::vector<BoostedCircle::CircleSample> samples;
  for (int c = 0; c < 19; ++c)
  {
    samples.push_back(family.circleSample(random.uniform(0.0, 6.283)));
  }
  samples[2].point.y = NAN;
  samples[5].tangent = Vec3{};
  samples[11].point.x = INFINITY;
  return samples;
}

// body(offset, count) for every run of `size` samples: every length at every offset.
template <class Body>
void forEveryRun(std::size_t size, Body body)
{
  for (std::size_t offset = 0; offset < size; ++offset)
  {
    for (std::size_t count = 0; offset + count <= size; ++count)
    {
      body(offset, count);
    }
  }
}

// pointsAndNormals, eight samples side by side, against firstDerivatives then surfaceNormal one
// sample at a time, bit for bit: trialFamily's families at 1, 1e-120 and 1e120 (squared
// derivative lengths outside [2^-200, 2^200]: the lane takes surfaceNormal itself), trialSamples
// and a tangent of 1e150 (out of range), in runs of every length at every offset.
TEST(BoostedCircleDerivatives, PointsAndNormalsAreTheOneSampleCodeBitForBit)
{
  cgatest::Random random(1307);
  int kinds[3] = { 0, 0, 0 };
  for (double scale : { 1.0, 1e-120, 1e120 })
  {
    for (int trial = 0; trial < 6; ++trial)
    {
      const BoostedCircle family = trialFamily(random, scale, trial % 3);
      const BoostedCircleRow row(family, random.uniform(-0.5, 0.5));
      std::vector<BoostedCircle::CircleSample> samples = trialSamples(random, family);
      samples[7].tangent = 1e150 * samples[7].tangent;
      forEveryRun(samples.size(), [&](std::size_t offset, std::size_t count) {
        const Vec3 untouched{ 42.0, 42.0, 42.0 };
        std::vector<Vec3> points(count + 1, untouched), normals(count + 1, untouched);
        std::vector<unsigned char> state(count + 1, 9);
        row.pointsAndNormals(
          samples.data() + offset, count, points.data(), normals.data(), state.data());
        for (std::size_t i = 0; i < count; ++i)
        {
          SurfaceDerivatives x;
          Vec3 normal = untouched;
          const bool mapped = row.firstDerivatives(samples[offset + i], x);
          const unsigned char expected = !mapped ? 0 : surfaceNormal(x.du, x.dv, normal) ? 2 : 1;
          ASSERT_EQ(state[i], expected) << scale << " " << offset << " " << i;
          ++kinds[expected];
          const Vec3 point = mapped ? x.point : untouched;
          EXPECT_EQ(0, std::memcmp(&points[i], &point, sizeof point)) << offset << " " << i;
          EXPECT_EQ(0, std::memcmp(&normals[i], &normal, sizeof normal)) << offset << " " << i;
        }
        EXPECT_EQ(state[count], 9); // nothing written past the run
        EXPECT_EQ(points[count].x, 42.0);
        EXPECT_EQ(normals[count].x, 42.0);
      });
    }
  }
  // Every outcome was met (the not-finite samples, the zero tangent, the regular ones).
  EXPECT_GT(kinds[0], 0);
  EXPECT_GT(kinds[1], 0);
  EXPECT_GT(kinds[2], 0);
}

bool sameBits(double a, double b)
{
  return std::memcmp(&a, &b, sizeof a) == 0;
}

bool sameBits(Vec3 a, Vec3 b)
{
  return sameBits(a.x, b.x) && sameBits(a.y, b.y) && sameBits(a.z, b.z);
}

// curvatures, eight samples side by side, against derivatives then surfaceCurvature one sample at
// a time, bit for bit (member by member): trialFamily's families at 1, 1e-120, 1e-78 (where the
// area element's square is subnormal without the rescaling) and 1e120 (first derivatives
// rescaled: the lane takes surfaceCurvature itself), trialSamples and second derivatives of 1e200
// (the radius beyond the lanes' range), 2^120 and 2^300 (where surfaceCurvature rescales them:
// the lane takes it too) and 0, in runs of every length at every offset.
TEST(BoostedCircleDerivatives, CurvaturesAreTheOneSampleCodeBitForBit)
{
  cgatest::Random random(1308);
  int regular = 0, degenerate = 0, unmapped = 0;
  for (double scale : { 1.0, 1e-120, 1e-78, 1e120 })
  {
    for (int trial = 0; trial < 6; ++trial)
    {
      const BoostedCircle family = trialFamily(random, scale, trial % 3);
      const BoostedCircleRow row(family, random.uniform(-0.5, 0.5));
      std::vector<BoostedCircle::CircleSample> samples = trialSamples(random, family);
      samples[7].second = 1e200 * samples[7].second;
      samples[9].second = Vec3{};
      samples[12].second = 0x1p120 * samples[12].second;
      samples[13].second = 0x1p300 * samples[13].second;
      forEveryRun(samples.size(), [&](std::size_t offset, std::size_t count) {
        const Vec3 untouched{ 42.0, 42.0, 42.0 };
        std::vector<Vec3> points(count + 1, untouched);
        std::vector<SurfaceCurvature> curvatures(count + 1);
        curvatures[count].k1 = 42.0;
        std::unique_ptr<bool[]> mapped(new bool[count + 1]);
        mapped[count] = true;
        row.curvatures(
          samples.data() + offset, count, points.data(), curvatures.data(), mapped.get());
        for (std::size_t i = 0; i < count; ++i)
        {
          SurfaceDerivatives x;
          const bool expectedMapped = row.derivatives(samples[offset + i], x);
          ASSERT_EQ(mapped[i], expectedMapped) << scale << " " << offset << " " << i;
          if (!expectedMapped)
          {
            ++unmapped;
            EXPECT_TRUE(sameBits(points[i], untouched));
            continue;
          }
          EXPECT_TRUE(sameBits(points[i], x.point)) << scale << " " << offset << " " << i;
          const SurfaceCurvature expected = surfaceCurvature(x);
          const SurfaceCurvature& k = curvatures[i];
          (expected.regular ? regular : degenerate) += 1;
          EXPECT_EQ(k.regular, expected.regular);
          EXPECT_TRUE(sameBits(k.normal, expected.normal) && sameBits(k.k1, expected.k1) &&
            sameBits(k.k2, expected.k2) && sameBits(k.direction1, expected.direction1) &&
            sameBits(k.direction2, expected.direction2) &&
            sameBits(k.gaussian, expected.gaussian) && sameBits(k.mean, expected.mean))
            << scale << " " << offset << " " << i;
        }
        EXPECT_TRUE(mapped[count]); // nothing written past the run
        EXPECT_EQ(points[count].x, 42.0);
        EXPECT_EQ(curvatures[count].k1, 42.0);
      });
    }
  }
  EXPECT_GT(regular, 0);
  EXPECT_GT(degenerate, 0);
  EXPECT_GT(unmapped, 0);
}
} // namespace
