/**
 * @class   vtkBoostedRowList
 * @brief   a list of rows of N numbers (generators, control points, base points) behind the one
 *          list API of the sources and filters
 *
 * Every class with a list (vtkPointPairDeformationFilter and vtkDipoleFieldSource: generators of
 * 7 numbers; vtkHopfFibrationSource: base points of 2; vtkCurvaturePatchSource: control points of
 * 11) offers the same methods, each a one-line call of this helper: AddX(...) returns the new
 * row's index, SetX(i, ...) changes row i < GetNumberOfX(), SetNumberOfX(n) resizes (new rows are
 * the class's blank row), GetX(i, values) copies row i (false when i is outside the list),
 * RemoveAllX() and GetNumberOfX(). Errors go to the owner through vtkErrorWithObjectMacro and
 * every change calls the owner's Modified().
 *
 * A list holds at most MaximumRows (10^6) rows, so that a wrong count cannot allocate gigabytes.
 * A request beyond it (SetNumberOfX(n > 10^6), or AddX on a full list) gives one error and marks
 * the list refused: the rows are kept, further SetX/AddX calls are ignored without a message (a
 * ParaView table of 10^6 + 1 rows sets them one by one), and every update that uses the list gives
 * one error and an empty output (CheckForUpdate, Problem), until RemoveAllX() or
 * SetNumberOfX(n <= 10^6).
 */
#ifndef vtkBoostedRowList_h
#define vtkBoostedRowList_h

#include "BoostedSurfacesCommonModule.h" // for export macro
#include "vtkIndent.h"

#include <initializer_list>
#include <ostream>
#include <string>
#include <vector>

class vtkObject;

class BOOSTEDSURFACESCOMMON_EXPORT vtkBoostedRowList
{
public:
  /// The most rows a list holds.
  static constexpr int MaximumRows = 1000000;

  /// rowName: the X of the owner's methods ("Generator"; its plural appends an s); blankRow: the
  /// values SetNumberOfX gives new rows (its length is the number of values per row).
  vtkBoostedRowList(vtkObject* owner, const char* rowName, std::vector<double> blankRow);

  int GetNumberOfValuesPerRow() const { return static_cast<int>(this->BlankRow.size()); }
  int GetNumberOfRows() const
  {
    return static_cast<int>(this->Values.size() / this->BlankRow.size());
  }

  /// The index of the new row, or -1 (the list is full or refused).
  int Add(std::initializer_list<double> row);
  void Set(int index, std::initializer_list<double> row);
  void SetNumberOfRows(int count);
  /// Copies row index to values; false (values untouched) when index is outside the list.
  bool Get(int index, double* values) const;
  void RemoveAll();

  /// Row index (no check): GetNumberOfValuesPerRow() numbers.
  const double* Row(int index) const { return this->Values.data() + this->BlankRow.size() * index; }
  /// Every row's values, row after row.
  const std::vector<double>& GetValues() const { return this->Values; }
  /// The location (the first three numbers) of row index as used: the selected row's location
  /// is selectedLocation (the handle ParaView moves), the others are their own.
  const double* Location(int index, int selected, const double selectedLocation[3]) const
  {
    return index == selected ? selectedLocation : this->Row(index);
  }

  /// Empty when the rows may be used, otherwise why not (the list was refused).
  std::string Problem() const;
  /// True when the rows may be used; false, after one error to the owner (the Problem), when the
  /// list was refused. RequestData then leaves its output empty.
  bool CheckForUpdate() const;

  /// The number of rows and every row, one per line.
  void Print(std::ostream& os, vtkIndent indent) const;

private:
  void Refuse(const std::string& call, long long count);

  vtkObject* Owner;
  std::string RowName;
  std::vector<double> BlankRow;
  std::vector<double> Values;
  long long RefusedCount = -1; // the row count asked for beyond MaximumRows, or -1
};

/// Defines the owner's SetNumberOfXs, GetX, RemoveAllXs and GetNumberOfXs as calls of its
/// vtkBoostedRowList member (AddX and SetX take the class's own argument lists, written out).
#define vtkBoostedRowListMethods(Class, Row, member)                                              \
  void Class::SetNumberOf##Row##s(int count) { this->member->SetNumberOfRows(count); }          \
  bool Class::Get##Row(int index, double* values) const                                         \
  {                                                                                               \
    return this->member->Get(index, values);                                                      \
  }                                                                                               \
  void Class::RemoveAll##Row##s() { this->member->RemoveAll(); }                                  \
  int Class::GetNumberOf##Row##s() const { return this->member->GetNumberOfRows(); }

#endif
