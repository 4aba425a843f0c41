// The Hopf fibration of docs/conventions.md section 4 (HopfFibration.h): the paper's boost-and-twist
// construction against the full multivector product, fibers that are circles, disjoint and linked
// once, the poles, and the classical mode against the stereographic images of S^3 great circles.
#include "LinkingNumber.h"
#include "TestSupport.h"

#include "cga/Conformal.h"
#include "cga/Exponential.h"
#include "cga/Logarithm.h"
#include "cga/PointSandwich.h"
#include "cga/surfaces/HopfFibration.h"

#include <complex>
#include <cstring>

namespace
{
using namespace cga;
using cgatest::gaussLinkingIntegral;
using cgatest::Random;
using cgatest::relativeDifference;
using cgatest::worseOf;

constexpr double kPi = 3.14159265358979323846;

struct EuclideanCircle
{
  Vec3 center, normal;
  double radius = 0.0;
};

// Circumcircle of three points, by plain Euclidean geometry (independent of the algebra).
EuclideanCircle circumcircle(Vec3 a, Vec3 b, Vec3 c)
{
  const Vec3 u = b - a, v = c - a;
  const Vec3 w = cross(u, v);
  const Vec3 offset = (norm2(u) * cross(v, w) + norm2(v) * cross(w, u)) / (2.0 * norm2(w));
  return { a + offset, normalized(w), norm(offset) };
}

// Largest distance of the points from the circle (in its plane and at its radius), relative to
// the radius.
double cocircularity(const std::vector<Vec3>& points, const EuclideanCircle& c)
{
  double worst = 0.0;
  for (Vec3 p : points)
  {
    const Vec3 d = p - c.center;
    const double height = dot(d, c.normal);
    const double inPlane = norm(d - height * c.normal);
    worst = worseOf(worst, worseOf(std::fabs(height) / c.radius, std::fabs(inPlane - c.radius) / c.radius));
  }
  return worst;
}

std::vector<HopfFibration> bothModes()
{
  HopfFibration paper, classical;
  classical.mode = HopfMode::Classical;
  return { paper, classical };
}

// Linking number of the circle through `a` (oriented by the order of its points) with the closed
// polygon `b`: signed crossings of b through the disk that a bounds.
int linkingNumber(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
  const std::size_t n = a.size();
  const EuclideanCircle circle = circumcircle(a[0], a[n / 3], a[(2 * n) / 3]);
  Vec3 newell{ 0, 0, 0 };
  for (std::size_t i = 0; i < n; ++i)
  {
    newell = newell + cross(a[i] - circle.center, a[(i + 1) % n] - circle.center);
  }
  const Vec3 normal = normalized(newell);
  int link = 0;
  for (std::size_t i = 0; i < b.size(); ++i)
  {
    const Vec3 p = b[i], q = b[(i + 1) % b.size()];
    const double dp = dot(p - circle.center, normal), dq = dot(q - circle.center, normal);
    if ((dp < 0.0) == (dq < 0.0))
    {
      continue;
    }
    const Vec3 x = p + (dp / (dp - dq)) * (q - p);
    if (norm(x - circle.center) < circle.radius)
    {
      link += dq > dp ? 1 : -1;
    }
  }
  return link;
}

double minimumDistance(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
  double d = std::numeric_limits<double>::infinity();
  for (Vec3 p : a)
  {
    for (Vec3 q : b)
    {
      d = std::min(d, norm(p - q));
    }
  }
  return d;
}

TEST(HopfFibration, BoostStraightensCircleIntoLineTheta)
{
  // K(theta, pi/2) C ~K is the line through v/2 along (-sin, cos, 0), with the same orientation
  // as boostedLine(); -ni _| C is the z axis, oriented as baseAxis().
  for (double theta : { 0.0, 0.4, 1.9, 3.0, 4.4, 6.0 })
  {
    const Multivector image =
      sandwich(HopfFibration::paperBoost(theta, 0.5 * kPi), HopfFibration::baseCircle()).dual();
    const Multivector line = HopfFibration::boostedLine(theta);
    const double scale = -scalarProduct(image, line);
    EXPECT_GT(scale, 0.0);
    EXPECT_LE(relativeDifference(image, scale * line), 1e-13) << "theta " << theta;
  }
  const Multivector axis = -leftContraction(ni(), HopfFibration::baseCircle());
  const double scale = -scalarProduct(axis, HopfFibration::baseAxis());
  EXPECT_GT(scale, 0.0);
  EXPECT_LE(relativeDifference(axis, scale * HopfFibration::baseAxis()), 1e-15);
}

TEST(HopfFibration, HalfLogTwistCarriesLineThetaOntoAxis)
{
  for (double theta : { 0.0, 0.4, 1.9, 3.0, 4.4, 6.0 })
  {
    Multivector twist;
    ASSERT_TRUE(HopfFibration::paperTwist(theta, 0.5 * kPi, twist));
    EXPECT_LE(relativeDifference(
                sandwich(twist, HopfFibration::boostedLine(theta)), HopfFibration::baseAxis()),
      1e-12)
      << "theta " << theta;
    // Without the 1/2 (exp(log(L L_theta^-1)) = the ratio itself) the line does not land on the
    // axis: the ratio is the square of the motor, a half-turn screw.
    const Multivector ratio =
      HopfFibration::baseAxis() * versorInverse(HopfFibration::boostedLine(theta));
    EXPECT_GT(relativeDifference(
                sandwich(ratio, HopfFibration::boostedLine(theta)), HopfFibration::baseAxis()),
      0.5);
  }
}

TEST(HopfFibration, TwistIsAQuarterScrewAboutTheCommonPerpendicular)
{
  // For theta = 0, M(k) L_0 ~M is the line through ((1 - k)/2, 0, 0) with direction
  // (0, cos(k pi/2), sin(k pi/2)): a screw about the x axis (the closed form Examples/fig4 draws).
  for (double k : { 0.0, 0.2, 0.5, 0.8, 1.0 })
  {
    Multivector twist;
    ASSERT_TRUE(HopfFibration::paperTwist(0.0, (k - 0.5) * kPi, twist));
    const Multivector image = sandwich(twist, HopfFibration::boostedLine(0.0));
    const Multivector expected = dualLine(
      { 0.5 * (1.0 - k), 0.0, 0.0 }, { 0.0, std::cos(0.5 * k * kPi), std::sin(0.5 * k * kPi) });
    EXPECT_LE(relativeDifference(image, expected / std::sqrt(-scalarProduct(expected, expected))),
      1e-12)
      << "k " << k;
  }
}

TEST(HopfFibration, FastVersorAndPointsMatchFullProduct)
{
  Random random(401);
  for (HopfFibration hopf : bothModes())
  {
    for (int n = 0; n < 200; ++n)
    {
      hopf.center = random.vec3(2.0);
      hopf.normal = random.unit();
      hopf.radius = random.uniform(0.2, 3.0);
      const double theta = random.uniform(-kPi, 3.0 * kPi);
      const double phi = random.uniform(-0.5 * kPi, 0.5 * kPi - 0.05);
      Even fast;
      Multivector reference;
      ASSERT_TRUE(hopf.versor(theta, phi, fast));
      ASSERT_TRUE(hopf.versorReference(theta, phi, reference));
      EXPECT_LE(relativeDifference(toMultivector(fast), reference), 1e-12);
      std::vector<Vec3> points;
      ASSERT_TRUE(hopf.fiberPoints(theta, phi, 7, points));
      for (int j = 0; j < 7; ++j)
      {
        const double t = 2.0 * kPi * j / 7;
        const Vec3 expected =
          hopf.toWorld(transformPoint(reference, { std::cos(t), std::sin(t), 0.0 }));
        EXPECT_TRUE(cgatest::pointsNear(points[j], expected, 1e-10));
      }
    }
  }
}

TEST(HopfFibration, FibersAreCircles)
{
  Random random(402);
  for (HopfFibration hopf : bothModes())
  {
    for (int n = 0; n < 300; ++n)
    {
      hopf.center = random.vec3(1.0);
      hopf.normal = random.unit();
      hopf.radius = random.uniform(0.5, 2.0);
      const double theta = random.uniform(0.0, 2.0 * kPi);
      const double phi = random.uniform(-0.5 * kPi, 0.5 * kPi - 0.1);
      std::vector<Vec3> points;
      ASSERT_TRUE(hopf.fiberPoints(theta, phi, 24, points));
      const EuclideanCircle circle = circumcircle(points[0], points[8], points[16]);
      EXPECT_LE(cocircularity(points, circle), 1e-9) << "theta " << theta << " phi " << phi;
    }
  }
}

TEST(HopfFibration, SouthPoleIsTheCircleAndNorthPoleTheAxis)
{
  HopfFibration hopf;
  hopf.center = { 0.5, -1.0, 2.0 };
  hopf.normal = { 1.0, 2.0, -0.5 };
  hopf.radius = 1.5;
  const Vec3 n = normalized(hopf.normal);
  for (HopfMode mode : { HopfMode::Paper, HopfMode::Classical })
  {
    hopf.mode = mode;
    for (double theta : { 0.0, 0.3, 1.0, 2.5, 3.5, 5.0, 6.2 })
    {
      std::vector<Vec3> points;
      ASSERT_TRUE(hopf.fiberPoints(theta, -0.5 * kPi, 16, points));
      for (Vec3 p : points)
      {
        const Vec3 d = p - hopf.center;
        EXPECT_NEAR(dot(d, n), 0.0, 1e-12);
        EXPECT_NEAR(norm(d), hopf.radius, 1e-12);
      }
      ASSERT_TRUE(hopf.fiberPoints(theta, 0.5 * kPi, 16, points));
      int onAxis = 0;
      for (Vec3 p : points)
      {
        if (isFinite(p))
        {
          const Vec3 d = p - hopf.center;
          EXPECT_LE(norm(d - dot(d, n) * n), 1e-12 * std::max(1.0, norm(d)));
          ++onAxis;
        }
      }
      EXPECT_GE(onAxis, 15); // at most one point goes to infinity
    }
  }
}

TEST(HopfFibration, FiberPointsAreTheOnePointFormulaBitForBit)
{
  // fiberPoints maps a fiber's circle eight points at a time: each point is the one-point formula
  // to the bit (up, the versor's point map, the weight test against the largest component,
  // normalizePoint, the world frame center + radius (x a + y b + z n)), NaN where that formula
  // drops the point; both modes, a moved and scaled frame, 19 points (a partial block), and
  // fibers through the point at infinity.
  Random random(409);
  int dropped = 0;
  for (HopfFibration hopf : bothModes())
  {
    hopf.center = { 0.3, -1.7, 2.0 };
    hopf.radius = 2.5;
    hopf.normal = { 0.2, -0.4, 0.9 };
    const Vec3 n = normalized(hopf.normal), a = orthogonalUnit(n), b = cross(n, a);
    for (int trial = 0; trial < 12; ++trial)
    {
      // Trials 0 to 3: theta a multiple of pi/2 on phi = pi/2, where one of 40 points lands on
      // the point at infinity; the others random, 19 points.
      const bool throughInfinity = trial < 4;
      const double theta = throughInfinity ? 0.5 * kPi * trial : random.uniform(0.0, 2.0 * kPi);
      const double phi = throughInfinity ? 0.5 * kPi : random.uniform(0.0, kPi);
      const std::vector<Vec3> circle = HopfFibration::circleSamples(throughInfinity ? 40 : 19);
      std::vector<Vec3> points(circle.size());
      Even kh;
      ASSERT_TRUE(hopf.versor(theta, phi, kh));
      ASSERT_TRUE(hopf.fiberPoints(theta, phi, circle, points.data()));
      const PointMap map(kh);
      for (std::size_t j = 0; j < circle.size(); ++j)
      {
        const ConformalVector image = map.apply(ConformalVector::point(circle[j]));
        Vec3 p;
        if (std::fabs(image.weight()) > 1e-13 * image.maxAbs() && normalizePoint(image, p))
        {
          const Vec3 expected = hopf.center + hopf.radius * (p.x * a + p.y * b + p.z * n);
          EXPECT_EQ(0, std::memcmp(&points[j], &expected, sizeof expected))
            << "trial " << trial << " point " << j;
        }
        else
        {
          EXPECT_TRUE(std::isnan(points[j].x) && std::isnan(points[j].y) && std::isnan(points[j].z))
            << "trial " << trial << " point " << j;
          ++dropped;
        }
      }
    }
  }
  EXPECT_GT(dropped, 0); // the fibers through infinity drop a point
}

TEST(HopfFibration, FibersAreDisjointAndLinkedOnceWithOneSign)
{
  Random random(403);
  for (const HopfFibration& hopf : bothModes())
  {
    int sign = 0;
    for (int n = 0; n < 300; ++n)
    {
      const double theta1 = random.uniform(0.0, 2.0 * kPi), theta2 = random.uniform(0.0, 2.0 * kPi);
      const double phi1 = random.uniform(-0.5 * kPi + 0.05, 0.5 * kPi - 0.3);
      const double phi2 = random.uniform(-0.5 * kPi + 0.05, 0.5 * kPi - 0.3);
      std::vector<Vec3> a, b;
      ASSERT_TRUE(hopf.fiberPoints(theta1, phi1, 720, a));
      ASSERT_TRUE(hopf.fiberPoints(theta2, phi2, 720, b));
      EXPECT_GT(minimumDistance(a, b), 1e-4);
      const int link = linkingNumber(a, b);
      EXPECT_EQ(std::abs(link), 1) << "(" << theta1 << ", " << phi1 << ") (" << theta2 << ", "
                                   << phi2 << ")";
      EXPECT_EQ(link, linkingNumber(b, a)); // the linking number is symmetric
      if (n % 10 == 0)
      {
        // The Gauss integral agrees (it converges slowly where the fibers come close).
        EXPECT_NEAR(gaussLinkingIntegral(a, b), link, 0.05);
      }
      if (sign == 0)
      {
        sign = link;
      }
      EXPECT_EQ(link, sign);
    }
  }
}

// The unit 3-sphere point of x: up(x) normalized to e- coefficient 1, on e1, e2, e3, e+, as the
// pair (z1, z2) = (s1 + i s2, s3 - i s+).
std::pair<std::complex<double>, std::complex<double>> liftToS3(Vec3 x)
{
  const double q = norm2(x);
  return { { 2.0 * x.x / (1.0 + q), 2.0 * x.y / (1.0 + q) },
    { 2.0 * x.z / (1.0 + q), -(1.0 - q) / (1.0 + q) } };
}

// Inverse of liftToS3: stereographic projection from s = -e+.
Vec3 stereographic(std::complex<double> z1, std::complex<double> z2)
{
  const double sPlus = -z2.imag();
  return Vec3{ z1.real(), z1.imag(), z2.real() } / (1.0 + sPlus);
}

TEST(HopfFibration, ClassicalFibersAreStereographicGreatCircles)
{
  HopfFibration hopf;
  hopf.mode = HopfMode::Classical;
  Random random(404);
  for (int n = 0; n < 300; ++n)
  {
    const double theta = random.uniform(0.0, 2.0 * kPi);
    const double phi = random.uniform(-0.5 * kPi, 0.5 * kPi - 0.1);
    std::vector<Vec3> fiber;
    ASSERT_TRUE(hopf.fiberPoints(theta, phi, 12, fiber));
    const EuclideanCircle circle = circumcircle(fiber[0], fiber[4], fiber[8]);
    // The great circle e^{it}(z1, z2) through one fiber point, projected back, is the fiber.
    const auto [z1, z2] = liftToS3(fiber[0]);
    std::vector<Vec3> greatCircle;
    for (int j = 0; j < 16; ++j)
    {
      const std::complex<double> phase = std::polar(1.0, 2.0 * kPi * (j + 0.5) / 16);
      const std::complex<double> w1 = phase * z1, w2 = phase * z2;
      if (1.0 - w2.imag() > 1e-3) // skip the point near the projection pole
      {
        greatCircle.push_back(stereographic(w1, w2));
      }
    }
    EXPECT_LE(cocircularity(greatCircle, circle), 1e-9);
    // Its Hopf image (2 z1 conj(z2), |z1|^2 - |z2|^2) is the base point in the closed form
    // (cos phi cos(theta + pi/2), cos phi sin(theta + pi/2), -sin phi).
    const std::complex<double> h = 2.0 * z1 * std::conj(z2);
    const Vec3 base{ std::cos(phi) * std::cos(theta + 0.5 * kPi),
      std::cos(phi) * std::sin(theta + 0.5 * kPi), -std::sin(phi) };
    EXPECT_TRUE(cgatest::pointsNear({ h.real(), h.imag(), std::norm(z1) - std::norm(z2) }, base, 1e-12));
  }
}

double relativeCommutator(const Multivector& a, const Multivector& b)
{
  return (a * b - b * a).coefficientNorm() / (a * b).coefficientNorm();
}

TEST(HopfFibration, AntipodalFibersAreOrthogonalAndOnlyClassicalOnesCommute)
{
  HopfFibration paper, classical;
  classical.mode = HopfMode::Classical;
  Random random(405);
  double worstPaperCommutator = 0.0;
  for (int n = 0; n < 100; ++n)
  {
    const double theta = random.uniform(0.0, 2.0 * kPi);
    const double phi = random.uniform(-0.5 * kPi + 0.1, 0.5 * kPi - 0.1);
    for (const HopfFibration* hopf : { &paper, &classical })
    {
      Multivector f1, f2;
      ASSERT_TRUE(hopf->fiberBladeReference(theta, phi, f1));
      ASSERT_TRUE(hopf->fiberBladeReference(theta + kPi, -phi, f2));
      // Orthogonal: <F1 F2>_0 = 0 relative to |F1| |F2|.
      EXPECT_LE(std::fabs(scalarProduct(f1, f2)) / (f1.coefficientNorm() * f2.coefficientNorm()), 1e-12);
      const double commutator = relativeCommutator(f1, f2);
      if (hopf == &classical)
      {
        EXPECT_LE(commutator, 1e-12);
      }
      else
      {
        worstPaperCommutator = worseOf(worstPaperCommutator, commutator);
      }
    }
  }
  EXPECT_GT(worstPaperCommutator, 0.05); // the paper's construction is not the round fibration
}

TEST(HopfFibration, BadParameters)
{
  HopfFibration hopf;
  EXPECT_TRUE(hopf.validate().empty());
  hopf.radius = 0.0;
  EXPECT_FALSE(hopf.validate().empty());
  hopf.radius = 1.0;
  hopf.normal = { 0, 0, 0 };
  EXPECT_FALSE(hopf.validate().empty());
  hopf.normal = { 0, 0, 1 };
  hopf.center = { std::nan(""), 0, 0 };
  EXPECT_FALSE(hopf.validate().empty());
  hopf.center = { 0, 0, 0 };
  Even k;
  std::vector<Vec3> points;
  EXPECT_FALSE(hopf.versor(std::nan(""), 0.0, k));
  EXPECT_FALSE(hopf.fiberPoints(0.0, std::nan(""), 8, points));
  EXPECT_TRUE(points.empty());
}

TEST(HopfFibration, CircleNormalOfAnyNonZeroLengthGivesTheSameFrame)
{
  HopfFibration unit;
  unit.normal = Vec3{ 1, 2, 2 } / 3.0;
  const Vec3 p{ 0.3, -0.4, 0.5 };
  for (const double length : { 1e-300, 1e-200, 1e200, 1e307 })
  {
    HopfFibration scaled = unit;
    scaled.normal = length * unit.normal;
    EXPECT_TRUE(scaled.validate().empty()) << "length " << length << ": " << scaled.validate();
    EXPECT_LT(norm(scaled.toWorld(p) - unit.toWorld(p)), 1e-15) << "length " << length;
  }
}
} // namespace
