// A plane patch bent by one of the paper's curvature operators (CurvatureOperators.h): the grid
// point p(a, b) = origin + a u + b v, a in [-sizeU/2, sizeU/2], b in [-sizeV/2, sizeV/2], goes to
// fn(<K up(p) ~K>_1) with K = exp(E(a, b)) by the Exact or Paper rule (docs/conventions.md section 2).
#pragma once

#include "cga/ExponentialMap.h"
#include "cga/PointPairField.h"
#include "cga/SurfaceCurvature.h"
#include "cga/surfaces/CurvatureOperators.h"

#include <array>
#include <string>
#include <vector>

namespace cga
{
enum class CurvatureMethod
{
  BentLine,           ///< eq 15, Fig 6: every u row bent with kappaU at its point on the v axis
  TranslatedTangents, ///< eq 16, Fig 7
  OsculatingCircles,  ///< eq 17-18, Fig 8: one control point at the origin
  ControlPoints,      ///< eq 21-22, Fig 9-10
  Linear,             ///< eq 24: generators at the ends of each u row (corners 1 and 2)
  Bilinear            ///< eq 25-26, Fig 12: generators at the four corners
};

/// The curvatures of the paper's Fig 7 presets: (kappaU, kappaV).
enum class CurvaturePreset
{
  Parabolic,  ///< (0.5, 0): a cylinder
  Elliptic,   ///< (0.5, 0.25)
  Umbilic,    ///< (0.5, 0.5): a sphere
  Hyperbolic  ///< (-0.5, 0.5): a saddle
};
void presetCurvatures(CurvaturePreset preset, double& kappaU, double& kappaV);

struct CurvaturePatch
{
  CurvatureMethod method = CurvatureMethod::TranslatedTangents;
  ExponentialRule rule = ExponentialRule::Exact;
  PatchFrame frame;
  double sizeU = 4.0, sizeV = 4.0; // sizeV = 0: a single line
  double kappaU = 0.5, kappaV = 0.5;
  double falloff = 1.0;  // k of eq 21-22
  double epsilon = 0.5; // added to every squared distance (see vtkCurvaturePatchSource)
  /// Used by ControlPoints; normalize() them (validate() does).
  std::vector<CurvatureControlPoint> controlPoints;
  /// Linear uses corners 0 (start, a = -sizeU/2) and 1 (end); Bilinear all four:
  /// 0 (-,-), 1 (+,-), 2 (-,+), 3 (+,+) in (a, b).
  std::array<CornerGenerator, 4> corners{};

  /// Empty when the patch can be built (normalizes the control points), otherwise the problem.
  std::string validate();

  /// Patch coordinates of row/column samples: a(column) and b(row).
  double a(int column, int columns) const;
  double b(int row, int rows) const;

  /// Corner locations in space, in the order of `corners`.
  std::array<Vec3, 4> cornerLocations() const;

  /// E(a, b) and the local weight.
  CurvatureGenerator generatorAt(double a, double b) const;

  /// The image of p(a, b); false (out unchanged) when it is at infinity or not finite, or its
  /// local weight is not (an overflowed generator). Computed
  /// about the origin (the patch and its control points moved by -origin, the image moved back),
  /// so that far from the space origin it rounds like eps |origin|, not eps |origin|^2.
  bool map(double a, double b, Vec3& out, double& weight) const;

  /// map() of the samples (a[i], b) of one row, i < count, at once: the generators one by one,
  /// their exponentials and sandwiches eight at a time in the block kernel
  /// (mapPointsByExponentials). mapped[i] is map()'s return value; out[i] and weights[i] are left
  /// unchanged where it is false. map() is this for one sample: the two agree bit for bit.
  void mapRow(double b, const double* a, std::size_t count, Vec3* out, double* weights,
    bool* mapped) const;

  /// generatorAt(a, b).exponent with its first and second derivatives in (a, b), ten components
  /// in Compact.h order, of the patch moved by -shift: the operators' formulas (eq 15-18, 21-22,
  /// 24-26), one template for double and for the jets (src/surfaces/CurvatureOperatorTerms.h), run
  /// on second-order dual numbers; the value is generatorAt's bit for bit. Every operator
  /// is a sum of w_i(a, b) tau(x_i(a, b), d_i): the weights rational in p(a, b) (osculating
  /// circles, control points) or polynomial (the interpolations), the locations linear in (a, b)
  /// and tau polynomial of degree 2 in its location. Call after validate().
  void exponentJet(double a, double b, Vec3 shift, SurfaceJet exponent[Bivector::Count]) const;

  /// The image of p(a, b) with its first and second derivatives, u = a, v = b: E(a, b) and
  /// p(a, b) as jets through mapJetsByExponential, about the origin as map(). False where map()
  /// would be, or where a derivative is not finite (out unchanged).
  bool derivatives(double a, double b, SurfaceDerivatives& out) const;

  /// derivatives() of the samples (a[i], b) of one row, i < count, at once: each exponent's jet
  /// as exponentJet, their images eight at a time (mapJetsByExponential). ok[i] is derivatives()'
  /// return value (out[i] unchanged where false); derivatives() is this for one sample. Where
  /// ok[i], out[i].point and, if weights is not null, weights[i] are mapRow's out[i] and
  /// weights[i] bit for bit (the same operations: the jets' value parts), so a caller that needs
  /// the derivatives need not map the samples again.
  void derivativesRow(double b, const double* a, std::size_t count, SurfaceDerivatives* out,
    bool* ok, double* weights = nullptr) const;

private:
  /// E(a, b) of the patch moved by -shift.
  CurvatureGenerator generatorAbout(double a, double b, Vec3 shift) const;
};
} // namespace cga
