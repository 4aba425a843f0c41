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

bool accurateTangentsInFieldFrame(int n, const double* b, const double* bTangents, const double* p,
  const double* pTangents, double* imageTangents)
{
  using Number = Dual<DoubleDouble, kExtendedTangentCount>;
  const auto number = [n](double value, const double* tangents) {
    Number x = constant<DoubleDouble, kExtendedTangentCount>(DoubleDouble(value));
    for (int k = 0; k < n; ++k)
    {
      x.d[k] = DoubleDouble(tangents[k]);
    }
    return x;
  };
  Number bivector[kBivector], point[3], result[3];
  for (int c = 0; c < kBivector; ++c)
  {
    bivector[c] = number(b[c], bTangents + n * c);
  }
  for (int i = 0; i < 3; ++i)
  {
    point[i] = number(p[i], pTangents + n * i);
  }
  bool finite = exactImageInFieldFrame(bivector, point, result);
  for (int i = 0; i < 3; ++i)
  {
    for (int k = 0; k < n; ++k)
    {
      imageTangents[n * i + k] = result[i].d[k].hi;
      finite = finite && __builtin_isfinite(imageTangents[n * i + k]);
    }
  }
  return finite;
}
} // namespace core
} // namespace cga
