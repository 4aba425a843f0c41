// The curvature patch's derivatives (CurvaturePatch::exponentJet, ::derivatives, ::derivativesRow): E(a, b)'s jet
// against generatorAt (its value bit for bit) and its central differences for every method, the
// image's against map(), and the curvatures they give against the paper's statements: eq 15's
// bent line has curvature kappa, and Fig 7's presets have the principal curvatures
// (kappaU, kappaV) at the origin.
#include "SurfaceJetDual.h"
#include "TestSupport.h"
#include "surfaces/CurvatureOperatorTerms.h"

#include "cga/ExponentialMap.h"
#include "cga/SurfaceCurvature.h"
#include "cga/surfaces/CurvaturePatch.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

namespace
{
using namespace cgatest;

// A patch of each method with generic parameters (two control points, four corners).
CurvaturePatch patchOf(CurvatureMethod method, Random& random)
{
  CurvaturePatch patch;
  patch.method = method;
  patch.frame = randomFrame(random);
  patch.kappaU = random.uniform(-1.0, 1.0);
  patch.kappaV = random.uniform(-1.0, 1.0);
  patch.epsilon = 0.3;
  patch.falloff = 0.7;
  for (int i = 0; i < 2; ++i)
  {
    patch.controlPoints.push_back({ patch.frame.at(random.uniform(-1, 1), random.uniform(-1, 1)),
      patch.frame.normal + 0.2 * random.unit(), patch.frame.u, random.uniform(-1.0, 1.0),
      random.uniform(-1.0, 1.0) });
  }
  for (CornerGenerator& g : patch.corners)
  {
    g.direction = patch.frame.normal + 0.3 * random.unit();
    g.weight = random.uniform(-0.5, 0.5);
  }
  EXPECT_TRUE(patch.validate().empty());
  return patch;
}

// The special cases of the bit-for-bit tests, by trial: 1 flat directions (kappa 0), 2 weights
// that cancel (kappaV = -kappaU), 3 no falloff, 4 a line patch (sizeV 0), 5 a far patch (moved by
// (1e6, -2e6, 3e5)), 6 a frame through the space origin; 0 and above 6 the patch as it is.
void applyTrial(CurvaturePatch& patch, int trial)
{
  patch.kappaU = trial == 1 ? 0.0 : patch.kappaU;
  patch.kappaV = trial == 2 ? -patch.kappaU : patch.kappaV;
  patch.falloff = trial == 3 ? 0.0 : patch.falloff;
  patch.sizeV = trial == 4 ? 0.0 : patch.sizeV;
  const bool moved = trial == 5 || trial == 6;
  const Vec3 shift = trial == 5 ? Vec3{ 1e6, -2e6, 3e5 } : -patch.frame.origin;
  patch.frame.origin = moved ? patch.frame.origin + shift : patch.frame.origin;
  for (CurvatureControlPoint& c : patch.controlPoints)
  {
    c.kappaU = trial == 1 ? 0.0 : c.kappaU;
    c.kappaV = trial == 2 ? -c.kappaU : c.kappaV;
    c.location = moved ? c.location + shift : c.location;
  }
}

// A row's parameters a, uniform in [-1, 1).
template <std::size_t N>
void randomRow(Random& random, double (&a)[N])
{
  for (double& value : a)
  {
    value = random.uniform(-1.0, 1.0);
  }
}

constexpr CurvatureMethod kMethods[] = { CurvatureMethod::BentLine,
  CurvatureMethod::TranslatedTangents, CurvatureMethod::OsculatingCircles,
  CurvatureMethod::ControlPoints, CurvatureMethod::Linear, CurvatureMethod::Bilinear };

// test(patch, method, trial) for a random patch (patchOf) of every method in each trial < trials
// (applyTrial).
template <typename Test>
void forEveryTrialPatch(Random& random, int trials, const Test& test)
{
  for (const CurvatureMethod method : kMethods)
  {
    for (int trial = 0; trial < trials; ++trial)
    {
      CurvaturePatch patch = patchOf(method, random);
      applyTrial(patch, trial);
      ASSERT_TRUE(patch.validate().empty());
      test(patch, method, trial);
    }
  }
}

// The patch's exponentJet at (a, b): its value generatorAt's (1e-14), its first and second
// derivatives generatorAt's central differences (1e-8).
void expectJetIsTheGeneratorWithItsDifferences(const CurvaturePatch& patch, double a, double b)
{
  SurfaceJet jet[Bivector::Count];
  patch.exponentJet(a, b, Vec3{}, jet);
  auto e = [&](double da, double db) { return patch.generatorAt(a + da, b + db).exponent; };
  const Bivector value = e(0, 0);
  // Central differences at h and h/2, extrapolated (Richardson): truncation O(h^4) = 1e-12,
  // rounding eps / (h/2)^2 = 1e-9 in the second differences.
  auto extrapolated = [](auto difference) {
    const double h = 1e-3;
    return (4.0 * difference(0.5 * h) - difference(h)) / 3.0;
  };
  const std::string where = "method " + std::to_string(static_cast<int>(patch.method)) + " at (" +
    std::to_string(a) + ", " + std::to_string(b) + ")";
  const double scale = std::max(1.0, value.maxAbs());
  for (int c = 0; c < Bivector::Count; ++c)
  {
    EXPECT_NEAR(jet[c].value, value[c], 1e-14 * scale) << where;
    // Each derivative to 1e-8 of the larger of the scale and itself.
    auto expectDerivative = [&](double got, auto difference) {
      const double expected = extrapolated(difference);
      EXPECT_NEAR(got, expected, 1e-8 * std::max(scale, std::fabs(expected))) << where;
    };
    expectDerivative(jet[c].da, [&](double h) { return (e(h, 0)[c] - e(-h, 0)[c]) / (2 * h); });
    expectDerivative(jet[c].db, [&](double h) { return (e(0, h)[c] - e(0, -h)[c]) / (2 * h); });
    expectDerivative(jet[c].daa,
      [&](double h) { return (e(h, 0)[c] - 2 * value[c] + e(-h, 0)[c]) / (h * h); });
    expectDerivative(jet[c].dbb,
      [&](double h) { return (e(0, h)[c] - 2 * value[c] + e(0, -h)[c]) / (h * h); });
    expectDerivative(jet[c].dab, [&](double h) {
      return (e(h, h)[c] - e(h, -h)[c] - e(-h, h)[c] + e(-h, -h)[c]) / (4 * h * h);
    });
  }
}

TEST(CurvaturePatchDerivatives, ExponentJetIsTheGeneratorWithItsDifferences)
{
  Random random(1303);
  for (const CurvatureMethod method : kMethods)
  {
    for (int trial = 0; trial < 5; ++trial)
    {
      const CurvaturePatch patch = patchOf(method, random);
      expectJetIsTheGeneratorWithItsDifferences(
        patch, random.uniform(-1.5, 1.5), random.uniform(-1.5, 1.5));
    }
  }
}

TEST(CurvaturePatchDerivatives, AWeightThatCancelsAtTheSampleKeepsItsDerivatives)
{
  // A saddle (kappaV = -kappaU) in the patch's plane, its normal the plane's: the patch's own
  // (OsculatingCircles, at the frame's origin) or a control point (ControlPoints). On the
  // diagonals through it the two osculating weights cancel exactly (the sample's offset (d, +-d)
  // is exact), so the generator's weight is 0 there while its derivatives are not (off the
  // diagonal one weight wins). The jet keeps those derivatives (only a weight zero with all its
  // tangents is a zero term) and its value is generatorAt's +0 to the bit.
  for (const CurvatureMethod method :
    { CurvatureMethod::OsculatingCircles, CurvatureMethod::ControlPoints })
  {
    CurvaturePatch patch;
    patch.method = method;
    patch.kappaU = 0.75;
    patch.kappaV = -0.75;
    patch.epsilon = 0.25;
    patch.falloff = 0.5;
    const Vec3 saddle = method == CurvatureMethod::ControlPoints ? Vec3{ 0.25, -0.5, 0.0 } : Vec3{};
    patch.controlPoints.push_back({ saddle, Vec3{ 0, 0, 1 }, Vec3{ 1, 0, 0 }, 0.75, -0.75 });
    ASSERT_TRUE(patch.validate().empty());
    for (const double d : { -0.375, 0.125, 0.5 })
    {
      for (const double sign : { 1.0, -1.0 })
      {
        const double a = saddle.x + d, b = saddle.y + sign * d;
        const CurvatureGenerator g = patch.generatorAt(a, b);
        ASSERT_EQ(0.0, g.weight) << "the weights do not cancel at (" << a << ", " << b << ")";
        SurfaceJet jet[Bivector::Count];
        patch.exponentJet(a, b, Vec3{}, jet);
        bool moves = false;
        for (int c = 0; c < Bivector::Count; ++c)
        {
          EXPECT_EQ(0, std::memcmp(&jet[c].value, &g.exponent.c[c], sizeof(double))) << c;
          moves = moves || jet[c].da != 0.0 || jet[c].db != 0.0;
        }
        EXPECT_TRUE(moves) << "the generator does not change near (" << a << ", " << b << ")";
        expectJetIsTheGeneratorWithItsDifferences(patch, a, b);
      }
    }
  }
}

TEST(CurvaturePatchDerivatives, ExponentJetValueIsTheGeneratorBitForBit)
{
  // The operators are one template for double and for the jets (CurvatureOperatorTerms.h): the
  // jet's value part is generatorAt's, to the bit (signs of zeros included), for every method, at
  // the grid samples mapRow uses (corners, edges, the center), with flat directions (kappa 0),
  // weights that cancel (kappaV = -kappaU), no falloff, a line patch (sizeV 0) and a far patch.
  Random random(1307);
  forEveryTrialPatch(random, 6, [](const CurvaturePatch& patch, CurvatureMethod method, int trial) {
    for (int row = 0; row < 5; ++row)
    {
      for (int column = 0; column < 5; ++column)
      {
        const double a = patch.a(column, 5), b = patch.b(row, 5);
        SurfaceJet jet[Bivector::Count];
        patch.exponentJet(a, b, Vec3{}, jet);
        const Bivector value = patch.generatorAt(a, b).exponent;
        for (int c = 0; c < Bivector::Count; ++c)
        {
          EXPECT_EQ(0, std::memcmp(&jet[c].value, &value.c[c], sizeof(double)))
            << static_cast<int>(method) << " trial " << trial << " component " << c << ": "
            << jet[c].value << " " << value[c];
        }
      }
    }
  });
}

TEST(CurvaturePatchDerivatives, ExponentJetIsTheScalarJetsBitForBit)
{
  // exponentJet runs the operators' template on the jets of eight samples in lanes
  // (generatorJets): every part, the derivatives too, is the same template's on the jets of one
  // sample in double (SurfaceJetDual.h) to the bit, at random samples of every method and trial.
  Random random(1308);
  forEveryTrialPatch(random, 7, [&random](const CurvaturePatch& patch, CurvatureMethod method, int trial) {
    const detail::PatchPieces pieces(patch, patch.frame.origin);
    for (int sample = 0; sample < 9; ++sample)
    {
      const double a = random.uniform(-1.0, 1.0), b = random.uniform(-1.0, 1.0);
      const double aParts[core::kJetParts] = { a, 1.0, 0.0, 0.0, 0.0, 0.0 };
      const double bParts[core::kJetParts] = { b, 0.0, 1.0, 0.0, 0.0, 0.0 };
      const auto scalar =
        detail::patchGeneratorOf(patch, pieces, core::secondOrderOf(aParts), core::secondOrderOf(bParts));
      SurfaceJet jet[Bivector::Count];
      patch.exponentJet(a, b, patch.frame.origin, jet);
      for (int c = 0; c < Bivector::Count; ++c)
      {
        double expected[core::kJetParts], parts[core::kJetParts];
        core::partsOf(scalar.exponent[c], expected);
        core::partsOf(jet[c], parts);
        EXPECT_EQ(0, std::memcmp(parts, expected, sizeof parts))
          << static_cast<int>(method) << " trial " << trial << " component " << c << ": daa "
          << parts[3] << " " << expected[3] << ", dab " << parts[4] << " " << expected[4];
      }
    }
  });
}

TEST(CurvaturePatchDerivatives, MapRowIsTheOneSampleGeneratorBitForBit)
{
  // mapRow computes a row's generators its own way (the control points' sums eight samples at a
  // time): its images are the exponential map of the one-sample generator (exponentJet's value
  // about the origin, the same template on double) to the bit, in rows of 21 samples (two whole
  // blocks and a partial one), with the trials above; at a frame through the space origin its
  // weights are generatorAt's.
  Random random(1309);
  const auto test = [&random](const CurvaturePatch& patch, CurvatureMethod method, int trial) {
    constexpr std::size_t kCount = 21;
    const double b = random.uniform(-1.0, 1.0);
    double a[kCount], weights[kCount];
    Vec3 out[kCount];
    bool mapped[kCount];
    randomRow(random, a);
    patch.mapRow(b, a, kCount, out, weights, mapped);
    for (std::size_t i = 0; i < kCount; ++i)
    {
      SurfaceJet jet[Bivector::Count];
      patch.exponentJet(a[i], b, patch.frame.origin, jet);
      Bivector exponent;
      for (int c = 0; c < Bivector::Count; ++c)
      {
        exponent[c] = jet[c].value;
      }
      const Vec3 point = Vec3{} + a[i] * patch.frame.u + b * patch.frame.v;
      Vec3 image;
      bool finite = false;
      mapPointsByExponentials(&exponent, &point, 1, patch.rule, &image, &finite);
      ASSERT_EQ(mapped[i], finite) << static_cast<int>(method) << " trial " << trial;
      if (!finite)
      {
        continue;
      }
      const Vec3 expected = patch.frame.origin + image;
      EXPECT_EQ(0, std::memcmp(&out[i], &expected, sizeof expected))
        << static_cast<int>(method) << " trial " << trial << " sample " << i;
      if (trial == 6)
      {
        const double weight = patch.generatorAt(a[i], b).weight;
        EXPECT_EQ(0, std::memcmp(&weights[i], &weight, sizeof weight))
          << static_cast<int>(method) << " sample " << i << ": " << weights[i] << " " << weight;
      }
    }
  };
  forEveryTrialPatch(random, 7, test);
}

TEST(CurvaturePatchDerivatives, DerivativesRowIsTheOneSampleJetsBitForBit)
{
  // derivativesRow maps a row's jets eight at a time (mapJetsByExponential): each sample's
  // derivatives are those of the jets of exponentJet and p(a, b) mapped alone
  // (mapJetByExponential), to the bit, in rows of 45 samples (whole blocks, a partial one, two
  // chunks of derivativesRow), with the trials above; where false, the output is untouched.
  Random random(1310);
  const auto test = [&random](const CurvaturePatch& patch, CurvatureMethod method, int trial) {
    constexpr std::size_t kCount = 45;
    const double b = random.uniform(-1.0, 1.0);
    double a[kCount];
    randomRow(random, a);
    SurfaceDerivatives sentinel;
    sentinel.point = Vec3{ 7, 8, 9 };
    std::vector<SurfaceDerivatives> out(kCount, sentinel);
    bool ok[kCount];
    patch.derivativesRow(b, a, kCount, out.data(), ok);
    int differentiated = 0;
    for (std::size_t i = 0; i < kCount; ++i)
    {
      SurfaceJet exponent[Bivector::Count], point[3], image[3];
      patch.exponentJet(a[i], b, patch.frame.origin, exponent);
      const Vec3 p = a[i] * patch.frame.u + b * patch.frame.v;
      const Vec3 us = patch.frame.u, vs = patch.frame.v;
      point[0] = SurfaceJet{ p.x, us.x, vs.x, 0.0, 0.0, 0.0 };
      point[1] = SurfaceJet{ p.y, us.y, vs.y, 0.0, 0.0, 0.0 };
      point[2] = SurfaceJet{ p.z, us.z, vs.z, 0.0, 0.0, 0.0 };
      SurfaceDerivatives expected = sentinel;
      const bool mapped = mapJetByExponential(exponent, point, patch.rule, image) &&
        isFinite(patch.frame.origin + Vec3{ image[0].value, image[1].value, image[2].value });
      ASSERT_EQ(ok[i], mapped) << static_cast<int>(method) << " trial " << trial << " sample " << i;
      if (mapped)
      {
        ++differentiated;
        const auto part = [&](double SurfaceJet::*member) {
          return Vec3{ image[0].*member, image[1].*member, image[2].*member };
        };
        expected.point = patch.frame.origin + part(&SurfaceJet::value);
        expected.du = part(&SurfaceJet::da);
        expected.dv = part(&SurfaceJet::db);
        expected.duu = part(&SurfaceJet::daa);
        expected.duv = part(&SurfaceJet::dab);
        expected.dvv = part(&SurfaceJet::dbb);
        SurfaceDerivatives one;
        ASSERT_TRUE(patch.derivatives(a[i], b, one));
        EXPECT_EQ(0, std::memcmp(&one, &expected, sizeof expected)) << static_cast<int>(method);
      }
      EXPECT_EQ(0, std::memcmp(&out[i], &expected, sizeof expected))
        << static_cast<int>(method) << " trial " << trial << " sample " << i;
    }
    EXPECT_GT(differentiated, 0) << static_cast<int>(method) << " trial " << trial;
  };
  forEveryTrialPatch(random, 7, test);
}

TEST(CurvaturePatchDerivatives, DerivativesRowPointsAndWeightsAreMapRowsBitForBit)
{
  // derivativesRow's points and weights are the jets' value parts: where it succeeds they are
  // mapRow's to the bit (the patch source takes its points from them with ComputeCurvatures), and
  // where mapRow fails it fails too; rows of 21 samples, the trials above.
  Random random(1311);
  const auto test = [&random](const CurvaturePatch& patch, CurvatureMethod method, int trial) {
    constexpr std::size_t kCount = 21;
    const double b = random.uniform(-1.0, 1.0);
    double a[kCount], weights[kCount], jetWeights[kCount];
    Vec3 out[kCount];
    bool mapped[kCount], ok[kCount];
    std::vector<SurfaceDerivatives> derivatives(kCount);
    randomRow(random, a);
    patch.mapRow(b, a, kCount, out, weights, mapped);
    patch.derivativesRow(b, a, kCount, derivatives.data(), ok, jetWeights);
    int compared = 0;
    for (std::size_t i = 0; i < kCount; ++i)
    {
      const std::string where =
        std::to_string(static_cast<int>(method)) + " trial " + std::to_string(trial);
      if (!mapped[i] || !ok[i])
      {
        EXPECT_TRUE(mapped[i] || !ok[i]) << where;
        continue;
      }
      ++compared;
      EXPECT_EQ(0, std::memcmp(&derivatives[i].point, &out[i], sizeof out[i])) << where;
      EXPECT_EQ(0, std::memcmp(&jetWeights[i], &weights[i], sizeof weights[i]))
        << where << ": " << jetWeights[i] << " " << weights[i];
    }
    EXPECT_GT(compared, 0) << static_cast<int>(method) << " trial " << trial;
  };
  forEveryTrialPatch(random, 7, test);
}

TEST(CurvaturePatchDerivatives, AnOverflowedWeightIsNotDifferentiated)
{
  // Curvatures near the largest double: the weight 0.5 (kappaU + kappaV) overflows while the
  // exponent and its image stay finite. mapRow drops such a sample; derivatives and
  // derivativesRow do too, leaving their outputs unchanged.
  Random random(1312);
  CurvaturePatch patch = patchOf(CurvatureMethod::TranslatedTangents, random);
  patch.kappaU = patch.kappaV = 1e308;
  patch.frame.origin = Vec3{}; // the generators' locations within the unit ball: tau stays small
  ASSERT_TRUE(patch.validate().empty());
  const double a = 0.3, b = -0.2;
  const CurvatureGenerator g = patch.generatorAt(a, b);
  ASSERT_FALSE(std::isfinite(g.weight));
  const Vec3 p = patch.frame.at(a, b);
  Vec3 image;
  bool finite = false;
  mapPointsByExponentials(&g.exponent, &p, 1, patch.rule, &image, &finite);
  ASSERT_TRUE(finite); // the premise: only the weight is not finite
  Vec3 point;
  double weight = 7.0;
  EXPECT_FALSE(patch.map(a, b, point, weight));
  SurfaceDerivatives x;
  x.point = Vec3{ 7, 8, 9 };
  EXPECT_FALSE(patch.derivatives(a, b, x));
  bool ok = true;
  patch.derivativesRow(b, &a, 1, &x, &ok, &weight);
  EXPECT_FALSE(ok);
  EXPECT_EQ(7.0, x.point.x);
  EXPECT_EQ(7.0, weight);
}

TEST(CurvaturePatchDerivatives, AFlatFarControlPointAddsNothingToTheDerivatives)
{
  // A control point with both curvatures zero has a zero weight, value and derivatives: its term
  // is exactly zero, even where its tau is not finite (a location near 1e160, |x|^2 overflows;
  // 0 * inf would be NaN). The derivatives are those without it, in every lane of a row.
  Random random(1313);
  CurvaturePatch patch = patchOf(CurvatureMethod::ControlPoints, random);
  CurvaturePatch withFlat = patch;
  CurvatureControlPoint flat = patch.controlPoints[0];
  flat.location = Vec3{ 1e160, -2e160, 5e159 };
  flat.kappaU = flat.kappaV = 0.0;
  withFlat.controlPoints.push_back(flat);
  // Both validated as often: validate() normalizes the frame again, which may move it by an ulp.
  ASSERT_TRUE(patch.validate().empty());
  ASSERT_TRUE(withFlat.validate().empty());
  constexpr std::size_t kCount = 11;
  const double b = 0.3;
  double a[kCount];
  randomRow(random, a);
  std::vector<SurfaceDerivatives> expected(kCount), got(kCount);
  bool expectedOk[kCount], gotOk[kCount];
  patch.derivativesRow(b, a, kCount, expected.data(), expectedOk);
  withFlat.derivativesRow(b, a, kCount, got.data(), gotOk);
  for (std::size_t i = 0; i < kCount; ++i)
  {
    ASSERT_TRUE(expectedOk[i]);
    ASSERT_TRUE(gotOk[i]) << "sample " << i;
    int k = 0;
    for (Vec3 SurfaceDerivatives::*part : { &SurfaceDerivatives::point, &SurfaceDerivatives::du,
           &SurfaceDerivatives::dv, &SurfaceDerivatives::duu, &SurfaceDerivatives::duv,
           &SurfaceDerivatives::dvv })
    {
      const Vec3 e = expected[i].*part, g = got[i].*part;
      EXPECT_EQ(e.x, g.x) << "sample " << i << " part " << k;
      EXPECT_EQ(e.y, g.y) << "sample " << i << " part " << k;
      EXPECT_EQ(e.z, g.z) << "sample " << i << " part " << k++;
    }
  }
}

TEST(CurvaturePatchDerivatives, ImageDerivativesAreMapsDifferences)
{
  Random random(1304);
  for (const ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
  {
    for (const CurvatureMethod method : kMethods)
    {
      CurvaturePatch patch = patchOf(method, random);
      patch.rule = rule;
      const double a = random.uniform(-1.5, 1.5), b = random.uniform(-1.5, 1.5);
      SurfaceDerivatives x;
      ASSERT_TRUE(patch.derivatives(a, b, x));
      auto at = [&](double da, double db) {
        Vec3 p;
        double weight;
        EXPECT_TRUE(patch.map(a + da, b + db, p, weight));
        return p;
      };
      const double h = 1e-4;
      const Vec3 p = at(0, 0);
      EXPECT_TRUE(pointsNear(x.point, p, 1e-13));
      const double scale = std::max({ 1.0, maxNorm(x.duu), maxNorm(x.dvv), maxNorm(x.duv) });
      EXPECT_LE(distance(x.du, (at(h, 0) - at(-h, 0)) / (2 * h)), 1e-7 * scale);
      EXPECT_LE(distance(x.dv, (at(0, h) - at(0, -h)) / (2 * h)), 1e-7 * scale);
      EXPECT_LE(distance(x.duu, (at(h, 0) - 2.0 * p + at(-h, 0)) / (h * h)), 1e-6 * scale);
      EXPECT_LE(distance(x.dvv, (at(0, h) - 2.0 * p + at(0, -h)) / (h * h)), 1e-6 * scale);
      EXPECT_LE(distance(x.duv, (at(h, h) - at(h, -h) - at(-h, h) + at(-h, -h)) / (4 * h * h)),
        1e-6 * scale);
    }
  }
}

TEST(CurvaturePatchDerivatives, BentLineHasCurvatureKappaAlongUAndNoneAlongV)
{
  // Eq 15: every u line is the circle of curvature kappa, and the rows are translates along v:
  // a cylinder, k = (kappa, 0) at every point (the center of curvature on the -n side: bending
  // away from the normal u x v, positive).
  Random random(1305);
  for (const double kappa : { 0.5, 2.0, -0.75 })
  {
    CurvaturePatch patch;
    patch.method = CurvatureMethod::BentLine;
    patch.frame = randomFrame(random);
    patch.kappaU = kappa;
    ASSERT_TRUE(patch.validate().empty());
    for (const double a : { -2.0, -0.5, 0.0, 1.0 })
    {
      for (const double b : { -1.0, 0.0, 0.7 })
      {
        SurfaceDerivatives x;
        ASSERT_TRUE(patch.derivatives(a, b, x));
        const SurfaceCurvature k = surfaceCurvature(x);
        ASSERT_TRUE(k.regular);
        EXPECT_NEAR(k.k1, std::max(kappa, 0.0), 1e-9) << kappa << " " << a << " " << b;
        EXPECT_NEAR(k.k2, std::min(kappa, 0.0), 1e-9);
        EXPECT_NEAR(k.gaussian, 0.0, 1e-9);
        EXPECT_NEAR(k.mean, 0.5 * kappa, 1e-9);
        // v (the cylinder's axis) is the flat direction.
        const Vec3 flat = kappa > 0 ? k.direction2 : k.direction1;
        EXPECT_NEAR(std::fabs(dot(flat, patch.frame.v)), 1.0, 1e-9);
      }
    }
  }
}

TEST(CurvaturePatchDerivatives, Fig7PresetsHaveTheirCurvaturesAtTheOrigin)
{
  Random random(1306);
  for (const CurvaturePreset preset : { CurvaturePreset::Parabolic, CurvaturePreset::Elliptic,
         CurvaturePreset::Umbilic, CurvaturePreset::Hyperbolic })
  {
    for (const ExponentialRule rule : { ExponentialRule::Exact, ExponentialRule::Paper })
    {
      CurvaturePatch patch;
      patch.method = CurvatureMethod::TranslatedTangents;
      patch.rule = rule;
      patch.frame = randomFrame(random);
      presetCurvatures(preset, patch.kappaU, patch.kappaV);
      ASSERT_TRUE(patch.validate().empty());
      SurfaceDerivatives x;
      ASSERT_TRUE(patch.derivatives(0.0, 0.0, x));
      const SurfaceCurvature k = surfaceCurvature(x);
      ASSERT_TRUE(k.regular);
      EXPECT_LE(distance(k.normal, patch.frame.normal), 1e-12);
      const double ku = patch.kappaU, kv = patch.kappaV;
      EXPECT_NEAR(k.k1, std::max(ku, kv), 1e-9) << static_cast<int>(preset);
      EXPECT_NEAR(k.k2, std::min(ku, kv), 1e-9) << static_cast<int>(preset);
      EXPECT_NEAR(k.gaussian, ku * kv, 1e-9);
      EXPECT_NEAR(k.mean, 0.5 * (ku + kv), 1e-9);
      if (ku != kv) // an umbilic has no principal directions
      {
        const Vec3 alongU = ku > kv ? k.direction1 : k.direction2;
        EXPECT_NEAR(std::fabs(dot(alongU, patch.frame.u)), 1.0, 1e-9);
      }
    }
  }
}
} // namespace
