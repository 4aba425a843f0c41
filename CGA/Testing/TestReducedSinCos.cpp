// ReducedSinCos.h: sin and cos of a long double with the argument reduced by π/2 in three parts,
// against glibc's sincosl (which reduces every argument exactly, Payne–Hanek), over the range
// reduced by hand, next to multiples of π/2 (where the reduction cancels), at its limit 2^30 and
// beyond it (sincosl itself), and for non-finite arguments.
#include "ReducedSinCos.h"

#include "TestSupport.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace
{
using cgatest::Random;

// Both results against sincosl's: within `absolute` + `relative` |reference| (units of 2^-64).
void expectSinCos(long double x, long double absolute, long double relative)
{
  long double s, c, sReference, cReference;
  cga::detail::reducedSinCos(x, s, c);
  ::sincosl(x, &sReference, &cReference);
  const long double unit = 0x1p-64L;
  EXPECT_LE(std::fabs(s - sReference), (absolute + relative * std::fabs(sReference)) * unit)
    << "sin of " << static_cast<double>(x) << " (" << static_cast<double>(s - sReference) << ")";
  EXPECT_LE(std::fabs(c - cReference), (absolute + relative * std::fabs(cReference)) * unit)
    << "cos of " << static_cast<double>(x) << " (" << static_cast<double>(c - cReference) << ")";
}

TEST(ReducedSinCos, AgreesWithSincoslOverTheReducedRange)
{
  // Angles of every size up to 2^30, both signs: within 2 units of 2^-64 (the roundings of the
  // reduced angle and the kernels' own error; 1 unit measured over 200,000 angles).
  Random random(4101);
  for (int i = 0; i < 20000; ++i)
  {
    const long double x = std::ldexp(static_cast<long double>(random.uniform(-1.0, 1.0)),
      static_cast<int>(random.uniform(-10.0, 30.0)));
    expectSinCos(x, 2.0L, 0.0L);
  }
  for (const long double x : { 0.0L, -0.0L, 0x1p-16000L, 0.785L, 2.0L, 0x1p30L, -0x1p30L })
  {
    expectSinCos(x, 2.0L, 0.0L);
  }
}

TEST(ReducedSinCos, KeepsSmallValuesNextToMultiplesOfHalfPi)
{
  // Next to n π/2 the reduction cancels: sin (or cos) is small there (down to about 2^-40 n),
  // and stays within 2 units of 2^-64 relative to itself, plus 2^-74 absolute for P3's part.
  Random random(4102);
  const long double halfPi = 0x1.921fb54442d1846ap+0L;
  for (int i = 0; i < 20000; ++i)
  {
    const long double n = std::nearbyint(std::ldexp(static_cast<long double>(random.uniform(-1.0, 1.0)),
      static_cast<int>(random.uniform(0.0, 30.0))));
    const long double x = n * halfPi * (1.0L + static_cast<long double>(random.uniform(-1.0, 1.0)) * 0x1p-40L);
    expectSinCos(x, 1.0L / 1024.0L, 2.0L);
  }
}

TEST(ReducedSinCos, TheReducedAnglesPolynomialsAreWithinAnUlpOfSincosl)
{
  // The kernels after the reduction (sinCosOfReduced) on |r| up to π/4 and a little beyond (the
  // reduction's rounding), every scale down to 2^-40 and subnormal r, both signs: within one unit
  // in the last place of sincosl's results (its own error below one: so within two of the exact).
  Random random(4103);
  const long double quarterPi = 0x1.921fb54442d1846ap-1L;
  auto ulpsApart = [](long double a, long double b) {
    const long double unit = std::nextafter(std::fabs(b), std::numeric_limits<long double>::infinity()) - std::fabs(b);
    return std::fabs(a - b) / unit;
  };
  long double worstSine = 0.0L, worstCosine = 0.0L;
  for (int i = 0; i < 200000; ++i)
  {
    long double r = static_cast<long double>(random.uniform(-1.0, 1.0)) * quarterPi * (1.0L + 0x1p-20L);
    if (i % 4 == 0)
    {
      r = std::ldexp(r, -static_cast<int>(random.uniform(0.0, 40.0)));
    }
    if (i == 1)
    {
      r = 0x1p-16440L; // subnormal
    }
    long double s, c, sReference, cReference;
    cga::detail::sinCosOfReduced(r, s, c);
    ::sincosl(r, &sReference, &cReference);
    worstSine = std::max(worstSine, ulpsApart(s, sReference));
    worstCosine = std::max(worstCosine, ulpsApart(c, cReference));
  }
  EXPECT_LE(worstSine, 1.0L);
  EXPECT_LE(worstCosine, 1.0L);
  long double s, c;
  cga::detail::sinCosOfReduced(-0.0L, s, c);
  EXPECT_TRUE(s == 0.0L && std::signbit(s)); // sin keeps the zero's sign
  EXPECT_EQ(c, 1.0L);
}

TEST(ReducedSinCos, BeyondTheRangeAndNonFiniteAreSincosls)
{
  for (const long double x : { 0x1.0000000000000002p30L, -0x1p31L, 0x1p60L, 0x1p16000L,
         std::numeric_limits<long double>::infinity(), std::numeric_limits<long double>::quiet_NaN() })
  {
    long double s, c, sReference, cReference;
    cga::detail::reducedSinCos(x, s, c);
    ::sincosl(x, &sReference, &cReference);
    if (std::isnan(sReference))
    {
      EXPECT_TRUE(std::isnan(s) && std::isnan(c)) << static_cast<double>(x);
      continue;
    }
    EXPECT_EQ(s, sReference) << static_cast<double>(x);
    EXPECT_EQ(c, cReference) << static_cast<double>(x);
  }
}
} // namespace
