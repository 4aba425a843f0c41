#include "cga/SurfaceCurvature.h"

#include "ForceInline.h"
#include "SurfaceCurvatureSteps.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cga
{
namespace
{
double maxAbs(Vec3 a)
{
  return std::max({ std::fabs(a.x), std::fabs(a.y), std::fabs(a.z) });
}

// The binary exponent e with 2^(e-1) <= m < 2^e (0 for m = 0): dividing by 2^e is exact.
int exponentOf(double m)
{
  int e = 0;
  std::frexp(m, &e);
  return e;
}

// The scale exponent of derivatives whose largest component is m: 0 (no scaling, the common
// case, without the cost of frexp and ldexp) from 2^-100 to 2^100, where every product below
// stays far from underflow and overflow; otherwise m's exponent.
int scaleExponent(double m)
{
  return (m >= 0x1p-100 && m <= 0x1p100) ? 0 : exponentOf(m);
}

Vec3 scaledBy(Vec3 v, int e)
{
  return Vec3{ std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e) };
}

// v / 2^e; inline, so that the common e = 0 costs no call.
BOOSTED_FORCE_INLINE Vec3 scaled(Vec3 v, int e)
{
  return e == 0 ? v : scaledBy(v, e);
}

// hypot(a, b) (to an ulp) as sqrt(a^2 + b^2) where both are 0 or neither square can overflow
// nor lose the result to underflow: hypot's call and scaling cost more than the rest of a
// curvature's eigenvalues.
double radiusOf(double a, double b)
{
  const double larger = std::max(std::fabs(a), std::fabs(b));
  return ((larger >= 0x1p-450 || larger == 0.0) && larger <= 0x1p450) ? std::sqrt(a * a + b * b)
                                                                      : std::hypot(a, b);
}

// x_u and x_v, divided by 2^e where their squared lengths are outside [2^-200, 2^200] (e the
// exponent of their largest component: then no square below underflows or overflows), their
// squared lengths and the unit normal; false at a degenerate point: the area element vanishes
// next to the larger derivative's square (x_u and x_v parallel, or one of them zero, as at a pole
// of latitude and longitude), or a derivative is not finite.
struct ScaledFirst
{
  Vec3 du, dv, normal;
  double lengthU2, lengthV2;
  int exponent;
};

bool scaledFirst(Vec3 du, Vec3 dv, ScaledFirst& out)
{
  out.exponent = 0;
  double uu = dot(du, du), vv = dot(dv, dv);
  double larger = std::max(uu, vv);
  if (!(larger >= 0x1p-200 && larger <= 0x1p200)) // also NaN and inf
  {
    const double first = std::max(maxAbs(du), maxAbs(dv));
    if (!isFinite(du) || !isFinite(dv) || !(first > 0.0))
    {
      return false;
    }
    out.exponent = exponentOf(first);
    du = scaled(du, out.exponent);
    dv = scaled(dv, out.exponent);
    uu = dot(du, du);
    vv = dot(dv, dv);
    larger = std::max(uu, vv);
  }
  const Vec3 area = cross(du, dv);
  const double areaSquared = dot(area, area);
  // |x_u x x_v| > 1e-12 max(|x_u|, |x_v|)^2, squared.
  if (!(areaSquared > 1e-24 * larger * larger))
  {
    return false;
  }
  out.du = du;
  out.dv = dv;
  out.lengthU2 = uu;
  out.lengthV2 = vv;
  out.normal = area * (1.0 / std::sqrt(areaSquared));
  return true;
}
} // namespace

bool surfaceNormal(Vec3 du, Vec3 dv, Vec3& normal)
{
  ScaledFirst first;
  if (!scaledFirst(du, dv, first))
  {
    return false;
  }
  normal = first.normal;
  return true;
}

Vec3 planeNormal(const Vec3* points, std::size_t count, Vec3 center)
{
  double largest = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    if (isFinite(points[i]))
    {
      largest = std::max(largest, maxAbs(points[i] - center));
    }
  }
  if (!(largest > 0.0) || !std::isfinite(largest))
  {
    return Vec3{};
  }
  const int e = exponentOf(largest); // |p - center| / 2^e < 1: no product below overflows
  // A product by 2^-e where that is a normal double: the same correctly rounded x 2^-e as
  // ldexp's, bit for bit, without two calls per coordinate (about an eighth of the boosted
  // surface's and the Hopf fibers' time per sample).
  const bool multiply = e >= -1021 && e <= 1021;
  const double factor = multiply ? std::ldexp(1.0, -e) : 1.0;
  auto scaledPoint = [&](Vec3 p) { return multiply ? (p - center) * factor : scaledBy(p - center, e); };
  // Each point checked and scaled once, carried to the next pair.
  Vec3 newell{};
  bool previousFinite = count > 0 && isFinite(points[0]);
  Vec3 previous = previousFinite ? scaledPoint(points[0]) : Vec3{};
  for (std::size_t i = 1; i < count; ++i)
  {
    const bool finite = isFinite(points[i]);
    const Vec3 current = finite ? scaledPoint(points[i]) : Vec3{};
    if (previousFinite && finite)
    {
      newell = newell + cross(previous, current);
    }
    previous = current;
    previousFinite = finite;
  }
  const double size = std::sqrt(dot(newell, newell));
  return size > 0.0 ? newell * (1.0 / size) : Vec3{};
}

void principalDirections(Vec3 n, Vec3 t1, Vec3 t2, double w11, double w12, double w22,
  double half, double radius, Vec3& direction1, Vec3& direction2)
{
  // The eigenvector of k1 at angle phi from e1, tan 2 phi = w12 / half, phi in (-pi/2, pi/2].
  // Its sign: positive along the nearer of e1 and e2, so that it flips only where it is at 45
  // degrees to both, not where it is along e2 (a surface of revolution's meridian is
  // perpendicular to the parallels x_u: there cos phi is rounding, and its sign would flip from
  // sample to sample). At an umbilic, where W's off-mean part is rounding, every direction is
  // principal: e1.
  const double size = std::max({ std::fabs(w11), std::fabs(w12), std::fabs(w22) });
  const bool umbilic = radius <= 64.0 * std::numeric_limits<double>::epsilon() * size;
  double along1 = 1.0, along2 = 0.0; // cos and sin of phi = 0, without the calls
  if (!umbilic)
  {
    const double phi = 0.5 * std::atan2(w12, half);
    along1 = std::cos(phi);
    along2 = std::sin(phi);
  }
  if (std::fabs(along2) > along1 && along2 < 0.0)
  {
    along1 = -along1;
    along2 = -along2;
  }
  direction1 = along1 * t1 + along2 * t2;
  direction2 = cross(n, direction1);
}

SurfaceCurvature surfaceCurvature(const SurfaceDerivatives& x)
{
  SurfaceCurvature result;
  ScaledFirst first;
  if (!scaledFirst(x.du, x.dv, first) || !isFinite(x.duu) || !isFinite(x.duv) || !isFinite(x.dvv))
  {
    return result;
  }
  // The second derivatives scaled by 2^e2 as the first ones by 2^e1 (scaledFirst): every
  // curvature is then divided by 2^(e2 - 2 e1).
  const int e1 = first.exponent;
  const double second = std::max({ maxAbs(x.duu), maxAbs(x.duv), maxAbs(x.dvv) });
  const int e2 = second == 0.0 ? 0 : scaleExponent(second);
  const Vec3 du = first.du, dv = first.dv, n = first.normal;
  const Vec3 duu = scaled(x.duu, e2), duv = scaled(x.duv, e2), dvv = scaled(x.dvv, e2);
  const double lengthU = std::sqrt(first.lengthU2);
  // The orthonormal tangent frame (e1 along x_u, e2 = n x e1) and x_u, x_v in it: x_u = alpha e1,
  // x_v = beta e1 + gamma e2 (gamma > 0).
  const Vec3 t1 = du / lengthU;
  const Vec3 t2 = cross(n, t1);
  const double alpha = lengthU, beta = dot(dv, t1), gamma = dot(dv, t2);
  // The second fundamental form with the sign that makes bending away from n positive.
  const double l = -dot(duu, n), m = -dot(duv, n), nn = -dot(dvv, n);
  // The shape operator in the frame (e1, e2): W = A^-T II A^-1 with A = [[alpha, beta], [0, gamma]].
  const double w11 = l / (alpha * alpha);
  const double w12 = (m * alpha - l * beta) / (alpha * alpha * gamma);
  const double w22 = (l * beta * beta - 2.0 * m * alpha * beta + nn * alpha * alpha) /
    (alpha * alpha * gamma * gamma);
  // Eigenvalues of the symmetric 2x2 W as mean +- radius: the radius as a hypotenuse, so that
  // k1 - k2 is accurate to rounding of W's entries even at an umbilic.
  const double half = 0.5 * (w11 - w22);
  const double radius = radiusOf(half, w12);
  const double center = 0.5 * (w11 + w22);
  const int scale = e2 - 2 * e1;
  const double k1 = scale == 0 ? center + radius : std::ldexp(center + radius, scale);
  const double k2 = scale == 0 ? center - radius : std::ldexp(center - radius, scale);
  const double gaussian = k1 * k2;
  const double mean = scale == 0 ? center : std::ldexp(center, scale);
  if (!std::isfinite(k1) || !std::isfinite(k2) || !std::isfinite(gaussian))
  {
    return result;
  }
  result.regular = true;
  result.normal = n;
  result.k1 = k1;
  result.k2 = k2;
  principalDirections(n, t1, t2, w11, w12, w22, half, radius, result.direction1, result.direction2);
  result.gaussian = gaussian;
  result.mean = mean;
  return result;
}
} // namespace cga
