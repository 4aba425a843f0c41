// Shared helpers of the kernel tests: seeded random inputs, relative comparisons, data files.
#pragma once

#include "cga/Compact.h"
#include "cga/CompactConversion.h"
#include "cga/Multivector.h"
#include "cga/PointPairField.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"
#include "cga/Vec3.h"
#include "cga/surfaces/CurvatureOperators.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace cgatest
{
/// Restores mapPoints()' instruction set of the test's start when the scope ends (tests that
/// switch it with useMapPointsInstructionSet).
struct InstructionSetScope
{
  std::string Saved = cga::mapPointsInstructionSet();
  ~InstructionSetScope() { cga::useMapPointsInstructionSet(Saved); }
};

using namespace cga;

/// Seeded generator so that every run sees the same inputs.
class Random
{
public:
  explicit Random(std::uint64_t seed)
    : Engine(seed)
  {
  }

  double uniform(double lo, double hi)
  {
    return std::uniform_real_distribution<double>(lo, hi)(Engine);
  }

  Vec3 vec3(double half)
  {
    return { uniform(-half, half), uniform(-half, half), uniform(-half, half) };
  }

  Vec3 unit()
  {
    for (;;)
    {
      const Vec3 v = vec3(1.0);
      const double n = norm(v);
      if (n > 0.1 && n <= 1.0)
      {
        return v / n;
      }
    }
  }

  Bivector bivector(double half)
  {
    Bivector b;
    for (double& x : b.c)
    {
      x = uniform(-half, half);
    }
    return b;
  }

  Quadvector quadvector(double half)
  {
    Quadvector q;
    for (double& x : q.c)
    {
      x = uniform(-half, half);
    }
    return q;
  }

  /// Scalar + bivector + 4-vector with independent coefficients: generally not a versor.
  Even even(double half)
  {
    Even k;
    k.scalar = uniform(-half, half);
    k.bivector = bivector(half);
    k.quadvector = quadvector(half);
    return k;
  }

  Multivector multivector(double half)
  {
    Multivector m;
    for (double& x : m.c)
    {
      x = uniform(-half, half);
    }
    return m;
  }

private:
  std::mt19937_64 Engine;
};

/// A wavy sheet of side x side points over [-half, half]^2 (z = 0.2 sin 3x cos 2y), xyz
/// interleaved: the generator tree tests' mesh through their generators and beyond them.
inline std::vector<double> wavySheet(int side, double half)
{
  std::vector<double> points;
  for (int i = 0; i < side; ++i)
  {
    for (int j = 0; j < side; ++j)
    {
      const double x = -half + 2.0 * half * i / (side - 1), y = -half + 2.0 * half * j / (side - 1);
      points.insert(points.end(), { x, y, 0.2 * std::sin(3.0 * x) * std::cos(2.0 * y) });
    }
  }
  return points;
}

/// A random orthonormal patch frame: origin in [-2, 2]^3, random u and v directions.
inline PatchFrame randomFrame(Random& random)
{
  PatchFrame frame;
  const std::string problem =
    PatchFrame::fromDirections(random.vec3(2.0), random.unit(), random.unit(), frame);
  EXPECT_TRUE(problem.empty()) << problem;
  return frame;
}

/// |a - b| / max(|b|, floor) in coefficient norm.
inline double relativeDifference(const Multivector& a, const Multivector& b, double floor = 1e-300)
{
  return (a - b).coefficientNorm() / std::max(b.coefficientNorm(), floor);
}

inline double relativeDifference(const Even& a, const Even& b, double floor = 1e-300)
{
  return relativeDifference(toMultivector(a), toMultivector(b), floor);
}

inline double relativeDifference(const Bivector& a, const Bivector& b, double floor = 1e-300)
{
  return relativeDifference(toMultivector(a), toMultivector(b), floor);
}

/// The larger of a running worst error and a new one, NaN when either is NaN. Fold errors with
/// this, never std::max: std::max(worst, NaN) keeps worst, so a NaN result would vanish and the
/// EXPECT_LE(worst, tolerance) after the loop could not fail.
inline double worseOf(double worst, double error)
{
  return std::isnan(worst) || std::isnan(error) ? std::numeric_limits<double>::quiet_NaN()
                                                : std::max(worst, error);
}

/// Maximum-norm distance of Euclidean vectors (NaN if a coordinate is: worseOf).
inline double distance(Vec3 a, Vec3 b)
{
  return worseOf(worseOf(std::fabs(a.x - b.x), std::fabs(a.y - b.y)), std::fabs(a.z - b.z));
}

inline double maxNorm(Vec3 a)
{
  return worseOf(worseOf(std::fabs(a.x), std::fabs(a.y)), std::fabs(a.z));
}

/// Relative closeness of Euclidean points: |a - b|_max <= tolerance * max(1, |b|_max).
inline ::testing::AssertionResult pointsNear(Vec3 a, Vec3 b, double tolerance)
{
  const double d = distance(a, b);
  if (d <= tolerance * std::max(1.0, maxNorm(b)))
  {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
    << "(" << a.x << ", " << a.y << ", " << a.z << ") vs (" << b.x << ", " << b.y << ", " << b.z
    << "), difference " << d;
}

inline std::string dataPath(const std::string& name)
{
  return std::string(BOOSTED_CGA_TEST_DATA_DIR) + "/" + name;
}

/// Signed area of a polygon in the xy plane (shoelace): positive when counter-clockwise.
inline double signedArea(const std::vector<Vec3>& points)
{
  double area = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const Vec3 a = points[i], b = points[(i + 1) % points.size()];
    area += a.x * b.y - b.x * a.y;
  }
  return 0.5 * area;
}

/// The transversion of docs/conventions.md section 2: x' = (x + v|x|^2)/(1 + 2 v.x + |v|^2 |x|^2).
inline Vec3 specialConformal(Vec3 v, Vec3 x)
{
  return (x + norm2(x) * v) / (1.0 + 2.0 * dot(v, x) + norm2(v) * norm2(x));
}

/// K = 1 + w tau(x, v).
inline Even boost(double w, Vec3 x, Vec3 v)
{
  return Even::identity() + Even::fromBivector(w * nullPointPairCompact(x, v));
}

/// fn(<K up(p) ~K>_1), expected to be finite.
inline Vec3 mapPoint(const Even& k, Vec3 p)
{
  Vec3 out{ NAN, NAN, NAN };
  EXPECT_TRUE(sandwichPoint(k, p, out));
  return out;
}
} // namespace cgatest
