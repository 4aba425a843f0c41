// Internal: the products of the exponentials and of the sandwich (PointMapCore.h), built at
// compile time: B ^ B, Q Q, Q _| B; K X (even times vector into odd) and <(K X) ~K>_1; K e_j (the
// terms of K X for X = e_j, whose one operand slot holds its coefficient). applyProduct<kWedge>
// and the others evaluate them as straight-line code (SparseProduct.h).
//
// Internal linkage only (constexpr objects in an unnamed namespace): see ProductTerms.h.
#pragma once

#include "CompactLayout.h"
#include "SparseProduct.h"

namespace cga
{
namespace detail
{
namespace
{
constexpr SparseProduct kWedge{ Bivector::kBlades, Bivector::kBlades, Quadvector::kBlades };
constexpr SparseProduct kQuadvectorSquare{ Quadvector::kBlades, Quadvector::kBlades, kScalarBlade };
constexpr SparseProduct kRightContraction{ Quadvector::kBlades, Bivector::kBlades, Bivector::kBlades };
constexpr SparseProduct kEvenTimesVector{ kEvenBlades, ConformalVector::kBlades, kOddBlades };
constexpr SparseProduct kOddTimesEvenToVector{ kOddBlades, kEvenBlades, ConformalVector::kBlades };
// K e_j for each basis vector e_j (ConformalVector order): the terms of K X that e_j contributes.
template <int J>
constexpr SparseProduct kEvenTimesBasis{ kEvenBlades,
                                         std::array<unsigned, 1>{ ConformalVector::kBlades[J] },
                                         kOddBlades };
} // namespace
} // namespace detail
} // namespace cga
