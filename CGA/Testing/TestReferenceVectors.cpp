// The reference vectors computed with the independent ganja.js geometric-algebra library (Data/*.json:
// each file names its conventions, seed and the checks it passed there).
#include "TestSupport.h"

#include "cga/CompactAlgebra.h"
#include "cga/Conformal.h"
#include "cga/Exponential.h"
#include "cga/PointPairs.h"
#include "cga/PointSandwich.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <string>
#include <vector>

namespace
{
using namespace cga;
using cgatest::signedArea;
using cgatest::pointsNear;
using cgatest::relativeDifference;
using cgatest::boost;
using cgatest::mapPoint;
using cgatest::specialConformal;
using nlohmann::json;

json load(const std::string& name)
{
  std::ifstream file(cgatest::dataPath(name));
  EXPECT_TRUE(file.good()) << "cannot open " << cgatest::dataPath(name);
  return json::parse(file);
}

Vec3 vec(const json& j)
{
  return { j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>() };
}

Bivector bivectorFromNull(const json& j)
{
  const char* keys[Bivector::Count] = { "e1^e2", "e1^e3", "e2^e3", "e1^no", "e2^no",
                                        "e3^no", "e1^ni", "e2^ni", "e3^ni", "no^ni" };
  Bivector b;
  for (int i = 0; i < Bivector::Count; ++i)
  {
    b[i] = j.at(keys[i]).get<double>();
  }
  return b;
}

ConformalVector vectorFromNull(const json& j)
{
  const char* keys[ConformalVector::Count] = { "no", "e1", "e2", "e3", "ni" };
  ConformalVector v;
  for (int i = 0; i < ConformalVector::Count; ++i)
  {
    v[i] = j.at(keys[i]).get<double>();
  }
  return v;
}

// ganja names: "1" is the scalar, "e14" is e1 ^ e4 with e4 = e+, e5 = e- (ascending indices).
Multivector fromGanja(const json& j)
{
  Multivector m;
  for (const auto& item : j.items())
  {
    unsigned mask = 0;
    if (item.key() != "1")
    {
      for (std::size_t i = 1; i < item.key().size(); ++i)
      {
        mask |= 1u << (item.key()[i] - '1');
      }
    }
    m[mask] = item.value().get<double>();
  }
  return m;
}

double relative(double a, double b)
{
  return std::fabs(a - b) / std::max(std::fabs(b), 1e-300);
}

TEST(ReferenceVectors, OriginBoostRandomCases)
{
  const json data = load("a_origin_boost.json");
  const json& cases = data.at("random_cases");
  ASSERT_EQ(cases.size(), 16u);
  int points = 0;
  for (const json& c : cases)
  {
    const Vec3 v = vec(c.at("v"));
    const Even k = boost(1.0, {}, v);
    EXPECT_EQ(k.scalar, c.at("K_scalar").get<double>());
    EXPECT_LE(relativeDifference(k.bivector, bivectorFromNull(c.at("K_bivector_null"))), 1e-16);
    EXPECT_LE(relativeDifference(toMultivector(k), fromGanja(c.at("K_ganja"))), 1e-16);
    for (const json& point : c.at("points"))
    {
      ++points;
      const Vec3 x = vec(point.at("x"));
      const ConformalVector image = sandwichGrade1(k, ConformalVector::point(x));
      const ConformalVector expected = vectorFromNull(point.at("Q_null"));
      EXPECT_LE((image - expected).maxAbs(), 1e-14 * expected.maxAbs());
      EXPECT_LE(relative(image.weight(), point.at("alpha").get<double>()), 1e-14);
      EXPECT_TRUE(pointsNear(mapPoint(k, x), vec(point.at("x_mapped")), 1e-13));
      EXPECT_TRUE(pointsNear(specialConformal(v, x), vec(point.at("x_mapped_closed_form")), 1e-14));
      EXPECT_TRUE(pointsNear(mapPoint(k, x), vec(point.at("x_mapped_closed_form")), 1e-13));
    }
  }
  EXPECT_EQ(points, 96);
}

TEST(ReferenceVectors, Fig1CircleBoostedAlongItsPlane)
{
  const json data = load("a_origin_boost.json");
  const std::vector<double> thetas = data.at("meta").at("fig1_thetas").get<std::vector<double>>();
  ASSERT_EQ(thetas.size(), 16u);
  const double deg = M_PI / 180.0;
  const Multivector sigma = circleThroughPoints({ std::cos(30 * deg), std::sin(30 * deg), 0 },
                                                { std::cos(150 * deg), std::sin(150 * deg), 0 },
                                                { 0, -1, 0 });
  const json& cases = data.at("fig1_circle_xy_boost_e1");
  ASSERT_EQ(cases.size(), 23u);
  for (const json& c : cases)
  {
    const double lambda = c.at("lambda").get<double>();
    const Even k = boost(lambda, {}, { 1, 0, 0 });
    EXPECT_LE(relativeDifference(k.bivector, bivectorFromNull(c.at("K_bivector_null")), 1.0),
              1e-16);
    // Mapped sample points and their weights.
    std::vector<Vec3> mapped;
    for (std::size_t i = 0; i < thetas.size(); ++i)
    {
      const Vec3 p{ std::cos(thetas[i]), std::sin(thetas[i]), 0.0 };
      const ConformalVector image = sandwichGrade1(k, ConformalVector::point(p));
      mapped.push_back(mapPoint(k, p));
      EXPECT_TRUE(pointsNear(mapped.back(), vec(c.at("mapped_points").at(i)), 1e-12)) << lambda;
      EXPECT_LE(relative(image.weight(), c.at("alphas").at(i).get<double>()), 1e-13) << lambda;
    }
    // Orientation of the mapped polygon.
    const std::string traversal = c.at("traversal").get<std::string>();
    const double area = signedArea(mapped);
    EXPECT_LE(relative(area, c.at("signed_area_2d").get<double>()),
              traversal == "degenerate" ? 1e9 : 1e-9);
    if (traversal == "ccw")
    {
      EXPECT_GT(area, 0.0);
    }
    else if (traversal == "cw")
    {
      EXPECT_LT(area, 0.0);
    }
    else
    {
      EXPECT_LE(std::fabs(area), 1e-12);
    }
    // The whole blade.
    const Multivector image = sandwich(toMultivector(k), sigma);
    const json& blade = c.at("blade");
    const double flatness = (ni() ^ image).coefficientNorm() / image.coefficientNorm();
    EXPECT_NEAR(flatness, blade.at("flatness").get<double>(), 1e-12) << lambda;
    const double orientation = -toQuadvector(ni() ^ image)[Quadvector::E12NONI];
    const double expectedOrientation = blade.at("plane_coef_ni_no_e12").get<double>();
    EXPECT_NEAR(
      orientation, expectedOrientation, 1e-12 * std::max(1.0, std::fabs(expectedOrientation)));
    const RoundInfo info = readCircle(image);
    if (blade.at("center").at(0).is_null())
    {
      EXPECT_TRUE(info.isLine) << lambda;
      EXPECT_EQ(c.at("image").at("kind").get<std::string>(), "line");
      EXPECT_NEAR(info.center.x, c.at("analytic").at("x_const").get<double>(), 1e-15);
      EXPECT_NEAR(info.center.x, c.at("image").at("x_const").get<double>(), 1e-14);
      continue;
    }
    EXPECT_FALSE(info.isLine) << lambda;
    const Vec3 center = down((image * ni() * image).grade(1));
    EXPECT_TRUE(pointsNear(center, vec(blade.at("center")), 1e-12)) << lambda;
    EXPECT_TRUE(pointsNear(info.center, vec(c.at("analytic").at("center")), 1e-12)) << lambda;
    EXPECT_TRUE(pointsNear(info.center, vec(c.at("image").at("center")), 1e-11)) << lambda;
    EXPECT_NEAR(info.normal.z, std::fabs(lambda) < 1.0 ? 1.0 : -1.0, 1e-12) << lambda;
    const double analyticRadius = c.at("analytic").at("radius").get<double>();
    // The blade reader works on coefficients of size lambda^2 that hold a radius of 1/lambda^2:
    // it cancels about lambda^4 ulps (ganja's radius2 shows the same loss). The points do not.
    const double bladeConditioning = std::pow(1.0 + lambda * lambda, 2.0);
    EXPECT_LE(relative(info.radius, analyticRadius), 1e-13 * bladeConditioning) << lambda;
    const Multivector axis = leftContraction(ni(), image);
    const double radius2 = scalarProduct(image, image.involution()) / scalarProduct(axis, axis);
    // ganja's value shares the cancellation of this formula for large lambda.
    EXPECT_LE(relative(radius2, blade.at("radius2").get<double>()), 1e-13 * bladeConditioning)
      << lambda;
    EXPECT_LE(relative(info.radius, c.at("image").at("radius").get<double>()),
              1e-13 * bladeConditioning)
      << lambda;
    const Vec3 analyticCenter = vec(c.at("analytic").at("center"));
    EXPECT_NEAR(
      analyticCenter.x, lambda / (lambda * lambda - 1.0), 1e-15 * std::fabs(analyticCenter.x));
    EXPECT_NEAR(analyticRadius, 1.0 / std::fabs(lambda * lambda - 1.0), 1e-15 * analyticRadius);
    for (const Vec3& p : mapped)
    {
      EXPECT_NEAR(
        norm(p - analyticCenter), analyticRadius, 1e-13 * std::max(1.0, cgatest::maxNorm(p)))
        << lambda;
    }
    // The point -e1/lambda goes to infinity.
    // The point -e1/lambda (none for lambda = 0) goes to infinity:
    // its weight 1 + 2 lambda x + lambda^2 x^2 = 1 - 2 + 1 is zero up to rounding.
    if (lambda != 0.0)
    {
      const Vec3 polePreimage = vec(c.at("pole_preimage"));
      EXPECT_TRUE(pointsNear(polePreimage, { -1.0 / lambda, 0, 0 }, 1e-16));
      const ConformalVector pole = sandwichGrade1(k, ConformalVector::point(polePreimage));
      EXPECT_LE(std::fabs(pole.weight()), 1e-15);
    }
    else
    {
      EXPECT_TRUE(c.at("pole_preimage").is_null());
    }
  }
}

TEST(ReferenceVectors, Fig2CircleBoostedAcrossItsPlane)
{
  const json data = load("a_origin_boost.json");
  const std::vector<double> thetas = data.at("meta").at("fig1_thetas").get<std::vector<double>>();
  const json& cases = data.at("fig2_circle_yz_boost_e1");
  ASSERT_EQ(cases.size(), 6u);
  for (const json& c : cases)
  {
    const double lambda = c.at("lambda").get<double>();
    const Even k = boost(lambda, {}, { 1, 0, 0 });
    const double planeX = c.at("image").at("plane_x").get<double>();
    const double radius = c.at("image").at("radius").get<double>();
    EXPECT_NEAR(planeX, lambda / (1.0 + lambda * lambda), 1e-16);
    EXPECT_NEAR(radius, 1.0 / (1.0 + lambda * lambda), 1e-16);
    for (std::size_t i = 0; i < thetas.size(); ++i)
    {
      const Vec3 p{ 0.0, std::cos(thetas[i]), std::sin(thetas[i]) };
      const Vec3 q = mapPoint(k, p);
      EXPECT_TRUE(pointsNear(q, vec(c.at("mapped_points").at(i)), 1e-15)) << lambda;
      const double alpha = sandwichGrade1(k, ConformalVector::point(p)).weight();
      EXPECT_LE(relative(alpha, c.at("alphas").at(i).get<double>()), 1e-15);
      EXPECT_NEAR(q.x, planeX, 1e-15);
      EXPECT_NEAR(std::hypot(q.y, q.z), radius, 1e-15);
    }
  }
}

TEST(ReferenceVectors, NullPointPairs)
{
  const json data = load("b_null_point_pair.json");
  const json& cases = data.at("cases");
  ASSERT_EQ(cases.size(), 24u);
  for (const json& c : cases)
  {
    const Vec3 x = vec(c.at("x")), v = vec(c.at("v"));
    const double w = c.at("w").get<double>();
    const Bivector tau = nullPointPairCompact(x, w * v);
    EXPECT_LE(relativeDifference(tau, bivectorFromNull(c.at("tau_null"))), 1e-15);
    EXPECT_LE(relativeDifference(toMultivector(tau), fromGanja(c.at("tau_ganja"))), 1e-15);
    EXPECT_LE((tau * tau).maxAbs(), 1e-15 * std::pow(tau.maxAbs(), 2.0));
    const Even plus = Even::identity() + Even::fromBivector(tau);
    const Even minus = Even::identity() - Even::fromBivector(tau);
    // exp(+-tau) = 1 +- tau, by the exact and the paper's rule.
    EXPECT_LE(relativeDifference(expExact(tau), plus), 4e-15);
    EXPECT_LE(relativeDifference(expPaper(tau), plus), 4e-15);
    EXPECT_LE(relativeDifference(expExact(-tau), minus), 4e-15);
    EXPECT_LE(relativeDifference(expPaper(-tau), minus), 4e-15);
    EXPECT_TRUE(pointsNear(mapPoint(plus, x), x, 1e-14));
    EXPECT_TRUE(pointsNear(mapPoint(minus, x), x, 1e-14));
    for (const json& point : c.at("points"))
    {
      const Vec3 p = vec(point.at("p"));
      const ConformalVector imagePlus = sandwichGrade1(plus, ConformalVector::point(p));
      const ConformalVector imageMinus = sandwichGrade1(minus, ConformalVector::point(p));
      EXPECT_LE(relative(imagePlus.weight(), point.at("alpha_plus").get<double>()), 1e-13);
      EXPECT_LE(relative(imageMinus.weight(), point.at("alpha_minus").get<double>()), 1e-13);
      EXPECT_TRUE(pointsNear(mapPoint(plus, p), vec(point.at("p_mapped_plus")), 1e-13));
      EXPECT_TRUE(pointsNear(mapPoint(minus, p), vec(point.at("p_mapped_minus")), 1e-13));
      EXPECT_TRUE(
        pointsNear(x + specialConformal(w * v, p - x), vec(point.at("closed_form_plus")), 1e-13));
      EXPECT_TRUE(
        pointsNear(x + specialConformal(-w * v, p - x), vec(point.at("closed_form_minus")), 1e-13));
      EXPECT_TRUE(pointsNear(mapPoint(plus, p), x + specialConformal(w * v, p - x), 1e-12));
    }
  }
}

// The variants of c_bend_line.json: K = 1 + factor * kappa * tau.
double variantFactor(const std::string& variant)
{
  if (variant == "paper_eq15: K = 1 - kappa*tau/2")
  {
    return -0.5;
  }
  if (variant == "K = 1 + kappa*tau/2")
  {
    return 0.5;
  }
  if (variant == "K = 1 - kappa*tau")
  {
    return -1.0;
  }
  EXPECT_EQ(variant, "K = 1 + kappa*tau");
  return 1.0;
}

TEST(ReferenceVectors, BendingALine)
{
  const json data = load("c_bend_line.json");
  const json& cases = data.at("cases");
  ASSERT_EQ(cases.size(), 63u);
  for (const json& c : cases)
  {
    const Vec3 p = vec(c.at("p")), n = vec(c.at("n"));
    const double kappa = c.at("kappa").get<double>();
    const double factor = variantFactor(c.at("variant").get<std::string>());
    const Bivector tau = nullPointPairCompact(p, n);
    EXPECT_LE(relativeDifference(tau, bivectorFromNull(c.at("tau_null"))), 1e-15);
    const Even k = Even::identity() + Even::fromBivector(factor * kappa * tau);
    EXPECT_EQ(k.scalar, c.at("K_scalar").get<double>());
    EXPECT_LE(relativeDifference(k.bivector, bivectorFromNull(c.at("K_bivector_null"))), 1e-15);

    // The circle the line becomes: curvature 2 |factor kappa|, center on the side of -sign(factor
    // kappa) n.
    const double radius = 1.0 / std::fabs(2.0 * factor * kappa);
    const Vec3 center = p + (1.0 / (2.0 * factor * kappa)) * n;
    const std::vector<double> s = c.at("line_params_s").get<std::vector<double>>();
    for (std::size_t i = 0; i < s.size(); ++i)
    {
      const Vec3 q = mapPoint(k, p + s[i] * Vec3{ 1, 0, 0 });
      EXPECT_TRUE(pointsNear(q, vec(c.at("mapped_points").at(i)), 1e-13));
      EXPECT_NEAR(norm(q - center), radius, 1e-12 * std::max(1.0, radius));
    }
    EXPECT_TRUE(pointsNear(mapPoint(k, p), vec(c.at("p_image")), 1e-15));
    EXPECT_TRUE(pointsNear(mapPoint(k, p), p, 1e-15));
    EXPECT_TRUE(pointsNear(vec(c.at("fit_center")), center, 1e-12));
    EXPECT_NEAR(c.at("fit_radius").get<double>(), radius, 1e-12 * radius);
    EXPECT_NEAR(
      c.at("measured_curvature_over_kappa").get<double>(), 2.0 * std::fabs(factor), 1e-12);
    EXPECT_EQ(c.at("center_side_along_n").get<double>(), dot(center - p, n) > 0 ? 1.0 : -1.0);
    const RoundInfo info = readCircle(sandwich(toMultivector(k), line(p, p + Vec3{ 1, 0, 0 })));
    EXPECT_FALSE(info.isLine);
    EXPECT_NEAR(info.radius, c.at("blade_radius").get<double>(), 1e-13 * radius);
    EXPECT_TRUE(pointsNear(info.center, vec(c.at("blade_center")), 1e-13));
    EXPECT_NEAR(info.radius, radius, 1e-13 * radius);
    EXPECT_TRUE(pointsNear(info.center, center, 1e-13));
  }
}

TEST(ReferenceVectors, StraighteningTheBentLine)
{
  const json data = load("c_bend_line.json");
  const json& cases = data.at("straighten");
  ASSERT_EQ(cases.size(), 3u);
  for (const json& c : cases)
  {
    const Vec3 p = vec(c.at("p")), n = vec(c.at("n"));
    const double kappa = c.at("kappa").get<double>();
    EXPECT_TRUE(pointsNear(vec(c.at("reversed_n")), -n, 0.0));
    const Even bend =
      Even::identity() + Even::fromBivector(-0.5 * kappa * nullPointPairCompact(p, n));
    const Even straighten =
      Even::identity() + Even::fromBivector(-0.5 * kappa * nullPointPairCompact(p, -n));
    EXPECT_TRUE(pointsNear(vec(c.at("circle_center")), p - n / kappa, 1e-15));
    const json& circlePoints = c.at("circle_points");
    for (std::size_t i = 0; i < circlePoints.size(); ++i)
    {
      const Vec3 q = mapPoint(straighten, vec(circlePoints.at(i)));
      EXPECT_TRUE(pointsNear(q, vec(c.at("straightened_points").at(i)), 1e-12));
      EXPECT_LE(std::fabs(q.y), 1e-13 * std::max(1.0, norm(q)));
      EXPECT_EQ(q.z, 0.0);
    }
    // Bending then straightening returns the line's points.
    for (int i = -20; i <= 20; ++i)
    {
      const Vec3 x = p + Vec3{ 0.2 * i, 0, 0 };
      EXPECT_TRUE(pointsNear(mapPoint(straighten, mapPoint(bend, x)), x, 1e-14));
    }
    EXPECT_LE(c.at("max_roundtrip_error").get<double>(), 1e-13);
  }
}
} // namespace
