// The base points of a Hopf fibration's output (docs/conventions.md section 4): which fibers are
// drawn, in which order, and how they group into the strips of a twistor mesh. One row per
// fiber: its base point (theta, phi) (theta the longitude, phi the latitude in [-pi/2, pi/2]) and
// its strip. Three ways to choose them:
//  * Grid: thetaResolution longitudes theta0 + i (theta1 - theta0) / thetaResolution,
//    i = 0 .. thetaResolution - 1 (half-open: theta is periodic), times phiResolution latitudes
//    phi0 + j (phi1 - phi0) / (phiResolution - 1), j = 0 .. phiResolution - 1 (closed; one sample:
//    phi0). Meridian strips (the default): theta-major, one strip per longitude through its
//    latitudes. Latitude strips: phi-major, one strip per latitude through theta0 .. theta1
//    inclusive (thetaResolution + 1 rows, closed when the range is a full turn).
//  * Base points: the given (theta, phi) pairs, one strip.
//  * Input points: the directions d = p - sphereCenter of given points: theta = atan2(d.y, d.x),
//    phi = atan2(d.z, hypot(d.x, d.y)), one strip; points at the center have no direction and are
//    skipped (counted).
#pragma once

#include "cga/Vec3.h"

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace cga
{
enum class HopfSamplingMode
{
  Grid,
  BasePoints,
  InputPoints
};

/// The rows of the output, one per fiber.
struct HopfRows
{
  std::vector<double> theta, phi;
  std::vector<int> strip;
  int rowsPerStrip = 0;     // 0: one strip of all rows
  std::size_t skipped = 0;  // input points at the sphere center (no direction)

  std::size_t size() const { return theta.size(); }
  /// The rows of the shortest strip (a twistor mesh needs at least 2).
  std::size_t stripLength() const { return rowsPerStrip > 0 ? rowsPerStrip : size(); }
};

struct HopfSampling
{
  HopfSamplingMode mode = HopfSamplingMode::Grid;

  // Grid
  double thetaRange[2] = { 0.0, 6.283185307179586 };
  double phiRange[2] = { -1.5707963267948966, 1.5707963267948966 };
  int thetaResolution = 8;
  int phiResolution = 9;
  bool latitudeStrips = false;

  // BasePoints: theta, phi pairs (an odd last value is ignored)
  std::vector<double> basePoints;

  // InputPoints: point(i) for i < inputCount; no input when `point` is empty.
  Vec3 sphereCenter{ 0, 0, 0 };
  std::size_t inputCount = 0;
  std::function<Vec3(std::size_t)> point;

  /// The rows sample() gives at most, without building them and without overflow: the grid's
  /// count, the base points', or the input points' (checked against a size cap first).
  long long rowCount() const;

  /// Fills `rows` and returns an empty string, or returns what is wrong (then `rows` is
  /// unspecified): a grid resolution below 1, non-finite or inverted ranges, phi outside
  /// [-pi/2, pi/2] (beyond 1e-12; values just outside are clamped), no input, non-finite base or
  /// input points or sphere center.
  std::string sample(HopfRows& rows) const;
};
} // namespace cga
