// cga::crossedDifferenceNormals: eight samples a block, in GCC's vector extension. Compiled with
// -fno-math-errno (CMakeLists.txt) so that the square roots become vector instructions; a square
// root is correctly rounded either way, and this file's arguments are never negative.
#include "cga/GridNormals.h"

#include "cga/Vec3.h"

#include "ForceInline.h"
#include "LaneClones.h"

#include <algorithm>
#include <cstring>

namespace cga
{
namespace
{
using detail::Eight;
constexpr int L = 8;

// Per lane, whether the square is squareIsSafe's (all-ones where it is).
BOOSTED_LANE_INLINE auto safeSquare(Eight square)
{
  return (square >= 1e-290) & detail::finiteLanes(square);
}
} // namespace

BOOSTED_LANE_CLONES
void crossedDifferenceNormals(const double* left, const double* right, const double* below,
  const double* above, std::size_t count, double minimumSine, double* normals, bool* plain)
{
  for (std::size_t first = 0; first < count; first += L)
  {
    const int n = static_cast<int>(std::min<std::size_t>(L, count - first));
    // The block's coordinates by component (a partial block repeats its last sample).
    alignas(64) double in[4][3][L];
    const double* sources[4] = { left, right, below, above };
    for (int s = 0; s < 4; ++s)
    {
      for (int l = 0; l < L; ++l)
      {
        const double* p = sources[s] + 3 * (first + static_cast<std::size_t>(std::min(l, n - 1)));
        for (int k = 0; k < 3; ++k)
        {
          in[s][k][l] = p[k];
        }
      }
    }
    Eight coordinates[4][3];
    std::memcpy(coordinates, in, sizeof coordinates);
    Eight a[3], b[3];
    for (int k = 0; k < 3; ++k)
    {
      a[k] = coordinates[1][k] - coordinates[0][k];
      b[k] = coordinates[3][k] - coordinates[2][k];
    }
    const Eight aSquare = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
    const Eight bSquare = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
    const Eight aLength = detail::squareRoot(aSquare), bLength = detail::squareRoot(bSquare);
    for (int k = 0; k < 3; ++k)
    {
      a[k] = a[k] / aLength;
      b[k] = b[k] / bLength;
    }
    const Eight normal[3] = { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
      a[0] * b[1] - a[1] * b[0] };
    const Eight length =
      detail::squareRoot(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    const auto usable = safeSquare(aSquare) & safeSquare(bSquare) & (length > minimumSine);
    const Eight inverse = 1.0 / length;
    for (int l = 0; l < n; ++l)
    {
      const std::size_t i = first + static_cast<std::size_t>(l);
      plain[i] = usable[l] != 0;
      for (int k = 0; k < 3; ++k)
      {
        normals[3 * i + k] = normal[k][l] * inverse[l];
      }
    }
  }
}
} // namespace cga
