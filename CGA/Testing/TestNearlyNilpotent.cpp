// mapPointBy's own copy of the nearly nilpotent test against nearlyNilpotentLanes
// (PointMapCore.h): the two are kept apart on purpose (the helper, called from mapPointBy,
// changed the kernel's object code), so this test keeps them the same test. mapPointBy's choice
// is seen in its image: where it maps around p the image is exactImageAroundPoint's to the bit,
// and in the field's frame (the other formula) it differs from it. The exponents straddle the
// threshold closely (found by bisection on the helper), on both sides, in both branches of the
// test (the early exit on |s|/2 and the plane squares).
#include "PointMapCore.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <vector>

namespace
{
using namespace cga::core;
constexpr int kComponents = cga::Bivector::Count;

struct Exponent
{
  double b[kComponents];
};

bool helperSaysAround(const Exponent& e)
{
  return nearlyNilpotentLanes(e.b, maxAbs(e.b));
}

// Whether mapPointBy (Exact) mapped b around p: its image is exactImageAroundPoint's, bit for
// bit (the field's frame, the other formula, gives other bits for every exponent here).
bool mapPointByMapsAround(const Exponent& e, const double* p)
{
  cga::kernel::FieldArgs args;
  args.exactRule = true;
  Exponent copy = e; // mapPointBy overwrites its exponent
  double image[3], around[3];
  bool mapped = false;
  mapPointBy(args, copy.b, p, image, &mapped);
  exactImageAroundPoint(p, e.b, around);
  return std::memcmp(image, around, sizeof image) == 0;
}

// An exponent of one parameter t, nearly nilpotent at `inside` and not at `outside`.
struct Family
{
  const char* name;
  std::function<Exponent(double)> exponent;
  double inside, outside;
};

// lambda N + t R: N nilpotent (N N = 0), R the rest.
Family plusRest(const char* name, const std::vector<std::pair<int, double>>& nilpotent,
  double lambda, const std::vector<std::pair<int, double>>& rest)
{
  const auto exponent = [=](double t)
  {
    Exponent e{};
    for (const auto& [c, v] : nilpotent)
    {
      e.b[c] += lambda * v;
    }
    for (const auto& [c, v] : rest)
    {
      e.b[c] += t * v;
    }
    return e;
  };
  return { name, exponent, 0.0, lambda };
}

TEST(NearlyNilpotent, MapPointByDecidesAsTheHelperOnBothSidesOfTheThreshold)
{
  using B = cga::Bivector;
  // lambda N + t R, the nilpotent part a translation's or a transversion's generator, the rest
  // one rotation (|s|/2 below the larger plane square: the plane squares decide), two rotations,
  // a rotation and a boost of opposite squares (s = 0: the plane squares alone), a boost. And two
  // rotations of equal squares -1 whose largest component t grows (e3 ^ (t no - ni / 2t), a
  // dilation's conjugate): |s|/2 equals the larger plane square, so the early exit and the
  // plane squares cross the threshold together.
  const std::vector<Family> families = {
    plusRest("translation + rotation", { { B::E1NI, 1.0 } }, 20.0, { { B::E12, 1.0 } }),
    plusRest("translation + two rotations", { { B::E1NI, 1.0 } }, 20.0,
      { { B::E12, 1.0 }, { B::E3NO, 1.0 }, { B::E3NI, -0.5 } }),
    plusRest("transversion + rotation and boost", { { B::E2NO, 1.0 } }, 3.0,
      { { B::E13, 1.0 }, { B::NONI, 1.0 } }),
    plusRest("translation + boost", { { B::E3NI, 1.0 } }, 37.0, { { B::NONI, 1.0 } }),
    { "two equal rotations",
      [](double t)
      {
        Exponent e{};
        e.b[B::E12] = 1.0;
        e.b[B::E3NO] = t;
        e.b[B::E3NI] = -0.5 / t;
        return e;
      },
      1e3, 1.0 },
  };
  const double points[][3] = { { 0.3, -0.7, 0.5 }, { -1.2, 0.4, 2.0 } };
  for (const Family& f : families)
  {
    double inside = f.inside, outside = f.outside;
    ASSERT_TRUE(helperSaysAround(f.exponent(inside))) << f.name;
    ASSERT_FALSE(helperSaysAround(f.exponent(outside))) << f.name;
    while (std::nextafter(inside, outside) != outside)
    {
      const double middle = inside + 0.5 * (outside - inside);
      (helperSaysAround(f.exponent(middle)) ? inside : outside) = middle;
    }
    // The two sides next to the crossing, a few ulps and relative steps of 1e-12 to 1e-3 away.
    const double away = inside < outside ? -1.0 : 1.0; // from the crossing, on inside's side
    std::vector<double> ts;
    double in = inside, out = outside;
    for (int k = 0; k < 4; ++k)
    {
      ts.push_back(in);
      ts.push_back(out);
      in = std::nextafter(in, away * HUGE_VAL);
      out = std::nextafter(out, -away * HUGE_VAL);
    }
    for (const double step : { 1e-12, 1e-9, 1e-6, 1e-3 })
    {
      ts.push_back(inside * (1.0 + away * step));
      ts.push_back(outside * (1.0 - away * step));
    }
    int around = 0;
    for (const double t : ts)
    {
      const Exponent e = f.exponent(t);
      const bool helper = helperSaysAround(e);
      around += helper;
      for (const auto& p : points)
      {
        EXPECT_EQ(mapPointByMapsAround(e, p), helper)
          << f.name << ", t " << t << ", point " << p[0];
      }
    }
    // Both answers, at least at the steps 1e-6 and 1e-3 (within about 1e-10 of the crossing
    // the plane squares' rounding may flip the answer: two equal rotations).
    EXPECT_GE(around, 2) << f.name;
    EXPECT_LE(around, static_cast<int>(ts.size()) - 2) << f.name;
  }
}
} // namespace
