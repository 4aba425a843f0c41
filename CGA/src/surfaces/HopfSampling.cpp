#include "cga/surfaces/HopfSampling.h"

#include <algorithm>
#include <cmath>

namespace cga
{
namespace
{
constexpr double kHalfPi = 1.5707963267948966;
// Latitudes this far beyond the poles are taken as round-off and clamped.
constexpr double kPoleTolerance = 1e-12;

bool finite2(const double v[2])
{
  return std::isfinite(v[0]) && std::isfinite(v[1]);
}

double clampLatitude(double phi)
{
  return std::max(-kHalfPi, std::min(kHalfPi, phi));
}

void addRow(HopfRows& rows, double theta, double phi, int strip)
{
  rows.theta.push_back(theta);
  rows.phi.push_back(phi);
  rows.strip.push_back(strip);
}

std::string gridProblem(const HopfSampling& s)
{
  if (s.thetaResolution < 1 || s.phiResolution < 1)
  {
    return "ThetaResolution and PhiResolution must be at least 1";
  }
  if (!finite2(s.thetaRange) || !finite2(s.phiRange))
  {
    return "ThetaRange and PhiRange must be finite";
  }
  if (s.thetaRange[0] > s.thetaRange[1] || s.phiRange[0] > s.phiRange[1])
  {
    return "ThetaRange and PhiRange must have minimum <= maximum";
  }
  if (s.phiRange[0] < -kHalfPi - kPoleTolerance || s.phiRange[1] > kHalfPi + kPoleTolerance)
  {
    return "PhiRange must lie within [-pi/2, pi/2]";
  }
  if (!std::isfinite(s.thetaRange[1] - s.thetaRange[0]))
  {
    return "ThetaRange's span (maximum - minimum) overflows: its ends must lie closer together";
  }
  return {};
}

void gridRows(const HopfSampling& s, HopfRows& rows)
{
  const int nTheta = s.thetaResolution, nPhi = s.phiResolution;
  auto thetaAt = [&s, nTheta](int i) {
    return s.thetaRange[0] + (s.thetaRange[1] - s.thetaRange[0]) * i / nTheta;
  };
  auto phiAt = [&s, nPhi](int j) {
    return clampLatitude(nPhi > 1
        ? s.phiRange[0] + (s.phiRange[1] - s.phiRange[0]) * j / (nPhi - 1)
        : s.phiRange[0]);
  };
  if (s.latitudeStrips)
  {
    rows.rowsPerStrip = nTheta + 1; // theta0 .. theta1 inclusive
    for (int j = 0; j < nPhi; ++j)
    {
      for (int i = 0; i <= nTheta; ++i)
      {
        addRow(rows, thetaAt(i), phiAt(j), j);
      }
    }
    return;
  }
  rows.rowsPerStrip = nPhi;
  for (int i = 0; i < nTheta; ++i)
  {
    for (int j = 0; j < nPhi; ++j)
    {
      addRow(rows, thetaAt(i), phiAt(j), i);
    }
  }
}

std::string inputRows(const HopfSampling& s, HopfRows& rows)
{
  if (!s.point)
  {
    return "SamplingMode INPUT_POINTS needs an input of points";
  }
  if (!isFinite(s.sphereCenter))
  {
    return "SphereCenter must be finite";
  }
  for (std::size_t i = 0; i < s.inputCount; ++i)
  {
    const Vec3 d = s.point(i) - s.sphereCenter;
    if (!isFinite(d))
    {
      return "the input points must be finite (a NaN or an infinity was given)";
    }
    if (d.x == 0.0 && d.y == 0.0 && d.z == 0.0)
    {
      ++rows.skipped; // no direction
      continue;
    }
    addRow(rows, std::atan2(d.y, d.x), std::atan2(d.z, std::hypot(d.x, d.y)), 0);
  }
  return {};
}

/// Every row finite with its latitude in [-pi/2, pi/2] (clamped within the tolerance).
std::string checkRows(HopfRows& rows)
{
  for (std::size_t r = 0; r < rows.size(); ++r)
  {
    if (!std::isfinite(rows.theta[r]) || !std::isfinite(rows.phi[r]))
    {
      return "base points must be finite (a NaN or an infinity was given)";
    }
    if (rows.phi[r] < -kHalfPi - kPoleTolerance || rows.phi[r] > kHalfPi + kPoleTolerance)
    {
      return "the latitude phi of a base point must lie within [-pi/2, pi/2]";
    }
    rows.phi[r] = clampLatitude(rows.phi[r]);
  }
  return {};
}
} // namespace

long long HopfSampling::rowCount() const
{
  switch (mode)
  {
    case HopfSamplingMode::Grid:
      return (static_cast<long long>(std::max(0, thetaResolution)) + (latitudeStrips ? 1 : 0)) *
        std::max(0, phiResolution);
    case HopfSamplingMode::BasePoints:
      return static_cast<long long>(basePoints.size() / 2);
    case HopfSamplingMode::InputPoints:
      return static_cast<long long>(inputCount);
  }
  return 0;
}

std::string HopfSampling::sample(HopfRows& rows) const
{
  rows = HopfRows();
  std::string problem;
  switch (mode)
  {
    case HopfSamplingMode::Grid:
      problem = gridProblem(*this);
      if (problem.empty())
      {
        gridRows(*this, rows);
      }
      break;
    case HopfSamplingMode::BasePoints:
      for (std::size_t k = 0; k + 1 < basePoints.size(); k += 2)
      {
        addRow(rows, basePoints[k], basePoints[k + 1], 0);
      }
      break;
    case HopfSamplingMode::InputPoints:
      problem = inputRows(*this, rows);
      break;
  }
  return problem.empty() ? checkRows(rows) : problem;
}
} // namespace cga
