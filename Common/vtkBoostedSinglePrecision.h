// The one rule of single-precision output, in every class that writes floats (points, and the
// dipole field's arrays): a finite value beyond the largest float (FLT_MAX, about 3.4e38) would
// become inf, so it is an error naming the class, with an empty output, instead.
#ifndef vtkBoostedSinglePrecision_h
#define vtkBoostedSinglePrecision_h

#include "vtkBoostedLargeArrays.h" // for the floats' memory
#include "vtkDoubleArray.h"        // for the points as built
#include "vtkFloatArray.h"         // for the points as written
#include "vtkNew.h"
#include "vtkPoints.h"

#include <cfloat>  // for FLT_MAX
#include <cmath>   // for std::fabs
#include <new>     // for std::bad_alloc
#include <sstream> // for the message
#include <string>  // for the problem

/// The largest |value| of the finite ones among `count` values at `values` (0 for none).
template <typename Value, typename Count>
double vtkBoostedLargestFinite(const Value* values, Count count)
{
  double largest = 0.0;
  for (Count i = 0; i < count; ++i)
  {
    const double a = std::fabs(static_cast<double>(values[i]));
    largest = a > largest && std::isfinite(a) ? a : largest;
  }
  return largest;
}

/// The error for single-precision output whose `what` ("the points reach 1e+39,", "the images
/// of 3 points are") are beyond the largest float.
inline std::string vtkBoostedSinglePrecisionProblem(const std::string& what)
{
  std::ostringstream message;
  message << what << " beyond the largest single-precision value (" << FLT_MAX
          << "): set OutputPointsPrecision to Double (DOUBLE_PRECISION); the output is empty";
  return message.str();
}

/// Empty when `largest` (the largest |value| of `name`) fits in a float, otherwise the error.
inline std::string vtkBoostedSinglePrecisionProblem(double largest, const std::string& name)
{
  if (!(largest > FLT_MAX))
  {
    return {};
  }
  std::ostringstream what;
  what << name << " reach " << largest << ",";
  return vtkBoostedSinglePrecisionProblem(what.str());
}

/// The last step of single-precision output built in double: converts `points` to floats, or
/// returns the error (`name` names them; the points are left as they are) when a coordinate is
/// beyond the largest float or the floats cannot be allocated. Points that are not doubles are
/// left as they are.
inline std::string vtkBoostedPointsToSinglePrecision(
  vtkPoints* points, const std::string& name = "the points")
{
  vtkDoubleArray* values = points ? vtkDoubleArray::SafeDownCast(points->GetData()) : nullptr;
  if (!values)
  {
    return {};
  }
  std::string problem = vtkBoostedSinglePrecisionProblem(
    vtkBoostedLargestFinite(values->GetPointer(0), 3 * values->GetNumberOfTuples()), name);
  if (problem.empty())
  {
    // In the project's large arrays (vtkBoostedLargeArrays: huge pages, kept for the next update),
    // not DeepCopy's new memory.
    vtkNew<vtkFloatArray> floats;
    floats->SetName(values->GetName());
    floats->SetNumberOfComponents(3);
    try
    {
      vtkBoostedLargeArrays::SetNumberOfTuples(floats, values->GetNumberOfTuples());
    }
    catch (const std::bad_alloc&)
    {
      return "not enough memory for " + name + " in single precision; the output is empty";
    }
    const double* from = values->GetPointer(0);
    float* to = floats->GetPointer(0);
    for (vtkIdType i = 0; i < 3 * values->GetNumberOfTuples(); ++i)
    {
      to[i] = static_cast<float>(from[i]);
    }
    points->SetData(floats);
  }
  return problem;
}

#endif
