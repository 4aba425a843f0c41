#include "cga/surfaces/CurvaturePatch.h"

#include "cga/ExponentialMap.h"

#include "CurvatureOperatorTerms.h"

#include <algorithm>
#include <cmath>

namespace cga
{
namespace
{
// controlPointSum.at(frame.at(a[i], b)) for i < count: its exponent and weight, eight samples at a
// time (the same operations in the same order, on LaneClones.h's Eight: the same bits).
BOOSTED_LANE_CLONES
void controlPointGenerators(const ControlPointSum& sum, const PatchFrame& frame, const double* a,
  double b, std::size_t count, Bivector* exponents, double* weights)
{
  constexpr int L = 8;
  for (std::size_t first = 0; first < count; first += L)
  {
    const int n = static_cast<int>(std::min<std::size_t>(L, count - first));
    detail::Eight lanes;
    for (int l = 0; l < L; ++l)
    {
      lanes[l] = a[first + static_cast<std::size_t>(std::min(l, n - 1))];
    }
    const detail::GeneratorOf<detail::Eight> g =
      detail::controlPointSumOf(sum, detail::patchPoint(frame, lanes, b));
    for (int l = 0; l < n; ++l)
    {
      for (int k = 0; k < Bivector::Count; ++k)
      {
        exponents[first + static_cast<std::size_t>(l)][k] = g.exponent[k][l];
      }
      weights[first + static_cast<std::size_t>(l)] = g.weight[l];
    }
  }
}
} // namespace

void presetCurvatures(CurvaturePreset preset, double& kappaU, double& kappaV)
{
  switch (preset)
  {
    case CurvaturePreset::Parabolic:
      kappaU = 0.5;
      kappaV = 0.0;
      break;
    case CurvaturePreset::Elliptic:
      kappaU = 0.5;
      kappaV = 0.25;
      break;
    case CurvaturePreset::Umbilic:
      kappaU = 0.5;
      kappaV = 0.5;
      break;
    case CurvaturePreset::Hyperbolic:
      kappaU = -0.5;
      kappaV = 0.5;
      break;
  }
}

std::string CurvaturePatch::validate()
{
  if (!(std::isfinite(sizeU) && std::isfinite(sizeV)) || !(sizeU > 0.0) || !(sizeV >= 0.0))
  {
    return "the patch size must be finite, positive along u and not negative along v";
  }
  if (!std::isfinite(kappaU) || !std::isfinite(kappaV))
  {
    return "the curvatures must be finite";
  }
  if (!(std::isfinite(falloff) && falloff >= 0.0) || !(std::isfinite(epsilon) && epsilon > 0.0))
  {
    return "the falloff must be finite and >= 0, epsilon finite and > 0";
  }
  const std::string frameProblem = PatchFrame::fromDirections(frame.origin, frame.u, frame.v, frame);
  if (!frameProblem.empty())
  {
    return frameProblem;
  }
  if (method == CurvatureMethod::ControlPoints)
  {
    if (controlPoints.empty())
    {
      return "the control points method needs at least one control point";
    }
    for (CurvatureControlPoint& c : controlPoints)
    {
      const std::string problem = c.normalize();
      if (!problem.empty())
      {
        return problem;
      }
    }
  }
  if (method == CurvatureMethod::Linear || method == CurvatureMethod::Bilinear)
  {
    for (const CornerGenerator& g : corners)
    {
      if (!isFinite(g.direction) || !std::isfinite(g.weight))
      {
        return "the corner directions and weights must be finite";
      }
    }
  }
  return {};
}

double CurvaturePatch::a(int column, int columns) const
{
  return columns > 1 ? sizeU * (static_cast<double>(column) / (columns - 1) - 0.5) : 0.0;
}

double CurvaturePatch::b(int row, int rows) const
{
  return rows > 1 ? sizeV * (static_cast<double>(row) / (rows - 1) - 0.5) : 0.0;
}

std::array<Vec3, 4> CurvaturePatch::cornerLocations() const
{
  const double hu = 0.5 * sizeU, hv = 0.5 * sizeV;
  return { frame.at(-hu, -hv), frame.at(hu, -hv), frame.at(-hu, hv), frame.at(hu, hv) };
}

CurvatureGenerator CurvaturePatch::generatorAt(double a, double b) const
{
  return generatorAbout(a, b, Vec3{});
}

CurvatureGenerator CurvaturePatch::generatorAbout(double a, double b, Vec3 shift) const
{
  return detail::patchGeneratorOf(*this, a, b, shift);
}

bool CurvaturePatch::map(double a, double b, Vec3& out, double& weight) const
{
  bool mapped = false;
  this->mapRow(b, &a, 1, &out, &weight, &mapped);
  return mapped;
}

void CurvaturePatch::mapRow(
  double b, const double* a, std::size_t count, Vec3* out, double* weights, bool* mapped) const
{
  // Computed about the origin (the patch moved by -origin, the images moved back).
  constexpr std::size_t kChunk = 64;
  // The pieces that do not depend on the sample, once for the row.
  const detail::PatchPieces pieces(*this, frame.origin);
  Bivector exponents[kChunk];
  Vec3 points[kChunk], images[kChunk];
  double chunkWeights[kChunk];
  bool finite[kChunk];
  for (std::size_t first = 0; first < count; first += kChunk)
  {
    const std::size_t n = std::min(kChunk, count - first);
    if (method == CurvatureMethod::ControlPoints)
    {
      controlPointGenerators(*pieces.controlPointSum, pieces.moved, a + first, b, n, exponents,
        chunkWeights);
    }
    for (std::size_t i = 0; i < n; ++i)
    {
      if (method != CurvatureMethod::ControlPoints)
      {
        const CurvatureGenerator g = detail::patchGeneratorOf(*this, pieces, a[first + i], b);
        exponents[i] = g.exponent;
        chunkWeights[i] = g.weight;
      }
      points[i] = Vec3{} + a[first + i] * frame.u + b * frame.v;
    }
    mapPointsByExponentials(exponents, points, n, rule, images, finite);
    for (std::size_t i = 0; i < n; ++i)
    {
      const Vec3 image = finite[i] ? frame.origin + images[i] : Vec3{};
      // A weight beyond the largest double (curvatures near it) is a generator that overflowed:
      // the sample is dropped like one at infinity rather than carried with an infinite weight.
      mapped[first + i] = finite[i] && isFinite(image) && std::isfinite(chunkWeights[i]);
      if (mapped[first + i])
      {
        out[first + i] = image;
        weights[first + i] = chunkWeights[i];
      }
    }
  }
}
} // namespace cga
