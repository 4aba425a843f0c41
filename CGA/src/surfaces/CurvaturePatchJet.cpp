// The curvature patch's E(a, b) as a second-order jet in (a, b), and the image's derivatives
// through mapJetsByExponential: the curvature operators' one template (CurvatureOperatorTerms.h)
// run on second-order dual numbers, so the jet's value is generatorAt's bit for bit.
#include "cga/surfaces/CurvaturePatch.h"

#include "../SurfaceJetDual.h"
#include "CurvatureOperatorTerms.h"

#include <algorithm>
#include <cmath>

namespace cga
{
namespace
{
/// exponentJet's jets of E(a, b) of the patch moved by pieces' shift, and the value of the local
/// weight (generatorAbout's).
void generatorJet(const CurvaturePatch& patch, const detail::PatchPieces& pieces, double aValue,
  double bValue, SurfaceJet exponent[Bivector::Count], double& weight)
{
  // The seeds: a with d/da = 1, b with d/db = 1.
  const core::SurfaceJetDual a = core::secondOf(SurfaceJet{ aValue, 1.0, 0.0, 0.0, 0.0, 0.0 });
  const core::SurfaceJetDual b = core::secondOf(SurfaceJet{ bValue, 0.0, 1.0, 0.0, 0.0, 0.0 });
  const auto generator = detail::patchGeneratorOf(patch, pieces, a, b);
  for (int c = 0; c < Bivector::Count; ++c)
  {
    core::jetOf(generator.exponent[c], exponent[c]); // finite or not: mapJetsByExponential checks
  }
  weight = detail::valuePart(generator.weight);
}
} // namespace

void CurvaturePatch::exponentJet(
  double a, double b, Vec3 shift, SurfaceJet exponent[Bivector::Count]) const
{
  double weight;
  generatorJet(*this, detail::PatchPieces(*this, shift), a, b, exponent, weight);
}

bool CurvaturePatch::derivatives(double a, double b, SurfaceDerivatives& out) const
{
  bool ok = false;
  this->derivativesRow(b, &a, 1, &out, &ok);
  return ok;
}

void CurvaturePatch::derivativesRow(double b, const double* a, std::size_t count,
  SurfaceDerivatives* out, bool* ok, double* weights) const
{
  // About the origin, as mapRow: the patch moved by -origin, p = a u + b v, the image moved back.
  // In chunks of a few blocks (the jets take 624 bytes a sample).
  constexpr std::size_t kChunk = 32;
  const detail::PatchPieces pieces(*this, frame.origin); // once for the row
  SurfaceJet exponents[kChunk * Bivector::Count], points[kChunk * 3], images[kChunk * 3];
  double chunkWeights[kChunk];
  bool mapped[kChunk];
  const double us[3] = { frame.u.x, frame.u.y, frame.u.z };
  const double vs[3] = { frame.v.x, frame.v.y, frame.v.z };
  for (std::size_t first = 0; first < count; first += kChunk)
  {
    const std::size_t n = std::min(kChunk, count - first);
    for (std::size_t i = 0; i < n; ++i)
    {
      const double at = a[first + i];
      generatorJet(*this, pieces, at, b, exponents + i * Bivector::Count, chunkWeights[i]);
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
      // As mapRow, a sample whose weight overflowed is dropped.
      ok[first + i] = mapped[i] && isFinite(point) && std::isfinite(chunkWeights[i]);
      if (ok[first + i])
      {
        if (weights)
        {
          weights[first + i] = chunkWeights[i];
        }
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
