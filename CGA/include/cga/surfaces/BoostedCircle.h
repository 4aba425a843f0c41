// A circle carried by the one-parameter family of boosts K(lambda) = exp(lambda tau) = 1 + lambda tau,
// tau = tau(location, direction) a null point pair (docs/conventions.md section 3 items 1-3, Fig 1-3).
//
// Because tau is null, exp(lambda tau) = 1 + lambda tau exactly, so no exponential rule is involved.
// The family maps a fixed circle point to a curve; sweeping lambda over a range gives a surface.
#pragma once

#include "cga/Compact.h"
#include "cga/Multivector.h"
#include "cga/Vec3.h"

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

  /// K(lambda) = 1 + lambda tau(boostLocation, boostDirection), full multivector (reference).
  Multivector boost(double lambda) const;

  /// The same K(lambda) as a compact even element, for the fast point map (PointSandwich.h).
  Even boostCompact(double lambda) const;

  /// The circle blade (up(a) ^ up(b) ^ up(c)) sandwiched by K(lambda): a circle, or a line where the
  /// circle passes through the boost's pole.
  Multivector imageBlade(double lambda) const;
};
} // namespace cga
