// The curvature patch's E(a, b) as a second-order jet in (a, b), and the image's derivatives
// through mapJetsByExponential: the curvature operators' one template (CurvatureOperatorTerms.h)
// run on second-order dual numbers, so the jet's value is generatorAt's bit for bit.
#include "cga/surfaces/CurvaturePatch.h"

#include "../SurfaceJetDual.h"
#include "CurvatureOperatorTerms.h"

#include <algorithm>

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
  bool ok = false;
  this->derivativesRow(b, &a, 1, &out, &ok);
  return ok;
}

void CurvaturePatch::derivativesRow(
  double b, const double* a, std::size_t count, SurfaceDerivatives* out, bool* ok) const
{
  // About the origin, as mapRow: the patch moved by -origin, p = a u + b v, the image moved back.
  // In chunks of a few blocks (the jets take 624 bytes a sample).
  constexpr std::size_t kChunk = 32;
  SurfaceJet exponents[kChunk * Bivector::Count], points[kChunk * 3], images[kChunk * 3];
  bool mapped[kChunk];
  const double us[3] = { frame.u.x, frame.u.y, frame.u.z };
  const double vs[3] = { frame.v.x, frame.v.y, frame.v.z };
  for (std::size_t first = 0; first < count; first += kChunk)
  {
    const std::size_t n = std::min(kChunk, count - first);
    for (std::size_t i = 0; i < n; ++i)
    {
      const double at = a[first + i];
      this->exponentJet(at, b, frame.origin, exponents + i * Bivector::Count);
      for (int k = 0; k < 3; ++k)
      {
        points[3 * i + k] = SurfaceJet{ at * us[k] + b * vs[k], us[k], vs[k], 0.0, 0.0, 0.0 };
      }
    }
    mapJetsByExponential(exponents, points, n, rule, images, mapped);
    for (std::size_t i = 0; i < n; ++i)
    {
      const SurfaceJet* image = images + 3 * i;
      auto component = [&](double SurfaceJet::*member) {
        return Vec3{ image[0].*member, image[1].*member, image[2].*member };
      };
      const Vec3 point = frame.origin + component(&SurfaceJet::value);
      ok[first + i] = mapped[i] && isFinite(point);
      if (ok[first + i])
      {
        SurfaceDerivatives& x = out[first + i];
        x.point = point;
        x.du = component(&SurfaceJet::da);
        x.dv = component(&SurfaceJet::db);
        x.duu = component(&SurfaceJet::daa);
        x.duv = component(&SurfaceJet::dab);
        x.dvv = component(&SurfaceJet::dbb);
      }
    }
  }
}
} // namespace cga
