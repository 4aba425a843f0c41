#include "vtkPointPairFieldAlgorithm.h"

#include "vtkBoostedGeneratorPort.h"
#include "vtkBoostedGeneratorRows.h"
#include "vtkBoostedRowList.h"
#include "vtkInformationVector.h"
#include "vtkPointSet.h"
#include "vtkStructuredData.h"
#include "vtkStructuredGrid.h"

#include <cmath>
#include <string>

vtkPointPairFieldAlgorithm::vtkPointPairFieldAlgorithm(int generatorsPort)
  : Generators(new vtkBoostedRowList(this, "Generator", vtkBoostedGeneratorRows::BlankRow()))
  , GeneratorsPort(generatorsPort)
{
  static_assert(vtkBoostedGeneratorKinds<vtkPointPairFieldAlgorithm>(), "");
  this->SetGeneratorDirectionArrayName("Direction");
  this->SetGeneratorWeightArrayName("Weight");
  this->SetGeneratorKindArrayName("Kind");
  this->SetGeneratorPitchArrayName("Pitch");
}

vtkPointPairFieldAlgorithm::~vtkPointPairFieldAlgorithm()
{
  this->SetGeneratorDirectionArrayName(nullptr);
  this->SetGeneratorWeightArrayName(nullptr);
  this->SetGeneratorKindArrayName(nullptr);
  this->SetGeneratorPitchArrayName(nullptr);
}

vtkBoostedGeneratorRowMethods(vtkPointPairFieldAlgorithm, Generators)

void vtkPointPairFieldAlgorithm::SetGeneratorsConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(this->GeneratorsPort, output);
}

void vtkPointPairFieldAlgorithm::SetGeneratorsData(vtkDataObject* data)
{
  this->SetInputData(this->GeneratorsPort, data);
}

bool vtkPointPairFieldAlgorithm::CheckMeshStructure(vtkDataSet* mesh, const char* name)
{
  vtkStructuredGrid* grid = vtkStructuredGrid::SafeDownCast(mesh);
  if (!grid)
  {
    return true;
  }
  int extent[6];
  grid->GetExtent(extent);
  const vtkIdType expected = vtkStructuredData::GetDataDescriptionFromExtent(extent) == VTK_EMPTY
    ? 0
    : vtkStructuredData::GetNumberOfPoints(extent);
  if (expected != grid->GetNumberOfPoints())
  {
    vtkErrorMacro(<< name << " is a vtkStructuredGrid of extent [" << extent[0] << ", "
                  << extent[1] << ", " << extent[2] << ", " << extent[3] << ", " << extent[4]
                  << ", " << extent[5] << "], which counts " << expected << " points, but it has "
                  << grid->GetNumberOfPoints());
    return false;
  }
  return true;
}

bool vtkPointPairFieldAlgorithm::CheckFieldParameters()
{
  if (!std::isfinite(this->Strength) || std::isnan(this->Falloff) || std::isnan(this->Epsilon))
  {
    vtkErrorMacro(<< "Strength must be finite and Falloff and Epsilon numbers; they are "
                  << this->Strength << ", " << this->Falloff << " and " << this->Epsilon);
    return false;
  }
  return true;
}

bool vtkPointPairFieldAlgorithm::ReadGenerators(
  vtkInformationVector** inputVector, std::vector<cga::GeneratorParameters>& generators)
{
  if (!this->Generators->CheckForUpdate())
  {
    return false;
  }
  generators.assign(this->GetNumberOfGenerators(), cga::GeneratorParameters{});
  std::string problem;
  const vtkBoostedGeneratorRows::Selection selection{ this->SelectedGenerator,
    this->SelectedGeneratorLocation, this->AimSelectedGenerator, this->SelectedGeneratorTip };
  for (int i = 0; i < this->GetNumberOfGenerators(); ++i)
  {
    double used[vtkBoostedGeneratorRows::NumberOfValues];
    const double* row =
      vtkBoostedGeneratorRows::Selected(this->Generators->Row(i), i, selection, used);
    if (!vtkBoostedGeneratorRows::Read(row, row, i, generators[i], problem))
    {
      vtkErrorMacro(<< problem);
      return false;
    }
  }
  vtkPointSet* generatorSet = vtkPointSet::GetData(inputVector[this->GeneratorsPort]);
  if (!generatorSet)
  {
    return true;
  }
  const vtkBoostedGeneratorPort::ArrayNames names{ this->GeneratorDirectionArrayName,
    this->GeneratorWeightArrayName, this->UseGeneratorWeightArray, this->GeneratorKindArrayName,
    this->GeneratorPitchArrayName };
  if (!vtkBoostedGeneratorPort::Read(generatorSet, names, generators, problem))
  {
    vtkErrorMacro(<< problem);
    return false;
  }
  return true;
}

void vtkPointPairFieldAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->Generators->Print(os, indent);
  vtkBoostedGeneratorRows::PrintSelection(os, indent,
    { this->SelectedGenerator, this->SelectedGeneratorLocation, this->AimSelectedGenerator,
      this->SelectedGeneratorTip });
  const auto name = [](const char* s) { return s ? s : "(none)"; };
  os << indent << "GeneratorDirectionArrayName: " << name(this->GeneratorDirectionArrayName)
     << "\n";
  os << indent << "GeneratorWeightArrayName: " << name(this->GeneratorWeightArrayName) << "\n";
  os << indent << "GeneratorKindArrayName: " << name(this->GeneratorKindArrayName) << "\n";
  os << indent << "GeneratorPitchArrayName: " << name(this->GeneratorPitchArrayName) << "\n";
  os << indent << "UseGeneratorWeightArray: " << this->UseGeneratorWeightArray << "\n";
  os << indent << "Strength: " << this->Strength << "\n";
  os << indent << "Falloff: " << this->Falloff << "\n";
  os << indent << "Epsilon: " << this->Epsilon << "\n";
  os << indent << "ExponentialRule: " << (this->ExponentialRule == PAPER ? "PAPER" : "EXACT")
     << "\n";
  os << indent << "OutputPointsPrecision: " << this->OutputPointsPrecision << "\n";
}
