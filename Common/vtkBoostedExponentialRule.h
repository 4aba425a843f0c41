// The one bridge from the ExponentialRule of the VTK classes (their EXACT and PAPER constants,
// wrapped for Python) to cga::ExponentialRule. The VTK headers cannot include the core, so the
// two enumerations are declared apart; the static_asserts make the value-preserving cast safe.
#ifndef vtkBoostedExponentialRule_h
#define vtkBoostedExponentialRule_h

#include "cga/PointPairField.h"

/// cga's rule for the ExponentialRule value of a VTK class (clamped to [EXACT, PAPER] by its
/// setter), checking at compile time that the class numbers the rules as cga does.
template <class VTKClass>
constexpr cga::ExponentialRule vtkBoostedExponentialRule(int rule)
{
  static_assert(VTKClass::EXACT == static_cast<int>(cga::ExponentialRule::Exact) &&
      VTKClass::PAPER == static_cast<int>(cga::ExponentialRule::Paper),
    "the class's EXACT and PAPER must be cga::ExponentialRule's Exact and Paper");
  return static_cast<cga::ExponentialRule>(rule);
}

#endif
