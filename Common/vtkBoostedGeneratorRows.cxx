#include "vtkBoostedGeneratorRows.h"

#include <algorithm>
#include <cmath>

namespace vtkBoostedGeneratorRows
{
std::vector<double> BlankRow()
{
  return std::vector<double>(NumberOfValues, 0.0);
}

std::string KindList()
{
  return "0 (POINT_PAIR), 1 (ROTATION), 2 (TWIST), 3 (DILATION), 4 (TRANSLATION)";
}

bool ReadKind(double value, const std::string& what, cga::GeneratorKind& kind, std::string& problem)
{
  if (!(value >= 0.0 && value <= 4.0) || value != std::floor(value) ||
    !cga::isGeneratorKind(static_cast<int>(value)))
  {
    problem = what + " has the kind " + std::to_string(value) + ", which is none of the kinds " +
      KindList();
    return false;
  }
  kind = static_cast<cga::GeneratorKind>(static_cast<int>(value));
  return true;
}

bool Read(const double* row, const double location[3], int index, cga::GeneratorParameters& out,
  std::string& problem)
{
  if (!ReadKind(row[KindValue], "generator row " + std::to_string(index), out.kind, problem))
  {
    return false;
  }
  out.location = { location[0], location[1], location[2] };
  out.direction = { row[3], row[4], row[5] };
  out.weight = row[6];
  out.pitch = row[PitchValue];
  return true;
}

const double* Selected(const double* row, int index, const Selection& selection,
  double used[NumberOfValues])
{
  if (index != selection.Index)
  {
    return row;
  }
  std::copy(row, row + NumberOfValues, used);
  for (int c = 0; c < 3; ++c)
  {
    used[c] = selection.Location[c];
    if (selection.Aim)
    {
      used[3 + c] = selection.Tip[c] - selection.Location[c];
    }
  }
  return used;
}

void PrintSelection(ostream& os, vtkIndent indent, const Selection& selection)
{
  auto vector3 = [&os](const double* v)
  { os << "(" << v[0] << ", " << v[1] << ", " << v[2] << ")\n"; };
  os << indent << "SelectedGenerator: " << selection.Index << "\n";
  os << indent << "SelectedGeneratorLocation: ";
  vector3(selection.Location);
  os << indent << "AimSelectedGenerator: " << selection.Aim << "\n";
  os << indent << "SelectedGeneratorTip: ";
  vector3(selection.Tip);
}
} // namespace vtkBoostedGeneratorRows
