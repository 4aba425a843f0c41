// The derivatives of the generators by their parameters (GeneratorDerivatives.h, the fit filter's
// Jacobian; docs/conventions.md section 3 item 17) against central differences of the generators'
// definitions on the full Multivector (GeneratorKindReference.h). G is a polynomial of degree <= 2
// in the location and linear in the direction (but for the dilation's |v|), so there the central
// difference is exact up to rounding and the comparison is tight.
#include "GeneratorKindReference.h"
#include "TestSupport.h"

#include "cga/CompactConversion.h"
#include "cga/GeneratorDerivatives.h"

#include <cmath>
#include <limits>

namespace
{
using namespace cga;
using cgatest::kAllKinds;
using cgatest::Random;

Bivector referenceG(const GeneratorParameters& g)
{
  return toBivector(cgatest::referenceBivector(g));
}

Bivector referenceTerm(const GeneratorParameters& g, Vec3 p, double falloff, double epsilon)
{
  return toBivector(cgatest::referenceField({ g }, p, falloff, epsilon));
}

double largestDifference(const Bivector& a, const Bivector& b)
{
  return (a - b).maxAbs();
}

// The parameter `index` of `g` (weight, location x y z, direction x y z, pitch) moved by `step`.
GeneratorParameters withParameterMoved(GeneratorParameters g, int index, double step)
{
  if (index == 0)
  {
    g.weight += step;
  }
  else if (index == 7)
  {
    g.pitch += step;
  }
  else if (index <= 3)
  {
    double* c[3] = { &g.location.x, &g.location.y, &g.location.z };
    *c[index - 1] += step;
  }
  else
  {
    double* c[3] = { &g.direction.x, &g.direction.y, &g.direction.z };
    *c[index - 4] += step;
  }
  return g;
}

GeneratorParameters randomGenerator(Random& random, GeneratorKind kind)
{
  return { kind, random.vec3(1.5), random.uniform(0.2, 1.5) * random.unit(),
           random.uniform(-1.0, 1.0), random.uniform(-2.0, 2.0) };
}

TEST(GeneratorDerivatives, GeneratorsByLocationAndDirectionMatchCentralDifferencesOfTheFullProduct)
{
  Random random(1301);
  for (int n = 0; n < 100; ++n)
  {
    for (GeneratorKind kind : kAllKinds)
    {
      const GeneratorParameters g = randomGenerator(random, kind);
      GeneratorDerivative d;
      ASSERT_TRUE(generatorDerivative(g, d));
      for (int j = 0; j < 3; ++j)
      {
        // Polynomial of degree <= 2: the central difference is exact but for rounding, about
        // 1e-16 |G| / h.
        const double h = 1e-3;
        const Bivector byLocation =
          (referenceG(withParameterMoved(g, 1 + j, h)) - referenceG(withParameterMoved(g, 1 + j, -h))) / (2.0 * h);
        EXPECT_LT(largestDifference(d.byLocation[j], byLocation), 1e-11)
          << "kind " << static_cast<int>(kind) << ", location " << j;
        // Linear in v, but the dilation's |v|: its central difference errs by h^2/6 |v|''',
        // hence the smaller step there.
        const double k = kind == GeneratorKind::Dilation ? 1e-5 : 1e-3;
        const Bivector byDirection =
          (referenceG(withParameterMoved(g, 4 + j, k)) - referenceG(withParameterMoved(g, 4 + j, -k))) / (2.0 * k);
        EXPECT_LT(largestDifference(d.byDirection[j], byDirection),
                  kind == GeneratorKind::Dilation ? 1e-9 : 1e-11)
          << "kind " << static_cast<int>(kind) << ", direction " << j;
      }
      // G is linear in the pitch (a twist's h/2 v ni; the other kinds do not read it).
      const double h = 1e-3;
      const Bivector byPitch =
        (referenceG(withParameterMoved(g, 7, h)) - referenceG(withParameterMoved(g, 7, -h))) / (2.0 * h);
      EXPECT_LT(largestDifference(d.byPitch, byPitch), 1e-11) << "kind " << static_cast<int>(kind);
      if (kind == GeneratorKind::Twist)
      {
        EXPECT_GT(d.byPitch.maxAbs(), 0.05); // |v| >= 0.2: the test compares something
      }
      else
      {
        EXPECT_EQ(d.byPitch.maxAbs(), 0.0) << "kind " << static_cast<int>(kind);
      }
    }
  }
}

// A twist's term by its pitch against the full product's twist minus its rotation: the
// difference of the definitions is h/2 v ni / D times w, so dT/dh is it divided by h.
TEST(GeneratorDerivatives, TwistTermByPitchIsItsScrewPartOverThePitch)
{
  Random random(1304);
  for (int n = 0; n < 100; ++n)
  {
    GeneratorParameters twist = randomGenerator(random, GeneratorKind::Twist);
    twist.pitch = random.uniform(0.1, 2.0) * (n % 2 ? 1.0 : -1.0);
    twist.weight = random.uniform(0.5, 2.0);
    GeneratorParameters rotation = twist;
    rotation.kind = GeneratorKind::Rotation;
    const Vec3 p = random.vec3(2.0);
    const double falloff = random.uniform(0.0, 2.0), epsilon = random.uniform(0.05, 1.0);
    Bivector d[kGeneratorParameters];
    ASSERT_TRUE(fieldTermDerivatives(twist, p, falloff, epsilon, d));
    const Bivector screw = (referenceTerm(twist, p, falloff, epsilon) -
                            referenceTerm(rotation, p, falloff, epsilon)) / twist.pitch;
    EXPECT_LT(largestDifference(d[7], screw), 1e-12 * (1.0 + screw.maxAbs()));
    EXPECT_GT(screw.maxAbs(), 1e-4); // not a comparison of zeros
  }
}

TEST(GeneratorDerivatives, FieldTermsMatchCentralDifferencesOfTheFullProduct)
{
  Random random(1302);
  for (int n = 0; n < 100; ++n)
  {
    for (GeneratorKind kind : kAllKinds)
    {
      const GeneratorParameters g = randomGenerator(random, kind);
      const Vec3 p = random.vec3(2.0);
      const double falloff = random.uniform(0.0, 2.0), epsilon = random.uniform(0.05, 1.0);
      Bivector d[kGeneratorParameters];
      ASSERT_TRUE(fieldTermDerivatives(g, p, falloff, epsilon, d));
      // The weight: exactly linear.
      EXPECT_LT(largestDifference(d[0] * g.weight, referenceTerm(g, p, falloff, epsilon)),
                1e-13 * (1.0 + referenceTerm(g, p, falloff, epsilon).maxAbs()));
      for (int index = 1; index < kGeneratorParameters; ++index)
      {
        // 1/D is not a polynomial: a fourth-order central difference (error h^4 f^(5)/30).
        const double h = 1e-3;
        const auto term = [&](double step) {
          return referenceTerm(withParameterMoved(g, index, step), p, falloff, epsilon);
        };
        const Bivector reference =
          (term(-2.0 * h) - 8.0 * term(-h) + 8.0 * term(h) - term(2.0 * h)) / (12.0 * h);
        EXPECT_LT(largestDifference(d[index], reference), 1e-8 * (1.0 + reference.maxAbs()))
          << "kind " << static_cast<int>(kind) << ", parameter " << index;
      }
    }
  }
}

TEST(GeneratorDerivatives, UnusableGeneratorsHaveNoDerivative)
{
  GeneratorDerivative d;
  Bivector terms[kGeneratorParameters];
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(generatorDerivative({ GeneratorKind::PointPair, { 0, 0, 0 }, { 0, 0, 0 } }, d));
  EXPECT_FALSE(generatorDerivative({ GeneratorKind::Rotation, { 0, 0, 0 }, { nan, 0, 1 } }, d));
  EXPECT_FALSE(generatorDerivative({ GeneratorKind::Twist, { 0, 0, 0 }, { 0, 0, 1 }, nan }, d));
  EXPECT_FALSE(
    generatorDerivative({ static_cast<GeneratorKind>(7), { 0, 0, 0 }, { 0, 0, 1 } }, d));
  EXPECT_FALSE(fieldTermDerivatives(
    { GeneratorKind::Dilation, { 0, 0, 0 }, { 0, 0, 0 } }, { 1, 0, 0 }, 1.0, 0.01, terms));
}
} // namespace

namespace
{
// The fit's Jacobian, d out / d theta by every parameter of every generator, against central
// differences of map() over fields rebuilt with the parameter moved (fourth order), and its weight
// columns against PointPairField::mapWithWeightDerivatives (automatic differentiation by the
// weights, another path through the core).
TEST(GeneratorDerivatives, MapDerivativesByEveryParameterMatchCentralDifferencesOfTheMap)
{
  Random random(1303);
  const FittedParameters all{ true, true, true, true };
  for (ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    for (int n = 0; n < 40; ++n)
    {
      std::vector<GeneratorParameters> generators;
      for (GeneratorKind kind : kAllKinds)
      {
        GeneratorParameters g = randomGenerator(random, kind);
        g.weight *= 0.3;
        generators.push_back(g);
      }
      const double falloff = random.uniform(0.5, 2.0), epsilon = random.uniform(0.05, 0.5);
      const PointPairField field(generators.data(), generators.size(), falloff, epsilon);
      const Vec3 p = random.vec3(2.0);
      const double strength = random.uniform(0.5, 1.5);
      Vec3 out, reference;
      const int unknowns = kGeneratorParameters * static_cast<int>(generators.size());
      std::vector<double> derivatives(3 * unknowns);
      ASSERT_TRUE(mapWithGeneratorDerivatives(field, generators.data(), generators.size(), all,
                                              p, strength, rule, out, derivatives.data()));
      ASSERT_TRUE(field.map(p, strength, rule, reference));
      EXPECT_EQ(out.x, reference.x);
      EXPECT_EQ(out.y, reference.y);
      EXPECT_EQ(out.z, reference.z);
      std::vector<double> byWeight(3 * generators.size());
      Vec3 unused;
      ASSERT_TRUE(field.mapWithWeightDerivatives(p, strength, rule, unused, byWeight.data()));
      for (std::size_t i = 0; i < generators.size(); ++i)
      {
        for (int k = 0; k < kGeneratorParameters; ++k)
        {
          const auto image = [&](double step) {
            std::vector<GeneratorParameters> moved = generators;
            moved[i] = withParameterMoved(generators[i], k, step);
            const PointPairField f(moved.data(), moved.size(), falloff, epsilon);
            Vec3 q;
            EXPECT_TRUE(f.map(p, strength, rule, q));
            return q;
          };
          const double h = 1e-4;
          const Vec3 difference =
            (image(-2.0 * h) - 8.0 * image(-h) + 8.0 * image(h) - image(2.0 * h)) / (12.0 * h);
          const double* column = derivatives.data() + 3 * (kGeneratorParameters * i + k);
          const double scale = 1.0 + norm(difference);
          for (int j = 0; j < 3; ++j)
          {
            EXPECT_NEAR(column[j], difference[j], 1e-7 * scale)
              << "rule " << static_cast<int>(rule) << ", generator " << i << ", parameter " << k
              << ", component " << j;
            if (k == 0)
            {
              EXPECT_NEAR(column[j], byWeight[3 * i + j], 1e-12 * (1.0 + std::fabs(column[j])));
            }
          }
        }
      }
    }
  }
}

TEST(GeneratorDerivatives, MapDerivativesNeedTheFieldOfTheGivenGenerators)
{
  const std::vector<GeneratorParameters> generators = {
    { GeneratorKind::PointPair, { 0, 0, 1 }, { 0, 0, 1 }, 0.0, 0.5 },
    { GeneratorKind::PointPair, { 0, 0, 0 }, { 0, 0, 0 }, 0.0, 0.5 } // skipped by the field
  };
  const PointPairField field(generators.data(), generators.size(), 1.0, 0.01);
  Vec3 out;
  double derivatives[6];
  EXPECT_FALSE(mapWithGeneratorDerivatives(field, generators.data(), generators.size(),
                                           FittedParameters{}, { 1, 0, 0 }, 1.0,
                                           ExponentialRule::Exact, out, derivatives));
  const PointPairField one(generators.data(), 1, 1.0, 0.01);
  EXPECT_TRUE(mapWithGeneratorDerivatives(one, generators.data(), 1, FittedParameters{},
                                          { 1, 0, 0 }, 1.0, ExponentialRule::Exact, out,
                                          derivatives));
  EXPECT_FALSE(mapWithGeneratorDerivatives(one, generators.data(), 1, FittedParameters{},
                                           { std::nan(""), 0, 0 }, 1.0, ExponentialRule::Exact,
                                           out, derivatives));
}
} // namespace
