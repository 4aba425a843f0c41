// The generator tree's signed remainder bound (src/TreeRemainder.h, docs/conventions.md section 3
// item 14, "Signed moments"): the kernel's degree-j term as a trace-free tensor of R^4, the norm of
// a moment tensor's trace-free part from its distinct entries, and the bound of the degree-j term of
// a cluster's sum seen from the points of a cube, each against an independent computation (the
// orthogonal projection onto trace-free tensors by Eigen, on full tensors of R^4; the Chebyshev
// series summed generator by generator in long double).
#include "TestSupport.h"

#include "../src/TreeRemainder.h"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace
{
using namespace cgatest;

int power4(int k)
{
  int n = 1;
  for (int i = 0; i < k; ++i)
  {
    n *= 4;
  }
  return n;
}

// The digits (base 4) of a full tensor's index.
std::vector<int> digits(int index, int k)
{
  std::vector<int> d(static_cast<std::size_t>(k));
  for (int i = k - 1; i >= 0; --i)
  {
    d[static_cast<std::size_t>(i)] = index % 4;
    index /= 4;
  }
  return d;
}

int indexOf(const std::vector<int>& d)
{
  int index = 0;
  for (int v : d)
  {
    index = 4 * index + v;
  }
  return index;
}

// The orthogonal projection of a symmetric tensor of degree k of R^4 (full, 4^k entries) onto the
// trace-free ones: V - sym(delta (x) A) with A such that the result's trace vanishes (sym(delta (x) A)
// spans the complement of the trace-free symmetric tensors).
Eigen::VectorXd traceFreePart(const Eigen::VectorXd& v, int k)
{
  if (k < 2)
  {
    return v;
  }
  const int n = power4(k), m = power4(k - 2);
  // L: A -> sym(delta (x) A), the mean over the k! orders of the indices.
  Eigen::MatrixXd lift = Eigen::MatrixXd::Zero(n, m);
  for (int row = 0; row < n; ++row)
  {
    std::vector<int> d = digits(row, k), order(static_cast<std::size_t>(k));
    for (int i = 0; i < k; ++i)
    {
      order[static_cast<std::size_t>(i)] = i;
    }
    int permutations = 0;
    do
    {
      ++permutations;
      const int a = d[static_cast<std::size_t>(order[0])], b = d[static_cast<std::size_t>(order[1])];
      if (a != b)
      {
        continue;
      }
      std::vector<int> rest;
      for (int i = 2; i < k; ++i)
      {
        rest.push_back(d[static_cast<std::size_t>(order[static_cast<std::size_t>(i)])]);
      }
      lift(row, indexOf(rest)) += 1.0;
    } while (std::next_permutation(order.begin(), order.end()));
    lift.row(row) /= permutations;
  }
  // The trace over the first two indices.
  Eigen::MatrixXd trace = Eigen::MatrixXd::Zero(m, n);
  for (int col = 0; col < m; ++col)
  {
    std::vector<int> rest = digits(col, k - 2);
    for (int a = 0; a < 4; ++a)
    {
      std::vector<int> full = { a, a };
      full.insert(full.end(), rest.begin(), rest.end());
      trace(col, indexOf(full)) = 1.0;
    }
  }
  const Eigen::MatrixXd system = trace * lift;
  const Eigen::VectorXd a = system.completeOrthogonalDecomposition().solve(trace * v);
  return v - lift * a;
}

// x^(k) as a full tensor of R^4.
Eigen::VectorXd outerPower(const std::array<double, 4>& x, int k)
{
  Eigen::VectorXd t(power4(k));
  for (int index = 0; index < t.size(); ++index)
  {
    double product = 1.0;
    for (int d : digits(index, k))
    {
      product *= x[static_cast<std::size_t>(d)];
    }
    t(index) = product;
  }
  return t;
}

long double chebyshevU(int j, long double x)
{
  long double previous = 1.0L, current = 2.0L * x;
  if (j == 0)
  {
    return previous;
  }
  for (int i = 1; i < j; ++i)
  {
    const long double next = 2.0L * x * current - previous;
    previous = current;
    current = next;
  }
  return current;
}

// Random points of R^3 in the unit ball and three-component weights (one part of the motion bound).
struct Cluster
{
  std::vector<Vec3> points;
  std::vector<std::array<double, 3>> weights;
};

Cluster randomCluster(Random& random, std::size_t count)
{
  Cluster c;
  while (c.points.size() < count)
  {
    const Vec3 y = random.vec3(1.0);
    if (norm(y) <= 1.0)
    {
      c.points.push_back(y);
      c.weights.push_back({ random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0), random.uniform(-1.0, 1.0) });
    }
  }
  return c;
}

// The distinct entries of the cluster's moment tensors, sum_i g_i y^a y^b y^c, as treeTraceFreeNorm
// reads them.
struct Moments
{
  int degree;
  std::vector<double> values; // (a, b, c) -> 3 values, (degree + 1)^3 slots
  Moments(const Cluster& c, int degree)
    : degree(degree)
    , values(static_cast<std::size_t>(3 * (degree + 1) * (degree + 1) * (degree + 1)), 0.0)
  {
    for (std::size_t i = 0; i < c.points.size(); ++i)
    {
      for (int a = 0; a <= degree; ++a)
      {
        for (int b = 0; a + b <= degree; ++b)
        {
          for (int e = 0; a + b + e <= degree; ++e)
          {
            const double power =
              std::pow(c.points[i].x, a) * std::pow(c.points[i].y, b) * std::pow(c.points[i].z, e);
            for (int k = 0; k < 3; ++k)
            {
              values[slot(a, b, e) + static_cast<std::size_t>(k)] += power * c.weights[i][static_cast<std::size_t>(k)];
            }
          }
        }
      }
    }
  }
  std::size_t slot(int a, int b, int c) const
  {
    return static_cast<std::size_t>(3 * ((a * (degree + 1) + b) * (degree + 1) + c));
  }
  const double* operator()(int a, int b, int c) const { return values.data() + slot(a, b, c); }
};

// The kernel's degree-j term |z|^j U_j(u.z/|z|) is 2^j <pi(X^(j)), Z^(j)> for X = (u, sqrt(1 - |u|^2)),
// Z = (z, 0), and its tensor's norm 2^j |pi(X^(j))| is treeHarmonicTermNorm(j).
TEST(TreeHarmonicBound, KernelTermIsTheTraceFreeTensorOfR4)
{
  Random random(7);
  for (int trial = 0; trial < 5; ++trial)
  {
    Vec3 u = random.vec3(1.0);
    u = (random.uniform(0.0, 0.999) / norm(u)) * u;
    const std::array<double, 4> x = { u.x, u.y, u.z, std::sqrt(1.0 - dot(u, u)) };
    const Vec3 z = random.vec3(1.0);
    for (int j = 0; j <= 4; ++j)
    {
      const Eigen::VectorXd harmonic = traceFreePart(outerPower(x, j), j);
      const double term = std::ldexp(harmonic.dot(outerPower({ z.x, z.y, z.z, 0.0 }, j)), j);
      const double expected = std::pow(norm(z), j) *
        static_cast<double>(chebyshevU(j, static_cast<long double>(dot(u, z) / norm(z))));
      EXPECT_NEAR(term, expected, 1e-12 * (j + 1)) << "j " << j;
      EXPECT_NEAR(std::ldexp(harmonic.norm(), j), cga::detail::treeHarmonicTermNorm(j), 1e-12 * (j + 1) * std::ldexp(1.0, j))
        << "j " << j;
    }
  }
}

// ||pi(V_k)|| from the distinct entries (the alternating sum of the traces' norms) against the
// projection of the full tensor, for clusters whose weights cancel and for one generator.
TEST(TreeHarmonicBound, TraceFreeNormIsTheProjectionsNorm)
{
  Random random(11);
  for (const std::size_t count : { std::size_t(1), std::size_t(5), std::size_t(60) })
  {
    const Cluster cluster = randomCluster(random, count);
    const Moments moments(cluster, 4);
    for (int k = 0; k <= 4; ++k)
    {
      double squared = 0.0;
      for (int part = 0; part < 3; ++part)
      {
        Eigen::VectorXd v = Eigen::VectorXd::Zero(power4(k));
        for (std::size_t i = 0; i < count; ++i)
        {
          const Vec3 y = cluster.points[i];
          v += cluster.weights[i][static_cast<std::size_t>(part)] * outerPower({ y.x, y.y, y.z, 0.0 }, k);
        }
        squared += traceFreePart(v, k).squaredNorm();
      }
      EXPECT_NEAR(cga::detail::treeTraceFreeNorm(k, 3, moments), std::sqrt(squared), 1e-8 * (1.0 + std::sqrt(squared)))
        << count << " generators, k " << k;
    }
  }
}

// The degree-j term of a cluster's sum at a point of a cube: with w_i = y_i - y_t (|y_i| <= rho,
// |y_t| <= r) and q = sqrt(kappa) (rho + r), a = rho/(rho + r), b = r/(rho + r),
//   |sum_i g_i |s w_i|^j U_j(u.w_i/|w_i|)| <= q^j sqrt((j + 1) 2^j) sum_k C(j, k) a^k b^(j-k) ||pi(V_k)||
// (V_k the moments of y_i/rho, s = sqrt(kappa)), at every degree to 16, summed in long double; the
// bound is reached by one generator at the rim along u seen from the cube's center (r = 0, |u| = 1),
// and the sum of a cancelling cluster is far below the absolute bound min(j + 1, S) sum_i |g_i| ...
TEST(TreeHarmonicBound, SignedTermBoundHoldsForTheClustersTerms)
{
  constexpr int kDegree = 16;
  Random random(13);
  for (int trial = 0; trial < 6; ++trial)
  {
    const Cluster cluster = randomCluster(random, trial < 3 ? 40 : 300);
    const double rho = random.uniform(0.1, 1.0), r = trial % 3 == 0 ? 0.0 : random.uniform(0.0, 1.0) * rho;
    const Moments moments(cluster, kDegree);
    double norms[kDegree + 1], absolutes[kDegree + 1];
    for (int k = 0; k <= kDegree; ++k)
    {
      norms[k] = cga::detail::treeTraceFreeNorm(k, 3, moments);
      absolutes[k] = 0.0;
      for (std::size_t i = 0; i < cluster.points.size(); ++i)
      {
        const auto& g = cluster.weights[i];
        absolutes[k] += std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]) * std::pow(norm(cluster.points[i]), k);
      }
    }
    Vec3 u = random.vec3(1.0);
    u = (random.uniform(0.5, 0.999) / norm(u)) * u;
    const double scale = random.uniform(0.2, 0.6) / (rho + r); // sqrt(kappa): q = 0.2 ... 0.6
    const double q = scale * (rho + r), a = rho / (rho + r), b = r / (rho + r);
    for (int point = 0; point < 4; ++point)
    {
      Vec3 yt = random.vec3(1.0);
      yt = (r * random.uniform(0.5, 1.0) / norm(yt)) * yt;
      for (int j = 0; j <= kDegree; ++j)
      {
        long double sum[3] = {};
        for (std::size_t i = 0; i < cluster.points.size(); ++i)
        {
          const Vec3 w = rho * cluster.points[i] - yt;
          const double length = norm(w);
          const long double term = length > 0.0
            ? std::pow(static_cast<long double>(scale * length), j) * chebyshevU(j, static_cast<long double>(dot(u, w) / length))
            : (j == 0 ? 1.0L : 0.0L);
          for (int k = 0; k < 3; ++k)
          {
            sum[k] += term * cluster.weights[i][static_cast<std::size_t>(k)];
          }
        }
        const double actual = std::sqrt(static_cast<double>(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]));
        const double bound =
          std::pow(q, j) * cga::detail::treeHarmonicTermNorm(j) * cga::detail::treeSpreadMoment(norms, j, a, b);
        EXPECT_LE(actual, bound * (1.0 + 1e-9) + 1e-14) << "trial " << trial << " j " << j;
        if (r == 0.0 && j >= 8 && cluster.points.size() >= 300)
        {
          // The cancellation the absolute bound (every generator at its own |y_i| with |U_j| <= j + 1) misses.
          EXPECT_LT(bound, 0.5 * std::pow(q, j) * (j + 1) * absolutes[j]) << "trial " << trial << " j " << j;
        }
      }
    }
  }
  // One generator at the rim, along u, |u| = 1, seen from the cube's center: the bound is reached.
  Cluster lone;
  lone.points.push_back({ 0.0, 0.0, 1.0 });
  lone.weights.push_back({ 0.0, 3.0, 4.0 });
  const Moments moments(lone, kDegree);
  for (int j = 0; j <= kDegree; ++j)
  {
    double norms[kDegree + 1];
    for (int k = 0; k <= kDegree; ++k)
    {
      norms[k] = cga::detail::treeTraceFreeNorm(k, 3, moments);
    }
    const double bound = cga::detail::treeHarmonicTermNorm(j) * cga::detail::treeSpreadMoment(norms, j, 1.0, 0.0);
    EXPECT_NEAR(bound, 5.0 * (j + 1), 1e-6 * (j + 1)) << "j " << j; // |g| U_j(1) = 5 (j + 1)
  }
}
} // namespace
