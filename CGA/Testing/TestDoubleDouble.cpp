// The double-double number type of the Exact rule's accurate branch (src/DoubleDouble.h,
// docs/conventions.md section 2 item 12): its arithmetic and elementary functions against values
// computed by mpmath at 60 digits from the same double arguments (the reference's hi and lo are
// the value rounded to double and the rest rounded to double).
#include "DoubleDouble.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace
{
using cga::core::DoubleDouble;

struct Reference
{
  double hi, lo;
};

// |x - reference| relative to |reference|, in double-double (the difference is formed exactly
// enough: both are near each other).
double relativeError(const DoubleDouble& x, const Reference& r)
{
  const DoubleDouble difference = x - DoubleDouble(r.hi, r.lo);
  return std::fabs(difference.hi) / std::fabs(r.hi);
}

// 2^-100: every function is within a few units of 2^-104 of its result.
constexpr double kTolerance = 0x1p-100;

struct Case
{
  double x;
  Reference exp, cosh, sinh, tanh, sin, cos;
};

// mpmath at 60 digits of mpf(x) for the double x.
const Case kCases[] = {
  { 0.3, { 1.3498588075760032, -9.447314673432387e-17 }, { 1.0453385141288605, 7.371812611119388e-18 }, { 0.3045202934471426, 9.177343117072388e-18 }, { 0.2913126124515909, -6.4602656586469586e-18 }, { 0.29552020666133955, 1.8315357276792536e-17 }, { 0.955336489125606, 4.1935600297907467e-17 } },
  { -1.7, { 0.18268352405273466, -5.430659906894856e-18 }, { 2.828315457889967, -1.0024752332269377e-16 }, { -2.6456319338372323, -1.5498331712486131e-16 }, { -0.935409070603099, -6.160665782786146e-18 }, { -0.9916648104524686, -5.077812604198573e-17 }, { -0.12884449429552464, -3.6530675885303595e-18 } },
  { 0.0009765625, { 1.0009770394924165, 8.141755997634129e-17 }, { 1.0000004768371962, -7.401366363924272e-17 }, { 0.0009765626552204365, -4.336791883732524e-20 }, { 0.0009765621895592603, -4.341379977097105e-20 }, { 0.0009765623447795783, -7.228182545327179e-21 }, { 0.9999995231628797, 3.700622948511186e-17 } },
  { 25.5, { 118716009132.16965, 3.7484041480402334e-06 }, { 59358004566.08482, 1.874206285751994e-06 }, { 59358004566.08482, 1.8741978622882394e-06 }, { 1.0, -1.4190948324569407e-22 }, { 0.3590583540221683, -8.420422152123147e-18 }, { 0.933315112063922, -4.27450022738087e-17 } },
  { -300.25, { 4.009422364622857e-131, -9.421845746665655e-148 }, { 1.2470624307674607e+130, -3.077472701531412e+113 }, { -1.2470624307674607e+130, 3.077472701531412e+113 }, { -1.0, 0.0 }, { 0.9741426430536687, -3.6239118156706843e-17 }, { 0.22593386418244757, -5.942921150041908e-18 } },
  { 3e-05, { 1.0000300004500045, 4.74177290145958e-17 }, { 1.00000000045, -3.7199416926788884e-17 }, { 3.0000000004500002e-05, -1.4454893199145401e-21 }, { 2.9999999991e-05, -4.935081491892927e-22 }, { 2.99999999955e-05, 1.4458943199145402e-21 }, { 0.99999999955, 3.7266916926788885e-17 } },
  { 40.0, { 2.3538526683702e+17, -14.592100089250966 }, { 1.1769263341851e+17, -7.296050044625483 }, { 1.1769263341851e+17, -7.296050044625483 }, { 1.0, -3.6097027756908306e-35 }, { 0.7451131604793488, -4.800921719561452e-17 }, { -0.6669380616522619, 3.771106789024549e-17 } },
};

TEST(DoubleDouble, ElementaryFunctionsMatchMpmath)
{
  for (const Case& c : kCases)
  {
    const DoubleDouble x(c.x);
    EXPECT_LT(relativeError(cga::core::exponential(x), c.exp), kTolerance) << "exp " << c.x;
    EXPECT_LT(relativeError(cga::core::laneCosh(x), c.cosh), kTolerance) << "cosh " << c.x;
    EXPECT_LT(relativeError(cga::core::laneSinh(x), c.sinh), kTolerance) << "sinh " << c.x;
    EXPECT_LT(relativeError(cga::core::laneTanh(x), c.tanh), kTolerance) << "tanh " << c.x;
    // sin and cos reduce by pi/2 to 107 bits: an error of |x| 2^-107 in the reduced argument
    const double reduced = kTolerance * std::max(1.0, std::fabs(c.x));
    DoubleDouble s, co;
    cga::core::laneSinCos(x, s, co);
    EXPECT_LT(relativeError(s, c.sin), reduced) << "sin " << c.x;
    EXPECT_LT(relativeError(co, c.cos), reduced) << "cos " << c.x;
  }
}

TEST(DoubleDouble, ArithmeticMatchesMpmath)
{
  EXPECT_LT(relativeError(DoubleDouble(1.0) / DoubleDouble(3.0), { 0.3333333333333333, 1.850371707708594e-17 }),
    kTolerance);
  EXPECT_LT(relativeError(DoubleDouble(0.1) * DoubleDouble(0.3), { 0.03, 1.6653345369377347e-18 }), kTolerance);
  EXPECT_LT(relativeError(cga::core::laneSqrt(DoubleDouble(2.0)), { 1.4142135623730951, -9.667293313452913e-17 }),
    kTolerance);
  EXPECT_LT(relativeError(cga::core::laneSqrt(DoubleDouble(0.3)), { 0.5477225575051661, 2.890126723719787e-17 }),
    kTolerance);
  EXPECT_LT(relativeError(cga::core::laneSqrt(DoubleDouble(7e-30)), { 2.645751311064591e-15, -1.7450578471138017e-31 }),
    kTolerance);
  // a + b - a recovers b below the ulp of a: the sum is exact to 2^-106
  const DoubleDouble big(1e16), small(0.123);
  EXPECT_EQ(((big + small) - big).hi, 0.123);
}

TEST(DoubleDouble, NonFiniteValuesStayNonFinite)
{
  const double inf = __builtin_inf();
  EXPECT_FALSE(std::isfinite((DoubleDouble(inf) + DoubleDouble(1.0)).hi));
  EXPECT_FALSE(std::isfinite((DoubleDouble(1e300) * DoubleDouble(1e300)).hi));
  EXPECT_TRUE(std::isnan((DoubleDouble(1.0) / DoubleDouble(0.0) - DoubleDouble(inf)).hi));
  EXPECT_TRUE(std::isnan(cga::core::laneSqrt(DoubleDouble(-1.0)).hi));
  EXPECT_FALSE(std::isfinite(cga::core::exponential(DoubleDouble(800.0)).hi));
  EXPECT_EQ(cga::core::exponential(DoubleDouble(-800.0)).hi, 0.0);
  DoubleDouble s, c;
  cga::core::laneSinCos(DoubleDouble(__builtin_nan("")), s, c);
  EXPECT_TRUE(std::isnan(s.hi) && std::isnan(c.hi));
  // a huge angle (beyond every integer type's range of k): finite values in [-1, 1], no overflow
  cga::core::laneSinCos(DoubleDouble(1e300), s, c);
  EXPECT_LE(std::fabs(s.hi), 1.0);
  EXPECT_LE(std::fabs(c.hi), 1.0);
}
} // namespace
