// The unit normals of a run of grid samples from their four neighbours, many at a time: the
// central differences the grid sources' builder (vtkBoostedGridBuilder) writes as point normals.
#pragma once

#include <cstddef>

namespace cga
{
/// For each i < count, the unit normal of sample i from its neighbours along the row (left_i,
/// right_i) and across it (below_i, above_i), each an array of count points (x, y, z):
///   a = normalized(right_i - left_i), b = normalized(above_i - below_i), n = cross(a, b),
///   normals_i = n * (1 / |n|),
/// in the order of operations of Vec3.h's plain normalized (the difference over the square root
/// of its square) and cross, and of vtkMath's Norm and MultiplyScalar: the same bits as that
/// composition. Eight samples at a time (compiled for AVX-512, AVX2 and the baseline, chosen at
/// load time).
///
/// plain[i] is false (and normals_i is then unspecified) where that plain path does not apply:
/// a coordinate not finite, a difference whose square is outside squareIsSafe's range (normalized
/// rescales it first), or |n| <= minimumSine (nearly parallel differences). The caller decides
/// those samples one at a time.
void crossedDifferenceNormals(const double* left, const double* right, const double* below,
  const double* above, std::size_t count, double minimumSine, double* normals, bool* plain);
} // namespace cga
