// Fast paths for fn(<K up(p) ~K>_1): the image of a point under an even element K.
//
// K need not be a versor: the paper's exponential of a sum of point pairs is scalar + bivector +
// 4-vector with K ~K != 1. docs/conventions.md then takes the grade-1 part of K up(p) ~K before normalizing,
// and so do these functions. Everything is computed in the null basis without heap allocation.
#pragma once

#include "cga/Compact.h"
#include "cga/Vec3.h"

#include <array>
#include <cstddef>
#include <vector>

namespace cga
{
/// <K X ~K>_1, as two sparse products: the odd element K X, then only the grade-1 part of (K X) ~K.
ConformalVector sandwichGrade1(const Even& k, const ConformalVector& x);

/// Euclidean point of fn(P) = P / (-ni.P). Returns false, leaving `out` unchanged, when the weight
/// -ni.P is zero or the result is not finite (the point went to infinity, or P holds NaN).
bool normalizePoint(const ConformalVector& p, Vec3& out);

/// out = Euclidean point of fn(<K up(p) ~K>_1); false (out unchanged) as normalizePoint.
bool sandwichPoint(const Even& k, Vec3 p, Vec3& out);

/// The linear map X -> <K X ~K>_1 of a fixed K as a 5x5 real matrix in the null basis
/// (ConformalVector order), so that many points through one K cost a matrix-vector product.
class PointMap
{
public:
  explicit PointMap(const Even& k);

  /// <K x ~K>_1.
  ConformalVector apply(const ConformalVector& x) const;

  /// out = Euclidean point of fn(<K up(p) ~K>_1); false (out unchanged) as normalizePoint.
  bool apply(Vec3 p, Vec3& out) const;

  /// Row-major: entry (i, j) is component i of the image of basis vector j.
  const std::array<double, 25>& matrix() const { return Matrix; }

private:
  friend class PointMaps;
  PointMap() = default;
  std::array<double, 25> Matrix{};
};

/// Many PointMaps applied to the same points (an orbit's maps at its sample times to each seed):
/// apply(p, out, mapped) gives mapped[i] and out[i] as maps[i].apply(p, out[i]) does, bit for bit
/// (out[i] unchanged where mapped[i] is false), eight maps side by side, their matrices stored
/// lane by lane once.
class PointMaps
{
public:
  PointMaps(const PointMap* maps, std::size_t count);
  /// The maps of `count` versors, PointMap(versors[i]) to the bit, eight made side by side.
  PointMaps(const Even* versors, std::size_t count);
  std::size_t size() const { return Count; }
  void apply(Vec3 p, Vec3* out, bool* mapped) const;
  /// Map i (i < size()) on its own.
  PointMap map(std::size_t i) const;
  /// Whether every entry of map i is finite.
  bool isFinite(std::size_t i) const { return Finite[i] != 0; }

private:
  std::size_t Count;
  std::vector<double> Entries; // per group of eight maps: entry e of lane l at [25 * 8 g + 8 e + l]
  std::vector<char> Finite;    // per map
};

/// The linear map X -> B X - X B of a bivector B on conformal vectors (a vector again: -2 X.B),
/// as PointMap's matrix (row-major, ConformalVector order). It is the derivative of the
/// sandwich: d/dt <exp(t B) X ~exp(t B)>_1 = B Y - Y B for Y the image at t, so that the
/// derivatives of a family of boosts in its parameter are this matrix applied again and again.
std::array<double, 25> commutatorMatrix(const Bivector& b);

/// The 5x5 matrix of commutatorMatrix or PointMap applied to x.
ConformalVector applyMatrix(const std::array<double, 25>& matrix, const ConformalVector& x);
} // namespace cga
