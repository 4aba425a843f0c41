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

/// Most tangents accurateTangentsInFieldFrame takes: the Jacobian's three (and the two
/// directional derivatives).
constexpr int kExtendedTangentCount = 3;

/// The tangents of the Exact image of p under exp(b) in the field's frame (PointMapCore.h's
/// exactImageInFieldFrame) computed in double-double, for the derivatives of a lane whose exponent
/// has huge tangents: in double they carry the image's rounding times those tangents
/// (docs/conventions.md section 3 item 15). b: ten components and their n tangents
/// (bTangents[n c + k]), p: three coordinates and their n tangents, n <= kExtendedTangentCount;
/// writes imageTangents[n i + k]. False where it is not mapped or a tangent is not finite.
bool accurateTangentsInFieldFrame(int n, const double* b, const double* bTangents, const double* p,
  const double* pTangents, double* imageTangents);
} // namespace core
} // namespace cga
