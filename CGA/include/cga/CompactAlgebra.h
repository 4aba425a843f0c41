// Products of the compact types (Compact.h), computed term by term in the null basis.
#pragma once

#include "cga/Compact.h"

namespace cga
{
/// Reverse ~K: the bivector changes sign, the scalar and the 4-vector do not.
Even reverse(const Even& k);

/// Geometric product of even elements (an even element again).
Even operator*(const Even& a, const Even& b);

/// Geometric product of two bivectors: <a b>_0 + <a b>_2 + <a b>_4.
Even operator*(const Bivector& a, const Bivector& b);

/// <B B>_0 = -(c12^2 + c13^2 + c23^2) + 2 a.b + d^2: the paper's s of eq 9-10 (no reverse).
double scalarSquare(const Bivector& b);

/// Q Q, a scalar: in five dimensions a 4-vector is the dual of a vector.
double scalarSquare(const Quadvector& q);

/// a ^ b (= <a b>_4).
Quadvector wedge(const Bivector& a, const Bivector& b);

/// Q _| b from the right, i.e. the grade-2 part <Q b>_2.
Bivector rightContraction(const Quadvector& q, const Bivector& b);

/// Inner product of conformal vectors: x.y - a_p b_q - b_p a_q for p = a_p no + x + b_p ni.
double dot(const ConformalVector& p, const ConformalVector& q);
} // namespace cga
