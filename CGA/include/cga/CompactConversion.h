// Exact conversions between the compact null-basis types (Compact.h) and the full orthonormal
// Multivector. Converting to a compact type keeps only the grades the type stores.
#pragma once

#include "cga/Compact.h"
#include "cga/Multivector.h"

namespace cga
{
Multivector toMultivector(const ConformalVector& v);
Multivector toMultivector(const Bivector& b);
Multivector toMultivector(const Quadvector& q);
Multivector toMultivector(const Even& k);

/// Grade-1 part of m.
ConformalVector toConformalVector(const Multivector& m);
/// Grade-2 part of m.
Bivector toBivector(const Multivector& m);
/// Grade-4 part of m.
Quadvector toQuadvector(const Multivector& m);
/// Grades 0, 2 and 4 of m.
Even toEven(const Multivector& m);
} // namespace cga
