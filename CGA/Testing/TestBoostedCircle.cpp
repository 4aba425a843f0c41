// BoostedCircle.h: the family's parameters and boosts. Which boosts of the family overflow was
// found by the sanitizer build (tools/test's second stage): boostProblem read the matrix of a
// temporary PointMap after its end (AddressSanitizer: stack-use-after-scope); the test runs it
// under the sanitizers there. The full multivector boost and image blade against the full
// product (Multivector.h, Conformal.h) and the compact point map.
#include "TestSupport.h"

#include "cga/Conformal.h"
#include "cga/PointSandwich.h"
#include "cga/surfaces/BoostedCircle.h"

#include <cmath>
#include <limits>

namespace
{
using namespace cgatest;

BoostedCircle tiltedFamily()
{
  BoostedCircle family;
  family.center = Vec3{ 0.3, -0.2, 0.5 };
  family.normal = Vec3{ 0.2, 1.0, 0.4 };
  family.radius = 1.3;
  family.boostLocation = Vec3{ -0.4, 0.1, 0.7 };
  family.boostDirection = Vec3{ 0.5, -0.3, 0.8 };
  return family;
}

constexpr double kLambdas[] = { -2.0, -0.5, 0.0, 0.75, 3.0 };

bool mapIsFinite(const BoostedCircle& family, double lambda)
{
  const PointMap map(family.boostCompact(lambda));
  for (const double entry : map.matrix())
  {
    if (!std::isfinite(entry))
    {
      return false;
    }
  }
  return true;
}

TEST(BoostedCircle, BoostProblemNamesTheEndOfTheRangeWhereTheBoostOverflows)
{
  BoostedCircle family;
  EXPECT_EQ(family.boostProblem(-1e3, 1e3), "");
  family.boostDirection = Vec3{ 1e200, 0.0, 0.0 };
  ASSERT_TRUE(mapIsFinite(family, 0.0));
  ASSERT_FALSE(mapIsFinite(family, 2.0));
  EXPECT_EQ(family.boostProblem(0.0, 0.0), ""); // lambda = 0: the identity
  const std::string upper = family.boostProblem(0.0, 2.0);
  EXPECT_NE(upper.find("the boost overflows at lambda = 2:"), std::string::npos) << upper;
  const std::string lower = family.boostProblem(-2.0, 0.0);
  EXPECT_NE(lower.find("the boost overflows at lambda = -2:"), std::string::npos) << lower;
}

TEST(BoostedCircle, ValidateNamesEachBadParameter)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto problem = [](auto change) {
    BoostedCircle family = tiltedFamily();
    change(family);
    return family.validate();
  };
  EXPECT_EQ(problem([](BoostedCircle&) {}), "");
  const std::string notFinite = "parameters must be finite numbers (a NaN or an infinity was given)";
  EXPECT_EQ(problem([&](BoostedCircle& f) { f.center.y = nan; }), notFinite);
  EXPECT_EQ(problem([&](BoostedCircle& f) { f.normal.z = inf; }), notFinite);
  EXPECT_EQ(problem([&](BoostedCircle& f) { f.radius = -inf; }), notFinite);
  EXPECT_EQ(problem([&](BoostedCircle& f) { f.boostLocation.x = nan; }), notFinite);
  EXPECT_EQ(problem([&](BoostedCircle& f) { f.boostDirection.y = inf; }), notFinite);
  EXPECT_EQ(problem([](BoostedCircle& f) { f.normal = Vec3{}; }),
    "the circle normal must not be the zero vector");
  EXPECT_EQ(problem([](BoostedCircle& f) { f.radius = 0.0; }), "the circle radius must be positive");
  EXPECT_EQ(problem([](BoostedCircle& f) { f.radius = -1.0; }), "the circle radius must be positive");
  EXPECT_EQ(problem([](BoostedCircle& f) { f.boostDirection = Vec3{}; }),
    "the boost direction must not be the zero vector");
  // Lengths need not be 1: only the normal's direction is used, the boost direction's length is
  // the generator's weight.
  EXPECT_EQ(problem([](BoostedCircle& f) { f.normal = Vec3{ 0.0, 0.0, 1e-300 }; }), "");
  EXPECT_EQ(problem([](BoostedCircle& f) { f.boostDirection = Vec3{ 1e-300, 0.0, 0.0 }; }), "");
}

// K(lambda) as a full multivector (the reference paths') is the compact boost, and a versor:
// K ~K = (1 + lambda tau)(1 - lambda tau) = 1 - lambda^2 tau^2 = 1 by the full product.
TEST(BoostedCircle, FullMultivectorBoostIsTheCompactBoostAndAVersor)
{
  const BoostedCircle family = tiltedFamily();
  for (const double lambda : kLambdas)
  {
    const Multivector k = family.boost(lambda);
    EXPECT_LT(relativeDifference(k, toMultivector(family.boostCompact(lambda))), 1e-15)
      << "lambda " << lambda;
    EXPECT_LT(relativeDifference(k * k.reverse(), Multivector::scalar(1.0)), 1e-14)
      << "lambda " << lambda;
  }
}

// The image blade is the circle through the images of the circle's points: up(x) ^ C' = 0 for x
// the compact point map of every sample, by the full outer product, and it is a 3-blade.
TEST(BoostedCircle, ImageBladeHoldsTheImagesOfTheCirclesPoints)
{
  const BoostedCircle family = tiltedFamily();
  for (const double lambda : kLambdas)
  {
    const Multivector blade = family.imageBlade(lambda);
    const double size = blade.coefficientNorm();
    ASSERT_GT(size, 0.0);
    EXPECT_LT((blade - blade.grade(3)).coefficientNorm(), 1e-15 * size) << "lambda " << lambda;
    const PointMap map(family.boostCompact(lambda));
    for (int i = 0; i < 12; ++i)
    {
      Vec3 image;
      ASSERT_TRUE(map.apply(family.circlePoint(0.5 * i), image));
      const Multivector point = up(image);
      EXPECT_LT((point ^ blade).coefficientNorm(), 1e-13 * point.coefficientNorm() * size)
        << "lambda " << lambda << " sample " << i;
    }
    // A point off the image circle is not on the blade.
    Vec3 image;
    ASSERT_TRUE(map.apply(family.center, image));
    const Multivector off = up(image);
    EXPECT_GT((off ^ blade).coefficientNorm(), 1e-3 * off.coefficientNorm() * size);
  }
}
} // namespace
