// The curvature patch's E(a, b) as a second-order jet in (a, b), and the image's derivatives
// through mapJetsByExponential: the curvature operators' one template (CurvatureOperatorTerms.h)
// run on second-order dual numbers, so the jet's value is generatorAt's bit for bit.
#include "cga/surfaces/CurvaturePatch.h"

#include "../SurfaceJetDual.h"
#include "CurvatureOperatorTerms.h"

#include <algorithm>
#include <cmath>

// Compiled per instruction set (LaneClones.h), but not where BOOSTED_FORCE_INLINE is a plain inline
// (BOOSTED_PLAIN_INLINE: AddressSanitizer, coverage; ForceInline.h): there DualNumber.h's
// operators on Eight may be called out of line, and a 64-byte vector must not cross a call
// between a clone and the default target; flattening the instrumented jets instead took 9.5
// minutes to compile.
#ifdef BOOSTED_PLAIN_INLINE
#define BOOSTED_JET_CLONES
#else
#define BOOSTED_JET_CLONES BOOSTED_LANE_CLONES
#endif

namespace cga
{
namespace
{
/// exponentJet of the samples (a[i], b), i < count, of the patch moved by pieces' shift, and the
/// values of their local weights (generatorAbout's), eight samples at a time: the operators'
/// template on the jets of LaneClones.h's Eight, the same operations in the same order as on
/// double (the same bits).
BOOSTED_JET_CLONES
void generatorJets(const CurvaturePatch& patch, const detail::PatchPieces& pieces, const double* a,
  double b, std::size_t count, SurfaceJet* exponents, double* weights)
{
  using detail::Eight;
  constexpr int L = 8;
  constexpr int P = core::kJetParts;
  const Eight zero{}, one = zero + 1.0;
  for (std::size_t first = 0; first < count; first += L)
  {
    const int n = static_cast<int>(std::min<std::size_t>(L, count - first));
    Eight lanes;
    for (int l = 0; l < L; ++l)
    {
      lanes[l] = a[first + static_cast<std::size_t>(std::min(l, n - 1))];
    }
    // The seeds: a with d/da = 1, b with d/db = 1.
    const Eight aParts[P] = { lanes, one, zero, zero, zero, zero };
    const Eight bParts[P] = { zero + b, zero, one, zero, zero, zero };
    const auto generator = detail::patchGeneratorOf(
      patch, pieces, core::secondOrderOf(aParts), core::secondOrderOf(bParts));
    for (int c = 0; c < Bivector::Count; ++c)
    {
      Eight parts[P];
      core::partsOf(generator.exponent[c], parts);
      for (int l = 0; l < n; ++l)
      {
        double lane[P];
        for (int j = 0; j < P; ++j)
        {
          lane[j] = parts[j][l];
        }
        core::jetOf(lane, exponents[(first + static_cast<std::size_t>(l)) * Bivector::Count + c]);
      }
    }
    for (int l = 0; l < n; ++l)
    {
      weights[first + static_cast<std::size_t>(l)] = generator.weight.v.v[l];
    }
  }
}
} // namespace

void CurvaturePatch::exponentJet(
  double a, double b, Vec3 shift, SurfaceJet exponent[Bivector::Count]) const
{
  double weight;
  generatorJets(*this, detail::PatchPieces(*this, shift), &a, b, 1, exponent, &weight);
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
  // In chunks of a few blocks (the jets take 624 bytes a sample); the exponents' jets eight
  // samples at a time (generatorJets), their images too (mapJetsByExponential).
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
    generatorJets(*this, pieces, a + first, b, n, exponents, chunkWeights);
    for (std::size_t i = 0; i < n; ++i)
    {
      const double at = a[first + i];
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
