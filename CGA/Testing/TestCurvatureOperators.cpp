// The curvature operators of docs/conventions.md section 3 items 5-8, 10, 11 (eq 15-18, 21-22, 24-26), checked
// against closed forms (circles, a quadric fit of the surface) and against the full Multivector
// product built from Conformal.h (an independent construction of every generator).
#include "TestSupport.h"

#include "cga/Conformal.h"
#include "cga/Exponential.h"
#include "cga/PointSandwich.h"
#include "cga/surfaces/CurvaturePatch.h"

#include <Eigen/Dense>

#include <limits>

namespace
{
using namespace cgatest;

Vec3 mapWith(const CurvaturePatch& patch, double a, double b)
{
  Vec3 out{ std::numeric_limits<double>::quiet_NaN(), 0, 0 };
  double weight = 0.0;
  EXPECT_TRUE(patch.map(a, b, out, weight)) << "a " << a << " b " << b;
  return out;
}

// Eq 15: the bent line is the circle of radius 1/|kappa| with center p - n/kappa, tangent at p.
TEST(CurvatureOperators, BentLineIsTheOsculatingCircle)
{
  Random random(15);
  for (int trial = 0; trial < 20; ++trial)
  {
    CurvaturePatch patch;
    patch.method = CurvatureMethod::BentLine;
    patch.frame = randomFrame(random);
    patch.kappaU = random.uniform(-3.0, 3.0);
    ASSERT_TRUE(patch.validate().empty());
    const double b = random.uniform(-1.0, 1.0);
    const Vec3 p = patch.frame.at(0.0, b);
    const Vec3 center = p - patch.frame.normal / patch.kappaU;
    // reference: the full product with K = 1 - kappa/2 tau(p, n) (docs/conventions.md item 5)
    const Multivector k =
      Multivector::scalar(1.0) - 0.5 * patch.kappaU * nullPointPair(p, patch.frame.normal);
    for (double a = -5.0; a <= 5.0; a += 0.25)
    {
      const Vec3 x = mapWith(patch, a, b);
      EXPECT_NEAR(norm(x - center), 1.0 / std::fabs(patch.kappaU), 1e-9);
      EXPECT_TRUE(pointsNear(x, transformPoint(k, patch.frame.at(a, b)), 1e-9));
    }
    EXPECT_TRUE(pointsNear(mapWith(patch, 0.0, b), p, 1e-12)); // p is fixed
    const double h = 1e-5;                                      // tangent at p is u
    const Vec3 tangent = (mapWith(patch, h, b) - mapWith(patch, -h, b)) / (2.0 * h);
    EXPECT_TRUE(pointsNear(tangent, patch.frame.u, 1e-8));
  }
}

// Eq 15: the generator with the tangent rotated by 180 degrees straightens the circle back.
TEST(CurvatureOperators, ReversedTangentStraightensTheCircle)
{
  Random random(16);
  for (int trial = 0; trial < 20; ++trial)
  {
    const PatchFrame frame = randomFrame(random);
    const double kappa = random.uniform(0.2, 3.0) * (trial % 2 ? 1.0 : -1.0);
    const CurvatureGenerator bend = bentLine(frame, kappa, 0.0);
    PatchFrame flipped = frame;
    flipped.normal = -frame.normal;
    const CurvatureGenerator straighten = bentLine(flipped, kappa, 0.0);
    for (double a = -4.0; a <= 4.0; a += 0.5)
    {
      Vec3 onCircle, back;
      ASSERT_TRUE(sandwichPoint(exponential(bend.exponent, ExponentialRule::Exact), frame.at(a, 0), onCircle));
      ASSERT_TRUE(sandwichPoint(exponential(straighten.exponent, ExponentialRule::Exact), onCircle, back));
      EXPECT_TRUE(pointsNear(back, frame.at(a, 0.0), 1e-9));
    }
  }
}

// Zero curvature is the identity; a huge curvature keeps every point finite and on the circle
// (the line never closes the circle: the far ends approach the antipode p - 2n/kappa).
TEST(CurvatureOperators, ZeroAndHugeCurvature)
{
  CurvaturePatch patch;
  patch.method = CurvatureMethod::BentLine;
  patch.kappaU = 0.0;
  ASSERT_TRUE(patch.validate().empty());
  for (double a = -2.0; a <= 2.0; a += 0.5)
  {
    EXPECT_TRUE(pointsNear(mapWith(patch, a, 0.3), patch.frame.at(a, 0.3), 0.0));
  }
  patch.method = CurvatureMethod::TranslatedTangents;
  patch.kappaV = 0.0;
  EXPECT_TRUE(pointsNear(mapWith(patch, 0.7, -0.4), patch.frame.at(0.7, -0.4), 0.0));

  patch.method = CurvatureMethod::BentLine;
  patch.kappaU = 1e6;
  const Vec3 center = patch.frame.origin - patch.frame.normal * 1e-6;
  for (double a = -2.0; a <= 2.0; a += 0.5)
  {
    const Vec3 x = mapWith(patch, a, 0.0);
    EXPECT_TRUE(isFinite(x));
    EXPECT_NEAR(norm(x - center), 1e-6, 1e-12);
  }
}

// A strip bent row by row (eq 15) is eq 16 with kappaV = 0 (the parabolic case).
TEST(CurvatureOperators, BentStripIsParabolicTranslatedTangents)
{
  Random random(17);
  CurvaturePatch strip, parabolic;
  strip.method = CurvatureMethod::BentLine;
  parabolic.method = CurvatureMethod::TranslatedTangents;
  strip.frame = parabolic.frame = randomFrame(random);
  strip.kappaU = parabolic.kappaU = 0.8;
  parabolic.kappaV = 0.0;
  for (double a = -2.0; a <= 2.0; a += 0.5)
  {
    for (double b = -2.0; b <= 2.0; b += 0.5)
    {
      EXPECT_TRUE(pointsNear(mapWith(strip, a, b), mapWith(parabolic, a, b), 1e-12));
    }
  }
}

// Principal curvatures at the patch origin from a least-squares quadric fit of the neighbourhood,
// in the frame (u, v, n): h = c0 + c1 x + c2 y + c3 x^2 + c4 x y + c5 y^2. Returns (k1 along u,
// k2 along v, mixed term) with the sign convention of eq 15 (positive: center on the -n side).
Eigen::Vector3d fittedCurvatures(const CurvaturePatch& patch, double radius)
{
  std::vector<Eigen::Matrix<double, 6, 1>> rows;
  std::vector<double> heights;
  for (int i = -4; i <= 4; ++i)
  {
    for (int j = -4; j <= 4; ++j)
    {
      const Vec3 d = mapWith(patch, radius * i / 4.0, radius * j / 4.0) - patch.frame.origin;
      const double x = dot(d, patch.frame.u), y = dot(d, patch.frame.v);
      Eigen::Matrix<double, 6, 1> row;
      row << 1.0, x, y, x * x, x * y, y * y;
      rows.push_back(row);
      heights.push_back(dot(d, patch.frame.normal));
    }
  }
  Eigen::MatrixXd a(rows.size(), 6);
  Eigen::VectorXd h(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i)
  {
    a.row(static_cast<Eigen::Index>(i)) = rows[i].transpose();
    h(static_cast<Eigen::Index>(i)) = heights[i];
  }
  const Eigen::VectorXd c = a.colPivHouseholderQr().solve(h);
  return { -2.0 * c(3), -2.0 * c(5), -c(4) };
}

// Eq 16: the principal curvatures at the origin are kappaU along u and kappaV along v, and the
// four presets of Fig 7 have the expected signs.
TEST(CurvatureOperators, TranslatedTangentsPrincipalCurvatures)
{
  Random random(18);
  for (int trial = 0; trial < 10; ++trial)
  {
    CurvaturePatch patch;
    patch.method = CurvatureMethod::TranslatedTangents;
    patch.frame = randomFrame(random);
    patch.kappaU = random.uniform(-2.0, 2.0);
    patch.kappaV = random.uniform(-2.0, 2.0);
    const Eigen::Vector3d k = fittedCurvatures(patch, 0.002);
    EXPECT_NEAR(k(0), patch.kappaU, 1e-5);
    EXPECT_NEAR(k(1), patch.kappaV, 1e-5);
    EXPECT_NEAR(k(2), 0.0, 1e-5); // u and v are the principal directions
  }

  struct Expected
  {
    CurvaturePreset preset;
    int signU, signV;
  };
  for (const Expected& e : { Expected{ CurvaturePreset::Parabolic, 1, 0 },
         Expected{ CurvaturePreset::Elliptic, 1, 1 }, Expected{ CurvaturePreset::Umbilic, 1, 1 },
         Expected{ CurvaturePreset::Hyperbolic, -1, 1 } })
  {
    CurvaturePatch patch;
    patch.method = CurvatureMethod::TranslatedTangents;
    presetCurvatures(e.preset, patch.kappaU, patch.kappaV);
    const Eigen::Vector3d k = fittedCurvatures(patch, 0.002);
    auto sign = [](double x) { return std::fabs(x) < 1e-6 ? 0 : (x > 0 ? 1 : -1); };
    EXPECT_EQ(sign(k(0)), e.signU);
    EXPECT_EQ(sign(k(1)), e.signV);
    if (e.preset == CurvaturePreset::Umbilic)
    {
      EXPECT_NEAR(k(0), k(1), 1e-6);
    }
    if (e.preset == CurvaturePreset::Elliptic)
    {
      EXPECT_GT(std::fabs(k(0) - k(1)), 0.1);
    }
  }
}

// Eq 16 sums two tangents of one direction: a 2-blade, so the paper's exponential is exact.
TEST(CurvatureOperators, TranslatedTangentsPaperIsExact)
{
  Random random(19);
  CurvaturePatch exact, paper;
  exact.method = paper.method = CurvatureMethod::TranslatedTangents;
  exact.frame = paper.frame = randomFrame(random);
  exact.kappaU = paper.kappaU = -0.7;
  exact.kappaV = paper.kappaV = 1.3;
  paper.rule = ExponentialRule::Paper;
  for (double a = -2.0; a <= 2.0; a += 0.5)
  {
    for (double b = -2.0; b <= 2.0; b += 0.5)
    {
      EXPECT_TRUE(pointsNear(mapWith(exact, a, b), mapWith(paper, a, b), 1e-12));
    }
  }
}

// Eq 18 closed form against (up(p) _| (sigma ^ pi))^2 in the full algebra; zero on the circle.
TEST(CurvatureOperators, SquaredCircleDistanceMatchesTheDualCircle)
{
  Random random(20);
  for (int trial = 0; trial < 50; ++trial)
  {
    const Vec3 c = random.vec3(2.0), m = random.unit(), p = random.vec3(3.0);
    const double r = random.uniform(0.1, 3.0);
    const Multivector sigma = up(c) - 0.5 * r * r * ni();
    const Multivector pi = vector(m) + dot(m, c) * ni();
    const Multivector contraction = leftContraction(up(p), sigma ^ pi);
    const double reference = (contraction * contraction).grade(0)[0];
    EXPECT_NEAR(squaredCircleDistance(p, c, r, m), reference, 1e-9 * (1.0 + std::fabs(reference)));
    const Vec3 e = orthogonalUnit(m);
    const Vec3 onCircle = c + r * (std::cos(0.3 * trial) * e + std::sin(0.3 * trial) * cross(m, e));
    EXPECT_NEAR(squaredCircleDistance(onCircle, c, r, m), 0.0, 1e-12);
  }
}

// Eq 17 and 21: the generators against their formulas, with tau from Conformal.h.
/// kappa / (d^2 + epsilon) of eq 17-18 by the full product: d = up(p) _| C* for the osculating
/// circle of center x - n/kappa and radius 1/|kappa| in the plane of unit normal `plane`, C* =
/// sigma ^ pi its dual (sigma the dual sphere, pi the dual plane through the center).
double osculatingWeightOfDualCircle(
  const CurvatureControlPoint& c, double kappa, Vec3 plane, Vec3 p, double epsilon)
{
  const Vec3 center = c.location - c.normal / kappa;
  const double r = 1.0 / std::fabs(kappa);
  const Multivector dual =
    (up(center) - 0.5 * r * r * ni()) ^ (vector(plane) + dot(plane, center) * ni());
  const Multivector x = leftContraction(up(p), dual);
  return kappa / ((x * x).grade(0)[0] + epsilon);
}

TEST(CurvatureOperators, ControlPointGeneratorsMatchTheFormula)
{
  Random random(21);
  std::vector<CurvatureControlPoint> points(3);
  for (CurvatureControlPoint& c : points)
  {
    c.location = random.vec3(2.0);
    c.normal = random.unit() * 2.0;
    c.uDirection = random.unit();
    c.kappaU = random.uniform(-1.0, 1.0);
    c.kappaV = random.uniform(-1.0, 1.0);
    ASSERT_TRUE(c.normalize().empty());
    EXPECT_NEAR(dot(c.normal, c.uDirection), 0.0, 1e-15);
  }
  const double falloff = 0.7, epsilon = 0.05;
  for (int trial = 0; trial < 20; ++trial)
  {
    const Vec3 p = random.vec3(3.0);
    Multivector expected;
    double expectedWeight = 0.0;
    for (const CurvatureControlPoint& c : points)
    {
      // The circle along u lies in the plane (u, n), the one along v in (v, n).
      const Vec3 v = cross(c.normal, c.uDirection);
      double w = osculatingWeightOfDualCircle(c, c.kappaU, v, p, epsilon) +
        osculatingWeightOfDualCircle(c, c.kappaV, c.uDirection, p, epsilon);
      const double dp2 = -2.0 * dot(up(p), up(c.location));
      w /= falloff * dp2 + epsilon;
      expected -= w * nullPointPair(c.location, c.normal);
      expectedWeight += w;
    }
    const CurvatureGenerator g = controlPoints(points.data(), points.size(), p, falloff, epsilon);
    EXPECT_LT(relativeDifference(toMultivector(g.exponent), expected), 1e-10);
    EXPECT_NEAR(g.weight, expectedWeight, 1e-10 * (1.0 + std::fabs(expectedWeight)));
  }
}

// Coincident control points add their generators: two copies double the exponent.
TEST(CurvatureOperators, CoincidentControlPointsAdd)
{
  CurvatureControlPoint c;
  c.kappaU = 0.5;
  c.kappaV = -0.3;
  ASSERT_TRUE(c.normalize().empty());
  const CurvatureControlPoint twice[2] = { c, c };
  for (double x = -1.0; x <= 1.0; x += 0.25)
  {
    const Vec3 p{ x, 0.3 * x, 0.0 };
    const CurvatureGenerator one = controlPoints(&c, 1, p, 1.0, 0.01);
    const CurvatureGenerator two = controlPoints(twice, 2, p, 1.0, 0.01);
    EXPECT_LT(relativeDifference(two.exponent, one.exponent * 2.0), 1e-15);
  }
  CurvaturePatch patch;
  patch.method = CurvatureMethod::ControlPoints;
  patch.controlPoints = { c, c };
  ASSERT_TRUE(patch.validate().empty());
  for (double a = -2.0; a <= 2.0; a += 0.125)
  {
    Vec3 out;
    double weight;
    if (patch.map(a, 0.5 * a, out, weight)) // a point at infinity is reported, never NaN
    {
      EXPECT_TRUE(isFinite(out));
    }
  }
}

// A control point's own location is fixed by its generator (eq 17 at p = x).
TEST(CurvatureOperators, OsculatingCirclesFixTheControlPoint)
{
  CurvaturePatch patch;
  patch.method = CurvatureMethod::OsculatingCircles;
  patch.kappaU = -0.5;
  patch.kappaV = 0.25;
  ASSERT_TRUE(patch.validate().empty());
  EXPECT_TRUE(pointsNear(mapWith(patch, 0.0, 0.0), patch.frame.origin, 1e-12));
}

// Eq 17-18 (osculatingCircles, one control point without the falloff): E = -W tau(x, n), W the
// two osculating circles' kappa / (d^2 + eps) by the full product.
TEST(CurvatureOperators, OsculatingCirclesMatchTheFormula)
{
  Random random(17);
  for (int trial = 0; trial < 20; ++trial)
  {
    CurvatureControlPoint c;
    c.location = random.vec3(2.0);
    c.normal = random.unit() * 3.0;
    c.uDirection = random.unit();
    c.kappaU = random.uniform(-1.0, 1.0);
    c.kappaV = trial == 0 ? 0.0 : random.uniform(-1.0, 1.0); // a flat direction weighs nothing
    ASSERT_TRUE(c.normalize().empty());
    const double epsilon = random.uniform(0.01, 1.0);
    const Vec3 p = random.vec3(3.0);
    const Vec3 v = cross(c.normal, c.uDirection);
    const double w = osculatingWeightOfDualCircle(c, c.kappaU, v, p, epsilon) +
      (c.kappaV == 0.0 ? 0.0 : osculatingWeightOfDualCircle(c, c.kappaV, c.uDirection, p, epsilon));
    const CurvatureGenerator g = osculatingCircles(c, p, epsilon);
    EXPECT_LT(relativeDifference(toMultivector(g.exponent), -w * nullPointPair(c.location, c.normal)),
      1e-10) << "trial " << trial;
    EXPECT_NEAR(g.weight, w, 1e-10 * (1.0 + std::fabs(w))) << "trial " << trial;
    EXPECT_EQ(osculatingTerm(c, c.uDirection, c.kappaU, p, epsilon) +
        osculatingTerm(c, v, c.kappaV, p, epsilon), g.weight) << "trial " << trial;
  }
}

// Eq 16 (translatedTangents): E = -1/2 (kappaU tau(o + b v, n) + kappaV tau(o + a u, n)) by
// Conformal.h's tau, with the weight (kappaU + kappaV) / 2; the patch's generator is it.
TEST(CurvatureOperators, TranslatedTangentsMatchTheFormula)
{
  Random random(16);
  for (int trial = 0; trial < 20; ++trial)
  {
    const PatchFrame frame = randomFrame(random);
    const double kappaU = random.uniform(-1.0, 1.0), kappaV = random.uniform(-1.0, 1.0);
    const double a = random.uniform(-2.0, 2.0), b = random.uniform(-2.0, 2.0);
    const Multivector expected = -0.5 *
      (kappaU * nullPointPair(frame.at(0.0, b), frame.normal) +
        kappaV * nullPointPair(frame.at(a, 0.0), frame.normal));
    const CurvatureGenerator g = translatedTangents(frame, kappaU, kappaV, a, b);
    EXPECT_LT(relativeDifference(toMultivector(g.exponent), expected), 1e-12) << "trial " << trial;
    EXPECT_EQ(g.weight, 0.5 * (kappaU + kappaV));

    CurvaturePatch patch;
    patch.method = CurvatureMethod::TranslatedTangents;
    patch.frame = frame;
    patch.kappaU = kappaU;
    patch.kappaV = kappaV;
    ASSERT_TRUE(patch.validate().empty());
    const CurvatureGenerator atPatch = patch.generatorAt(a, b);
    EXPECT_LT(relativeDifference(atPatch.exponent, g.exponent), 1e-12) << "trial " << trial;
    EXPECT_EQ(atPatch.weight, g.weight);
  }
}

// The corners of eq 24-26 sit at the patch's corners, in the order the header gives: t runs from
// corner 1 to 2 along u, s from 1 to 3 along v.
TEST(CurvatureOperators, CornerLocationsAreThePatchsCorners)
{
  Random random(26);
  CurvaturePatch patch;
  patch.frame = randomFrame(random);
  patch.sizeU = 3.0;
  patch.sizeV = 1.5;
  const std::array<Vec3, 4> corners = patch.cornerLocations();
  const Vec3 o = patch.frame.origin, u = patch.frame.u, v = patch.frame.v;
  EXPECT_TRUE(pointsNear(corners[0], o - 1.5 * u - 0.75 * v, 1e-15));
  EXPECT_TRUE(pointsNear(corners[1], o + 1.5 * u - 0.75 * v, 1e-15));
  EXPECT_TRUE(pointsNear(corners[2], o - 1.5 * u + 0.75 * v, 1e-15));
  EXPECT_TRUE(pointsNear(corners[3], o + 1.5 * u + 0.75 * v, 1e-15));
}

std::array<CornerGenerator, 4> cornersAlong(const std::array<Vec3, 4>& directions)
{
  std::array<CornerGenerator, 4> g;
  const double weights[4] = { 0.8, -0.5, 0.3, 1.1 };
  for (int i = 0; i < 4; ++i)
  {
    g[i].direction = directions[i];
    g[i].weight = weights[i];
  }
  return g;
}

// Eq 24 and 25 against the interpolated sums of Conformal.h's tau.
TEST(CurvatureOperators, InterpolationMatchesTheFormula)
{
  Random random(24);
  const Vec3 x[4] = { random.vec3(2), random.vec3(2), random.vec3(2), random.vec3(2) };
  const std::array<CornerGenerator, 4> g =
    cornersAlong({ random.unit(), random.unit(), random.unit(), random.unit() });
  Multivector tau[4];
  for (int i = 0; i < 4; ++i)
  {
    tau[i] = g[i].weight * nullPointPair(x[i], g[i].direction);
  }
  for (double s = 0.0; s <= 1.0; s += 0.25)
  {
    for (double t = 0.0; t <= 1.0; t += 0.25)
    {
      const Multivector st = (1 - s) * ((1 - t) * tau[0] + t * tau[1]) + s * ((1 - t) * tau[2] + t * tau[3]);
      EXPECT_LT(relativeDifference(toMultivector(bilinearInterpolation(x, g.data(), s, t).exponent),
                  -0.5 * st, 1e-300),
        1e-13);
      const Multivector line = (1 - t) * tau[0] + t * tau[1];
      EXPECT_LT(relativeDifference(toMultivector(linearInterpolation(x[0], g[0], x[1], g[1], t).exponent),
                  -0.5 * line, 1e-300),
        1e-13);
    }
  }
}

// Eq 25: with all four directions along the patch normal the interpolated generator is a blade and
// Paper equals Exact; with in-plane directions they differ and only Exact gives null points.
TEST(CurvatureOperators, BilinearPaperAgainstExact)
{
  Random random(25);
  CurvaturePatch exact;
  exact.method = CurvatureMethod::Bilinear;
  exact.frame = randomFrame(random);
  exact.sizeU = 3.0;
  exact.sizeV = 2.0;
  const Vec3 n = exact.frame.normal;
  exact.corners = cornersAlong({ n, n, n, n });
  ASSERT_TRUE(exact.validate().empty());
  CurvaturePatch paper = exact;
  paper.rule = ExponentialRule::Paper;
  for (double a = -1.5; a <= 1.5; a += 0.25)
  {
    for (double b = -1.0; b <= 1.0; b += 0.25)
    {
      EXPECT_TRUE(pointsNear(mapWith(exact, a, b), mapWith(paper, a, b), 1e-12));
    }
  }

  const Vec3 u = exact.frame.u, v = exact.frame.v;
  exact.corners = paper.corners = cornersAlong({ u, v, -u, u + v });
  double largest = 0.0;
  for (double a = -1.5; a <= 1.5; a += 0.25)
  {
    for (double b = -1.0; b <= 1.0; b += 0.25)
    {
      largest = worseOf(largest, distance(mapWith(exact, a, b), mapWith(paper, a, b)));
      const CurvatureGenerator g = exact.generatorAt(a, b);
      const Multivector k = toMultivector(expExact(g.exponent));
      const Multivector image = k * up(exact.frame.at(a, b)) * k.reverse();
      const double weight = -dot(ni(), image);
      EXPECT_NEAR(dot(image.grade(1), image.grade(1)) / (weight * weight), 0.0, 1e-12);
      EXPECT_LT(image.maxAbs(3), 1e-12 * image.maxAbs(1)); // a pure vector: K is a versor
    }
  }
  EXPECT_GT(largest, 1e-4);
}

// Curvatures so small that 1/kappa^2 overflows, and control points so far that |p - x|^2 does,
// weigh (next to) nothing: |W| <= |kappa|/eps since d^2 >= 0, and the patch stays the flat plane
// instead of every sample becoming NaN (which dropped the whole patch).
TEST(CurvatureOperators, TinyCurvaturesAndFarControlPointsLeaveThePatchFlat)
{
  const double epsilon = 0.5;
  for (double kappa : { 1e-200, -1e-200, 1e-300, std::numeric_limits<double>::denorm_min() })
  {
    CurvatureControlPoint c;
    c.kappaU = kappa;
    c.kappaV = -kappa;
    ASSERT_TRUE(c.normalize().empty());
    for (const Vec3 p : { Vec3{ 0.3, -1.2, 0.0 }, Vec3{ 1.0, 1.0, 0.5 }, Vec3{ 0.0, 0.0, 0.0 } })
    {
      const double w = osculatingTerm(c, c.uDirection, kappa, p, epsilon);
      EXPECT_TRUE(std::isfinite(w)) << kappa;
      EXPECT_LE(std::fabs(w), std::fabs(kappa) / epsilon) << kappa;
    }
    for (CurvatureMethod method : { CurvatureMethod::OsculatingCircles, CurvatureMethod::ControlPoints })
    {
      CurvaturePatch patch;
      patch.method = method;
      patch.kappaU = kappa;
      patch.kappaV = kappa;
      patch.epsilon = epsilon;
      patch.controlPoints = { c };
      ASSERT_TRUE(patch.validate().empty());
      for (double a = -2.0; a <= 2.0; a += 0.5)
      {
        EXPECT_TRUE(pointsNear(mapWith(patch, a, 0.25 * a), patch.frame.at(a, 0.25 * a), 1e-12))
          << kappa;
      }
    }
  }
  CurvatureControlPoint far;
  far.location = { 1e200, 0.0, 0.0 };
  far.kappaU = 0.5;
  far.kappaV = 0.5;
  ASSERT_TRUE(far.normalize().empty());
  CurvaturePatch patch;
  patch.method = CurvatureMethod::ControlPoints;
  patch.controlPoints = { far };
  ASSERT_TRUE(patch.validate().empty());
  for (double a = -2.0; a <= 2.0; a += 0.5)
  {
    EXPECT_TRUE(pointsNear(mapWith(patch, a, -0.5 * a), patch.frame.at(a, -0.5 * a), 1e-12));
  }
}

TEST(CurvatureOperators, BadInputIsReported)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto problem = [](auto change) {
    CurvaturePatch patch;
    change(patch);
    return patch.validate();
  };
  EXPECT_TRUE(problem([](CurvaturePatch&) {}).empty());
  EXPECT_FALSE(problem([](CurvaturePatch& p) { p.sizeU = 0.0; }).empty());
  EXPECT_FALSE(problem([](CurvaturePatch& p) { p.sizeV = -1.0; }).empty());
  EXPECT_FALSE(problem([&](CurvaturePatch& p) { p.kappaU = nan; }).empty());
  EXPECT_FALSE(problem([&](CurvaturePatch& p) { p.frame.origin.x = nan; }).empty());
  EXPECT_FALSE(problem([](CurvaturePatch& p) { p.frame.v = p.frame.u * 2.0; }).empty());
  EXPECT_FALSE(problem([](CurvaturePatch& p) { p.frame.u = Vec3{}; }).empty());
  EXPECT_FALSE(problem([](CurvaturePatch& p) { p.epsilon = 0.0; }).empty());
  EXPECT_FALSE(problem([](CurvaturePatch& p) { p.method = CurvatureMethod::ControlPoints; }).empty());
  EXPECT_FALSE(problem([](CurvaturePatch& p) {
    p.method = CurvatureMethod::ControlPoints;
    p.controlPoints.resize(1);
    p.controlPoints[0].uDirection = p.controlPoints[0].normal;
  }).empty());
  EXPECT_FALSE(problem([&](CurvaturePatch& p) {
    p.method = CurvatureMethod::Bilinear;
    p.corners[2].weight = nan;
  }).empty());
}

// A control point's normalize() names what is wrong with it.
TEST(CurvatureOperators, BadControlPointsAreNamed)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto problem = [](auto change) {
    CurvatureControlPoint c;
    c.normal = Vec3{ 0.0, 0.0, 2.0 };
    change(c);
    return c.normalize();
  };
  EXPECT_EQ(problem([](CurvatureControlPoint&) {}), "");
  const std::string notFinite =
    "a control point has a non-finite location, normal, u direction or curvature";
  EXPECT_EQ(problem([&](CurvatureControlPoint& c) { c.location.x = nan; }), notFinite);
  EXPECT_EQ(problem([&](CurvatureControlPoint& c) { c.normal.y = inf; }), notFinite);
  EXPECT_EQ(problem([&](CurvatureControlPoint& c) { c.uDirection.z = nan; }), notFinite);
  EXPECT_EQ(problem([&](CurvatureControlPoint& c) { c.kappaU = -inf; }), notFinite);
  EXPECT_EQ(problem([&](CurvatureControlPoint& c) { c.kappaV = nan; }), notFinite);
  EXPECT_EQ(problem([](CurvatureControlPoint& c) { c.normal = Vec3{}; }),
    "a control point has a zero normal");
  const std::string parallel = "a control point's u direction is zero or parallel to its normal";
  EXPECT_EQ(problem([](CurvatureControlPoint& c) { c.uDirection = Vec3{}; }), parallel);
  EXPECT_EQ(problem([](CurvatureControlPoint& c) { c.uDirection = Vec3{ 0.0, 0.0, -5.0 }; }),
    parallel);
  // A normal of any non-zero length, a u direction with a part along the normal: made unit and
  // orthogonal.
  CurvatureControlPoint c;
  c.normal = Vec3{ 0.0, 0.0, 1e-200 };
  c.uDirection = Vec3{ 3.0, 0.0, 4.0 };
  ASSERT_EQ(c.normalize(), "");
  EXPECT_TRUE(pointsNear(c.normal, Vec3{ 0.0, 0.0, 1.0 }, 1e-15));
  EXPECT_TRUE(pointsNear(c.uDirection, Vec3{ 1.0, 0.0, 0.0 }, 1e-15));
}

TEST(CurvatureOperators, DirectionsOfAnyNonZeroLengthGiveTheSameFrame)
{
  const Vec3 origin{ 1, 2, 3 }, u = Vec3{ 2, -1, 2 } / 3.0, v{ 0, 0, 1 };
  PatchFrame reference;
  ASSERT_TRUE(PatchFrame::fromDirections(origin, u, v, reference).empty());
  auto expectSameFrame = [&reference](const PatchFrame& f, double length) {
    EXPECT_LT(norm(f.u - reference.u), 1e-15) << "length " << length;
    EXPECT_LT(norm(f.v - reference.v), 1e-15) << "length " << length;
    EXPECT_LT(norm(f.normal - reference.normal), 1e-15) << "length " << length;
  };
  for (const double length : { 1e-300, 1e-200, 1e160, 1e200, 1e307 })
  {
    PatchFrame frame;
    const std::string problem = PatchFrame::fromDirections(origin, length * u, length * v, frame);
    EXPECT_TRUE(problem.empty()) << "length " << length << ": " << problem;
    expectSameFrame(frame, length);

    CurvatureControlPoint point;
    point.normal = length * reference.normal;
    point.uDirection = length * reference.u;
    EXPECT_TRUE(point.normalize().empty()) << "length " << length;
    EXPECT_LT(norm(point.normal - reference.normal), 1e-15) << "length " << length;
    EXPECT_LT(norm(point.uDirection - reference.u), 1e-15) << "length " << length;
  }
}
} // namespace
