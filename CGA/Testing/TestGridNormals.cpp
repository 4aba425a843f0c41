// cga::crossedDifferenceNormals against the plain composition it stands for (Vec3.h's normalized
// and cross, then the cross product times one over its length), bit for bit, on random samples at
// many scales and partial blocks; and the samples it must leave to the caller.
#include "cga/GridNormals.h"
#include "cga/Vec3.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <vector>

namespace
{
// The composition, one sample: the plain path only (the caller's one-at-a-time code decides the
// others, so here they are only flagged).
bool plainNormal(const double* left, const double* right, const double* below, const double* above,
  double minimumSine, double normal[3])
{
  const cga::Vec3 a{ right[0] - left[0], right[1] - left[1], right[2] - left[2] };
  const cga::Vec3 b{ above[0] - below[0], above[1] - below[1], above[2] - below[2] };
  if (!cga::squareIsSafe(cga::dot(a, a)) || !cga::squareIsSafe(cga::dot(b, b)))
  {
    return false;
  }
  const cga::Vec3 n = cga::cross(cga::normalized(a), cga::normalized(b));
  const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  if (!(length > minimumSine))
  {
    return false;
  }
  const double inverse = 1.0 / length;
  normal[0] = n.x * inverse;
  normal[1] = n.y * inverse;
  normal[2] = n.z * inverse;
  return true;
}

struct Samples
{
  std::vector<double> left, right, below, above;
  explicit Samples(std::size_t count)
    : left(3 * count), right(3 * count), below(3 * count), above(3 * count)
  {
  }
  std::size_t count() const { return left.size() / 3; }
};

void expectTheComposition(const Samples& s, double minimumSine, std::size_t& plainCount)
{
  const std::size_t count = s.count();
  std::vector<double> normals(3 * count, -7.0);
  std::unique_ptr<bool[]> plain(new bool[count + 1]);
  plain[count] = true; // past the end: must stay untouched
  cga::crossedDifferenceNormals(s.left.data(), s.right.data(), s.below.data(), s.above.data(),
    count, minimumSine, normals.data(), plain.get());
  EXPECT_TRUE(plain[count]);
  for (std::size_t i = 0; i < count; ++i)
  {
    double expected[3];
    const bool expectedPlain = plainNormal(&s.left[3 * i], &s.right[3 * i], &s.below[3 * i],
      &s.above[3 * i], minimumSine, expected);
    ASSERT_EQ(plain[i], expectedPlain) << "sample " << i << " of " << count;
    if (expectedPlain)
    {
      ++plainCount;
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_EQ(normals[3 * i + k], expected[k]) << "sample " << i << " component " << k;
      }
    }
  }
}
} // namespace

TEST(GridNormals, TheSameBitsAsThePlainCompositionAtEveryScaleAndBlockSize)
{
  std::mt19937_64 random(20261204);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-140, 140);
  std::size_t plainCount = 0, total = 0;
  for (std::size_t count : { 0, 1, 7, 8, 9, 16, 21, 64, 257 })
  {
    Samples s(count);
    for (std::size_t i = 0; i < count; ++i)
    {
      // A sample's four neighbours near one point, at a scale of 10^-140 ... 10^140.
      const double scale = std::pow(10.0, exponent(random));
      for (std::size_t k = 3 * i; k < 3 * i + 3; ++k)
      {
        const double center = unit(random) * scale;
        s.left[k] = center + unit(random) * scale;
        s.right[k] = center + unit(random) * scale;
        s.below[k] = center + unit(random) * scale;
        s.above[k] = center + unit(random) * scale;
      }
    }
    expectTheComposition(s, 1e-12, plainCount);
    total += count;
  }
  // Random neighbours are almost never parallel: nearly every sample takes the plain path.
  EXPECT_GT(plainCount, total * 9 / 10);
}

TEST(GridNormals, LeavesToTheCallerWhatThePlainPathCannotDo)
{
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // Sample 0 is a plain one (a unit square: normal +z); each other sample breaks it one way.
  Samples s(9);
  for (std::size_t i = 0; i < 9; ++i)
  {
    const double left[3] = { -1, 0, 0 }, right[3] = { 1, 0, 0 }, below[3] = { 0, -1, 0 },
                 above[3] = { 0, 1, 0 };
    for (int k = 0; k < 3; ++k)
    {
      s.left[3 * i + k] = left[k];
      s.right[3 * i + k] = right[k];
      s.below[3 * i + k] = below[k];
      s.above[3 * i + k] = above[k];
    }
  }
  s.left[3 * 1] = nan;                 // not finite
  s.above[3 * 2 + 1] = inf;            // not finite
  s.right[3 * 3] = -1;                 // coincident neighbours: a zero difference
  s.right[3 * 4] = -1 + 1e-150;        // a difference whose square underflows
  s.right[3 * 5] = 1e200;              // one whose square overflows
  s.left[3 * 6] = -1e308;              // a difference that overflows (1e308 + 1e308)
  s.right[3 * 6] = 1e308;
  s.right[3 * 7] = 0;                  // parallel differences: along y both
  s.right[3 * 7 + 1] = 1;
  s.left[3 * 7] = 0;
  s.left[3 * 7 + 1] = -1;
  s.right[3 * 8 + 1] = 1e-13;          // nearly parallel: |n| below the minimum sine
  s.right[3 * 8] = 0;
  s.left[3 * 8] = 0;
  s.left[3 * 8 + 1] = -1;
  std::vector<double> normals(3 * 9);
  bool plain[9];
  cga::crossedDifferenceNormals(s.left.data(), s.right.data(), s.below.data(), s.above.data(), 9,
    1e-12, normals.data(), plain);
  EXPECT_TRUE(plain[0]);
  EXPECT_EQ(normals[0], 0.0);
  EXPECT_EQ(normals[1], 0.0);
  EXPECT_EQ(normals[2], 1.0);
  for (int i = 1; i < 9; ++i)
  {
    EXPECT_FALSE(plain[i]) << "sample " << i;
  }
  std::size_t plainCount = 0;
  expectTheComposition(s, 1e-12, plainCount);
  EXPECT_EQ(plainCount, 1u);
}
