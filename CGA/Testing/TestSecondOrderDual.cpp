// The second-order dual numbers of SurfaceJetDual.h (Dual<Dual<double, 2>, 2>, DualNumber.h), on
// which the curvature patch's jets run: each operation's six parts (value, two first and three
// second derivatives) against the chain and product rules written out here, and its duplicate
// parts (each first derivative and the mixed one are held twice) equal to the bit.
#include "SurfaceJetDual.h"

#include "TestSupport.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

namespace
{
using namespace cga;
using namespace cgatest;
using Jet = core::SurfaceJetDual;

// A jet by its parts: value, da, db, daa, dab, dbb.
struct Parts
{
  double p[core::kJetParts];
};

Jet dualOf(const Parts& x)
{
  return core::secondOrderOf(x.p);
}

Parts randomParts(Random& random, double lo, double hi)
{
  Parts x;
  x.p[0] = random.uniform(lo, hi);
  for (int j = 1; j < core::kJetParts; ++j)
  {
    x.p[j] = random.uniform(-1.0, 1.0);
  }
  return x;
}

// F(u) from F(u), F'(u), F''(u): (F o u)_ij = F' u_ij + F'' u_i u_j.
Parts composed(const Parts& u, double f, double f1, double f2)
{
  const double* d = u.p;
  return { { f, f1 * d[1], f1 * d[2], f1 * d[3] + f2 * d[1] * d[1], f1 * d[4] + f2 * d[1] * d[2],
    f1 * d[5] + f2 * d[2] * d[2] } };
}

// u w: (u w)_ij = u_ij w + u_i w_j + u_j w_i + u w_ij.
Parts product(const Parts& u, const Parts& w)
{
  const double* a = u.p;
  const double* b = w.p;
  return { { a[0] * b[0], a[1] * b[0] + a[0] * b[1], a[2] * b[0] + a[0] * b[2],
    a[3] * b[0] + 2.0 * a[1] * b[1] + a[0] * b[3], a[4] * b[0] + a[1] * b[2] + a[2] * b[1] + a[0] * b[4],
    a[5] * b[0] + 2.0 * a[2] * b[2] + a[0] * b[5] } };
}

Parts sum(const Parts& u, const Parts& w, double sign)
{
  Parts r;
  for (int j = 0; j < core::kJetParts; ++j)
  {
    r.p[j] = u.p[j] + sign * w.p[j];
  }
  return r;
}

Parts reciprocal(const Parts& w)
{
  const double x = w.p[0];
  return composed(w, 1.0 / x, -1.0 / (x * x), 2.0 / (x * x * x));
}

// The six parts agree with the rules' to 1e-13 of the parts' size, and the held-twice parts are
// copies.
void expectJet(const Jet& x, const Parts& expected, const std::string& what)
{
  double parts[core::kJetParts];
  core::partsOf(x, parts);
  double size = 1.0;
  for (double e : expected.p)
  {
    size = std::max(size, std::abs(e));
  }
  const char* names[] = { "value", "da", "db", "daa", "dab", "dbb" };
  for (int j = 0; j < core::kJetParts; ++j)
  {
    EXPECT_NEAR(parts[j], expected.p[j], 1e-13 * size) << what << " " << names[j];
  }
  for (int k = 0; k < 2; ++k)
  {
    EXPECT_EQ(std::memcmp(&x.v.d[k], &x.d[k].v, sizeof(double)), 0)
      << what << ": the first derivative " << k << " held twice differs";
  }
  EXPECT_EQ(std::memcmp(&x.d[0].d[1], &x.d[1].d[0], sizeof(double)), 0)
    << what << ": the mixed derivative held twice differs";
}

TEST(SecondOrderDual, OperationsFollowTheProductAndChainRules)
{
  Random random(20261205);
  for (int trial = 0; trial < 200; ++trial)
  {
    const Parts u = randomParts(random, 0.5, 2.0), w = randomParts(random, 0.5, 2.0),
                c = randomParts(random, -2.0, 2.0);
    const Jet ju = dualOf(u), jw = dualOf(w), jc = dualOf(c);
    const double x = u.p[0];
    const std::string at = " (trial " + std::to_string(trial) + ")";

    expectJet(ju + jw, sum(u, w, 1.0), "u + w" + at);
    expectJet(ju - jw, sum(u, w, -1.0), "u - w" + at);
    expectJet(-ju, composed(u, -x, -1.0, 0.0), "-u" + at);
    expectJet(ju * jw, product(u, w), "u w" + at);
    expectJet(ju / jw, product(u, reciprocal(w)), "u / w" + at);
    expectJet(core::fusedMultiplyAdd(ju, jw, jc), sum(product(u, w), c, 1.0), "u w + c" + at);
    expectJet(core::fusedMultiplyAdd(ju, 0.75, jc), sum(composed(u, 0.75 * x, 0.75, 0.0), c, 1.0),
      "0.75 u + c" + at);
    expectJet(ju + 3.0, composed(u, x + 3.0, 1.0, 0.0), "u + 3" + at);
    expectJet(3.0 - ju, composed(u, 3.0 - x, -1.0, 0.0), "3 - u" + at);
    expectJet(ju * 3.0, composed(u, 3.0 * x, 3.0, 0.0), "3 u" + at);
    expectJet(ju / 4.0, composed(u, x / 4.0, 0.25, 0.0), "u / 4" + at);
    expectJet(1.0 / jw, reciprocal(w), "1 / w" + at);
    expectJet(core::laneSqrt(ju), composed(u, std::sqrt(x), 0.5 / std::sqrt(x), -0.25 / (x * std::sqrt(x))),
      "sqrt(u)" + at);
    expectJet(core::laneExp(ju), composed(u, std::exp(x), std::exp(x), std::exp(x)), "exp(u)" + at);
    expectJet(core::laneCosh(ju), composed(u, std::cosh(x), std::sinh(x), std::cosh(x)), "cosh(u)" + at);
    expectJet(core::laneSinh(ju), composed(u, std::sinh(x), std::cosh(x), std::sinh(x)), "sinh(u)" + at);
    const double t = std::tanh(x);
    expectJet(core::laneTanh(ju), composed(u, t, 1.0 - t * t, -2.0 * t * (1.0 - t * t)), "tanh(u)" + at);
    Jet sine, cosine;
    core::laneSinCos(ju, sine, cosine);
    expectJet(sine, composed(u, std::sin(x), std::cos(x), -std::sin(x)), "sin(u)" + at);
    expectJet(cosine, composed(u, std::cos(x), -std::sin(x), -std::cos(x)), "cos(u)" + at);
    expectJet(core::select(core::lessThan(ju, jw), ju, jw), u.p[0] < w.p[0] ? u : w, "min(u, w)" + at);
    expectJet(core::magnitude(jc), c.p[0] < 0.0 ? composed(c, -c.p[0], -1.0, 0.0) : c, "|c|" + at);
  }
}

// A square root's value 0 (the plane squares that vanish in a whole neighbourhood) has zero
// derivatives of both orders, as DualNumber.h documents.
TEST(SecondOrderDual, SquareRootOfZeroHasNoDerivatives)
{
  const Parts zero{ { 0.0, 0.5, -0.25, 1.0, 2.0, -3.0 } };
  expectJet(core::laneSqrt(dualOf(zero)), Parts{ { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 } }, "sqrt(0)");
}
} // namespace
