// Internal: a bilinear product of two compact types, reduced once to its non-zero terms.
//
// The operands and the result are given as lists of null blades (the kBlades of Compact.h).
// Products that land on a blade missing from the result list are dropped: that is how grade
// projections such as <K X ~K>_1 are computed without forming the other grades.
// The terms are kept sorted by result slot (ProductTerms.h). The constructor is constexpr: the
// products of the point map (BoostProducts.h) are built by the compiler, and applyProduct unrolls
// their terms into straight-line code.
//
// Internal linkage only for what the block kernel instantiates (see ProductTerms.h).
#pragma once

#include "ForceInline.h"
#include "cga/NullBasis.h"

#include "NullBladeProduct.h"
#include "ProductTerms.h"

#include <array>
#include <cstddef>
#include <utility>

namespace cga
{
namespace detail
{
class SparseProduct
{
public:
  template <std::size_t NA, std::size_t NB, std::size_t NR>
  constexpr SparseProduct(const std::array<unsigned, NA>& slotsA,
                          const std::array<unsigned, NB>& slotsB,
                          const std::array<unsigned, NR>& slotsR)
  {
    static_assert(NA * NB * 2 <= 512, "operands too large for the term capacity");
    std::array<int, kBladeCount> resultSlot{};
    for (int& slot : resultSlot)
    {
      slot = -1;
    }
    for (std::size_t r = 0; r < NR; ++r)
    {
      resultSlot[slotsR[r]] = static_cast<int>(r);
    }
    for (std::size_t i = 0; i < NA; ++i)
    {
      for (std::size_t j = 0; j < NB; ++j)
      {
        NullTerm terms[2] = {};
        const int count = nullBladeTerms(slotsA[i], slotsB[j], terms);
        for (int t = 0; t < count; ++t)
        {
          const int r = resultSlot[terms[t].blade];
          if (r >= 0)
          {
            Terms[Size++] = { static_cast<std::uint8_t>(i),
                              static_cast<std::uint8_t>(j),
                              static_cast<std::uint8_t>(r),
                              terms[t].coefficient };
          }
        }
      }
    }
    // Sorted by result slot, stably (insertion sort: constexpr): each slot sums its terms in the
    // order of the blade pairs.
    for (int t = 1; t < Size; ++t)
    {
      const ProductTerm moving = Terms[t];
      int u = t;
      for (; u > 0 && Terms[u - 1].r > moving.r; --u)
      {
        Terms[u] = Terms[u - 1];
      }
      Terms[u] = moving;
    }
    Results = static_cast<int>(NR);
  }

  /// r = a * b (only the kept terms). r must hold as many values as the result list.
  void apply(const double* a, const double* b, double* r) const
  {
    applyTerms(this->terms(), Results, a, b, r);
  }

  ProductTerms terms() const { return { Terms.data(), Size }; }

  constexpr int size() const { return Size; }
  constexpr int results() const { return Results; }
  constexpr ProductTerm term(int t) const { return Terms[t]; }

private:
  // 16 x 16 slot pairs with at most two terms each.
  std::array<ProductTerm, 512> Terms{};
  int Size = 0;
  int Results = 0;
};

namespace
{

/// sum[r] += c a[i] b[j] for term I of P, its slots and coefficient constants.
template <const SparseProduct& P, int I, bool Magnitudes, typename T>
BOOSTED_FORCE_INLINE void addTerm(const T* a, const T* b, T* sum)
{
  constexpr ProductTerm t = P.term(I);
  constexpr double c = Magnitudes && t.coefficient < 0.0 ? -t.coefficient : t.coefficient;
  sum[t.r] = sum[t.r] + c * a[t.a] * b[t.b];
}

template <const SparseProduct& P, bool Magnitudes, typename T, int... I>
BOOSTED_FORCE_INLINE void applyUnrolled(const T* a, const T* b, T* r,
                                          std::integer_sequence<int, I...>)
{
  constexpr int kResults = P.results();
  T sum[kResults];
  for (int i = 0; i < kResults; ++i)
  {
    sum[i] = T{};
  }
  (addTerm<P, I, Magnitudes>(a, b, sum), ...);
  for (int i = 0; i < kResults; ++i)
  {
    r[i] = sum[i];
  }
}

/// r = a b for a product built at compile time: applyTerms of its terms (each slot the sum from
/// zero of its terms in the table's order, so the same bits), unrolled, with the coefficients and
/// slots constants the compiler folds (all are +-1 here: a sign, not a multiplication).
template <const SparseProduct& P, typename T>
BOOSTED_FORCE_INLINE void applyProduct(const T* a, const T* b, T* r)
{
  applyUnrolled<P, false>(a, b, r, std::make_integer_sequence<int, P.size()>{});
}

/// applyTermMagnitudes of a product built at compile time (a and b hold magnitudes).
template <const SparseProduct& P, typename T>
BOOSTED_FORCE_INLINE void applyProductMagnitudes(const T* a, const T* b, T* r)
{
  applyUnrolled<P, true>(a, b, r, std::make_integer_sequence<int, P.size()>{});
}
} // namespace
} // namespace detail
} // namespace cga
