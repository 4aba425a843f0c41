// The one layout of a generator row, shared by vtkPointPairDeformationFilter, vtkPointPairFitFilter,
// vtkDipoleFieldSource and vtkConformalOrbitSource (their lists and ParaView tables, and the row
// their line widget selects): x, y, z, direction x, y, z, weight,
// kind, pitch. A row given without its last two values (the 7-value AddGenerator/SetGenerator,
// old scripts) is a point pair of pitch 0. The kind constants of the VTK classes are
// cga::GeneratorKind's values (checked at compile time by vtkBoostedGeneratorKinds).
#ifndef vtkBoostedGeneratorRows_h
#define vtkBoostedGeneratorRows_h

#include "BoostedSurfacesCommonModule.h" // for export macro
#include "vtkBoostedRowList.h"           // for vtkBoostedRowListMethods
#include "vtkIndent.h"                   // for PrintSelection
#include "cga/PointPairField.h"

#include <string>
#include <vector>

namespace vtkBoostedGeneratorRows
{
constexpr int NumberOfValues = 9;
constexpr int KindValue = 7;
constexpr int PitchValue = 8;

/// The value of a row that SetNumberOfGenerators adds: all zero (a point pair of zero direction,
/// ignored until set).
BOOSTEDSURFACESCOMMON_EXPORT std::vector<double> BlankRow();

/// The kinds as messages and documentation list them: "0 (POINT_PAIR), 1 (ROTATION), ...".
BOOSTEDSURFACESCOMMON_EXPORT std::string KindList();

/// The kind a row's value names; false (with `problem` set) when it is not one of the five
/// integers 0 ... 4. `what` names the value in the message ("row 3", "point 12").
BOOSTEDSURFACESCOMMON_EXPORT bool ReadKind(double value, const std::string& what, cga::GeneratorKind& kind, std::string& problem);

/// Row `row` of a list as the core's generator, at `location` (the row's own or the handle's).
BOOSTEDSURFACESCOMMON_EXPORT bool Read(const double* row, const double location[3], int index, cga::GeneratorParameters& out,
  std::string& problem);

/// The row that ParaView's *Selected Generator* line widget moves (its start) and aims (its end):
/// each class's SelectedGenerator (-1: none), SelectedGeneratorLocation, AimSelectedGenerator
/// and SelectedGeneratorTip.
struct Selection
{
  int Index = -1;
  const double* Location = nullptr;
  bool Aim = false;
  const double* Tip = nullptr;
};

/// Row `index` of a list as used: `row` itself, or, when it is the selected row, a copy in `used`
/// at the selection's location and, when aimed, along Tip - Location (that length multiplies the
/// weight, as a row's direction's). Returns `row` or `used`.
BOOSTEDSURFACESCOMMON_EXPORT const double* Selected(
  const double* row, int index, const Selection& selection, double used[NumberOfValues]);

/// PrintSelf's lines for a class's selection properties.
BOOSTEDSURFACESCOMMON_EXPORT void PrintSelection(
  ostream& os, vtkIndent indent, const Selection& selection);
} // namespace vtkBoostedGeneratorRows

/// Checks at compile time that a VTK class numbers the kinds as cga::GeneratorKind does.
template <class VTKClass>
constexpr bool vtkBoostedGeneratorKinds()
{
  static_assert(VTKClass::POINT_PAIR == static_cast<int>(cga::GeneratorKind::PointPair) &&
      VTKClass::ROTATION == static_cast<int>(cga::GeneratorKind::Rotation) &&
      VTKClass::TWIST == static_cast<int>(cga::GeneratorKind::Twist) &&
      VTKClass::DILATION == static_cast<int>(cga::GeneratorKind::Dilation) &&
      VTKClass::TRANSLATION == static_cast<int>(cga::GeneratorKind::Translation),
    "the class's kind constants must be cga::GeneratorKind's values");
  return true;
}

/// The definitions of a class's generator list methods (declared in its header, where VTK's
/// wrapping sees them): AddGenerator and SetGenerator with 9 values or the 7 of a point pair,
/// and the list API of vtkBoostedRowListMethods, over the vtkBoostedRowList `member`.
#define vtkBoostedGeneratorRowMethods(Class, member)                                              \
  int Class::AddGenerator(                                                                        \
    double x, double y, double z, double vx, double vy, double vz, double weight)                \
  {                                                                                               \
    return this->AddGenerator(x, y, z, vx, vy, vz, weight, POINT_PAIR, 0.0);                      \
  }                                                                                               \
  int Class::AddGenerator(double x, double y, double z, double vx, double vy, double vz,         \
    double weight, double kind, double pitch)                                                     \
  {                                                                                               \
    return this->member->Add({ x, y, z, vx, vy, vz, weight, kind, pitch });                       \
  }                                                                                               \
  void Class::SetGenerator(                                                                       \
    int index, double x, double y, double z, double vx, double vy, double vz, double weight)     \
  {                                                                                               \
    this->SetGenerator(index, x, y, z, vx, vy, vz, weight, POINT_PAIR, 0.0);                      \
  }                                                                                               \
  void Class::SetGenerator(int index, double x, double y, double z, double vx, double vy,        \
    double vz, double weight, double kind, double pitch)                                          \
  {                                                                                               \
    this->member->Set(index, { x, y, z, vx, vy, vz, weight, kind, pitch });                       \
  }                                                                                               \
  vtkBoostedRowListMethods(Class, Generator, member)

#endif
