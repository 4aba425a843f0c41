// SegmentSphere.h: the crossing of a segment with a sphere, against the sphere's equation and the
// segment's line, including far outside points (the huge fibers near the Hopf north pole).
#include "TestSupport.h"

#include "cga/SegmentSphere.h"

#include <limits>

namespace
{
using namespace cga;
using cgatest::Random;

TEST(SegmentSphere, CrossingLiesOnTheSphereAndOnTheSegment)
{
  Random random(77);
  for (int n = 0; n < 2000; ++n)
  {
    const Vec3 center = random.vec3(3.0);
    const double radius = random.uniform(0.1, 5.0);
    const Vec3 inside = center + random.uniform(0.0, 0.999) * radius * normalized(random.vec3(1.0));
    // From just outside to 1e8 radii away.
    const Vec3 outside =
      center + std::pow(10.0, random.uniform(0.0, 8.0)) * 1.001 * radius * normalized(random.vec3(1.0));
    const double s = segmentSphereExit(inside, outside, center, radius);
    ASSERT_GE(s, 0.0);
    ASSERT_LE(s, 1.0);
    const Vec3 onSegment = inside + s * (outside - inside);
    EXPECT_NEAR(norm(onSegment - center) / radius, 1.0, 1e-9);
    const Vec3 p = segmentSphereExitPoint(inside, outside, center, radius);
    EXPECT_NEAR(norm(p - center) / radius, 1.0, 1e-14);
    // On the line through the segment: the part of p - inside across it is round-off.
    const Vec3 d = normalized(outside - inside);
    const Vec3 offset = p - inside;
    EXPECT_LE(norm(offset - dot(offset, d) * d), 1e-9 * radius);
    EXPECT_GE(dot(offset, d), -1e-12 * radius);
  }
}

TEST(SegmentSphere, InsidePointOnTheSphereIsItsOwnCrossing)
{
  const Vec3 center{ 1.0, 2.0, 3.0 };
  const Vec3 onSphere = center + Vec3{ 0.0, 2.0, 0.0 };
  EXPECT_EQ(segmentSphereExit(onSphere, center + Vec3{ 0.0, 5.0, 0.0 }, center, 2.0), 0.0);
  // A segment along the diameter: the closed form s = (r - |u|)/|d|.
  EXPECT_NEAR(segmentSphereExit(center, center + Vec3{ 8.0, 0.0, 0.0 }, center, 2.0), 0.25, 1e-15);
}

// Found by the property fuzz (Testing/Python/test_property_fuzz.py --seed 7 --trial 116): a patch
// 1e20 from the origin, cut at a sphere of radius 100 whose center lies a subnormal 5e-324 off the
// sampled points. The crossing's step (0.6 % of 1e4) is below the spacing of doubles at 1e20, so
// the crossing rounds onto the center's line and its distance from the center is 5e-324:
// radius / distance overflowed, and the point became (NaN, inf, NaN).
TEST(SegmentSphere, ExitPointIsFiniteWhenTheCrossingRoundsOntoTheCenter)
{
  const Vec3 inside{ -0.63956858854195886, -0.0, -1e20 };
  const Vec3 outside{ -0.63956858854195886, -0.0, -9.9999999999999984e19 };
  const Vec3 center{ -0.63956858854195886, -4.9406564584124654e-324, -1e20 };
  const Vec3 p = segmentSphereExitPoint(inside, outside, center, 100.0);
  ASSERT_TRUE(isFinite(p)) << p.x << " " << p.y << " " << p.z;
  EXPECT_NEAR(norm(p - center), 100.0, 1e-12);
}

// An outside point near the largest double: the squared length of the segment overflows (the
// crossing parameter was NaN, clamped to 1: the outside point's end instead of the crossing), and
// with the center on the other side outside - inside itself overflows (the exit point was NaN).
TEST(SegmentSphere, SegmentsToPointsNearTheLargestDoubleHaveTheirCrossing)
{
  const double huge = std::numeric_limits<double>::max();
  const Vec3 center{ 1.0, 2.0, 3.0 };
  const Vec3 outside{ -0.5 * huge, 0.25 * huge, 0.0 };
  const double s = segmentSphereExit(center, outside, center, 2.0);
  // From the center, the crossing is one radius along the segment.
  EXPECT_NEAR(s * norm(outside - center) / 2.0, 1.0, 1e-12);
  const Vec3 p = segmentSphereExitPoint(center, outside, center, 2.0);
  EXPECT_NEAR(norm(p - center) / 2.0, 1.0, 1e-14);
  EXPECT_NEAR(dot(normalized(p - center), normalized(Vec3{ -1.0, 0.5, 0.0 })), 1.0, 1e-14);

  const Vec3 farCenter{ 0.9 * huge, 0.0, 0.0 };
  const Vec3 inside = farCenter + Vec3{ 0.0, 1.0, 0.0 };
  const Vec3 farOutside{ -huge, 0.0, 0.0 }; // outside - inside overflows to -inf
  const double t = segmentSphereExit(inside, farOutside, farCenter, 2.0);
  EXPECT_GE(t, 0.0);
  EXPECT_LE(t, 1e-300);
  const Vec3 q = segmentSphereExitPoint(inside, farOutside, farCenter, 2.0);
  ASSERT_TRUE(isFinite(q)) << q.x << " " << q.y << " " << q.z;
  EXPECT_NEAR(norm(q - farCenter) / 2.0, 1.0, 1e-12);
}
} // namespace
