#include "AccurateImage.h"

#include "DoubleDouble.h"
#include "PointMapCore.h"

namespace cga
{
namespace core
{
bool accurateImageAroundPoint(const double* b, const double* p, double* image)
{
  DoubleDouble bivector[kBivector], point[3], result[3];
  for (int c = 0; c < kBivector; ++c)
  {
    bivector[c] = DoubleDouble(b[c]);
  }
  for (int i = 0; i < 3; ++i)
  {
    point[i] = DoubleDouble(p[i]);
  }
  const bool mapped = exactImageAroundPoint(point, bivector, result);
  for (int i = 0; i < 3; ++i)
  {
    // hi is the sum rounded to double (the parts are normalized: |lo| <= ulp(hi)/2)
    image[i] = result[i].hi;
  }
  return mapped;
}
} // namespace core
} // namespace cga
