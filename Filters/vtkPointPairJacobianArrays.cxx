#include "vtkPointPairJacobianArrays.h"

#include "vtkAOSDataArrayTemplate.h"
#include "vtkBoostedLargeArrays.h"
#include "vtkDataArray.h"
#include "vtkDataArraySelection.h"
#include "vtkPointData.h"

#include "vtk_eigen.h"
#include VTK_EIGEN(Dense)

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace
{
// The largest |entry| of a 3x3 matrix or a 3-vector.
template <int N>
double largestEntry(const double* values)
{
  double largest = 0.0;
  for (int i = 0; i < N; ++i)
  {
    largest = std::max(largest, std::fabs(values[i]));
  }
  return largest;
}

// |v| without overflow or underflow on the way.
double length(const double v[3])
{
  const double m = largestEntry<3>(v);
  if (!(m > 0.0))
  {
    return 0.0;
  }
  const double x = v[0] / m, y = v[1] / m, z = v[2] / m;
  return m * std::sqrt(x * x + y * y + z * z);
}

void cross(const double a[3], const double b[3], double out[3])
{
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// J's three columns, each scaled to largest entry 1 (a zero column stays zero, scale 1), and the
// scales: cross products and determinants of the scaled columns neither overflow nor underflow,
// however unlike the columns' sizes are (J = I + v g^T with |g| = 1e304, say).
void columnsScaledApart(const double* jacobian, double columns[3][3], double scales[3])
{
  for (int column = 0; column < 3; ++column)
  {
    const double v[3] = { jacobian[column], jacobian[3 + column], jacobian[6 + column] };
    const double scale = largestEntry<3>(v);
    scales[column] = scale > 0.0 ? scale : 1.0;
    for (int row = 0; row < 3; ++row)
    {
      columns[column][row] = v[row] / scales[column];
    }
  }
}

// J scaled to largest entry 1, as its three columns; the scale is returned (0 for J = 0).
double scaledColumns(const double* jacobian, double columns[3][3])
{
  const double scale = largestEntry<9>(jacobian);
  const double inverse = scale > 0.0 ? 1.0 / scale : 0.0;
  // 1 / scale overflows for a subnormal scale (J about 1e-310 I): then each entry divided by it.
  const bool divide = !std::isfinite(inverse);
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 3; ++column)
    {
      const double entry = jacobian[3 * row + column];
      columns[column][row] = divide ? entry / scale : entry * inverse;
    }
  }
  return scale;
}

// Squared lengths in this range are computed without overflow or underflow, and so is the ratio
// of two of them (at most 1e280 either way; with 1e-280 and 1e280 it overflowed).
constexpr double SafeLow = 1e-140, SafeHigh = 1e140;

// out = image scaled to the length of n, directly, when both squared lengths are in the safe
// range (the common case); false otherwise (then the caller scales apart).
bool withLengthOf(const double image[3], const double n[3], double out[3])
{
  const double n2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
  const double image2 = image[0] * image[0] + image[1] * image[1] + image[2] * image[2];
  if (!(n2 > SafeLow && n2 < SafeHigh && image2 > SafeLow && image2 < SafeHigh))
  {
    return false;
  }
  const double factor = std::sqrt(n2 / image2);
  for (int i = 0; i < 3; ++i)
  {
    out[i] = image[i] * factor;
  }
  return true;
}

// out = image scaled to length `size` through length(), which neither overflows nor underflows;
// false when image is 0 or not finite.
bool withLength(const double image[3], double size, double out[3])
{
  const double imageLength = length(image);
  if (!(imageLength > 0.0) || !std::isfinite(imageLength))
  {
    return false;
  }
  for (int i = 0; i < 3; ++i)
  {
    out[i] = image[i] / imageLength * size;
  }
  return true;
}

// n' = |n| cof(J) n / |cof(J) n|; false when cof(J) n = 0 (n' then untouched).
bool transformNormal(const double* jacobian, const double n[3], double out[3])
{
  // The common case, directly: J's columns and n of moderate size.
  {
    const double* j = jacobian;
    const double c1[3] = { j[0], j[3], j[6] }, c2[3] = { j[1], j[4], j[7] },
                 c3[3] = { j[2], j[5], j[8] };
    double c23[3], c31[3], c12[3];
    cross(c2, c3, c23);
    cross(c3, c1, c31);
    cross(c1, c2, c12);
    double image[3];
    for (int i = 0; i < 3; ++i)
    {
      image[i] = n[0] * c23[i] + n[1] * c31[i] + n[2] * c12[i];
    }
    if (withLengthOf(image, n, out))
    {
      return true;
    }
  }
  // Otherwise with scaled columns, which neither overflow nor underflow.
  const double size = length(n);
  if (size == 0.0)
  {
    out[0] = out[1] = out[2] = 0.0;
    return true;
  }
  // cof(J) e1 = J e2 x J e3 and cyclically, since cof(J)(a x b) = (J a) x (J b). With the
  // columns c_i = s_i c'_i: cof(J) n / (s1 s2 s3) = (n1 / s1) c'2 x c'3 + (n2 / s2) c'3 x c'1 +
  // (n3 / s3) c'1 x c'2, the same direction.
  double c[3][3], scales[3];
  columnsScaledApart(jacobian, c, scales);
  double c23[3], c31[3], c12[3];
  cross(c[1], c[2], c23);
  cross(c[2], c[0], c31);
  cross(c[0], c[1], c12);
  double m[3] = { n[0] / size / scales[0], n[1] / size / scales[1], n[2] / size / scales[2] };
  if (!(largestEntry<3>(m) < 1e307))
  {
    // A column scale below about 1e-307 (J about 1e-310 I: a dilation's strong contraction) would
    // overflow the sum (at most 6 max |m_i|): the same direction, each factor taken relative to
    // the smallest scale.
    const double smallest = std::min({ scales[0], scales[1], scales[2] });
    for (int i = 0; i < 3; ++i)
    {
      m[i] = n[i] / size * (smallest / scales[i]);
    }
  }
  double image[3];
  for (int i = 0; i < 3; ++i)
  {
    image[i] = m[0] * c23[i] + m[1] * c31[i] + m[2] * c12[i];
  }
  return withLength(image, size, out);
}

// Two unit tangents with t1 x t2 = n for a unit n, without a branch on n's direction (Duff et al.,
// "Building an orthonormal basis, revisited", JCGT 6(1), 2017).
void tangentsOf(const double n[3], double t1[3], double t2[3])
{
  const double sign = std::copysign(1.0, n[2]);
  const double a = -1.0 / (sign + n[2]);
  const double b = n[0] * n[1] * a;
  t1[0] = 1.0 + sign * n[0] * n[0] * a;
  t1[1] = sign * b;
  t1[2] = -sign * n[0];
  t2[0] = b;
  t2[1] = sign + n[1] * n[1] * a;
  t2[2] = -n[1];
}

// n' = |n| (a x b) / |a x b| for the images a = J t1, b = J t2 of the tangents of n (tangentsOf):
// the direction of cof(J) n, as transformNormal; false when a x b = 0 (n' then untouched).
bool normalFromTangentImages(const double a[3], const double b[3], const double n[3], double out[3])
{
  double image[3];
  cross(a, b, image);
  if (withLengthOf(image, n, out))
  {
    return true;
  }
  // Otherwise from a and b each scaled to largest entry 1 (the same direction), which neither
  // overflow nor underflow.
  const double size = length(n);
  const double sizeA = largestEntry<3>(a), sizeB = largestEntry<3>(b);
  if (size == 0.0)
  {
    out[0] = out[1] = out[2] = 0.0;
    return true;
  }
  if (!(sizeA > 0.0) || !(sizeB > 0.0))
  {
    return false;
  }
  const double scaledA[3] = { a[0] / sizeA, a[1] / sizeA, a[2] / sizeA };
  const double scaledB[3] = { b[0] / sizeB, b[1] / sizeB, b[2] / sizeB };
  cross(scaledA, scaledB, image);
  return withLength(image, size, out);
}

// v' = J v; false when it is not finite.
bool transformVector(const double* jacobian, const double v[3], double out[3])
{
  for (int i = 0; i < 3; ++i)
  {
    out[i] = jacobian[3 * i] * v[0] + jacobian[3 * i + 1] * v[1] + jacobian[3 * i + 2] * v[2];
  }
  return std::isfinite(out[0]) && std::isfinite(out[1]) && std::isfinite(out[2]);
}

// |det J|^(1/3), without overflow or underflow: det J = s1 s2 s3 det(c'1, c'2, c'3).
double conformalScale(const double* jacobian)
{
  double c[3][3], scales[3];
  columnsScaledApart(jacobian, c, scales);
  double c23[3];
  cross(c[1], c[2], c23);
  const double det = c[0][0] * c23[0] + c[0][1] * c23[1] + c[0][2] * c23[2];
  return std::cbrt(scales[0]) * std::cbrt(scales[1]) * std::cbrt(scales[2]) *
    std::cbrt(std::fabs(det));
}

// 1 - sigma_min / sigma_max from Eigen's two-sided Jacobi SVD (singular values to relative
// rounding, sorted decreasing; 0.7 us a matrix against 3.9 us for vtkMath's
// SingularValueDecomposition3x3, measured), of J scaled to largest entry 1.
double conformalityDefect(const double* jacobian)
{
  double c[3][3];
  if (!(scaledColumns(jacobian, c) > 0.0))
  {
    return 1.0; // J = 0: singular
  }
  Eigen::Matrix3d a;
  for (int row = 0; row < 3; ++row)
  {
    for (int column = 0; column < 3; ++column)
    {
      a(row, column) = c[column][row];
    }
  }
  const Eigen::Vector3d sigma = Eigen::JacobiSVD<Eigen::Matrix3d>(a).singularValues();
  return sigma[0] > 0.0 ? std::min(1.0, std::max(0.0, 1.0 - sigma[2] / sigma[0])) : 1.0;
}

// The output array for `input`: float when it is float, double otherwise, AOS.
vtkSmartPointer<vtkDataArray> outputFor(vtkDataArray* input, vtkIdType count)
{
  auto output = vtk::TakeSmartPointer(
    vtkDataArray::CreateDataArray(input->GetDataType() == VTK_FLOAT ? VTK_FLOAT : VTK_DOUBLE));
  output->SetName(input->GetName());
  output->SetNumberOfComponents(3);
  vtkBoostedLargeArrays::SetNumberOfTuples(output, count);
  return output;
}

vtkSmartPointer<vtkDataArray> scalarArray(const char* name, int type, vtkIdType count)
{
  auto output = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(type));
  output->SetName(name);
  vtkBoostedLargeArrays::SetNumberOfTuples(output, count);
  return output;
}

// Reads tuple i of an input array: in place for float and double AOS arrays (their values found
// once), through vtkDataArray's API for any other.
struct TupleReader
{
  explicit TupleReader(vtkDataArray* array)
    : Array(array)
  {
    if (auto* floats = vtkAOSDataArrayTemplate<float>::FastDownCast(array))
    {
      this->Floats = floats->GetPointer(0);
    }
    else if (auto* doubles = vtkAOSDataArrayTemplate<double>::FastDownCast(array))
    {
      this->Doubles = doubles->GetPointer(0);
    }
  }
  void operator()(vtkIdType i, double v[3]) const
  {
    if (this->Doubles)
    {
      const double* p = this->Doubles + 3 * i;
      v[0] = p[0], v[1] = p[1], v[2] = p[2];
    }
    else if (this->Floats)
    {
      const float* p = this->Floats + 3 * i;
      v[0] = p[0], v[1] = p[1], v[2] = p[2];
    }
    else
    {
      this->Array->GetTuple(i, v);
    }
  }
  vtkDataArray* Array;
  const float* Floats = nullptr;
  const double* Doubles = nullptr;
};

// Writes N values of tuple i of an AOS float or double array (the output arrays: outputFor,
// scalarArray), its values found once.
template <int N>
struct TupleWriter
{
  explicit TupleWriter(vtkDataArray* array)
  {
    if (auto* doubles = vtkAOSDataArrayTemplate<double>::FastDownCast(array))
    {
      this->Doubles = doubles->GetPointer(0);
    }
    else
    {
      this->Floats = vtkAOSDataArrayTemplate<float>::FastDownCast(array)->GetPointer(0);
    }
  }
  void operator()(vtkIdType i, const double* values) const
  {
    if (this->Doubles)
    {
      std::copy(values, values + N, this->Doubles + N * i);
      return;
    }
    for (int c = 0; c < N; ++c)
    {
      this->Floats[N * i + c] = static_cast<float>(values[c]);
    }
  }
  double* Doubles = nullptr;
  float* Floats = nullptr;
};

bool fitsIn(vtkDataArray* array, const double v[3])
{
  if (array->GetDataType() != VTK_FLOAT)
  {
    return true;
  }
  return std::fabs(v[0]) <= FLT_MAX && std::fabs(v[1]) <= FLT_MAX && std::fabs(v[2]) <= FLT_MAX;
}

// The names enabled in a selection (none for a null selection).
std::vector<std::string> enabledNames(vtkDataArraySelection* selection)
{
  std::vector<std::string> names;
  for (int i = 0; selection && i < selection->GetNumberOfArrays(); ++i)
  {
    if (selection->GetArraySetting(i))
    {
      names.emplace_back(selection->GetArrayName(i));
    }
  }
  return names;
}
} // namespace

double vtkPointPairJacobianArrays::BytesPerPoint(
  const Request& request, vtkPointData* input, int scalarBytes)
{
  const double arrays = (request.TransformNormals && input->GetNormals() ? 1.0 : 0.0) +
    static_cast<double>(enabledNames(request.VectorArrays).size() +
      enabledNames(request.NormalArrays).size());
  return arrays * 3 * sizeof(double) +
    ((request.ConformalScale ? 1 : 0) + (request.ConformalityDefect ? 1 : 0)) * scalarBytes;
}

bool vtkPointPairJacobianArrays::Prepare(const Request& request, vtkPointData* input,
  vtkIdType count, int scalarType, std::string& problem, std::string& missing)
{
  this->Arrays.clear();
  this->Scale = this->Defect = nullptr;
  vtkDataArray* activeNormals = input->GetNormals();
  std::vector<std::pair<std::string, bool>> asked; // name, as a normal
  if (request.TransformNormals && activeNormals && activeNormals->GetName())
  {
    asked.emplace_back(activeNormals->GetName(), true);
  }
  for (const bool asNormal : { false, true })
  {
    for (const std::string& name :
      enabledNames(asNormal ? request.NormalArrays : request.VectorArrays))
    {
      const auto same = std::find_if(asked.begin(), asked.end(),
        [&name](const std::pair<std::string, bool>& a) { return a.first == name; });
      if (same == asked.end())
      {
        asked.emplace_back(name, asNormal);
      }
      else if (same->second != asNormal)
      {
        problem = "the point array '" + name + "' is asked to be transformed both as a vector " +
          "(VectorArrays) and as a normal (" +
          (request.TransformNormals && activeNormals && name == activeNormals->GetName()
              ? "the active normals, TransformNormals"
              : "NormalArrays") +
          "); choose one";
        return false;
      }
    }
  }
  // An active normals array without a name cannot be asked for by name: transform it too.
  if (request.TransformNormals && activeNormals && !activeNormals->GetName())
  {
    asked.emplace_back(std::string(), true);
  }
  for (const auto& [name, asNormal] : asked)
  {
    vtkAbstractArray* found = name.empty() ? activeNormals : input->GetAbstractArray(name.c_str());
    if (!found)
    {
      missing += (missing.empty() ? "'" : ", '") + name + "'";
      continue;
    }
    auto* array = vtkDataArray::SafeDownCast(found);
    if (!array || array->GetNumberOfComponents() != 3)
    {
      problem = "the point array '" + name + "' cannot be transformed as " +
        (asNormal ? "a normal" : "a vector") + ": it must be a numeric array of 3 components, " +
        "it is a " + found->GetClassName() + " of " +
        std::to_string(found->GetNumberOfComponents()) + " components";
      return false;
    }
    this->Arrays.push_back(
      { array, outputFor(array, count), asNormal, asNormal && array == activeNormals });
  }
  if (request.ConformalScale)
  {
    this->Scale = scalarArray("ConformalScale", scalarType, count);
  }
  if (request.ConformalityDefect)
  {
    this->Defect = scalarArray("ConformalityDefect", scalarType, count);
  }
  return true;
}

void vtkPointPairJacobianArrays::Write(vtkIdType first, vtkIdType count, const double* jacobians)
{
  vtkIdType nonFinite = 0, collapsed = 0, overflowed = 0, scaleBeyondFloat = 0;
  for (const Transformed& t : this->Arrays)
  {
    const TupleReader read(t.Input);
    const TupleWriter<3> write(t.Output);
    for (vtkIdType i = 0; i < count; ++i)
    {
      double v[3], out[3];
      read(first + i, v);
      const double* jacobian = jacobians + 9 * i;
      bool done = false;
      if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2]))
      {
        ++nonFinite;
      }
      else if (t.AsNormal)
      {
        // n' keeps |n|, which in a float array may exceed the largest float (up to sqrt 3 times).
        done = transformNormal(jacobian, v, out);
        collapsed += done ? 0 : 1;
        if (done && !fitsIn(t.Output, out))
        {
          done = false;
          ++overflowed;
        }
      }
      else
      {
        done = transformVector(jacobian, v, out) && fitsIn(t.Output, out);
        overflowed += done ? 0 : 1;
      }
      write(first + i, done ? out : v);
    }
  }
  if (this->Scale)
  {
    const TupleWriter<1> write(this->Scale);
    const bool isFloat = this->Scale->GetDataType() == VTK_FLOAT;
    for (vtkIdType i = 0; i < count; ++i)
    {
      const double scale = conformalScale(jacobians + 9 * i);
      scaleBeyondFloat += isFloat && scale > FLT_MAX ? 1 : 0;
      write(first + i, &scale);
    }
  }
  if (this->Defect)
  {
    const TupleWriter<1> write(this->Defect);
    for (vtkIdType i = 0; i < count; ++i)
    {
      const double defect = conformalityDefect(jacobians + 9 * i);
      write(first + i, &defect);
    }
  }
  this->NonFinite += nonFinite;
  this->Collapsed += collapsed;
  this->Overflowed += overflowed;
  this->ScaleBeyondFloat += scaleBeyondFloat;
}

void vtkPointPairJacobianArrays::Tangents(vtkIdType first, vtkIdType count, double* tangents) const
{
  const TupleReader read(this->Arrays[0].Input);
  for (vtkIdType i = 0; i < count; ++i)
  {
    double n[3];
    read(first + i, n);
    double* t = tangents + 6 * i;
    const double size = length(n);
    if (!(size > 0.0) || !std::isfinite(size))
    {
      std::fill(t, t + 6, 0.0); // (the normal passes unchanged: WriteNormal)
      continue;
    }
    const double unit[3] = { n[0] / size, n[1] / size, n[2] / size };
    tangentsOf(unit, t, t + 3);
  }
}

void vtkPointPairJacobianArrays::WriteNormal(
  vtkIdType first, vtkIdType count, const double* tangents, const double* tangentImages)
{
  const Transformed& t = this->Arrays[0];
  const TupleReader read(t.Input);
  const TupleWriter<3> write(t.Output);
  vtkIdType nonFinite = 0, collapsed = 0, overflowed = 0;
  for (vtkIdType i = 0; i < count; ++i)
  {
    double n[3], out[3];
    read(first + i, n);
    const double* a = tangentImages + 6 * i;
    const double* b = a + 3;
    bool done = false;
    if (!std::isfinite(n[0]) || !std::isfinite(n[1]) || !std::isfinite(n[2]))
    {
      ++nonFinite;
    }
    else if (!std::equal(a, a + 6, tangents + 6 * i))
    {
      done = normalFromTangentImages(a, b, n, out);
      collapsed += done ? 0 : 1;
      if (done && !fitsIn(t.Output, out))
      {
        done = false;
        ++overflowed;
      }
    }
    // (J fixes both tangents, e.g. J = I where a point is left in place: n' = n exactly, without
    // the rounding of t1 x t2; also for n = 0, whose tangents are 0)
    write(first + i, done ? out : n);
  }
  this->NonFinite += nonFinite;
  this->Collapsed += collapsed;
  this->Overflowed += overflowed;
}

void vtkPointPairJacobianArrays::AddTo(vtkPointData* output) const
{
  for (const Transformed& t : this->Arrays)
  {
    if (t.ActiveNormals)
    {
      output->SetNormals(t.Output);
    }
    else
    {
      output->AddArray(t.Output);
    }
  }
  for (vtkDataArray* array : { this->Scale.Get(), this->Defect.Get() })
  {
    if (array)
    {
      output->AddArray(array);
    }
  }
}
