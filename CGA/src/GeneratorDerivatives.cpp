#include "cga/GeneratorDerivatives.h"

#include <cmath>

namespace cga
{
namespace
{
const Vec3 kAxes[3] = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };

// d tau(x, v) / dx_j, from tau = up(x) ^ (v + (v.x) ni) in components (PointPairs.cpp):
// e_a^e_b: x_a v_b - x_b v_a; e_i^no: -v_i; e_i^ni: (v.x) x_i - |x|^2/2 v_i; no^ni: v.x.
Bivector pointPairByLocation(Vec3 x, Vec3 v, int j)
{
  using B = Bivector;
  const double xs[3] = { x.x, x.y, x.z };
  const double vs[3] = { v.x, v.y, v.z };
  const auto delta = [j](int a) { return a == j ? 1.0 : 0.0; };
  Bivector d;
  d[B::E12] = delta(0) * vs[1] - delta(1) * vs[0];
  d[B::E13] = delta(0) * vs[2] - delta(2) * vs[0];
  d[B::E23] = delta(1) * vs[2] - delta(2) * vs[1];
  const double vx = dot(v, x);
  for (int i = 0; i < 3; ++i)
  {
    d[B::E1NI + i] = vs[j] * xs[i] + vx * delta(i) - xs[j] * vs[i];
  }
  d[B::NONI] = vs[j];
  return d;
}
} // namespace

bool generatorDerivative(const GeneratorParameters& g, GeneratorDerivative& out)
{
  const double length = norm(g.direction);
  if (!isGeneratorKind(static_cast<int>(g.kind)) || !isFinite(g.direction) || length == 0.0 ||
    !std::isfinite(length) || (g.kind == GeneratorKind::Twist && !std::isfinite(g.pitch)))
  {
    return false;
  }
  const Vec3 x = g.location, v = g.direction;
  GeneratorDerivative d;
  for (int j = 0; j < 3; ++j)
  {
    const Vec3 e = kAxes[j];
    switch (g.kind)
    {
      case GeneratorKind::Rotation:
      case GeneratorKind::Twist:
        // G = 1/2 (A - (x _| A) ni), A = v I3: linear in x and in v. The location's derivative is
        // the ni part of G at e_j (the A parts cancel exactly); the pitch's term h/2 v ni is
        // linear in v.
        d.byLocation[j] =
          FieldGenerator::rotation(e, v).bivector - FieldGenerator::rotation({}, v).bivector;
        d.byDirection[j] = FieldGenerator::rotation(x, e).bivector;
        if (g.kind == GeneratorKind::Twist)
        {
          d.byDirection[j] += FieldGenerator::translation(x, g.pitch * e).bivector;
          d.byPitch = FieldGenerator::translation(x, v).bivector; // d(h/2 v ni)/dh = 1/2 v ni
        }
        break;
      case GeneratorKind::Dilation:
        // G = -1/2 |v| (no^ni + x^ni): the location enters linearly, |v| as a factor.
        d.byLocation[j] = (-length) * FieldGenerator::translation(x, e).bivector; // -|v|/2 e_j ni
        d.byDirection[j] = (v[j] / length) * FieldGenerator::dilation(x).bivector;
        break;
      case GeneratorKind::Translation:
        // G = 1/2 v ni: no location (it only places the falloff).
        d.byLocation[j] = Bivector{};
        d.byDirection[j] = FieldGenerator::translation(x, e).bivector;
        break;
      case GeneratorKind::PointPair:
      default:
        d.byLocation[j] = pointPairByLocation(x, v, j);
        d.byDirection[j] = FieldGenerator::pointPair(x, e).bivector; // tau is linear in v
        break;
    }
  }
  out = d;
  return true;
}

bool fieldTermDerivatives(const GeneratorParameters& g, Vec3 p, double falloff, double epsilon,
                          Bivector out[kGeneratorParameters])
{
  GeneratorDerivative d;
  if (!generatorDerivative(g, d))
  {
    return false;
  }
  const Bivector G = g.field().bivector;
  const Vec3 r = p - g.location;
  const double inverse = 1.0 / (falloff * norm2(r) + epsilon);
  out[0] = G * inverse;
  const double rs[3] = { r.x, r.y, r.z };
  for (int j = 0; j < 3; ++j)
  {
    // d(1/D)/dx_j = 2 f (p - x)_j / D^2.
    out[1 + j] = g.weight * inverse * (d.byLocation[j] + (2.0 * falloff * rs[j] * inverse) * G);
    out[4 + j] = (g.weight * inverse) * d.byDirection[j];
  }
  out[7] = (g.weight * inverse) * d.byPitch;
  return true;
}

bool mapWithGeneratorDerivatives(const PointPairField& field,
                                 const GeneratorParameters* generators,
                                 std::size_t count,
                                 FittedParameters fitted,
                                 Vec3 p,
                                 double strength,
                                 ExponentialRule rule,
                                 Vec3& out,
                                 double* derivatives)
{
  if (field.size() != count || field.skippedGenerators() != 0)
  {
    return false;
  }
  double byBivector[3 * Bivector::Count];
  if (!field.mapWithBivectorDerivative(p, strength, rule, out, byBivector))
  {
    return false;
  }
  // d out / d B is by B(p) in space (PointPairField::generatorAt): the terms' derivatives there.
  const bool use[kGeneratorParameters] = { fitted.weight,    fitted.location,  fitted.location,
                                           fitted.location,  fitted.direction, fitted.direction,
                                           fitted.direction, fitted.pitch };
  double* row = derivatives;
  for (std::size_t i = 0; i < count; ++i)
  {
    const GeneratorParameters& g = generators[i];
    Bivector terms[kGeneratorParameters];
    if (!fieldTermDerivatives(g, p, field.falloff(), field.epsilon(), terms))
    {
      return false;
    }
    for (int k = 0; k < kGeneratorParameters; ++k)
    {
      if (!use[k])
      {
        continue;
      }
      for (int j = 0; j < 3; ++j)
      {
        double sum = 0.0;
        for (int c = 0; c < Bivector::Count; ++c)
        {
          sum += byBivector[Bivector::Count * j + c] * terms[k][c];
        }
        row[j] = sum;
      }
      row += 3;
    }
  }
  return true;
}
} // namespace cga
