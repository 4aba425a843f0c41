#include "cga/Orbit.h"

#include "cga/CompactAlgebra.h"
#include "cga/CompactConversion.h"
#include "cga/Exponential.h"
#include "cga/PointSandwich.h"

#include "LaneClones.h"
#include "PointPairKernelDispatch.h"
#include "ReducedSinCos.h"
#include "SandwichScaling.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace cga
{
namespace
{
using Real = long double;

// <B B>_0 and (B ^ B)^2 of a bivector in extended precision, from its null-basis components
// (docs/conventions.md section 1 item 12): with F the e_ij part, a the e_i^no part, b the e_i^ni
// part and d the no^ni part, B ^ B = 2 (F^a) ^ no + 2 (F^b) ^ ni + 2 (d F - a^b) ^ no^ni.
struct Invariants
{
  Real s = 0.0L, w2 = 0.0L;
};

Invariants invariants(const Bivector& b)
{
  const Real c12 = b[Bivector::E12], c13 = b[Bivector::E13], c23 = b[Bivector::E23];
  const Real a1 = b[Bivector::E1NO], a2 = b[Bivector::E2NO], a3 = b[Bivector::E3NO];
  const Real b1 = b[Bivector::E1NI], b2 = b[Bivector::E2NI], b3 = b[Bivector::E3NI];
  const Real d = b[Bivector::NONI];
  Invariants r;
  r.s = -(c12 * c12 + c13 * c13 + c23 * c23) + 2.0L * (a1 * b1 + a2 * b2 + a3 * b3) + d * d;
  const Real alpha = 2.0L * (c12 * a3 - c13 * a2 + c23 * a1);  // e123^no
  const Real beta = 2.0L * (c12 * b3 - c13 * b2 + c23 * b1);   // e123^ni
  const Real g12 = 2.0L * (d * c12 - (a1 * b2 - a2 * b1));      // e12^no^ni
  const Real g13 = 2.0L * (d * c13 - (a1 * b3 - a3 * b1));
  const Real g23 = 2.0L * (d * c23 - (a2 * b3 - a3 * b2));
  r.w2 = -2.0L * alpha * beta - (g12 * g12 + g13 * g13 + g23 * g23);
  return r;
}

// The roots l1 >= l2 of l^2 - s l + w2/4 (the planeSquares of the exponential, extended). A
// discriminant within the rounding of s^2 - w2 is a double root: the two squares are equal (an
// isoclinic double rotation), not split by rounding into rates about 1e-9 apart.
void squares(const Invariants& v, Real& l1, Real& l2)
{
  const Real disc = v.s * v.s - v.w2;
  if (!(disc > 16.0L * std::numeric_limits<Real>::epsilon() * (v.s * v.s + std::fabs(v.w2))))
  {
    l1 = l2 = 0.5L * v.s;
    return;
  }
  const Real r = std::sqrt(disc);
  if (v.s >= 0.0L)
  {
    l1 = 0.5L * (v.s + r);
    l2 = l1 != 0.0L ? 0.25L * v.w2 / l1 : 0.0L;
  }
  else
  {
    l2 = 0.5L * (v.s - r);
    l1 = 0.25L * v.w2 / l2;
  }
}

OrbitPartKind kindOf(Real square, bool zeroBlade, Real tolerance)
{
  if (zeroBlade)
  {
    return OrbitPartKind::Zero;
  }
  if (square < -tolerance)
  {
    return OrbitPartKind::Elliptic;
  }
  return square > tolerance ? OrbitPartKind::Hyperbolic : OrbitPartKind::Parabolic;
}

// One plane's factors at x = t r for exp(t B): c = cos x and sHat = sin x / r for a negative
// square, cosh and sinh for a positive one, divided by cosh beyond the threshold of
// Exponential.h (as expExact's AvoidOverflow), 1 and t for a zero square.
void planeFactors(Real square, Real rate, Real t, Real& c, Real& sHat)
{
  const Real x = t * rate;
  if (rate == 0.0L)
  {
    c = 1.0L;
    sHat = t;
  }
  else if (square < 0.0L)
  {
    Real sine;
    detail::reducedSinCos(x, sine, c);
    sHat = sine / rate;
  }
  else if (std::fabs(x) > static_cast<Real>(kExpScalingThreshold))
  {
    c = 1.0L;
    sHat = std::tanh(x) / rate;
  }
  else
  {
    c = std::cosh(x);
    sHat = std::sinh(x) / rate;
  }
}

// k divided by a power of two (exactly) where its largest component passes 2^64: the point map
// does not change (K up(p) ~K scales by the square, which fn divides out), and the 5 x 5 point
// map's entries, products of two components, stay finite for every finite t. A transversion's
// 1 + t B at |t| = 1e160 had entries of 1e320, and every sample but t = 0 was lost. The factor is
// at least 2^-kLargestSandwichDownscale: a translator's weight is its scalar's square alone times
// the factor squared, which a smaller factor rounded to 0 (from |t| ~ 1e297 every sample was lost
// as if at infinity).
Even withinRange(const Even& k)
{
  // Even::maxAbs's decision (no scaling where a component is NaN) without its chain of
  // NaN-propagating selects (a tenth of the extended form's time): the largest |component| and,
  // apart, whether one is NaN.
  double largest = std::fabs(k.scalar);
  bool notANumber = std::isnan(k.scalar);
  auto include = [&](double x) {
    largest = std::max(largest, std::fabs(x)); // a NaN x leaves it
    notANumber = notANumber || std::isnan(x);
  };
  std::for_each(k.bivector.c.begin(), k.bivector.c.end(), include);
  std::for_each(k.quadvector.c.begin(), k.quadvector.c.end(), include);
  if (!notANumber && std::isfinite(largest) && largest > 0x1p64)
  {
    return k * std::ldexp(1.0, -std::min(std::ilogb(largest), core::kLargestSandwichDownscale));
  }
  return k;
}

// std::fmax of two long doubles (the other where one is NaN) without glibc's fmaxl, which is a
// call that is not inlined (two per versor).
Real larger(Real a, Real b)
{
  return std::isnan(a) ? b : (std::isnan(b) || b <= a ? a : b);
}

// The closed form's factors and coefficients (extendedVersor's first branch) at kLanes times, in
// double: per part the angle x = t r as xh + xl (t times the rate's high part, with its rounding
// error by a fused multiply-add, plus t times the low part: within 2^-104 |x|), cos and sin (or
// cosh and sinh) of xh by the kernel's vector functions, then of xh + xl to first order in xl
// (|xl| <= 2^-52 |x|: the second order is below 2^-104 x^2).
BOOSTED_LANE_CLONES
void laneCoefficients(const detail::OrbitLanes& lanes, kernel::SinCosBlock sinCos,
  const double* times, double* scalar, double* coefW, double* coefB, double* coefWB)
{
  using detail::Eight;
  static_assert(sizeof(Eight) == kernel::kLanes * sizeof(double), "one Eight per block");
  Eight t;
  std::memcpy(&t, times, sizeof t);
  Eight c[2], sHat[2];
  for (int i = 0; i < 2; ++i)
  {
    if (lanes.kind[i] == OrbitPartKind::Zero)
    {
      c[i] = Eight{} + 1.0;
      sHat[i] = t;
      continue;
    }
    alignas(64) double high[kernel::kLanes], low[kernel::kLanes], even[kernel::kLanes],
      odd[kernel::kLanes];
    for (int l = 0; l < kernel::kLanes; ++l)
    {
      high[l] = times[l] * lanes.rateHigh[i];
      low[l] = __builtin_fma(times[l], lanes.rateHigh[i], -high[l]) + times[l] * lanes.rateLow[i];
    }
    const bool hyperbolic = lanes.kind[i] == OrbitPartKind::Hyperbolic;
    sinCos(hyperbolic, high, even, odd);
    Eight xl, ev, od;
    std::memcpy(&xl, low, sizeof xl);
    std::memcpy(&ev, even, sizeof ev);
    std::memcpy(&od, odd, sizeof od);
    // cos(xh + xl) = cos xh - xl sin xh, cosh(xh + xl) = cosh xh + xl sinh xh; the odd ones
    // sin xh + xl cos xh and sinh xh + xl cosh xh.
    c[i] = hyperbolic ? ev + xl * od : ev - xl * od;
    sHat[i] = (od + xl * ev) / lanes.rateHigh[i];
  }
  const Eight s = c[0] * c[1];
  const Eight w = 0.5 * sHat[0] * sHat[1];
  const Eight b =
    (lanes.square[0] * sHat[0] * c[1] - lanes.square[1] * sHat[1] * c[0]) / lanes.difference;
  const Eight wb = 0.5 * (c[0] * sHat[1] - c[1] * sHat[0]) / lanes.difference;
  std::memcpy(scalar, &s, sizeof s);
  std::memcpy(coefW, &w, sizeof w);
  std::memcpy(coefB, &b, sizeof b);
  std::memcpy(coefWB, &wb, sizeof wb);
}

Real sine(Real x)
{
  Real s, c;
  detail::reducedSinCos(x, s, c);
  return s;
}

Real sinc(Real x)
{
  return std::fabs(x) < 1e-5L ? 1.0L - x * x / 6.0L : sine(x) / x;
}
} // namespace

Orbit::Orbit(const Bivector& b)
  : B(b)
{
  this->classify(b);
  if (!this->Problem.empty() || this->Identity)
  {
    return;
  }
  const Real scale = static_cast<Real>(b.maxAbs());
  const Invariants v = invariants(b);
  Real l[2];
  squares(v, l[0], l[1]);
  // The blades: known for a 2-blade (B, 0) and from the decomposition when the squares differ.
  InvariantDecomposition split;
  const bool blade = std::fabs(v.w2) <= 1e-24L * scale * scale * scale * scale;
  const bool known = blade || (l[0] != l[1] && invariantDecomposition(b, split));
  for (int i = 0; i < 2; ++i)
  {
    const bool zero = blade && i == 1;
    this->setPart(i, zero ? Bivector() : (blade ? b : (i == 0 ? split.first : split.second)),
      zero ? 0.0L : (blade ? v.s : l[i]), zero);
  }
  this->KnownParts = known;
  this->findPeriod();
  this->prepareLanes();
}

Orbit::Orbit(const Bivector& first, const Bivector& second)
  : B(first + second)
{
  this->classify(this->B);
  if (!this->Problem.empty() || this->Identity)
  {
    return;
  }
  const Bivector parts[2] = { first, second };
  for (int i = 0; i < 2; ++i)
  {
    this->setPart(i, parts[i], invariants(parts[i]).s, parts[i].maxAbs() == 0.0);
  }
  this->KnownParts = true;
  this->findPeriod();
  this->prepareLanes();
}

void Orbit::setPart(int i, const Bivector& blade, long double square, bool zero)
{
  const Real scale = static_cast<Real>(this->B.maxAbs());
  OrbitPart& part = this->Parts[i];
  part.blade = blade;
  part.square = static_cast<double>(square);
  part.rate = zero ? 0.0L : std::sqrt(std::fabs(square));
  part.kind = kindOf(square, zero, 1e-12L * scale * scale);
  this->Squares[i] = zero ? 0.0L : square;
  if (i == 1)
  {
    this->W = wedge(this->B, this->B);
    this->WB = rightContraction(this->W, this->B);
  }
}

void Orbit::classify(const Bivector& b)
{
  if (!b.isFinite())
  {
    this->Problem = "the bivector B is not finite";
  }
  else if (b.maxAbs() > kMaximumCoefficient)
  {
    this->Problem = "the bivector B is too large (a coefficient above 1e150)";
  }
  this->Identity = this->Problem.empty() && b.maxAbs() == 0.0;
}

void Orbit::findPeriod()
{
  int elliptic = 0, other = 0;
  for (const OrbitPart& part : this->Parts)
  {
    elliptic += part.kind == OrbitPartKind::Elliptic;
    other += part.kind == OrbitPartKind::Parabolic || part.kind == OrbitPartKind::Hyperbolic;
  }
  const Real pi = 3.141592653589793238462643383279502884L;
  if (other > 0 || elliptic == 0)
  {
    return; // a drift or a boost never returns (or B is the identity)
  }
  if (elliptic == 1)
  {
    const int i = this->Parts[0].kind == OrbitPartKind::Elliptic ? 0 : 1;
    this->Period = static_cast<double>(pi / this->Parts[i].rate);
    this->Windings[i] = 1;
    return;
  }
  // Both rotate: the convergents m/n of r1/r2 (continued fraction), the first whose two periods
  // m pi/r1 and n pi/r2 agree.
  const Real r1 = this->Parts[0].rate, r2 = this->Parts[1].rate;
  const Real ratio = r1 / r2;
  Real x = ratio;
  long long h0 = 1, h1 = 0, k0 = 0, k1 = 1; // convergents h/k
  for (int step = 0; step < 64; ++step)
  {
    const Real a = std::floor(x);
    const long long m = static_cast<long long>(a) * h0 + h1;
    const long long n = static_cast<long long>(a) * k0 + k1;
    if (m > kMaximumWindings || n > kMaximumWindings)
    {
      return;
    }
    h1 = h0;
    h0 = m;
    k1 = k0;
    k0 = n;
    const Real t1 = m * pi / r1, t2 = n * pi / r2;
    if (m > 0 && std::fabs(t1 - t2) <= static_cast<Real>(kPeriodTolerance) * t1)
    {
      this->Period = static_cast<double>(t1);
      this->Windings[0] = static_cast<int>(m);
      this->Windings[1] = static_cast<int>(n);
      return;
    }
    const Real fraction = x - a;
    if (!(fraction > 0.0L))
    {
      return;
    }
    x = 1.0L / fraction;
  }
}

void Orbit::prepareLanes()
{
  const Real l1 = this->Squares[0], l2 = this->Squares[1];
  const Real d = l1 - l2;
  // The first branch of extendedVersor (symmetric in the two parts: given parts may come in
  // either order) with the squares at least a quarter of the larger apart: the coefficients'
  // division by l1 - l2 then amplifies the factors' rounding at most about four times (closer
  // squares keep the extended branches' 11 more bits).
  // The squares must also not be small against B's coefficients (a nearly null B, whose W B is
  // large against l1 - l2, as a drift's): the coefficient of <W B>_2 would amplify the factors'
  // rounding by |W B| / (|B| |l1 - l2|).
  const Real scale = static_cast<Real>(this->B.maxAbs());
  detail::OrbitLanes& lanes = this->Lanes;
  lanes.form = this->Problem.empty() && !this->Identity && d != 0.0L &&
    std::fabs(d) >= 0.25L * larger(std::fabs(l1), std::fabs(l2)) &&
    std::fabs(d) >= 0.25L * scale * scale;
  for (int i = 0; i < 2; ++i)
  {
    const Real rate = this->Parts[i].rate;
    lanes.rateHigh[i] = static_cast<double>(rate);
    lanes.rateLow[i] = static_cast<double>(rate - static_cast<Real>(lanes.rateHigh[i]));
    lanes.kind[i] = rate == 0.0L ? OrbitPartKind::Zero
      : this->Squares[i] < 0.0L   ? OrbitPartKind::Elliptic
                                  : OrbitPartKind::Hyperbolic;
    lanes.square[i] = static_cast<double>(this->Squares[i]);
  }
  lanes.difference = static_cast<double>(d);
  lanes.largestW = this->W.maxAbs();
  lanes.largestB = this->B.maxAbs();
  lanes.largestWB = this->WB.maxAbs();
}

bool Orbit::inLanes(double t) const
{
  // Small angles too: there the coefficients' roundings stay a few units of 2^-53 of the versor
  // (measured against the extended form's power series) and of its part that moves points.
  if (!this->Lanes.form || !std::isfinite(t))
  {
    return false;
  }
  for (int i = 0; i < 2; ++i)
  {
    const double x = std::fabs(t) * this->Lanes.rateHigh[i];
    // Hyperbolic: below the scaling threshold (beyond it the factors are divided by cosh).
    // Circular: t r far from overflowing.
    const OrbitPartKind kind = this->Lanes.kind[i];
    const double limit = kind == OrbitPartKind::Hyperbolic ? kExpScalingThreshold : 0x1p60;
    if (kind != OrbitPartKind::Zero && !(x <= limit))
    {
      return false;
    }
  }
  return true;
}

Even Orbit::versor(double t) const
{
  Even k;
  this->versors(&t, 1, &k);
  return k;
}

void Orbit::versors(const double* times, std::size_t count, Even* out) const
{
  constexpr std::size_t L = kernel::kLanes;
  const detail::OrbitLanes& lanes = this->Lanes;
  const kernel::SinCosBlock sinCos = lanes.form ? kernel::activeSinCosBlock() : nullptr;
  for (std::size_t first = 0; first < count; first += L)
  {
    const std::size_t n = std::min(L, count - first);
    alignas(64) double t[L] = {}, scalar[L], coefW[L], coefB[L], coefWB[L];
    bool lane[L] = {};
    bool any = false;
    for (std::size_t l = 0; l < n; ++l)
    {
      lane[l] = this->inLanes(times[first + l]);
      t[l] = lane[l] ? times[first + l] : 0.0; // the other lanes' arithmetic stays finite
      any = any || lane[l];
    }
    if (any)
    {
      laneCoefficients(lanes, sinCos, t, scalar, coefW, coefB, coefWB);
    }
    for (std::size_t l = 0; l < n; ++l)
    {
      if (!lane[l])
      {
        out[first + l] = this->extendedVersor(times[first + l]);
        continue;
      }
      Even k;
      k.scalar = scalar[l];
      k.quadvector = this->W * coefW[l];
      k.bivector = this->B * coefB[l] + this->WB * coefWB[l];
      // A bound on the largest component: at most 2^63 (finite), withinRange would return the
      // versor unchanged, so it is not called (a tenth of the update with one seed).
      const double bound = std::fabs(scalar[l]) + std::fabs(coefW[l]) * lanes.largestW +
        std::fabs(coefB[l]) * lanes.largestB + std::fabs(coefWB[l]) * lanes.largestWB;
      out[first + l] = bound <= 0x1p63 ? k : withinRange(k);
    }
  }
}

Even Orbit::extendedVersor(double t) const
{
  if (!this->Problem.empty() || !std::isfinite(t))
  {
    return expExact(Bivector() * std::numeric_limits<double>::quiet_NaN());
  }
  if (this->Identity)
  {
    return Even::identity();
  }
  // exp(t B) = scalar + coefW W + coefB B + coefWB <W B>_2, W = B ^ B: expExact's closed form
  // (Exponential.h), with the angles t r_i and the coefficients in extended precision. expExact
  // of t B itself would round t B first, putting about 1e-16 t into every angle.
  const Real l1 = this->Squares[0], l2 = this->Squares[1];
  const Real r1 = this->Parts[0].rate, r2 = this->Parts[1].rate;
  const Real tt = t;
  const Real largest = larger(std::fabs(l1), std::fabs(l2));
  const Real d = l1 - l2;
  if (std::fabs(tt) * larger(r1, r2) < 1.0L)
  {
    return withinRange(expExact(t * this->B)); // small angles: its power series, nothing to amplify
  }
  Real scalar, coefW, coefB, coefWB;
  if (d > 0.0L && (d >= 0.05L * largest || l1 > 0.0L))
  {
    Real c1, s1, c2, s2;
    planeFactors(l1, r1, tt, c1, s1);
    planeFactors(l2, r2, tt, c2, s2);
    scalar = c1 * c2;
    coefW = 0.5L * s1 * s2;
    coefB = (l1 * s1 * c2 - l2 * s2 * c1) / d;
    coefWB = 0.5L * (c1 * s2 - c2 * s1) / d;
  }
  else if (l1 < 0.0L && l2 < 0.0L)
  {
    // Two rotations at nearly equal rates: the divided differences by sums of angles.
    const Real t1 = tt * r1, t2 = tt * r2;
    const Real sincSum = sine(t1 + t2) / (r1 + r2), sincDiff = tt * sinc(t2 - t1);
    Real s1, c1, s2, c2;
    detail::reducedSinCos(t1, s1, c1);
    detail::reducedSinCos(t2, s2, c2);
    scalar = c1 * c2;
    coefW = 0.5L * (s1 / r1) * (s2 / r2);
    coefB = 0.5L * (sincSum + sincDiff);
    coefWB = 0.25L * (sincDiff - sincSum) / (r1 * r2);
  }
  else
  {
    return withinRange(expExact(t * this->B)); // both squares about zero: no angle to keep exact
  }
  Even k;
  k.scalar = static_cast<double>(scalar);
  k.quadvector = this->W * static_cast<double>(coefW);
  k.bivector = this->B * static_cast<double>(coefB) + this->WB * static_cast<double>(coefWB);
  return withinRange(k);
}

bool Orbit::point(Vec3 p, double t, Vec3& out) const
{
  if (!this->Problem.empty() || !isFinite(p) || !std::isfinite(t))
  {
    return false;
  }
  return sandwichPoint(this->versor(t), p, out);
}

bool Orbit::core(int i, RoundInfo& out) const
{
  const OrbitPart& part = this->Parts[i];
  if (!this->Problem.empty() || part.kind != OrbitPartKind::Elliptic || !this->KnownParts)
  {
    return false;
  }
  out = readCircle(toMultivector(part.blade).undual());
  // readCircle orients the undual against the turn: flip it, so that the rotation turns space
  // right-handed about the oriented core (a small orbit about it links it +1).
  out.normal = -out.normal;
  out.direction = -out.direction;
  return isFinite(out.center) && (out.isLine ? isFinite(out.direction) : std::isfinite(out.radius));
}
} // namespace cga
