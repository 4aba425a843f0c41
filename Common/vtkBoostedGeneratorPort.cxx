#include "vtkBoostedGeneratorPort.h"

#include "vtkBoostedGeneratorRows.h"
#include "vtkDataArray.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"

namespace
{
// One tuple per generator point: a shorter array would be read past its end, a longer one is a
// mistake of the same kind.
bool hasOneTuplePerPoint(vtkDataArray* array, vtkIdType points, std::string& problem)
{
  if (array->GetNumberOfTuples() == points)
  {
    return true;
  }
  problem = std::string("the Generators point array '") + array->GetName() + "' has " +
    std::to_string(array->GetNumberOfTuples()) + " tuples for " + std::to_string(points) +
    " points; it needs one per point";
  return false;
}

// The optional 1-component array `name` of the Generators input: null when there is none (or no
// name); false with `problem` set when it has the wrong type, components or length.
bool optionalPortArray(vtkPointData* pointData, const char* name, const char* what,
  vtkIdType points, vtkDataArray*& array, std::string& problem)
{
  array = nullptr;
  vtkAbstractArray* found = name && *name ? pointData->GetAbstractArray(name) : nullptr;
  if (!found)
  {
    return true;
  }
  array = vtkDataArray::SafeDownCast(found);
  if (!array || array->GetNumberOfComponents() != 1)
  {
    problem = std::string("the Generators point array '") + name +
      "' must be a numeric array of 1 component (" + what + "), it is a " +
      found->GetClassName() + " of " + std::to_string(found->GetNumberOfComponents()) +
      " components";
    return false;
  }
  return hasOneTuplePerPoint(array, points, problem);
}

} // namespace

namespace vtkBoostedGeneratorPort
{
bool Read(vtkPointSet* generators, const ArrayNames& names,
  std::vector<cga::GeneratorParameters>& out, std::string& problem)
{
  const vtkIdType count = generators->GetNumberOfPoints();
  if (count == 0)
  {
    return true;
  }
  vtkPointData* pointData = generators->GetPointData();
  const std::string direction = names.Direction ? names.Direction : "";
  vtkAbstractArray* directionArray = pointData->GetAbstractArray(direction.c_str());
  if (direction.empty() || !directionArray)
  {
    problem = "the Generators input has no point array named '" + direction +
      "' (GeneratorDirectionArrayName)";
    return false;
  }
  vtkDataArray* directions = vtkDataArray::SafeDownCast(directionArray);
  if (!directions || directions->GetNumberOfComponents() != 3)
  {
    problem = "the Generators point array '" + direction +
      "' must be a numeric array of 3 components (directions), it is a " +
      directionArray->GetClassName() + " of " +
      std::to_string(directionArray->GetNumberOfComponents()) + " components";
    return false;
  }
  if (!hasOneTuplePerPoint(directions, count, problem))
  {
    return false;
  }
  vtkDataArray* weights = nullptr;
  if (names.UseWeights)
  {
    const std::string weight = names.Weight ? names.Weight : "";
    vtkAbstractArray* weightArray = pointData->GetAbstractArray(weight.c_str());
    if (weight.empty() || !weightArray)
    {
      problem = "the Generators input has no point array named '" + weight +
        "' (GeneratorWeightArrayName; turn UseGeneratorWeightArray off for unit weights)";
      return false;
    }
    weights = vtkDataArray::SafeDownCast(weightArray);
    if (!weights || weights->GetNumberOfComponents() != 1)
    {
      problem = "the Generators point array '" + weight +
        "' must be a numeric array of 1 component (weights), it is a " +
        weightArray->GetClassName() + " of " +
        std::to_string(weightArray->GetNumberOfComponents()) + " components";
      return false;
    }
    if (!hasOneTuplePerPoint(weights, count, problem))
    {
      return false;
    }
  }
  vtkDataArray* kinds = nullptr;
  vtkDataArray* pitches = nullptr;
  if (!optionalPortArray(pointData, names.Kind, "kinds", count, kinds, problem) ||
    !optionalPortArray(pointData, names.Pitch, "pitches", count, pitches, problem))
  {
    return false;
  }
  out.reserve(out.size() + static_cast<std::size_t>(count));
  for (vtkIdType i = 0; i < count; ++i)
  {
    cga::GeneratorParameters g;
    if (kinds &&
      !vtkBoostedGeneratorRows::ReadKind(kinds->GetComponent(i, 0),
        "the Generators point " + std::to_string(i) + " ('" + names.Kind + "')", g.kind, problem))
    {
      return false;
    }
    double x[3], v[3];
    generators->GetPoint(i, x);
    directions->GetTuple(i, v);
    g.location = { x[0], x[1], x[2] };
    g.direction = { v[0], v[1], v[2] };
    g.weight = weights ? weights->GetComponent(i, 0) : 1.0;
    g.pitch = pitches ? pitches->GetComponent(i, 0) : 0.0;
    out.push_back(g);
  }
  return true;
}
} // namespace vtkBoostedGeneratorPort
