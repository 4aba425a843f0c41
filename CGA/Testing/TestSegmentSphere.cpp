// SegmentSphere.h: the crossing of a segment with a sphere, against the sphere's equation and the
// segment's line, including far outside points (the huge fibers near the Hopf north pole).
#include "TestSupport.h"

#include "cga/SegmentSphere.h"

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
} // namespace
