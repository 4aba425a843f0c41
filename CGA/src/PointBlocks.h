// Internal: the one block loop of the batch maps (forEachBlock): PointPairField's (mapPoints,
// mapPointsWithJacobians, mapPointsWithDirectionalDerivatives: mapPointsInBlocks, kernel::kLanes
// points at a time relative to the field's center c, as map(), each image written back as
// p + (image - (p - c)), so that a point the map leaves in place comes back to the bit) and
// mapPointsByExponentials (given exponents, no center).
//
// Internal linkage only (see PointMapCore.h).
#pragma once

#include "ForceInline.h"
#include "PointPairKernel.h"

#include "cga/Vec3.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

namespace cga
{
namespace
{
/// Copies `count` points, xyz interleaved, from `in` to `out` (which may be `in`): the map without
/// generators or at strength 0. onPointWritten(index, finite) is called for each. Returns the count
/// of points not finite.
template <typename In, typename Out, typename OnPointWritten>
std::size_t copyPoints(const In* in, Out* out, std::size_t count, OnPointWritten&& onPointWritten)
{
  std::size_t unchanged = 0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const In* p = in + 3 * i;
    const bool finite = std::isfinite(static_cast<double>(p[0])) &&
      std::isfinite(static_cast<double>(p[1])) && std::isfinite(static_cast<double>(p[2]));
    unchanged += finite ? 0 : 1;
    Out* o = out + 3 * i;
    o[0] = static_cast<Out>(p[0]);
    o[1] = static_cast<Out>(p[1]);
    o[2] = static_cast<Out>(p[2]);
    onPointWritten(i, finite);
  }
  return unchanged;
}

/// The block loop of every batch map (mapPointsInBlocks, mapPointsByExponentials): for each block
/// of kernel::kLanes points first ... first + n - 1, fillLane(lane, index) for every lane (the
/// unused lanes of the last block repeat its last point), then mapBlock(first, n), then
/// writePoint(index, lane) for each point of the block, which returns whether it was mapped.
/// Returns the count of points not mapped.
template <typename FillLane, typename MapBlock, typename WritePoint>
BOOSTED_FORCE_INLINE std::size_t forEachBlock(
  std::size_t count, FillLane&& fillLane, MapBlock&& mapBlock, WritePoint&& writePoint)
{
  constexpr int L = kernel::kLanes;
  std::size_t unmapped = 0;
  for (std::size_t first = 0; first < count; first += L)
  {
    const int n = static_cast<int>(std::min<std::size_t>(L, count - first));
    for (int l = 0; l < L; ++l)
    {
      fillLane(l, first + static_cast<std::size_t>(std::min(l, n - 1)));
    }
    mapBlock(first, n);
    for (int l = 0; l < n; ++l)
    {
      unmapped += writePoint(first + static_cast<std::size_t>(l), l) ? 0 : 1;
    }
  }
  return unmapped;
}

/// A block's lanes from per-point arrays: lanes[j L + l] = values[per i + j] * factor for j < per
/// and lane l's point i = first + min(l, n - 1) (as forEachBlock fills them).
BOOSTED_FORCE_INLINE void gatherLanes(const double* values, int per, std::size_t first, int n,
                                      double factor, double* lanes)
{
  constexpr int L = kernel::kLanes;
  for (int l = 0; l < L; ++l)
  {
    const double* v = values + per * (first + static_cast<std::size_t>(std::min(l, n - 1)));
    for (int j = 0; j < per; ++j)
    {
      lanes[j * L + l] = v[j] * factor;
    }
  }
}

/// Maps `count` points, xyz interleaved, from `in` to `out` (which may be `in`). For each block,
/// mapLanes(first, n, xyz, image, mapped) maps the block's lanes (the points first ... first + n - 1
/// relative to c in xyz, component-major; the unused lanes of the last block repeat its last
/// point) into image and sets mapped[l] for each lane whose image (and whatever else it computes)
/// is usable; then each point is written, its image or itself (counted) where not mapped, and
/// onPointWritten(index, lane, mapped) is called for it. Returns the count of points not mapped.
template <typename In, typename Out, typename MapLanes, typename OnPointWritten>
std::size_t mapPointsInBlocks(Vec3 c, const In* in, Out* out, std::size_t count,
  MapLanes&& mapLanes, OnPointWritten&& onPointWritten)
{
  constexpr int L = kernel::kLanes;
  alignas(64) double xyz[3 * L];
  alignas(64) double image[3 * L];
  std::uint8_t mapped[L];
  return forEachBlock(
    count,
    [&](int l, std::size_t i) {
      const In* p = in + 3 * i;
      xyz[l] = static_cast<double>(p[0]) - c.x;
      xyz[L + l] = static_cast<double>(p[1]) - c.y;
      xyz[2 * L + l] = static_cast<double>(p[2]) - c.z;
    },
    [&](std::size_t first, int n) { mapLanes(first, n, xyz, image, mapped); },
    [&](std::size_t i, int l) {
      Out* o = out + 3 * i;
      const In* p = in + 3 * i;
      if (mapped[l])
      {
        o[0] = static_cast<Out>(static_cast<double>(p[0]) + (image[l] - xyz[l]));
        o[1] = static_cast<Out>(static_cast<double>(p[1]) + (image[L + l] - xyz[L + l]));
        o[2] = static_cast<Out>(static_cast<double>(p[2]) + (image[2 * L + l] - xyz[2 * L + l]));
      }
      else
      {
        // (in may be out: then each coordinate onto itself)
        o[0] = static_cast<Out>(p[0]);
        o[1] = static_cast<Out>(p[1]);
        o[2] = static_cast<Out>(p[2]);
      }
      onPointWritten(i, l, mapped[l] != 0);
      return mapped[l] != 0;
    });
}

/// Whether a written image o and its displacement d are finite in Out (an image beyond the largest
/// float, or a difference that overflows, is not): v - v is 0 for a finite v and NaN otherwise,
/// so one comparison checks all six values without a branch each.
template <typename Out>
bool finiteImageAndDisplacement(const Out* o, const Out* d)
{
  const double check = (double(o[0]) - double(o[0])) + (double(o[1]) - double(o[1])) +
    (double(o[2]) - double(o[2])) + (double(d[0]) - double(d[0])) +
    (double(d[1]) - double(d[1])) + (double(d[2]) - double(d[2]));
  return check == 0.0;
}

/// What mapPointsAndDisplacementsInBlocks found (PointPairField::DisplacementCounts).
struct BlockDisplacementCounts
{
  std::size_t unchanged = 0;
  std::size_t notFinite = 0;
  std::size_t beyondRange = 0;
};

/// mapPointsInBlocks with each point's displacement out - in (computed in double from the image
/// as written, rounded to Out; 0 for a point that is not finite), counting the points not mapped,
/// those of them not finite, and the finite ones whose image or displacement is not finite in Out.
/// The images and displacements of a block are computed in lanes (component-major, as the
/// kernel's), so that the compiler vectorizes them; then each point is written.
template <typename In, typename Out, typename MapLanes>
BlockDisplacementCounts mapPointsAndDisplacementsInBlocks(Vec3 c, const In* in, Out* out,
  Out* displacements, std::size_t count, MapLanes&& mapLanes)
{
  constexpr int L = kernel::kLanes;
  alignas(64) double point[3 * L];
  alignas(64) double xyz[3 * L];
  alignas(64) double image[3 * L];
  alignas(64) Out images[3 * L];
  alignas(64) Out shifts[3 * L];
  std::uint8_t mapped[L];
  const double center[3] = { c.x, c.y, c.z };
  BlockDisplacementCounts counts;
  std::size_t beyondRange = 0;
  counts.unchanged = forEachBlock(
    count,
    [&](int l, std::size_t i) {
      const In* p = in + 3 * i;
      for (int k = 0; k < 3; ++k)
      {
        point[k * L + l] = static_cast<double>(p[k]);
        xyz[k * L + l] = point[k * L + l] - center[k];
      }
    },
    [&](std::size_t first, int n) {
      mapLanes(first, n, xyz, image, mapped);
      // Every lane as if mapped (a lane that is not is written below from its point).
      for (int j = 0; j < 3 * L; ++j)
      {
        images[j] = static_cast<Out>(point[j] + (image[j] - xyz[j]));
        shifts[j] = static_cast<Out>(static_cast<double>(images[j]) - point[j]);
      }
      // v - v is 0 for a finite v and NaN otherwise: one sum checks a lane's six values.
      double finiteness[L] = {};
      for (int k = 0; k < 3; ++k)
      {
        for (int l = 0; l < L; ++l)
        {
          const double o = static_cast<double>(images[k * L + l]);
          const double d = static_cast<double>(shifts[k * L + l]);
          finiteness[l] += (o - o) + (d - d);
        }
      }
      for (int l = 0; l < n; ++l)
      {
        beyondRange += mapped[l] && finiteness[l] != 0.0 ? 1 : 0;
      }
    },
    [&](std::size_t i, int l) {
      Out* o = out + 3 * i;
      Out* d = displacements + 3 * i;
      if (mapped[l])
      {
        for (int k = 0; k < 3; ++k)
        {
          o[k] = images[k * L + l];
          d[k] = shifts[k * L + l];
        }
        return true;
      }
      // Left in place (in may be out: then each coordinate onto itself).
      const In* p = in + 3 * i;
      const double x = point[l], y = point[L + l], z = point[2 * L + l];
      o[0] = static_cast<Out>(p[0]);
      o[1] = static_cast<Out>(p[1]);
      o[2] = static_cast<Out>(p[2]);
      if (!(std::isfinite(x) && std::isfinite(y) && std::isfinite(z)))
      {
        ++counts.notFinite;
        d[0] = d[1] = d[2] = Out(0);
        return false;
      }
      d[0] = static_cast<Out>(static_cast<double>(o[0]) - x);
      d[1] = static_cast<Out>(static_cast<double>(o[1]) - y);
      d[2] = static_cast<Out>(static_cast<double>(o[2]) - z);
      beyondRange += finiteImageAndDisplacement(o, d) ? 0 : 1;
      return false;
    });
  counts.beyondRange = beyondRange;
  return counts;
}
} // namespace
} // namespace cga
