// The batch point map of constructions with their own exponent per point (the curvature patch):
// p_i -> fn(<K_i up(p_i) ~K_i>_1) with K_i = exp(B_i), eight points at a time through the block
// kernel of PointPairField::mapPoints after its B(p) (src/PointMapCore.h, mapPointBy), on the
// instruction set mapPoints uses.
#pragma once

#include "cga/Compact.h"
#include "cga/PointPairField.h"
#include "cga/Vec3.h"

#include <cstddef>

namespace cga
{
/// out[i] = fn(<K up(p[i]) ~K>_1) with K = exp(b[i]) by `rule`, for i < count; mapped[i] says
/// whether that image is finite (p[i] and b[i] finite, the image's weight non-zero); out[i] is
/// left unchanged where it is not. Returns how many points were not mapped.
///
/// The same numbers as the pointwise sandwichPoint(exponential(b[i], rule), p[i]): to the bit for
/// the Exact rule where b[i] is far from nilpotent (one template source) and has no strong
/// hyperbolic plane (angle above 1: there the map scales the plane's null directions exactly or
/// maps through the two fixed points, which the sandwich of K is not: it loses about e^{2 angle}
/// units of 2^-53; docs/conventions.md section 2 item 12), to round-off for the
/// Paper rule (its closed-form sandwich of c + B). Where b[i] is nearly nilpotent (a point pair,
/// a generator next to p) the Exact rule maps in a frame around p[i] instead, which is more
/// exact than the pointwise sandwich next to the nilpotent part's location (far from it, under a
/// huge nilpotent part with a rest, neither is exact to the problem's condition:
/// docs/conventions.md section 2 item 12). The same bits on
/// every instruction set and however the points are split into calls.
std::size_t mapPointsByExponentials(const Bivector* b,
                                    const Vec3* p,
                                    std::size_t count,
                                    ExponentialRule rule,
                                    Vec3* out,
                                    bool* mapped);

/// A value with its first and second derivatives with respect to two parameters (a, b): a point
/// of a parametric surface and what its curvatures need.
struct SurfaceJet
{
  double value = 0.0, da = 0.0, db = 0.0, daa = 0.0, dab = 0.0, dbb = 0.0;
};

/// The image fn(<K up(p) ~K>_1), K = exp(b) by `rule`, with its first and second derivatives in
/// (a, b), given those of b (ten components, Compact.h order) and of p (three): forward-mode
/// differentiation (second order) of the same computation as mapPointsByExponentials, exact to
/// rounding; the values are its images. Returns false, image unchanged, where the image is not
/// mapped or a derivative is not finite.
bool mapJetByExponential(
  const SurfaceJet* bivector, const SurfaceJet* point, ExponentialRule rule, SurfaceJet* image);

/// mapJetByExponential of `count` samples at once: eight at a time in the block kernel on CPUs with
/// AVX-512, one at a time elsewhere (the same bits either way): sample i's exponent is bivectors[10 i, 10 i + 10), its point
/// points[3 i, 3 i + 3), its image images[3 i, 3 i + 3); mapped[i] is mapJetByExponential's
/// return value (images left unchanged where false). Returns the count of samples not mapped.
std::size_t mapJetsByExponential(const SurfaceJet* bivectors,
                                 const SurfaceJet* points,
                                 std::size_t count,
                                 ExponentialRule rule,
                                 SurfaceJet* images,
                                 bool* mapped);
} // namespace cga
