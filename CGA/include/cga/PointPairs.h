// Null point pairs (tangents, eq 7) in compact form, and the weighted sums the field deformations
// of the paper (eq 21-23, 27-28) exponentiate.
#pragma once

#include "cga/Compact.h"
#include "cga/Vec3.h"

#include <cstddef>

namespace cga
{
/// tau(x, v) = up(x) ^ (v + (v.x) ni) = T(x) (no ^ v) ~T(x) in closed form:
/// x ^ v + (v.x) no^ni - v ^ no + ((v.x) x - |x|^2/2 v) ^ ni. The length of v is the weight.
Bivector nullPointPairCompact(Vec3 location, Vec3 direction);

/// T(d) b ~T(d), T(d) = 1 - d ni / 2: the bivector b moved by d, in closed form (exact in the
/// algebra; rounds like b's largest component times |d|^2).
Bivector translatedBivector(const Bivector& b, Vec3 d);

/// The first-order motion of p under the bivector b: d/ds of fn(K up(p) ~K), K = exp(-s b), at
/// s = 0. It is twice the translation part (e_i^ni) of b moved to p (translatedBivector(b, -p)):
/// b's other parts leave p in place there (docs/conventions.md section 3 item 14).
Vec3 firstOrderMotion(const Bivector& b, Vec3 p);

/// sum_i weights[i] * bivectors[i].
Bivector weightedSum(const Bivector* bivectors, const double* weights, std::size_t count);

/// sum_i weights[i] * tau(locations[i], directions[i]), without storing the individual pairs.
Bivector weightedNullPointPairSum(const Vec3* locations,
                                  const Vec3* directions,
                                  const double* weights,
                                  std::size_t count);
} // namespace cga
