// Internal: the compact types as flat coefficient arrays, and the null blades of each slot, for
// the product tables (SparseProduct.h).
#pragma once

#include "cga/Compact.h"

#include <array>

namespace cga
{
namespace detail
{
using EvenArray = std::array<double, Even::kCount>;

/// Slots of an even element: scalar, Bivector::kBlades, Quadvector::kBlades.
constexpr std::array<unsigned, Even::kCount> kEvenBlades = {
  0u, 3u, 5u, 6u, 9u, 10u, 12u, 17u, 18u, 20u, 24u, 15u, 23u, 27u, 29u, 30u
};

/// Slots of an odd element: vector (ConformalVector order), ten trivectors, pseudoscalar.
constexpr std::array<unsigned, 16> kOddBlades = { 8u,  1u,  2u,  4u,  16u, 7u,  11u, 13u,
                                                  14u, 19u, 21u, 22u, 25u, 26u, 28u, 31u };

constexpr std::array<unsigned, 1> kScalarBlade = { 0u };

inline EvenArray pack(const Even& k)
{
  EvenArray a{};
  a[0] = k.scalar;
  for (int i = 0; i < Bivector::Count; ++i)
  {
    a[1 + i] = k.bivector[i];
  }
  for (int i = 0; i < Quadvector::Count; ++i)
  {
    a[1 + Bivector::Count + i] = k.quadvector[i];
  }
  return a;
}

inline Even unpack(const EvenArray& a)
{
  Even k;
  k.scalar = a[0];
  for (int i = 0; i < Bivector::Count; ++i)
  {
    k.bivector[i] = a[1 + i];
  }
  for (int i = 0; i < Quadvector::Count; ++i)
  {
    k.quadvector[i] = a[1 + Bivector::Count + i];
  }
  return k;
}
} // namespace detail
} // namespace cga
