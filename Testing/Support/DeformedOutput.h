// What the deformation filter's GoogleTests read back from an output: a point as a cga::Vec3,
// and the bytes of the points and of Displacement (for bit-for-bit comparisons).
#ifndef DeformedOutput_h
#define DeformedOutput_h

#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"

#include "cga/Vec3.h"

#include <string>

inline cga::Vec3 pointOf(vtkPointSet* data, vtkIdType i)
{
  double p[3];
  data->GetPoint(i, p);
  return { p[0], p[1], p[2] };
}

/// The output's point type, then the bytes of its points and of its "Displacement" array.
inline std::string outputBytes(vtkPointSet* output)
{
  std::string bytes = std::to_string(output->GetPoints()->GetDataType()) + ":";
  for (vtkDataArray* array :
    { output->GetPoints()->GetData(), output->GetPointData()->GetArray("Displacement") })
  {
    const auto* begin = static_cast<const char*>(array->GetVoidPointer(0));
    bytes.append(begin, begin + array->GetDataSize() * array->GetDataTypeSize());
  }
  return bytes;
}

#endif
