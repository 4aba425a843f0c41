// cga::HopfSampling: the base points of the Hopf fibration's rows (grid with meridian or latitude
// strips, base points, directions of input points) against their closed forms, and every refusal.
#include "TestSupport.h"

#include "cga/surfaces/HopfSampling.h"

#include <limits>

namespace
{
using namespace cga;
using cgatest::Random;

constexpr double kPi = 3.14159265358979323846;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

HopfSampling grid(int nTheta, int nPhi, bool latitudes)
{
  HopfSampling s;
  s.thetaRange[0] = 0.25;
  s.thetaRange[1] = 2.0;
  s.phiRange[0] = -1.0;
  s.phiRange[1] = 0.5;
  s.thetaResolution = nTheta;
  s.phiResolution = nPhi;
  s.latitudeStrips = latitudes;
  return s;
}

TEST(HopfSampling, MeridianStripsAreThetaMajorWithAHalfOpenThetaAndAClosedPhi)
{
  const HopfSampling s = grid(4, 3, false);
  HopfRows rows;
  ASSERT_EQ(s.sample(rows), "");
  ASSERT_EQ(rows.size(), 12u);
  EXPECT_EQ(s.rowCount(), 12);
  EXPECT_EQ(rows.rowsPerStrip, 3);
  EXPECT_EQ(rows.stripLength(), 3u);
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      const size_t r = 3 * i + j;
      EXPECT_NEAR(rows.theta[r], 0.25 + 1.75 * i / 4.0, 1e-15) << r;
      EXPECT_NEAR(rows.phi[r], -1.0 + 0.75 * j, 1e-15) << r;
      EXPECT_EQ(rows.strip[r], i) << r;
    }
  }
  EXPECT_EQ(rows.phi[2], 0.5); // the range's ends exactly
  EXPECT_EQ(rows.theta[0], 0.25);
}

TEST(HopfSampling, LatitudeStripsArePhiMajorThroughBothThetaEnds)
{
  const HopfSampling s = grid(4, 3, true);
  HopfRows rows;
  ASSERT_EQ(s.sample(rows), "");
  ASSERT_EQ(rows.size(), 15u);
  EXPECT_EQ(s.rowCount(), 15);
  EXPECT_EQ(rows.rowsPerStrip, 5);
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i <= 4; ++i)
    {
      const size_t r = 5 * j + i;
      EXPECT_NEAR(rows.theta[r], 0.25 + 1.75 * i / 4.0, 1e-15) << r;
      EXPECT_NEAR(rows.phi[r], -1.0 + 0.75 * j, 1e-15) << r;
      EXPECT_EQ(rows.strip[r], j) << r;
    }
    EXPECT_EQ(rows.theta[5 * j + 4], 2.0);
  }
}

TEST(HopfSampling, OneLatitudeIsTheRangeStartAndPolesAreClamped)
{
  HopfSampling s = grid(2, 1, false);
  HopfRows rows;
  ASSERT_EQ(s.sample(rows), "");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows.phi[0], -1.0);
  EXPECT_EQ(rows.phi[1], -1.0);

  // Round-off beyond the poles (within 1e-12) is clamped onto them.
  s.phiResolution = 2;
  s.phiRange[0] = -kPi / 2 - 1e-13;
  s.phiRange[1] = kPi / 2 + 1e-13;
  ASSERT_EQ(s.sample(rows), "");
  EXPECT_EQ(rows.phi[0], -1.5707963267948966);
  EXPECT_EQ(rows.phi[1], 1.5707963267948966);
}

TEST(HopfSampling, RowCountDoesNotOverflow)
{
  HopfSampling s = grid(100000, 100000, true);
  EXPECT_EQ(s.rowCount(), 100001LL * 100000LL);
  s.latitudeStrips = false;
  EXPECT_EQ(s.rowCount(), 100000LL * 100000LL);
  s.thetaResolution = 0;
  EXPECT_EQ(s.rowCount(), 0);
}

TEST(HopfSampling, BadGridsAreRefused)
{
  auto problem = [](void (*breaker)(HopfSampling&)) {
    HopfSampling s = grid(4, 3, false);
    breaker(s);
    HopfRows rows;
    return s.sample(rows);
  };
  EXPECT_NE(problem([](HopfSampling& s) { s.thetaResolution = 0; }), "");
  EXPECT_NE(problem([](HopfSampling& s) { s.phiResolution = 0; }), "");
  EXPECT_NE(problem([](HopfSampling& s) { s.thetaRange[1] = kNaN; }), "");
  EXPECT_NE(problem([](HopfSampling& s) { s.phiRange[0] = -std::numeric_limits<double>::infinity(); }), "");
  EXPECT_NE(problem([](HopfSampling& s) { s.thetaRange[0] = 3.0; }), ""); // inverted
  EXPECT_NE(problem([](HopfSampling& s) { s.phiRange[0] = 0.6; }), "");   // inverted
  EXPECT_NE(problem([](HopfSampling& s) { s.phiRange[1] = kPi / 2 + 1e-9; }), "");
  EXPECT_NE(problem([](HopfSampling& s) { s.phiRange[0] = -2.0; }), "");
  EXPECT_EQ(problem([](HopfSampling&) {}), "");
}

TEST(HopfSampling, AnOverflowingThetaSpanIsNamedAsSuch)
{
  HopfSampling s = grid(4, 3, false);
  s.thetaRange[0] = -1e308;
  s.thetaRange[1] = 1e308; // both finite, their difference is not
  HopfRows rows;
  const std::string problem = s.sample(rows);
  EXPECT_NE(problem.find("ThetaRange's span (maximum - minimum) overflows"), std::string::npos)
    << problem;
  EXPECT_EQ(problem.find("finite"), std::string::npos) << problem;
}

TEST(HopfSampling, BasePointsAreTakenInOrderAsOneStrip)
{
  HopfSampling s;
  s.mode = HopfSamplingMode::BasePoints;
  s.basePoints = { 0.5, 0.25, -3.0, -1.5, 7.0, kPi / 2 + 1e-13, 99.0 }; // an odd last value
  EXPECT_EQ(s.rowCount(), 3);
  HopfRows rows;
  ASSERT_EQ(s.sample(rows), "");
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(rows.rowsPerStrip, 0);
  EXPECT_EQ(rows.stripLength(), 3u);
  EXPECT_EQ(rows.theta[0], 0.5);
  EXPECT_EQ(rows.phi[0], 0.25);
  EXPECT_EQ(rows.theta[1], -3.0); // theta is periodic: any value
  EXPECT_EQ(rows.phi[1], -1.5);
  EXPECT_EQ(rows.phi[2], 1.5707963267948966); // clamped onto the pole
  for (int strip : rows.strip)
  {
    EXPECT_EQ(strip, 0);
  }

  s.basePoints = { 0.5, kNaN };
  EXPECT_NE(s.sample(rows), "");
  s.basePoints = { std::numeric_limits<double>::infinity(), 0.0 };
  EXPECT_NE(s.sample(rows), "");
  s.basePoints = { 0.0, 1.6 };
  EXPECT_NE(s.sample(rows), "");
  s.basePoints.clear();
  ASSERT_EQ(s.sample(rows), "");
  EXPECT_EQ(rows.size(), 0u);
}

TEST(HopfSampling, InputPointsGiveTheDirectionFromTheSphereCenter)
{
  Random random(15);
  std::vector<Vec3> points(200);
  for (Vec3& p : points)
  {
    p = random.vec3(5.0);
  }
  const Vec3 center{ 0.5, -1.0, 2.0 };
  points[17] = center; // no direction: skipped
  points[50] = center + Vec3{ 0.0, 0.0, 3.0 };  // the north pole
  points[51] = center + Vec3{ 0.0, 0.0, -1e-3 }; // the south pole

  HopfSampling s;
  s.mode = HopfSamplingMode::InputPoints;
  s.sphereCenter = center;
  s.inputCount = points.size();
  s.point = [&points](size_t i) { return points[i]; };
  EXPECT_EQ(s.rowCount(), 200);
  HopfRows rows;
  ASSERT_EQ(s.sample(rows), "");
  ASSERT_EQ(rows.size(), 199u);
  EXPECT_EQ(rows.skipped, 1u);
  for (size_t i = 0, r = 0; i < points.size(); ++i)
  {
    if (i == 17)
    {
      continue;
    }
    // The base point's unit vector points along p - center.
    const Vec3 d = points[i] - center;
    const Vec3 base{ std::cos(rows.phi[r]) * std::cos(rows.theta[r]),
      std::cos(rows.phi[r]) * std::sin(rows.theta[r]), std::sin(rows.phi[r]) };
    EXPECT_LE(norm(cross(base, d / norm(d))), 1e-15) << i;
    EXPECT_GT(dot(base, d), 0.0) << i;
    EXPECT_LE(std::fabs(rows.phi[r]), kPi / 2) << i;
    ++r;
  }
  EXPECT_EQ(rows.phi[49], kPi / 2); // point 50, after the skipped 17
  EXPECT_EQ(rows.phi[50], -kPi / 2);

  points[3].y = kNaN;
  EXPECT_NE(s.sample(rows), "");
  points[3].y = 0.0;
  s.sphereCenter.x = std::numeric_limits<double>::infinity();
  EXPECT_NE(s.sample(rows), "");
  s.sphereCenter = center;
  s.point = nullptr; // no input
  EXPECT_NE(s.sample(rows), "");
}
} // namespace
