// BOOSTED_LANE_CLONES: a function whose loops run over many independent values (lanes of points,
// the ten components of a bivector) is compiled for AVX-512, AVX2 and the baseline and chosen at
// load time (GCC's function multiversioning), as the block kernel is (PointPairKernel.h). The core
// is compiled with -ffp-contract=off, so every version rounds alike: the same bits on every
// instruction set.
#pragma once

#include "ForceInline.h"

#include <limits>

#if defined(BOOSTED_KERNEL_X86_DISPATCH) && defined(__GNUC__) && !defined(__clang__)
#define BOOSTED_LANE_CLONES __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define BOOSTED_LANE_CLONES
#endif

namespace cga
{
namespace detail
{
/// GCC's vector extension: eight doubles (a block of kernel::kLanes points, eight of a bivector's
/// ten components, eight samples), for loops where GCC's own vectorization did worse.
typedef double Eight __attribute__((vector_size(8 * sizeof(double))));
/// A comparison's result on Eight: all ones in the lanes where it holds.
using EightMask = decltype(Eight{} < Eight{});

// Templates on the lane vector (Eight), so that only the files that use them, compiled with
// -Wno-psabi, declare functions passing 64-byte vectors.

/// Per lane |v| (std::fabs, which the vector extension lacks).
template <class Lanes>
BOOSTED_LANE_INLINE Lanes magnitude(Lanes v)
{
  return v < 0.0 ? -v : v;
}

/// Per lane sqrt, correctly rounded as std::sqrt: one vector instruction in the files compiled
/// with -fno-math-errno (CMakeLists.txt), a call per lane elsewhere (the same values).
template <class Lanes>
BOOSTED_LANE_INLINE Lanes squareRoot(Lanes x)
{
  Lanes r;
  for (int l = 0; l < static_cast<int>(sizeof(Lanes) / sizeof(double)); ++l)
  {
    r[l] = __builtin_sqrt(x[l]);
  }
  return r;
}

/// Per lane, all ones where v is finite, as std::isfinite (a NaN fails the comparison).
template <class Lanes>
BOOSTED_LANE_INLINE auto finiteLanes(Lanes v)
{
  return magnitude(v) <= std::numeric_limits<double>::max();
}
} // namespace detail
} // namespace cga
