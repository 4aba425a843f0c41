// Internal: the terms of a bilinear product of compact types as plain data, and the one loop that
// evaluates them for any number type (double, or the block kernel's vector of lanes).
//
// Plain data and templates with internal linkage only: the block kernel includes this file in
// translation units compiled for AVX2 and AVX-512, whose copy of a shared (vague-linkage) inline
// function or template instance the linker could hand to code running on any CPU.
#pragma once

#include <cstdint>

namespace cga
{
namespace detail
{
/// One term r[r] += coefficient a[a] b[b].
struct ProductTerm
{
  std::uint8_t a, b, r;
  double coefficient;
};

/// The terms of one product, sorted by result slot (each slot's terms in a fixed order).
struct ProductTerms
{
  const ProductTerm* terms;
  int size;
};

namespace
{
/// r = a b for the first `results` slots: each is the sum, from zero and in the table's order, of
/// its terms.
template <typename T>
void applyTerms(const ProductTerms& table, int results, const T* a, const T* b, T* r)
{
  int t = 0;
  for (int i = 0; i < results; ++i)
  {
    T sum{};
    for (; t < table.size && table.terms[t].r == i; ++t)
    {
      const ProductTerm term = table.terms[t];
      sum = sum + term.coefficient * a[term.a] * b[term.b];
    }
    r[i] = sum;
  }
}

/// The same with every term's coefficient by its magnitude (a and b hold magnitudes): the sum of
/// the terms' magnitudes, which bounds the rounding of applyTerms.
template <typename T>
void applyTermMagnitudes(const ProductTerms& table, int results, const T* a, const T* b, T* r)
{
  int t = 0;
  for (int i = 0; i < results; ++i)
  {
    T sum{};
    for (; t < table.size && table.terms[t].r == i; ++t)
    {
      const ProductTerm term = table.terms[t];
      const double coefficient = term.coefficient < 0.0 ? -term.coefficient : term.coefficient;
      sum = sum + coefficient * a[term.a] * b[term.b];
    }
    r[i] = sum;
  }
}
} // namespace
} // namespace detail
} // namespace cga
