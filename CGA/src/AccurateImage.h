// Internal: the Exact image of a point around itself computed in double-double (DoubleDouble.h),
// for the lanes of PointMapCore.h's exactImageAroundPoint that double precision cannot map within
// the bound of docs/conventions.md section 2 item 12: a huge, nearly nilpotent B far from the
// point its nilpotent part fixes. Compiled once, for the baseline instruction set: every
// instantiation of the kernel (scalar, AVX2, AVX-512) calls this one function per such lane, so
// their images agree to the bit.
#pragma once

namespace cga
{
namespace core
{
/// The image of p under exp(b) (b: the ten Bivector components, p: three coordinates), computed
/// as exactImageAroundPoint in double-double and rounded to double; false where it is not mapped
/// (as the double computation: a zero or non-finite weight, non-finite input).
bool accurateImageAroundPoint(const double* b, const double* p, double* image);
} // namespace core
} // namespace cga
