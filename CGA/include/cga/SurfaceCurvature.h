// The differential geometry of a parametric surface x(u, v) at one point, from its first and
// second derivatives (docs/conventions.md section 6): the unit normal, the principal curvatures
// and directions, the Gaussian and the mean curvature. The sources compute these derivatives from
// their constructions (no mesh, no finite differences) and output the result as point arrays.
#pragma once

#include <cstddef>

#include "cga/Vec3.h"

namespace cga
{
/// A point of a parametric surface with its partial derivatives.
struct SurfaceDerivatives
{
  Vec3 point;
  Vec3 du, dv;           // x_u, x_v
  Vec3 duu, duv, dvv;    // x_uu, x_uv, x_vv
};

/// The curvature of a surface at one point.
///
/// Sign convention (the one of VTK's vtkCurvatures, so that the two compare directly): the normal
/// is n = x_u x x_v / |x_u x x_v|, and a normal curvature is positive where the surface bends away
/// from n (a sphere whose normal points outward has k1 = k2 = 1/r, H = 1/r, K = 1/r^2). Reversing
/// the parametrization's orientation flips n, the principal curvatures and H; K does not change.
struct SurfaceCurvature
{
  /// False at a degenerate point: |x_u x x_v| at most 1e-12 max(|x_u|, |x_v|)^2 (x_u and x_v
  /// parallel, or one of them (nearly) zero, as at a pole of latitude and longitude; 1e-12 is
  /// also the grid sources' threshold for their mesh normals), a non-finite derivative, or
  /// curvatures that overflow. Every other member is then zero (never NaN): the normal is not
  /// defined there, and the curvatures are reported as 0 with zero principal directions, the
  /// mark by which a user tells these points from regular ones.
  bool regular = false;
  Vec3 normal;          // unit
  double k1 = 0.0;      // the larger principal curvature
  double k2 = 0.0;      // the smaller one (k1 >= k2)
  Vec3 direction1;      // unit tangent along which the normal curvature is k1
  Vec3 direction2;      // n x direction1: (direction1, direction2, normal) is right-handed
  double gaussian = 0.0; // K = k1 k2
  double mean = 0.0;     // H = (k1 + k2) / 2
};

/// The curvature at the point whose derivatives are given. The principal directions are defined
/// up to sign; direction1's sign: positive along the nearer of e1 = x_u / |x_u| and e2 = n x e1
/// (e2 on x_v's side), so that it varies continuously over a grid except where it crosses 45
/// degrees between them (a direction along a parameter line, as a surface of revolution's, never
/// flips). At an umbilic (k1 = k2 to rounding: every direction principal) direction1 is e1. Accurate at any scale: the derivatives are rescaled by powers of two
/// first, so a surface 1e-160 or 1e150 across has its curvatures (while they are finite), and
/// the eigenvalues are computed without the cancellation of H +- sqrt(H^2 - K) (an umbilic's k1
/// and k2 agree to rounding, not to its square root).
SurfaceCurvature surfaceCurvature(const SurfaceDerivatives& x);

/// The unit normal x_u x x_v / |x_u x x_v| alone (surfaceCurvature's, at a third of its cost):
/// false at a degenerate point (surfaceCurvature's first-derivative tests), normal unchanged.
bool surfaceNormal(Vec3 du, Vec3 dv, Vec3& normal);

/// The unit normal of the plane of a closed polyline (the first point repeated last): Newell's
/// sum of (p_i - center) x (p_{i+1} - center) over its segments with both ends finite, oriented
/// as the polyline turns; (0, 0, 0) where that sum vanishes. At any scale: the points are moved
/// to center and divided by a power of two first (the products of a polyline 1e-200 across
/// would underflow), so a close center keeps precision.
Vec3 planeNormal(const Vec3* points, std::size_t count, Vec3 center);
} // namespace cga
