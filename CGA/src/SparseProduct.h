// Internal: a bilinear product of two compact types, reduced once to its non-zero terms.
//
// The operands and the result are given as lists of null blades (the kBlades of Compact.h).
// Products that land on a blade missing from the result list are dropped: that is how grade
// projections such as <K X ~K>_1 are computed without forming the other grades.
// The terms are kept sorted by result slot (ProductTerms.h), the form the block kernel reads too.
#pragma once

#include "cga/NullBasis.h"

#include "ProductTerms.h"

#include <algorithm>
#include <array>

namespace cga
{
namespace detail
{
class SparseProduct
{
public:
  template <std::size_t NA, std::size_t NB, std::size_t NR>
  SparseProduct(const std::array<unsigned, NA>& slotsA,
                const std::array<unsigned, NB>& slotsB,
                const std::array<unsigned, NR>& slotsR)
  {
    static_assert(NA * NB * 2 <= 512, "operands too large for the term capacity");
    std::array<int, kBladeCount> resultSlot;
    resultSlot.fill(-1);
    for (std::size_t r = 0; r < NR; ++r)
    {
      resultSlot[slotsR[r]] = static_cast<int>(r);
    }
    for (std::size_t i = 0; i < NA; ++i)
    {
      for (std::size_t j = 0; j < NB; ++j)
      {
        NullTerm terms[2];
        const int count = nullBladeProduct(slotsA[i], slotsB[j], terms);
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
    // Stable: each slot sums its terms in the order of the blade pairs.
    std::stable_sort(Terms.begin(), Terms.begin() + Size,
                     [](const ProductTerm& x, const ProductTerm& y) { return x.r < y.r; });
    Results = static_cast<int>(NR);
  }

  /// r = a * b (only the kept terms). r must hold as many values as the result list.
  void apply(const double* a, const double* b, double* r) const
  {
    applyTerms(this->terms(), Results, a, b, r);
  }

  ProductTerms terms() const { return { Terms.data(), Size }; }

private:
  // 16 x 16 slot pairs with at most two terms each.
  std::array<ProductTerm, 512> Terms{};
  int Size = 0;
  int Results = 0;
};
} // namespace detail
} // namespace cga
