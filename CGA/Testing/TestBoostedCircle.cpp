// BoostedCircle.h: which boosts of the family overflow. Found by the sanitizer build (tools/test's
// second stage): boostProblem read the matrix of a temporary PointMap after its end
// (AddressSanitizer: stack-use-after-scope); this test runs it under the sanitizers there.
#include "TestSupport.h"

#include "cga/PointSandwich.h"
#include "cga/surfaces/BoostedCircle.h"

#include <cmath>

namespace
{
using namespace cga;

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
} // namespace
