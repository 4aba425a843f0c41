// Internal: how far a versor K may be divided by a power of two before its sandwich <K X ~K>_1
// (the point map's kernel, PointMapCore.h, and the orbits' point maps, Orbit.cpp).
#pragma once

namespace cga
{
namespace core
{
/// The largest h of a division of K by 2^h: the image fn(<K X ~K>_1) does not change (both of its
/// parts scale by 2^-2h), and a component of 1 (the scalar of a nilpotent B's K = 1 + B, or of a
/// translator: at a point pair's location and for a translation the only term of the image's
/// weight) becomes 2^-2h >= 2^-1074, the smallest subnormal, instead of rounding to 0.
constexpr int kLargestSandwichDownscale = 537;
} // namespace core
} // namespace cga
