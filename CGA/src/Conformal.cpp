#include "cga/Conformal.h"

#include <cmath>
#include <limits>

namespace cga
{
Multivector e1()
{
  return Multivector::basisBlade(blade::e1);
}
Multivector e2()
{
  return Multivector::basisBlade(blade::e2);
}
Multivector e3()
{
  return Multivector::basisBlade(blade::e3);
}
Multivector no()
{
  Multivector m;
  m[blade::em] = 0.5;
  m[blade::ep] = 0.5;
  return m;
}
Multivector ni()
{
  Multivector m;
  m[blade::em] = 1.0;
  m[blade::ep] = -1.0;
  return m;
}
Multivector euclideanPseudoscalar()
{
  return Multivector::basisBlade(blade::e1 | blade::e2 | blade::e3);
}
Multivector minkowskiPlane()
{
  return no() ^ ni();
}

Multivector vector(Vec3 v)
{
  Multivector m;
  m[blade::e1] = v.x;
  m[blade::e2] = v.y;
  m[blade::e3] = v.z;
  return m;
}

Vec3 euclideanPart(const Multivector& m)
{
  return { m[blade::e1], m[blade::e2], m[blade::e3] };
}

Multivector up(Vec3 x)
{
  return no() + vector(x) + (0.5 * norm2(x)) * ni();
}

bool normalizePoint(const Multivector& p, Vec3& out)
{
  // -ni.P for P = a no + x + b ni is a; in the orthonormal basis a = P[e-] + P[e+].
  const double alpha = p[blade::em] + p[blade::ep];
  if (alpha == 0.0 || !std::isfinite(alpha))
  {
    return false;
  }
  out = euclideanPart(p) / alpha;
  return true;
}

Vec3 down(const Multivector& p)
{
  const double inf = std::numeric_limits<double>::infinity();
  Vec3 x{ inf, inf, inf };
  normalizePoint(p, x);
  return x;
}

Multivector translator(Vec3 d)
{
  return Multivector::scalar(1.0) - 0.5 * (vector(d) * ni());
}

Multivector rotor(Vec3 axis, double angle)
{
  const Multivector plane = vector(normalized(axis)) * euclideanPseudoscalar(); // e3 -> e12
  return Multivector::scalar(std::cos(0.5 * angle)) - std::sin(0.5 * angle) * plane;
}

Multivector sandwich(const Multivector& k, const Multivector& x)
{
  return k * x * k.reverse();
}

Multivector versorInverse(const Multivector& k)
{
  const Multivector rev = k.reverse();
  return rev / (k * rev).scalarPart();
}

Vec3 transformPoint(const Multivector& k, Vec3 x)
{
  return down(sandwich(k, up(x)).grade(1));
}

Multivector tangent(Vec3 v)
{
  return no() ^ vector(v);
}

Multivector nullPointPair(Vec3 location, Vec3 direction)
{
  return up(location) ^ (vector(direction) + dot(direction, location) * ni());
}

Multivector pointPair(Vec3 a, Vec3 b)
{
  return up(a) ^ up(b);
}

Multivector circleThroughPoints(Vec3 a, Vec3 b, Vec3 c)
{
  return up(a) ^ up(b) ^ up(c);
}

Multivector circle(Vec3 center, Vec3 normal, double radius)
{
  const Vec3 n = normalized(normal);
  const Vec3 u = orthogonalUnit(n);
  const Vec3 v = cross(n, u);
  return circleThroughPoints(center + radius * u, center + radius * v, center - radius * u);
}

Multivector line(Vec3 a, Vec3 b)
{
  return up(a) ^ up(b) ^ ni();
}

Multivector dualLine(Vec3 point, Vec3 direction)
{
  return line(point, point + direction).dual();
}

RoundInfo readCircle(const Multivector& x, double flatTolerance)
{
  RoundInfo info;
  const Multivector blade = x.grade(3);
  const Multivector flatness = ni() ^ blade;
  const double scale = blade.coefficientNorm();
  if (!(scale > 0.0) || !std::isfinite(scale))
  {
    info.radius = std::numeric_limits<double>::quiet_NaN();
    return info;
  }
  if (flatness.coefficientNorm() <= flatTolerance * scale)
  {
    // Lambda = no^d^ni + m^ni: d = (ni^no) _| Lambda, m = Euclidean part of -(no _| Lambda).
    info.isLine = true;
    info.radius = std::numeric_limits<double>::infinity();
    const Vec3 d = euclideanPart(leftContraction(ni() ^ no(), blade));
    Multivector moment;
    const Multivector noContracted = -leftContraction(no(), blade);
    for (unsigned mask : { blade::e1 | blade::e2, blade::e1 | blade::e3, blade::e2 | blade::e3 })
    {
      moment[mask] = noContracted[mask];
    }
    const double d2 = norm2(d);
    info.direction = normalized(d);
    info.center = d2 > 0.0 ? euclideanPart((moment * vector(d)).grade(1)) / d2 : Vec3{};
    return info;
  }
  info.center = down((blade * ni() * blade).grade(1));
  const Multivector axisPart = leftContraction(ni(), blade);
  const double radius2 = -scalarProduct(blade, blade) / scalarProduct(axisPart, axisPart);
  info.radius = std::sqrt(std::fabs(radius2));
  // The carrier plane is blade ^ ni; its dual is the vector n + delta ni.
  info.normal = normalized(euclideanPart((blade ^ ni()).dual()));
  return info;
}
} // namespace cga
