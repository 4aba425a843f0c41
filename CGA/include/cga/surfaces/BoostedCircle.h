// A circle carried by the one-parameter family of boosts K(lambda) = exp(lambda tau) = 1 + lambda tau,
// tau = tau(location, direction) a null point pair (docs/conventions.md section 3 items 1-3, Fig 1-3).
//
// Because tau is null, exp(lambda tau) = 1 + lambda tau exactly, so no exponential rule is involved.
// The family maps a fixed circle point to a curve; sweeping lambda over a range gives a surface.
#pragma once

#include "cga/Compact.h"
#include "cga/Multivector.h"
#include "cga/PointSandwich.h"
#include "cga/SurfaceCurvature.h"
#include "cga/Vec3.h"

#include <array>
#include <cstddef>
#include <string>

namespace cga
{
struct BoostedCircle
{
  Vec3 center{ 0, 0, 0 };
  Vec3 normal{ 1, 0, 0 }; // need not be unit; only its direction is used
  double radius = 1.0;
  Vec3 boostLocation{ 0, 0, 0 };
  Vec3 boostDirection{ 1, 0, 0 }; // its length is the generator's weight

  /// The same family moved by -center: the circle about the origin, the boost's location
  /// relative to the circle's. Far from the origin its images (plus center) keep their precision:
  /// up(p) holds |p|^2, so a family at distance t rounds like eps t^2, the centered one like eps t.
  BoostedCircle centered() const;

  /// Empty when the parameters describe a valid family, otherwise what is wrong with them.
  std::string validate() const;

  /// Empty when K(lambda) has a finite point map for every lambda in [lambdaMin, lambdaMax],
  /// otherwise why not: |lambda| times the boost direction's length (its weight) so large that the
  /// sandwich overflows, which would leave nothing of the surface but lambda = 0.
  std::string boostProblem(double lambdaMin, double lambdaMax) const;

  /// Unit vectors (a, b) spanning the circle's plane with a x b along the normal; theta = 0 is a.
  void planeFrame(Vec3& a, Vec3& b) const;

  /// The point of the undeformed circle at angle theta.
  Vec3 circlePoint(double theta) const;

  /// That point (the same bits) with its first and second derivatives in theta.
  struct CircleSample
  {
    Vec3 point, tangent, second;
  };
  CircleSample circleSample(double theta) const;

  /// K(lambda) = 1 + lambda tau(boostLocation, boostDirection), full multivector (reference).
  Multivector boost(double lambda) const;

  /// The same K(lambda) as a compact even element, for the fast point map (PointSandwich.h).
  Even boostCompact(double lambda) const;

  /// The circle blade (up(a) ^ up(b) ^ up(c)) sandwiched by K(lambda): a circle, or a line where the
  /// circle passes through the boost's pole.
  Multivector imageBlade(double lambda) const;
};

/// One circle of the surface, x(theta, lambda) = fn(K(lambda) up(circlePoint(theta)) ~K(lambda))
/// at a fixed lambda, with the surface's derivatives in closed form (docs/conventions.md
/// section 6): the maps of K(lambda) and of the commutator with tau are built once per circle.
class BoostedCircleRow
{
public:
  BoostedCircleRow(const BoostedCircle& family, double lambda);

  /// The surface point at the circle sample (the same bits as PointMap(K(lambda)).apply of its
  /// point) and its first and second derivatives, u = theta, v = lambda. K(lambda) =
  /// exp(lambda tau) commutes with tau, so d/dlambda Y = tau Y - Y tau for the image Y = K X ~K:
  /// one commutator for each derivative in lambda. The derivatives in theta are the circle's,
  /// carried by the same linear map, and fn(Y) = Y_e / Y_no gives the point's by the quotient
  /// rule. False where the point goes to infinity (as PointMap::apply): out unchanged.
  bool derivatives(const BoostedCircle::CircleSample& sample, SurfaceDerivatives& out) const;

  /// The same with the first derivatives only (the second ones left as they are in out): what
  /// the normal needs, at half the cost.
  bool firstDerivatives(const BoostedCircle::CircleSample& sample, SurfaceDerivatives& out) const;

  /// The points and unit normals of `count` circle samples, eight side by side: state[i] is 0
  /// where firstDerivatives is false (the point at infinity; points[i] and normals[i] unchanged),
  /// 1 where only the point is given (surfaceNormal of the first derivatives is false: a
  /// degenerate sample; normals[i] unchanged) and 2 with both. The same bits as firstDerivatives
  /// and then surfaceNormal, sample by sample.
  void pointsAndNormals(const BoostedCircle::CircleSample* samples, std::size_t count,
    Vec3* points, Vec3* normals, unsigned char* state) const;

  /// The points and curvatures of `count` circle samples, eight side by side: mapped[i] as
  /// derivatives gives it (false: the point at infinity; points[i] and out[i] unchanged), and
  /// where it is true points[i] and out[i] = surfaceCurvature of the derivatives. The same bits
  /// as derivatives and then surfaceCurvature, sample by sample.
  void curvatures(const BoostedCircle::CircleSample* samples, std::size_t count, Vec3* points,
    SurfaceCurvature* out, bool* mapped) const;

  /// The point alone: PointMap(K(lambda)).apply.
  bool point(Vec3 p, Vec3& out) const { return this->Boost.apply(p, out); }

private:
  template <bool Second>
  bool compute(const BoostedCircle::CircleSample& sample, SurfaceDerivatives& out) const;

  PointMap Boost;
  // The boost's matrix and the commutator's (commutatorMatrix of the boost's point pair),
  // transposed (column after column), for the derivatives' products.
  std::array<double, 25> BoostColumns, CommutatorColumns;
};
} // namespace cga
