#include "vtkBoostedGeneratorRows.h"

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
} // namespace vtkBoostedGeneratorRows
