// The one reader of a "Generators" input port (vtkPointPairDeformationFilter,
// vtkPointPairFitFilter): any vtkPointSet whose points are the generators' locations, with a
// 3-component point array of directions, optionally a 1-component array of weights (otherwise
// every weight is 1) and optional 1-component arrays of kinds and pitches (absent: every generator
// there is a POINT_PAIR of pitch 0). The format of every class's "Generators" output port
// (vtkBoostedGeneratorGlyphs), so one class's output feeds another's input.
#ifndef vtkBoostedGeneratorPort_h
#define vtkBoostedGeneratorPort_h

#include "BoostedSurfacesCommonModule.h" // for export macro
#include "cga/PointPairField.h"

#include <string>
#include <vector>

class vtkPointSet;

namespace vtkBoostedGeneratorPort
{
/// The names of the port's arrays (the class's Generator*ArrayName properties); UseWeights: read
/// the weight array (UseGeneratorWeightArray), otherwise every weight is 1.
struct ArrayNames
{
  const char* Direction;
  const char* Weight;
  bool UseWeights;
  const char* Kind;
  const char* Pitch;
};

/// Appends the generators of `generators` to `out`; false with `problem` set (naming the array
/// and the property) when an array is missing, of the wrong type or components, has another
/// number of tuples than the port's points, or a kind is none of the five.
BOOSTEDSURFACESCOMMON_EXPORT bool Read(vtkPointSet* generators, const ArrayNames& names,
  std::vector<cga::GeneratorParameters>& out, std::string& problem);
} // namespace vtkBoostedGeneratorPort

#endif
