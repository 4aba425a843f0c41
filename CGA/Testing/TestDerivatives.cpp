// The derivatives of the map (PointPairField::mapWithJacobian, mapPointsWithJacobians,
// mapWithBivectorDerivative, mapWithWeightDerivatives; mapJetByExponential): against an
// independent reference built on the full multivector and Eigen's matrix exponential (the
// Frechet derivative of exp from the block matrix [[A, E], [0, A]], in long double), against
// fourth-order central differences of map() itself, the images to the bit of map(), and the
// batch to the bit of the pointwise form on every instruction set.
#include "cga/ExponentialMap.h"
#include "cga/PointPairField.h"
#include "cga/PointSandwich.h"

#include "GeneratorKindReference.h"
#include "MatrixExponentialReference.h"
#include "TestSupport.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <vector>

namespace
{
using namespace cga;
using namespace cgatest;

using Jacobian = std::array<double, 9>;

/// Fourth-order central difference of f at x along e_j (error O(h^4) + O(eps/h)).
Vec3 centralDifference(const std::function<Vec3(Vec3)>& f, Vec3 x, int j, double h)
{
  Vec3 e{};
  (j == 0 ? e.x : (j == 1 ? e.y : e.z)) = h;
  const Vec3 d = (8.0 * (f(x + e) - f(x - e)) - (f(x + 2.0 * e) - f(x - 2.0 * e))) / (12.0 * h);
  return d;
}

double component(Vec3 v, int i)
{
  return i == 0 ? v.x : (i == 1 ? v.y : v.z);
}

Jacobian differenceJacobian(const std::function<Vec3(Vec3)>& f, Vec3 x, double h)
{
  Jacobian j{};
  for (int c = 0; c < 3; ++c)
  {
    const Vec3 column = centralDifference(f, x, c, h);
    for (int r = 0; r < 3; ++r)
    {
      j[3 * r + c] = component(column, r);
    }
  }
  return j;
}

double largestDifference(const Jacobian& a, const Jacobian& b)
{
  double d = 0.0;
  for (int i = 0; i < 9; ++i)
  {
    d = worseOf(d, std::fabs(a[i] - b[i]));
  }
  return d;
}

double largestEntry(const Jacobian& a)
{
  double m = 0.0;
  for (const double x : a)
  {
    m = worseOf(m, std::fabs(x));
  }
  return m;
}

std::vector<GeneratorParameters> mixedGenerators(Random& random, int count, double spread)
{
  std::vector<GeneratorParameters> g;
  for (int i = 0; i < count; ++i)
  {
    GeneratorParameters row;
    row.kind = kAllKinds[i % 5];
    row.location = random.vec3(spread);
    row.direction = random.unit() * random.uniform(0.5, 1.5);
    row.pitch = random.uniform(-0.5, 0.5);
    row.weight = random.uniform(-1.0, 1.0);
    g.push_back(row);
  }
  return g;
}

// The Exact rule's reference: x' = fn(M(p) up(p)), M = expm(A(p)), A = the 5x5 matrix of
// -strength B(p) on vectors (B(p) of the full multivector); dM/dp_j = the Frechet derivative
// L(A, dA/dp_j), the upper right block of expm([[A, dA], [0, A]]), in long double.
struct ReferenceDerivative
{
  Vec3 image;
  Jacobian jacobian;
};

/// With `nilpotent` (a lone point pair: A^3 = 0), exp(A) = 1 + A + A^2/2 and its derivative
/// dA + (A dA + dA A)/2 in closed form instead: Eigen's scaling and squaring loses the
/// cancellations of a large non-normal A (|A| ~ 1/eps next to the generator).
ReferenceDerivative exactReference(const std::vector<GeneratorParameters>& generators, Vec3 p,
  double falloff, double epsilon, double strength, bool nilpotent = false)
{
  using Matrix10 = Eigen::Matrix<long double, 10, 10>;
  using Vector5 = Eigen::Matrix<long double, 5, 1>;
  const Matrix5 a = generator(referenceField(generators, p, falloff, epsilon) * (-strength));
  // dB/dp_j = sum_i w_i G_i d/dp_j (1 / (k |p - x_i|^2 + eps)).
  Multivector dB[3];
  for (const GeneratorParameters& g : generators)
  {
    const Vec3 d = p - g.location;
    const double den = falloff * norm2(d) + epsilon;
    const double common = -2.0 * falloff * g.weight / (den * den);
    const Multivector G = referenceBivector(g);
    dB[0] += G * (common * d.x);
    dB[1] += G * (common * d.y);
    dB[2] += G * (common * d.z);
  }
  const Multivector x = up(p);
  Vector5 y0;
  for (int i = 0; i < 5; ++i)
  {
    y0(i) = x[kVectorMasks[i]];
  }
  // d up(p)/dp_j = e_j + p_j ni, ni = e- - e+ (Conformal.cpp).
  const long double pj[3] = { p.x, p.y, p.z };
  Eigen::Matrix<long double, 5, 5> m;
  Vector5 y;
  Vector5 dy[3];
  for (int j = 0; j < 3; ++j)
  {
    Matrix10 block = Matrix10::Zero();
    const Matrix5 da = generator(dB[j] * (-strength));
    block.topLeftCorner<5, 5>() = a.cast<long double>();
    block.bottomRightCorner<5, 5>() = a.cast<long double>();
    block.topRightCorner<5, 5>() = da.cast<long double>();
    Matrix10 e;
    if (nilpotent)
    {
      const Matrix10 blockSquare = block * block;
      e = Matrix10::Identity() + block + 0.5L * blockSquare;
      EXPECT_LT((blockSquare * block).cwiseAbs().maxCoeff(), 1e-6L * blockSquare.cwiseAbs().maxCoeff());
    }
    else
    {
      e = block.exp();
    }
    m = e.topLeftCorner<5, 5>();
    Vector5 dx = Vector5::Zero();
    dx(j) = 1.0L;
    dx(3) = -pj[j];
    dx(4) = pj[j];
    y = m * y0.cast<long double>();
    dy[j] = e.topRightCorner<5, 5>() * y0.cast<long double>() + m * dx;
  }
  // fn: x' = y_e / alpha with alpha = -ni.y = y- + y+ (the no coefficient, normalizePoint).
  const long double alpha = y(4) + y(3);
  ReferenceDerivative r;
  r.image = { static_cast<double>(y(0) / alpha), static_cast<double>(y(1) / alpha),
    static_cast<double>(y(2) / alpha) };
  for (int j = 0; j < 3; ++j)
  {
    const long double dAlpha = dy[j](4) + dy[j](3);
    for (int i = 0; i < 3; ++i)
    {
      r.jacobian[3 * i + j] = static_cast<double>((dy[j](i) * alpha - y(i) * dAlpha) / (alpha * alpha));
    }
  }
  return r;
}

struct Case
{
  std::vector<GeneratorParameters> generators;
  double falloff, epsilon, strength;
};

std::vector<Case> cases()
{
  Random random(20261202);
  std::vector<Case> c;
  for (int n : { 1, 2, 3, 5, 8 })
  {
    for (double strength : { 0.3, 1.0, 2.5 })
    {
      c.push_back({ mixedGenerators(random, n, 1.5), 1.0, 0.5, strength });
    }
  }
  // A lone point pair (nilpotent B), and one with a small epsilon (large B near it).
  c.push_back({ { GeneratorParameters{ GeneratorKind::PointPair, { 0.2, 0.1, 0.0 }, { 0, 0, 1 }, 0, 0.8 } },
    1.0, 0.5, 1.0 });
  c.push_back({ { GeneratorParameters{ GeneratorKind::PointPair, { 0.0, 0.0, 0.0 }, { 1, 0, 0 }, 0, 1.0 },
                  GeneratorParameters{ GeneratorKind::Rotation, { 1.0, 0.0, 0.0 }, { 0, 0, 1 }, 0, 0.7 } },
    1.0, 0.05, 1.0 });
  return c;
}

TEST(Derivatives, JacobianMatchesTheMatrixExponentialReference)
{
  Random random(7);
  double worst = 0.0;
  for (const Case& c : cases())
  {
    const PointPairField field(c.generators.data(), c.generators.size(), c.falloff, c.epsilon);
    for (int trial = 0; trial < 20; ++trial)
    {
      const Vec3 p = random.vec3(2.0);
      Vec3 image;
      Jacobian j;
      ASSERT_TRUE(field.mapWithJacobian(p, c.strength, ExponentialRule::Exact, image, j.data()));
      const ReferenceDerivative r = exactReference(c.generators, p, c.falloff, c.epsilon, c.strength);
      EXPECT_TRUE(pointsNear(image, r.image, 1e-11 * std::max(1.0, maxNorm(r.image))));
      const double error = largestDifference(j, r.jacobian) / std::max(1.0, largestEntry(r.jacobian));
      worst = worseOf(worst, error);
      EXPECT_LT(error, 1e-10) << "trial " << trial << " at " << p.x << " " << p.y << " " << p.z;
    }
  }
  RecordProperty("worstRelativeError", std::to_string(worst));
}

TEST(Derivatives, JacobianMatchesCentralDifferencesForBothRules)
{
  Random random(11);
  for (const ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    for (const Case& c : cases())
    {
      const PointPairField field(c.generators.data(), c.generators.size(), c.falloff, c.epsilon);
      const auto f = [&](Vec3 x) {
        Vec3 out;
        EXPECT_TRUE(field.map(x, c.strength, rule, out));
        return out;
      };
      // The field varies on the scale sqrt(eps / k): the step is a small part of it.
      const double h = 1e-3 * std::sqrt(c.epsilon / c.falloff);
      for (int trial = 0; trial < 10; ++trial)
      {
        const Vec3 p = random.vec3(2.0);
        Vec3 image;
        Jacobian j;
        ASSERT_TRUE(field.mapWithJacobian(p, c.strength, rule, image, j.data()));
        const Jacobian d = differenceJacobian(f, p, h);
        EXPECT_LT(largestDifference(j, d) / std::max(1.0, largestEntry(d)), 1e-8);
      }
    }
  }
}

TEST(Derivatives, ImagesAreTheBitsOfMapAndTheBatchOfThePointwiseForm)
{
  Random random(3);
  const std::string active = mapPointsInstructionSet();
  for (const Case& c : cases())
  {
    const PointPairField field(c.generators.data(), c.generators.size(), c.falloff, c.epsilon);
    for (const ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
    {
      std::vector<double> points;
      for (int i = 0; i < 21; ++i) // not a multiple of the block size
      {
        const Vec3 p = random.vec3(2.0);
        points.insert(points.end(), { p.x, p.y, p.z });
      }
      std::vector<double> expectedImages, expectedJacobians;
      for (int i = 0; i < 21; ++i)
      {
        const Vec3 p{ points[3 * i], points[3 * i + 1], points[3 * i + 2] };
        Vec3 viaMap, image;
        Jacobian j;
        ASSERT_TRUE(field.map(p, c.strength, rule, viaMap));
        ASSERT_TRUE(field.mapWithJacobian(p, c.strength, rule, image, j.data()));
        EXPECT_EQ(0, std::memcmp(&viaMap, &image, sizeof image));
        expectedImages.insert(expectedImages.end(), { image.x, image.y, image.z });
        expectedJacobians.insert(expectedJacobians.end(), j.begin(), j.end());
      }
      for (const std::string& isa : mapPointsInstructionSets())
      {
        ASSERT_TRUE(useMapPointsInstructionSet(isa));
        std::vector<double> images(points.size()), jacobians(9 * 21);
        EXPECT_EQ(0u, field.mapPointsWithJacobians(
          points.data(), images.data(), jacobians.data(), 21, c.strength, rule));
        EXPECT_EQ(0, std::memcmp(images.data(), expectedImages.data(), 8 * images.size())) << isa;
        EXPECT_EQ(0, std::memcmp(jacobians.data(), expectedJacobians.data(), 8 * jacobians.size()))
          << isa;
        std::vector<double> viaMapPoints(points.size());
        field.mapPoints(points.data(), viaMapPoints.data(), 21, c.strength, rule);
        EXPECT_EQ(0, std::memcmp(images.data(), viaMapPoints.data(), 8 * images.size())) << isa;
      }
      ASSERT_TRUE(useMapPointsInstructionSet(active));
    }
  }
}

// The batch derivatives along two directions per point (two tangents through the map) against
// J t from the Jacobians (three tangents), on every instruction set: the images to the bit, J t to
// rounding. Directions of any size, the last block partial, a NaN point (its directions back).
TEST(Derivatives, DirectionalDerivativesAreTheJacobianAlongTheDirections)
{
  Random random(5);
  const std::string active = mapPointsInstructionSet();
  double worst = 0.0;
  for (const Case& c : cases())
  {
    const PointPairField field(c.generators.data(), c.generators.size(), c.falloff, c.epsilon);
    for (const ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
    {
      constexpr int count = 21; // not a multiple of the block size
      std::vector<double> points, directions;
      for (int i = 0; i < count; ++i)
      {
        const Vec3 p = random.vec3(2.0);
        points.insert(points.end(), { i == 9 ? std::nan("") : p.x, p.y, p.z });
        for (int k = 0; k < 2; ++k)
        {
          const Vec3 t = random.vec3(1.0) * std::pow(10.0, random.uniform(-3.0, 3.0));
          directions.insert(directions.end(), { t.x, t.y, t.z });
        }
      }
      for (const std::string& isa : mapPointsInstructionSets())
      {
        ASSERT_TRUE(useMapPointsInstructionSet(isa));
        std::vector<double> images(3 * count), jacobians(9 * count), viaJacobians(3 * count),
          derivatives(6 * count);
        EXPECT_EQ(1u, field.mapPointsWithJacobians(
          points.data(), viaJacobians.data(), jacobians.data(), count, c.strength, rule));
        EXPECT_EQ(1u, field.mapPointsWithDirectionalDerivatives(points.data(), directions.data(),
          images.data(), derivatives.data(), count, c.strength, rule));
        EXPECT_EQ(0, std::memcmp(images.data(), viaJacobians.data(), 8 * images.size())) << isa;
        for (int i = 0; i < count; ++i)
        {
          const double* j = jacobians.data() + 9 * i;
          for (int k = 0; k < 2; ++k)
          {
            const double* t = directions.data() + 6 * i + 3 * k;
            const double* got = derivatives.data() + 6 * i + 3 * k;
            if (i == 9)
            {
              EXPECT_EQ(0, std::memcmp(t, got, 3 * sizeof(double))) << isa;
              continue;
            }
            const double size = std::max(1.0, largestEntry(Jacobian{ j[0], j[1], j[2], j[3],
              j[4], j[5], j[6], j[7], j[8] })) * std::max({ std::fabs(t[0]), std::fabs(t[1]),
              std::fabs(t[2]) });
            for (int r = 0; r < 3; ++r)
            {
              const double expected = j[3 * r] * t[0] + j[3 * r + 1] * t[1] + j[3 * r + 2] * t[2];
              const double error = std::fabs(got[r] - expected) / size;
              worst = worseOf(worst, error);
              EXPECT_LT(error, 1e-12) << isa << " point " << i;
            }
          }
        }
      }
      ASSERT_TRUE(useMapPointsInstructionSet(active));
    }
  }
  // No generators: the points and the directions themselves.
  const PointPairField empty(static_cast<const GeneratorParameters*>(nullptr), 0, 1.0, 0.5);
  const double in[3] = { 1, 2, 3 }, t[6] = { 1, 0, 0, 0, 2, 0 };
  double out[3], d[6];
  EXPECT_EQ(0u, empty.mapPointsWithDirectionalDerivatives(in, t, out, d, 1, 1.0, ExponentialRule::Exact));
  EXPECT_EQ(0, std::memcmp(in, out, sizeof in));
  EXPECT_EQ(0, std::memcmp(t, d, sizeof t));
  RecordProperty("worstRelativeError", std::to_string(worst));
}

TEST(Derivatives, NearAGeneratorTheJacobianMatchesTheReference)
{
  // A lone point pair with a small epsilon: B is nilpotent and large next to it (the Exact rule
  // maps in the frame around p there); points on it, and 1e-6 ... 1e-2 away.
  const std::vector<GeneratorParameters> g = { GeneratorParameters{
    GeneratorKind::PointPair, { 0.3, -0.2, 0.1 }, { 0.0, 0.6, 0.8 }, 0.0, 1.0 } };
  for (const double epsilon : { 1e-2, 1e-4 })
  {
    const PointPairField field(g.data(), g.size(), 1.0, epsilon);
    for (const double distance : { 0.0, 1e-6, 1e-4, 1e-2 })
    {
      const Vec3 p = g[0].location + distance * normalized(Vec3{ 1.0, 2.0, -0.5 });
      Vec3 image;
      Jacobian j;
      ASSERT_TRUE(field.mapWithJacobian(p, 1.0, ExponentialRule::Exact, image, j.data()));
      const ReferenceDerivative r = exactReference(g, p, 1.0, epsilon, 1.0, true);
      // The reference's M = 1 + A + A^2/2 is rounded like |A|^2 eps in its double inputs
      // (|A| ~ 1/epsilon here): its own error, which the tolerance allows.
      const double a = 1.0 / (norm2(p - g[0].location) + epsilon);
      const double tolerance = 1e-10 + 1e-15 * a * a;
      if (distance == 0.0)
      {
        // On the generator: B'(p) = 0 and the transversion's differential at its fixed point is
        // the identity, exactly.
        EXPECT_EQ((Jacobian{ 1, 0, 0, 0, 1, 0, 0, 0, 1 }), j);
      }
      EXPECT_LT(largestDifference(j, r.jacobian) / std::max(1.0, largestEntry(r.jacobian)), tolerance)
        << "epsilon " << epsilon << " distance " << distance;
    }
  }
}

// Next to a strong general bivector (given in space: a rotation by 1.8 and a boost by 0.64 times
// w / (|p - x|^2 + eps), here up to 1.8e9) the map is taken in the field's frame and every point
// goes to the boost's attracting fixed point; its exponent's tangents reach 1e14, and in double
// the derivative carried the image's rounding times them (0.009 of max(1, |J|) at 1e-5 from x):
// those lanes take their tangents in double-double (docs/conventions.md section 3 item 15).
// Against fourth-order central differences of map() (the step 1e-3 of the field's scale
// sqrt(eps) = 1e-5: truncation and rounding below 1e-7), the batch to the bit of the pointwise
// form and the directional derivatives J t on every instruction set (the previous code missed
// the first at every point within 1e-5 of x: 1.3e-5 at 1e-9, up to 0.03 at 1e-5).
TEST(Derivatives, NextToAStrongGeneralBivectorTheJacobianIsExactToRounding)
{
  const Vec3 x{ 0.7, -0.1, -0.1 };
  Bivector rest;
  rest.c = { 0.3, -0.2, 0.5, 0.1, 0.4, -0.3, 0.2, -0.1, 0.6, 0.25 };
  const std::vector<FieldGenerator> g = { FieldGenerator{ x, rest, 0.3 },
    FieldGenerator::pointPair({ 0.3, -0.2, 0.1 }, { 0.4, 0.7, -0.5 }, 0.5) };
  const double epsilon = 1e-10;
  const PointPairField field(g.data(), g.size(), 1.0, epsilon);
  const auto f = [&](Vec3 q) {
    Vec3 out;
    EXPECT_TRUE(field.map(q, 1.0, ExponentialRule::Exact, out));
    return out;
  };
  std::vector<double> points, directions, expectedJacobians;
  Random random(17);
  constexpr int count = 21; // not a multiple of the block size
  for (int i = 0; i < count; ++i)
  {
    // near x (1e-9 ... 1e-5 away) and far from it, mixed in each block
    const double distance = i % 3 == 2 ? 0.5 : std::pow(10.0, -9.0 + 2.0 * (i % 3 + i / 3 % 2));
    const Vec3 p = x + distance * normalized(random.vec3(1.0));
    points.insert(points.end(), { p.x, p.y, p.z });
    for (int k = 0; k < 2; ++k)
    {
      const Vec3 t = random.vec3(1.0);
      directions.insert(directions.end(), { t.x, t.y, t.z });
    }
    Vec3 image;
    Jacobian j;
    ASSERT_TRUE(field.mapWithJacobian(p, 1.0, ExponentialRule::Exact, image, j.data()));
    expectedJacobians.insert(expectedJacobians.end(), j.begin(), j.end());
    const Jacobian d = differenceJacobian(f, p, 1e-8);
    EXPECT_LT(largestDifference(j, d) / std::max(1.0, largestEntry(d)), 1e-7)
      << "distance " << distance;
  }
  const std::string active = mapPointsInstructionSet();
  for (const std::string& isa : mapPointsInstructionSets())
  {
    ASSERT_TRUE(useMapPointsInstructionSet(isa));
    std::vector<double> images(3 * count), jacobians(9 * count), derivatives(6 * count);
    EXPECT_EQ(0u, field.mapPointsWithJacobians(
      points.data(), images.data(), jacobians.data(), count, 1.0, ExponentialRule::Exact));
    EXPECT_EQ(0, std::memcmp(jacobians.data(), expectedJacobians.data(), 8 * jacobians.size())) << isa;
    EXPECT_EQ(0u, field.mapPointsWithDirectionalDerivatives(points.data(), directions.data(),
      images.data(), derivatives.data(), count, 1.0, ExponentialRule::Exact));
    for (int i = 0; i < count; ++i)
    {
      const double* j = jacobians.data() + 9 * i;
      const double size = std::max(1.0, largestEntry(Jacobian{ j[0], j[1], j[2], j[3], j[4], j[5],
        j[6], j[7], j[8] }));
      for (int k = 0; k < 2; ++k)
      {
        const double* t = directions.data() + 6 * i + 3 * k;
        for (int r = 0; r < 3; ++r)
        {
          const double expected = j[3 * r] * t[0] + j[3 * r + 1] * t[1] + j[3 * r + 2] * t[2];
          // Two tangents seeded with t round B's tangents differently from three: J moves by up
          // to 3e-11 of max(1, |J|) when B(p) and dB/dp change by one ulp here
          // (exact_reference.jacobian_sensitivity), so that is all they can agree to.
          EXPECT_LT(std::fabs(derivatives[6 * i + 3 * k + r] - expected), 1e-10 * size)
            << isa << " point " << i;
        }
      }
    }
  }
  ASSERT_TRUE(useMapPointsInstructionSet(active));
}

// A strong boost between the origin and x2 = (0.7, -0.1, -0.1) given in space (up(0) ^ up(x2):
// e_i^no parts -x2, no^ni |x2|^2 / 2), whose repeller for strength -1 is the origin, c = 30 and
// 700 there. map() and mapPoints map every point next to it (the same bits). The derivatives do
// while |p - r|^2 is a normal double; within about 1e-154 of r the inversion's tangent
// (1/|p - r|^2) passes the doubles though J is finite, and they refuse the point: false and
// nothing written, the batch copying it with the identity and counting it (docs/conventions.md
// section 3 item 15). At c = 30 the map is linear there, J = e^30 Q (Q orthogonal).
TEST(Derivatives, NextToAStrongBoostsRepellerTheDerivativesRefuseOnlyWhereTheInversionOverflows)
{
  Bivector boost;
  boost.c = { 0.0, 0.0, 0.0, -0.7, 0.1, 0.1, 0.0, 0.0, 0.0, 0.255 };
  const double epsilon = 1e-10;
  const Vec3 direction = normalized(Vec3{ 0.6, -0.3, 0.74 });
  for (const double c : { 30.0, 700.0 })
  {
    const FieldGenerator g{ { 0.0, 0.0, 0.0 }, boost, c / 2.0 * epsilon / 0.255 };
    const PointPairField field(&g, 1, 1.0, epsilon);
    for (const double distance : { 1e-140, 1e-150, 1e-160, 1e-200, 1e-300 })
    {
      const Vec3 p = distance * direction;
      Vec3 image, batch;
      ASSERT_TRUE(field.map(p, -1.0, ExponentialRule::Exact, image)) << c << " " << distance;
      EXPECT_TRUE(isFinite(image));
      EXPECT_EQ(0u, field.mapPoints(&p.x, &batch.x, 1, -1.0, ExponentialRule::Exact));
      EXPECT_EQ(0, std::memcmp(&image, &batch, sizeof image));
      const bool expected = distance > 1e-154;
      Vec3 withJacobian{ 7, 7, 7 };
      Jacobian j;
      j.fill(5.0);
      EXPECT_EQ(expected, field.mapWithJacobian(p, -1.0, ExponentialRule::Exact, withJacobian, j.data()))
        << c << " " << distance;
      double out[3], jacobian[9];
      EXPECT_EQ(expected ? 0u : 1u,
        field.mapPointsWithJacobians(&p.x, out, jacobian, 1, -1.0, ExponentialRule::Exact));
      if (!expected)
      {
        EXPECT_EQ(7.0, withJacobian.x);
        EXPECT_EQ(5.0, j[0]);
        EXPECT_TRUE(out[0] == p.x && out[1] == p.y && out[2] == p.z);
        EXPECT_TRUE(jacobian[0] == 1.0 && jacobian[1] == 0.0 && jacobian[4] == 1.0 && jacobian[8] == 1.0);
        continue;
      }
      EXPECT_EQ(0, std::memcmp(&image, &withJacobian, sizeof image));
      EXPECT_EQ(0, std::memcmp(j.data(), jacobian, sizeof jacobian));
      for (const double e : j)
      {
        EXPECT_TRUE(std::isfinite(e));
      }
      if (c == 30.0)
      {
        // J^T J = e^60 I
        const double scale = std::exp(60.0);
        for (int a = 0; a < 3; ++a)
        {
          for (int b = 0; b < 3; ++b)
          {
            const double entry = j[a] * j[b] + j[3 + a] * j[3 + b] + j[6 + a] * j[6 + b];
            EXPECT_NEAR(entry / scale, a == b ? 1.0 : 0.0, 1e-9) << distance << " " << a << b;
          }
        }
      }
    }
  }
}

TEST(Derivatives, WeightDerivativesMatchCentralDifferencesAlsoAtZeroWeights)
{
  Random random(5);
  std::vector<GeneratorParameters> g = mixedGenerators(random, 4, 1.0);
  g[1].weight = 0.0; // a generator that does not act yet still moves the image when it grows
  for (const bool allZero : { false, true })
  {
    if (allZero)
    {
      for (GeneratorParameters& row : g)
      {
        row.weight = 0.0;
      }
    }
    const PointPairField field(g.data(), g.size(), 1.0, 0.5);
    ASSERT_EQ(g.size(), field.size());
    for (const ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
    {
      for (int trial = 0; trial < 5; ++trial)
      {
        const Vec3 p = random.vec3(1.5);
        Vec3 image;
        std::vector<double> derivatives(3 * g.size());
        ASSERT_TRUE(field.mapWithWeightDerivatives(p, 1.2, rule, image, derivatives.data()));
        Vec3 viaMap;
        ASSERT_TRUE(field.map(p, 1.2, rule, viaMap));
        EXPECT_EQ(0, std::memcmp(&viaMap, &image, sizeof image));
        for (std::size_t i = 0; i < g.size(); ++i)
        {
          const auto f = [&](Vec3 w) {
            std::vector<GeneratorParameters> moved = g;
            moved[i].weight = g[i].weight + w.x;
            const PointPairField other(moved.data(), moved.size(), 1.0, 0.5);
            Vec3 out;
            EXPECT_TRUE(other.map(p, 1.2, rule, out));
            return out;
          };
          const Vec3 d = centralDifference(f, Vec3{}, 0, 1e-3);
          const Vec3 analytic{ derivatives[3 * i], derivatives[3 * i + 1], derivatives[3 * i + 2] };
          EXPECT_TRUE(pointsNear(analytic, d, 1e-8 * std::max(1.0, maxNorm(d))))
            << "generator " << i << (allZero ? " (all weights 0)" : "");
        }
      }
    }
  }
}

TEST(Derivatives, BivectorDerivativeMatchesCentralDifferencesOfTheSandwich)
{
  Random random(9);
  const std::vector<GeneratorParameters> g = mixedGenerators(random, 3, 1.0);
  const PointPairField field(g.data(), g.size(), 1.0, 0.5);
  const double strength = 0.8;
  for (const ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    for (int trial = 0; trial < 5; ++trial)
    {
      const Vec3 p = random.vec3(1.5);
      Vec3 image;
      double byBivector[30];
      ASSERT_TRUE(field.mapWithBivectorDerivative(p, strength, rule, image, byBivector));
      const Bivector b = field.generatorAt(p);
      for (int c = 0; c < Bivector::Count; ++c)
      {
        const auto f = [&](Vec3 t) {
          Bivector moved = b;
          moved[c] += t.x;
          Vec3 out;
          EXPECT_TRUE(sandwichPoint(exponential(moved * (-strength), rule), p, out));
          return out;
        };
        const Vec3 d = centralDifference(f, Vec3{}, 0, 1e-4);
        const Vec3 analytic{ byBivector[c], byBivector[10 + c], byBivector[20 + c] };
        EXPECT_TRUE(pointsNear(analytic, d, 1e-8 * std::max(1.0, maxNorm(d)))) << "component " << c;
      }
    }
  }
}

TEST(Derivatives, SurfaceJetMatchesDifferencesOfItsFirstDerivatives)
{
  // b(a, s) and p(a, s) polynomial in two parameters; the jet's second derivatives against
  // central differences of its own first derivatives, its first against differences of the map.
  Random random(13);
  Bivector b0 = random.bivector(0.6), b1 = random.bivector(0.4), b2 = random.bivector(0.4),
           b3 = random.bivector(0.2);
  const Vec3 p0 = random.vec3(1.0), p1 = random.vec3(1.0), p2 = random.vec3(1.0);
  const auto exponentJet = [&](double a, double s, SurfaceJet* out) {
    for (int c = 0; c < Bivector::Count; ++c)
    {
      // b0 + a b1 + s b2 + a s b3 + a^2 b3
      out[c].value = b0[c] + a * b1[c] + s * b2[c] + a * s * b3[c] + a * a * b3[c];
      out[c].da = b1[c] + s * b3[c] + 2.0 * a * b3[c];
      out[c].db = b2[c] + a * b3[c];
      out[c].daa = 2.0 * b3[c];
      out[c].dab = b3[c];
      out[c].dbb = 0.0;
    }
  };
  const auto pointJet = [&](double a, double s, SurfaceJet* out) {
    for (int i = 0; i < 3; ++i)
    {
      const double x0 = component(p0, i), x1 = component(p1, i), x2 = component(p2, i);
      out[i].value = x0 + a * x1 + s * s * x2;
      out[i].da = x1;
      out[i].db = 2.0 * s * x2;
      out[i].dbb = 2.0 * x2;
    }
  };
  for (const ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    const auto jetAt = [&](double a, double s) {
      SurfaceJet bj[10], pj[3], image[3];
      exponentJet(a, s, bj);
      pointJet(a, s, pj);
      EXPECT_TRUE(mapJetByExponential(bj, pj, rule, image));
      return std::array<SurfaceJet, 3>{ image[0], image[1], image[2] };
    };
    const double h = 1e-3;
    for (int trial = 0; trial < 5; ++trial)
    {
      const double a = random.uniform(-1, 1), s = random.uniform(-1, 1);
      const std::array<SurfaceJet, 3> j = jetAt(a, s);
      // The value: mapPointsByExponentials' image.
      SurfaceJet bj[10], pj[3];
      exponentJet(a, s, bj);
      pointJet(a, s, pj);
      Bivector b;
      for (int c = 0; c < 10; ++c)
      {
        b[c] = bj[c].value;
      }
      const Vec3 p{ pj[0].value, pj[1].value, pj[2].value };
      Vec3 image;
      bool mapped = false;
      mapPointsByExponentials(&b, &p, 1, rule, &image, &mapped);
      ASSERT_TRUE(mapped);
      EXPECT_EQ(image.x, j[0].value);
      EXPECT_EQ(image.y, j[1].value);
      EXPECT_EQ(image.z, j[2].value);
      const auto diff = [&](const std::function<double(const SurfaceJet&)>& of, bool alongA, int i) {
        const double da = alongA ? h : 0.0, ds = alongA ? 0.0 : h;
        return (8.0 * (of(jetAt(a + da, s + ds)[i]) - of(jetAt(a - da, s - ds)[i])) -
                 (of(jetAt(a + 2 * da, s + 2 * ds)[i]) - of(jetAt(a - 2 * da, s - 2 * ds)[i]))) /
          (12.0 * h);
      };
      for (int i = 0; i < 3; ++i)
      {
        const auto value = [](const SurfaceJet& x) { return x.value; };
        const auto da = [](const SurfaceJet& x) { return x.da; };
        const auto db = [](const SurfaceJet& x) { return x.db; };
        EXPECT_NEAR(j[i].da, diff(value, true, i), 1e-9);
        EXPECT_NEAR(j[i].db, diff(value, false, i), 1e-9);
        EXPECT_NEAR(j[i].daa, diff(da, true, i), 1e-8);
        EXPECT_NEAR(j[i].dab, diff(da, false, i), 1e-8);
        EXPECT_NEAR(j[i].dab, diff(db, true, i), 1e-8);
        EXPECT_NEAR(j[i].dbb, diff(db, false, i), 1e-8);
      }
    }
  }
}

TEST(Derivatives, SecondDerivativesAtAZeroExponent)
{
  // b(a, s) = a B1 + s B2: b = 0 at the origin, where exp takes the series with m = 1; the second
  // derivative of exp there is (B1 B2 + B2 B1) / 2, which a first-order identity would lose.
  Random random(17);
  const Bivector b1 = random.bivector(0.5), b2 = random.bivector(0.5);
  const Vec3 p{ 0.3, -0.4, 0.5 };
  for (const ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    const auto jetAt = [&](double a, double s, SurfaceJet* image) {
      SurfaceJet bj[10], pj[3];
      for (int c = 0; c < 10; ++c)
      {
        bj[c].value = a * b1[c] + s * b2[c];
        bj[c].da = b1[c];
        bj[c].db = b2[c];
      }
      pj[0].value = p.x;
      pj[1].value = p.y;
      pj[2].value = p.z;
      return mapJetByExponential(bj, pj, rule, image);
    };
    SurfaceJet at[3];
    ASSERT_TRUE(jetAt(0.0, 0.0, at));
    EXPECT_EQ(p.x, at[0].value);
    const double h = 1e-3;
    for (int i = 0; i < 3; ++i)
    {
      SurfaceJet plus[3], minus[3], plus2[3], minus2[3];
      ASSERT_TRUE(jetAt(h, 0.0, plus) && jetAt(-h, 0.0, minus) && jetAt(2 * h, 0.0, plus2) &&
        jetAt(-2 * h, 0.0, minus2));
      EXPECT_NEAR(at[i].daa, (8.0 * (plus[i].da - minus[i].da) - (plus2[i].da - minus2[i].da)) / (12 * h), 1e-8);
      ASSERT_TRUE(jetAt(0.0, h, plus) && jetAt(0.0, -h, minus) && jetAt(0.0, 2 * h, plus2) &&
        jetAt(0.0, -2 * h, minus2));
      EXPECT_NEAR(at[i].dab, (8.0 * (plus[i].da - minus[i].da) - (plus2[i].da - minus2[i].da)) / (12 * h), 1e-8);
      EXPECT_NEAR(at[i].dbb, (8.0 * (plus[i].db - minus[i].db) - (plus2[i].db - minus2[i].db)) / (12 * h), 1e-8);
      EXPECT_GT(std::fabs(at[0].daa) + std::fabs(at[1].daa) + std::fabs(at[2].daa), 1e-3);
    }
  }
}

TEST(Derivatives, BadInputIsNotMapped)
{
  const std::vector<GeneratorParameters> g = { GeneratorParameters{} };
  const PointPairField field(g.data(), g.size(), 1.0, 0.5);
  Vec3 image{ 7, 7, 7 };
  Jacobian j{};
  j.fill(5.0);
  const double nan = std::nan("");
  EXPECT_FALSE(field.mapWithJacobian({ nan, 0, 0 }, 1.0, ExponentialRule::Exact, image, j.data()));
  EXPECT_EQ(7.0, image.x);
  EXPECT_EQ(5.0, j[0]);
  const double in[6] = { nan, 0, 0, 0.5, 0.5, 0.5 };
  double out[6], jacobians[18];
  EXPECT_EQ(1u, field.mapPointsWithJacobians(in, out, jacobians, 2, 1.0, ExponentialRule::Exact));
  EXPECT_TRUE(std::isnan(out[0]));
  EXPECT_EQ(1.0, jacobians[0]);
  EXPECT_EQ(0.0, jacobians[1]);
  EXPECT_EQ(1.0, jacobians[8]);
  // No generators: the identity and its derivative.
  const PointPairField empty(static_cast<const GeneratorParameters*>(nullptr), 0, 1.0, 0.5);
  ASSERT_TRUE(empty.mapWithJacobian({ 1, 2, 3 }, 1.0, ExponentialRule::Exact, image, j.data()));
  EXPECT_EQ(2.0, image.y);
  EXPECT_EQ(1.0, j[4]);
  EXPECT_EQ(0.0, j[5]);
}
} // namespace
