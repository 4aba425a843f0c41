// The curvature patch's E(a, b) as a second-order jet in (a, b), and the image's derivatives
// through mapJetByExponential: the curvature operators' one template (CurvatureOperatorTerms.h)
// run on second-order dual numbers, so the jet's value is generatorAt's bit for bit.
#include "cga/surfaces/CurvaturePatch.h"

#include "../SurfaceJetDual.h"
#include "CurvatureOperatorTerms.h"

namespace cga
{
void CurvaturePatch::exponentJet(
  double aValue, double bValue, Vec3 shift, SurfaceJet exponent[Bivector::Count]) const
{
  // The seeds: a with d/da = 1, b with d/db = 1.
  const core::SurfaceJetDual a = core::secondOf(SurfaceJet{ aValue, 1.0, 0.0, 0.0, 0.0, 0.0 });
  const core::SurfaceJetDual b = core::secondOf(SurfaceJet{ bValue, 0.0, 1.0, 0.0, 0.0, 0.0 });
  const auto generator = detail::patchGeneratorOf(*this, a, b, shift);
  for (int c = 0; c < Bivector::Count; ++c)
  {
    core::jetOf(generator.exponent[c], exponent[c]); // finite or not: mapJetByExponential checks its result
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
