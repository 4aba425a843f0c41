// The derivatives of the field's generators with respect to their parameters, for fitting
// generators to a target (vtkPointPairFitFilter; docs/conventions.md section 3 item 17).
//
// A generator of kind k at location x with direction v (and, for a twist, pitch h) is the bivector
// G(x, v) of FieldGenerator::of; in the field it adds the term w G(x, v) / (f |p - x|^2 + eps) to
// B(p). G is a polynomial in x of degree 2 (the point pair: tau(x, v) = up(x) ^ (v + (v.x) ni)),
// 1 (rotation, twist, dilation) or 0 (translation), and linear in v except for the dilation, which
// |v| multiplies; a twist's pitch h enters linearly, through its term h/2 v ni. The derivatives
// below are those closed forms, exact to rounding.
#pragma once

#include "cga/Compact.h"
#include "cga/PointPairField.h"
#include "cga/Vec3.h"

namespace cga
{
/// dG/dx_j and dG/dv_j (j = x, y, z) and dG/dh of FieldGenerator::of(kind, location, direction,
/// pitch)'s bivector, the weight left out. byPitch is 1/2 v ni for a twist and 0 for the other
/// kinds (they do not read the pitch).
struct GeneratorDerivative
{
  Bivector byLocation[3];
  Bivector byDirection[3];
  Bivector byPitch;
};

/// The parameters of one generator that a fit can move, in the order of fieldTermDerivatives and
/// of FittedParameters: the weight, the location (x, y, z), the direction (x, y, z), the pitch.
constexpr int kGeneratorParameters = 8;

/// The derivative of the generator `g` (its weight is not used). False, `out` unchanged, where
/// FieldGenerator::of gives no generator (an unknown kind, a zero or non-finite direction, a
/// twist's non-finite pitch).
bool generatorDerivative(const GeneratorParameters& g, GeneratorDerivative& out);

/// The derivatives of one generator's term T = w G(x, v, h) / (f |p - x|^2 + eps) of B(p) by its
/// kGeneratorParameters parameters, in the order weight, location x, y, z, direction x, y, z,
/// pitch:
///   dT/dw = G / D,  dT/dx_j = w (dG/dx_j / D + G 2 f (p - x)_j / D^2),  dT/dv_j = w dG/dv_j / D,
///   dT/dh = w dG/dh / D (w/2 v ni / D for a twist, 0 for the other kinds),
/// D = f |p - x|^2 + eps, `g.location` and `p` in space (the frame of
/// PointPairField::mapWithBivectorDerivative's B(p)). False where generatorDerivative is.
bool fieldTermDerivatives(const GeneratorParameters& g, Vec3 p, double falloff, double epsilon,
                          Bivector out[kGeneratorParameters]);

/// Which parameters of every generator are unknowns of a fit, in this order per generator: the
/// weight, the location (x, y, z), the direction (x, y, z), the pitch (read by twists only: for
/// another kind its column is 0).
struct FittedParameters
{
  bool weight = true;
  bool location = false;
  bool direction = false;
  bool pitch = false;
  int perGenerator() const
  {
    return (weight ? 1 : 0) + (location ? 3 : 0) + (direction ? 3 : 0) + (pitch ? 1 : 0);
  }
};

/// field.map(p) and its derivatives by the fitted parameters of every generator:
/// derivatives[3 * u + j] = d out_j / d theta_u, u running over the generators in their order and
/// within each over the fitted parameters (count * fitted.perGenerator() unknowns). The chain
/// rule d out / d theta = (d out / d B) (d B / d theta), with d out / d B from
/// PointPairField::mapWithBivectorDerivative and d B / d theta from fieldTermDerivatives (both
/// for B(p) in space). `field` must be PointPairField(generators, count, falloff, epsilon) with every
/// generator kept (skippedGenerators() == 0, size() == count); false otherwise, and where map()
/// is false (out and derivatives are then unchanged or partly written).
bool mapWithGeneratorDerivatives(const PointPairField& field,
                                 const GeneratorParameters* generators,
                                 std::size_t count,
                                 FittedParameters fitted,
                                 Vec3 p,
                                 double strength,
                                 ExponentialRule rule,
                                 Vec3& out,
                                 double* derivatives);
} // namespace cga
