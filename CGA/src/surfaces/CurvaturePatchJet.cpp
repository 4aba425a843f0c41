// The curvature patch's E(a, b) as a second-order jet in (a, b), and the image's derivatives
// through mapJetByExponential: the curvature operators of CurvatureOperators.cpp written once
// more on second-order dual numbers, with the null point pair's one template
// (NullPointPairTerms.h). The value path keeps its own, faster code; the tests hold the two to
// rounding and the derivatives to central differences.
#include "cga/surfaces/CurvaturePatch.h"

#include "../NullPointPairTerms.h"
#include "../SurfaceJetDual.h"

#include <array>
#include <cmath>

namespace cga
{
namespace
{
using Jet = core::SurfaceJetDual; // value, d/da, d/db, and the derivatives of those

Jet constant(double x)
{
  return core::secondOf(SurfaceJet{ x, 0.0, 0.0, 0.0, 0.0, 0.0 });
}

// The seeds: a with d/da = 1, b with d/db = 1.
Jet seed(double x, int k)
{
  return core::secondOf(SurfaceJet{ x, k == 0 ? 1.0 : 0.0, k == 1 ? 1.0 : 0.0, 0.0, 0.0, 0.0 });
}

struct JetPoint
{
  Jet x[3];
};

JetPoint plus(Vec3 origin, const Jet& a, Vec3 u, const Jet& b, Vec3 v)
{
  // origin + a u + b v, as PatchFrame::at
  return { { origin.x + a * u.x + b * v.x, origin.y + a * u.y + b * v.y,
    origin.z + a * u.z + b * v.z } };
}

Jet dotJet(const JetPoint& p, Vec3 v)
{
  return p.x[0] * v.x + p.x[1] * v.y + p.x[2] * v.z;
}

// osculatingTerm: kappa / (sphere^2 + plane^2 + epsilon) with q = p - x.
Jet osculatingTerm(const JetPoint& q, const Jet& q2, const Jet& qn, Vec3 planeNormal, double kappa,
  double epsilon)
{
  if (kappa == 0.0)
  {
    return constant(0.0);
  }
  const Jet sphere = 0.5 * q2 + qn / kappa;
  const Jet plane = dotJet(q, planeNormal) / kappa;
  return kappa / (sphere * sphere + plane * plane + epsilon);
}

JetPoint minus(const JetPoint& p, Vec3 x)
{
  return { { p.x[0] - x.x, p.x[1] - x.y, p.x[2] - x.z } };
}

Jet squaredLength(const JetPoint& q)
{
  return q.x[0] * q.x[0] + q.x[1] * q.x[1] + q.x[2] * q.x[2];
}

void addPair(std::array<Jet, Bivector::Count>& e, const Jet& w, const JetPoint& x, Vec3 d)
{
  detail::addNullPointPair(e.data(), w, x.x, d);
}

void addPair(std::array<Jet, Bivector::Count>& e, const Jet& w, Vec3 x, Vec3 d)
{
  addPair(e, w, JetPoint{ { constant(x.x), constant(x.y), constant(x.z) } }, d);
}
} // namespace

void CurvaturePatch::exponentJet(
  double aValue, double bValue, Vec3 shift, SurfaceJet exponent[Bivector::Count]) const
{
  const Jet a = seed(aValue, 0), b = seed(bValue, 1), zero = constant(0.0);
  const Vec3 origin = frame.origin - shift, u = frame.u, v = frame.v, n = frame.normal;
  std::array<Jet, Bivector::Count> e{};
  switch (method)
  {
    case CurvatureMethod::BentLine: // eq 15: -kappa/2 tau(at(0, b), n)
      addPair(e, constant(-0.5 * kappaU), plus(origin, zero, u, b, v), n);
      break;
    case CurvatureMethod::TranslatedTangents: // eq 16
      addPair(e, constant(-0.5 * kappaU), plus(origin, zero, u, b, v), n);
      addPair(e, constant(-0.5 * kappaV), plus(origin, a, u, zero, v), n);
      break;
    case CurvatureMethod::OsculatingCircles: // eq 17-18, the control point at the origin
    {
      const JetPoint q = minus(plus(origin, a, u, b, v), origin);
      const Jet q2 = squaredLength(q), qn = dotJet(q, n);
      const Jet w = osculatingTerm(q, q2, qn, cross(u, n), kappaU, epsilon) +
        osculatingTerm(q, q2, qn, cross(cross(n, u), n), kappaV, epsilon);
      addPair(e, -w, origin, n);
      break;
    }
    case CurvatureMethod::ControlPoints: // eq 21-22
    {
      const JetPoint p = plus(origin, a, u, b, v);
      for (const CurvatureControlPoint& c : controlPoints)
      {
        const Vec3 x = c.location - shift;
        const JetPoint q = minus(p, x);
        const Jet q2 = squaredLength(q), qn = dotJet(q, c.normal);
        const Jet w = osculatingTerm(q, q2, qn, cross(c.uDirection, c.normal), c.kappaU, epsilon) +
          osculatingTerm(q, q2, qn, cross(cross(c.normal, c.uDirection), c.normal), c.kappaV, epsilon);
        addPair(e, -w / (falloff * q2 + epsilon), x, c.normal);
      }
      break;
    }
    case CurvatureMethod::Linear: // eq 24: the generators at the ends of the row
    {
      const double hu = 0.5 * sizeU;
      const Jet t = 0.5 + a / sizeU;
      addPair(e, -0.5 * (1.0 - t) * corners[0].weight, plus(origin, constant(-hu), u, b, v),
        corners[0].direction);
      addPair(e, -0.5 * t * corners[1].weight, plus(origin, constant(hu), u, b, v),
        corners[1].direction);
      break;
    }
    case CurvatureMethod::Bilinear: // eq 25-26
    {
      const double hu = 0.5 * sizeU, hv = 0.5 * sizeV;
      const Jet t = 0.5 + a / sizeU;
      const Jet s = sizeV > 0.0 ? 0.5 + b / sizeV : zero;
      const Jet factors[4] = { (1.0 - s) * (1.0 - t), (1.0 - s) * t, s * (1.0 - t), s * t };
      const double signs[4][2] = { { -1, -1 }, { 1, -1 }, { -1, 1 }, { 1, 1 } };
      for (int i = 0; i < 4; ++i)
      {
        addPair(e, -0.5 * factors[i] * corners[i].weight,
          origin + signs[i][0] * hu * u + signs[i][1] * hv * v, corners[i].direction);
      }
      break;
    }
  }
  for (int c = 0; c < Bivector::Count; ++c)
  {
    core::jetOf(e[c], exponent[c]); // finite or not: mapJetByExponential checks its result
  }
}

bool CurvaturePatch::derivatives(double a, double b, SurfaceDerivatives& out) const
{
  // About the origin, as mapRow: the patch moved by -origin, p = a u + b v, the image moved back.
  SurfaceJet exponent[Bivector::Count], point[3], image[3];
  this->exponentJet(a, b, frame.origin, exponent);
  const double pointValue[3] = { a * frame.u.x + b * frame.v.x, a * frame.u.y + b * frame.v.y,
    a * frame.u.z + b * frame.v.z };
  const double us[3] = { frame.u.x, frame.u.y, frame.u.z };
  const double vs[3] = { frame.v.x, frame.v.y, frame.v.z };
  for (int i = 0; i < 3; ++i)
  {
    point[i].value = pointValue[i];
    point[i].da = us[i];
    point[i].db = vs[i];
  }
  if (!mapJetByExponential(exponent, point, rule, image))
  {
    return false;
  }
  const Vec3 value{ image[0].value, image[1].value, image[2].value };
  auto component = [&](double SurfaceJet::*member) {
    return Vec3{ image[0].*member, image[1].*member, image[2].*member };
  };
  out.point = frame.origin + value;
  out.du = component(&SurfaceJet::da);
  out.dv = component(&SurfaceJet::db);
  out.duu = component(&SurfaceJet::daa);
  out.duv = component(&SurfaceJet::dab);
  out.dvv = component(&SurfaceJet::dbb);
  return isFinite(out.point);
}
} // namespace cga
