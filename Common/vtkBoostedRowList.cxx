#include "vtkBoostedRowList.h"

#include "vtkObject.h"
#include "vtkSetGet.h"

#include <algorithm>

vtkBoostedRowList::vtkBoostedRowList(
  vtkObject* owner, const char* rowName, std::vector<double> blankRow)
  : Owner(owner)
  , RowName(rowName)
  , BlankRow(std::move(blankRow))
{
}

void vtkBoostedRowList::Refuse(const std::string& call, long long count)
{
  this->RefusedCount = count;
  vtkErrorWithObjectMacro(this->Owner,
    << call << ": a list holds at most " << MaximumRows << " rows; until RemoveAll"
    << this->RowName << "s() or SetNumberOf" << this->RowName << "s(n <= " << MaximumRows
    << ") every update that uses the list gives an error and an empty output");
  this->Owner->Modified();
}

int vtkBoostedRowList::Add(std::initializer_list<double> row)
{
  if (this->RefusedCount >= 0)
  {
    return -1;
  }
  const int index = this->GetNumberOfRows();
  if (index >= MaximumRows)
  {
    this->Refuse("Add" + this->RowName, index + 1LL);
    return -1;
  }
  this->Values.insert(this->Values.end(), row.begin(), row.end());
  this->Owner->Modified();
  return index;
}

void vtkBoostedRowList::Set(int index, std::initializer_list<double> row)
{
  if (this->RefusedCount >= 0)
  {
    return;
  }
  if (index < 0 || index >= this->GetNumberOfRows())
  {
    vtkErrorWithObjectMacro(this->Owner,
      << "Set" << this->RowName << ": index " << index << " is outside the list of "
      << this->GetNumberOfRows() << " rows (SetNumberOf" << this->RowName
      << "s or Add" << this->RowName << " makes rows)");
    return;
  }
  double* values = this->Values.data() + this->BlankRow.size() * index;
  if (!std::equal(row.begin(), row.end(), values))
  {
    std::copy(row.begin(), row.end(), values);
    this->Owner->Modified();
  }
}

void vtkBoostedRowList::SetNumberOfRows(int count)
{
  if (count > MaximumRows)
  {
    this->Refuse("SetNumberOf" + this->RowName + "s(" + std::to_string(count) + ")", count);
    return;
  }
  const bool wasRefused = this->RefusedCount >= 0;
  this->RefusedCount = -1;
  count = std::max(0, count);
  const int before = this->GetNumberOfRows();
  if (count < before)
  {
    this->Values.resize(this->BlankRow.size() * count);
  }
  for (int i = before; i < count; ++i)
  {
    this->Values.insert(this->Values.end(), this->BlankRow.begin(), this->BlankRow.end());
  }
  if (count != before || wasRefused)
  {
    this->Owner->Modified();
  }
}

bool vtkBoostedRowList::Get(int index, double* values) const
{
  if (index < 0 || index >= this->GetNumberOfRows())
  {
    return false;
  }
  std::copy_n(this->Row(index), this->BlankRow.size(), values);
  return true;
}

void vtkBoostedRowList::RemoveAll()
{
  if (!this->Values.empty() || this->RefusedCount >= 0)
  {
    this->Values.clear();
    this->RefusedCount = -1;
    this->Owner->Modified();
  }
}

std::string vtkBoostedRowList::Problem() const
{
  if (this->RefusedCount < 0)
  {
    return {};
  }
  return "the " + this->RowName + " list was asked to hold " +
    std::to_string(this->RefusedCount) + " rows, more than the " + std::to_string(MaximumRows) +
    " it may hold: the output is empty";
}

bool vtkBoostedRowList::CheckForUpdate() const
{
  const std::string problem = this->Problem();
  if (!problem.empty())
  {
    vtkErrorWithObjectMacro(this->Owner, << problem);
  }
  return problem.empty();
}

void vtkBoostedRowList::Print(std::ostream& os, vtkIndent indent) const
{
  os << indent << this->RowName << "s: " << this->GetNumberOfRows();
  if (this->RefusedCount >= 0)
  {
    os << " (refused: " << this->RefusedCount << " rows were asked for)";
  }
  os << "\n";
  for (int i = 0; i < this->GetNumberOfRows(); ++i)
  {
    os << indent.GetNextIndent() << this->RowName << " " << i << ": (";
    for (int c = 0; c < this->GetNumberOfValuesPerRow(); ++c)
    {
      os << (c ? ", " : "") << this->Row(i)[c];
    }
    os << ")\n";
  }
}
