#include "cga/PointSandwich.h"

#include "cga/CompactAlgebra.h"

#include "CompactLayout.h"
#include "ConformalLanes.h"
#include "LaneClones.h"
#include "PointMapCore.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace cga
{
ConformalVector sandwichGrade1(const Even& k, const ConformalVector& x)
{
  const detail::EvenArray kk = detail::pack(k);
  ConformalVector r;
  core::sandwichEven(kk.data(), x.c.data(), r.c.data());
  return r;
}

bool normalizePoint(const ConformalVector& p, Vec3& out)
{
  const double origin[3] = { 0.0, 0.0, 0.0 };
  double image[3];
  bool mapped = false;
  core::normalize(origin, p.c.data(), image, &mapped);
  if (mapped)
  {
    out = { image[0], image[1], image[2] };
  }
  return mapped;
}

bool sandwichPoint(const Even& k, Vec3 p, Vec3& out)
{
  return normalizePoint(sandwichGrade1(k, ConformalVector::point(p)), out);
}

namespace
{
// PointMaps' layout: the maps in groups of kLanes, entry e of lane l of group g at
// [kGroupEntries g + kLanes e + l].
constexpr std::size_t kLanes = sizeof(detail::Eight) / sizeof(double);
constexpr std::size_t kEntries = ConformalVector::Count * ConformalVector::Count;
constexpr std::size_t kGroupEntries = kEntries * kLanes;

std::size_t groups(std::size_t count)
{
  return (count + kLanes - 1) / kLanes;
}

// Where entry e of map i is.
std::size_t entryIndex(std::size_t i, std::size_t e)
{
  return kGroupEntries * (i / kLanes) + kLanes * e + i % kLanes;
}

// Column j of eight maps (images[i]: entry i of each lane's), stored as entries (i, j) (PointMaps'
// layout: entry e of lane l at [kLanes e + l]); allFinite cleared on the lanes with an entry that
// is not finite.
BOOSTED_FORCE_INLINE void storeColumn(
  int j, const detail::Eight* images, double* entries, detail::EightMask& allFinite)
{
  constexpr int n = ConformalVector::Count;
  for (int i = 0; i < n; ++i)
  {
    std::memcpy(entries + kLanes * (i * n + j), &images[i], sizeof images[i]);
    allFinite &= detail::finiteLanes(images[i]);
  }
}

// Column J: each lane's <K e_J ~K>_1 (core::sandwichBasisInlined).
template <int J>
BOOSTED_FORCE_INLINE void storeBasisImage(const detail::Eight* lanes, const detail::Eight* reversed,
  double* entries, detail::EightMask& allFinite)
{
  detail::Eight images[ConformalVector::Count];
  core::sandwichBasisInlined<J>(lanes, reversed, images);
  storeColumn(J, images, entries, allFinite);
}

// Each lane's versor's sandwich of basis vector j (lane l: versors[min(l, count - 1)]), in
// sandwichGrade1's bits, stored as entries (i, j) of eight maps side by side; finite[l] whether
// all of lane l's are finite (l < min(count, kLanes)).
BOOSTED_LANE_CLONES
void groupImages(const Even* versors, std::size_t count, double* entries, char* finite)
{
  using detail::Eight;
  constexpr int n = ConformalVector::Count;
  Eight lanes[Even::kCount];
  for (std::size_t l = 0; l < kLanes; ++l)
  {
    const detail::EvenArray packed = detail::pack(versors[std::min<std::size_t>(l, count - 1)]);
    for (std::size_t s = 0; s < packed.size(); ++s)
    {
      lanes[s][l] = packed[s];
    }
  }
  detail::EightMask allFinite = Eight{} == Eight{};
  detail::EightMask finiteVersors = allFinite;
  for (const Eight& component : lanes)
  {
    finiteVersors &= detail::finiteLanes(component);
  }
  bool versorsFinite = true;
  for (std::size_t l = 0; l < kLanes; ++l)
  {
    versorsFinite = versorsFinite && finiteVersors[l] != 0;
  }
  if (versorsFinite)
  {
    // Only the terms of each basis vector's one non-zero component: 480 terms per map instead of
    // 800, the same bits (core::sandwichBasisInlined).
    Eight reversed[Even::kCount];
    core::reverseEven(lanes, reversed);
    storeBasisImage<ConformalVector::NO>(lanes, reversed, entries, allFinite);
    storeBasisImage<ConformalVector::E1>(lanes, reversed, entries, allFinite);
    storeBasisImage<ConformalVector::E2>(lanes, reversed, entries, allFinite);
    storeBasisImage<ConformalVector::E3>(lanes, reversed, entries, allFinite);
    storeBasisImage<ConformalVector::NI>(lanes, reversed, entries, allFinite);
  }
  else
  {
    // The whole product with the basis vectors' zeros, whose products with inf or NaN give
    // sandwichGrade1's NaN.
    for (int j = 0; j < n; ++j)
    {
      Eight basis[n];
      for (int i = 0; i < n; ++i)
      {
        const double v = i == j ? 1.0 : 0.0;
        basis[i] = Eight{ v, v, v, v, v, v, v, v };
      }
      Eight images[n];
      core::sandwichEvenInlined(lanes, basis, images);
      storeColumn(j, images, entries, allFinite);
    }
  }
  for (std::size_t l = 0; l < std::min(count, kLanes); ++l)
  {
    finite[l] = allFinite[l] != 0;
  }
}
} // namespace

PointMap::PointMap(const Even& k)
{
  // One versor in every lane: lane 0 holds its map.
  double entries[kGroupEntries];
  char finite[1];
  groupImages(&k, 1, entries, finite);
  for (std::size_t e = 0; e < kEntries; ++e)
  {
    this->Matrix[e] = entries[entryIndex(0, e)];
  }
}

ConformalVector applyMatrix(const std::array<double, 25>& matrix, const ConformalVector& x)
{
  ConformalVector r;
  for (int i = 0; i < ConformalVector::Count; ++i)
  {
    double s = 0.0;
    for (int j = 0; j < ConformalVector::Count; ++j)
    {
      s += matrix[i * ConformalVector::Count + j] * x[j];
    }
    r[i] = s;
  }
  return r;
}

ConformalVector PointMap::apply(const ConformalVector& x) const
{
  return applyMatrix(this->Matrix, x);
}

PointMaps::PointMaps(const PointMap* maps, std::size_t count)
  : Count(count)
  , Entries(kGroupEntries * groups(count))
  , Finite(count)
{
  for (std::size_t i = 0; i < count; ++i)
  {
    const std::array<double, 25>& m = maps[i].matrix();
    this->Finite[i] = std::all_of(m.begin(), m.end(), [](double v) { return std::isfinite(v); });
  }
  // A partial group repeats its last map.
  for (std::size_t i = 0; i < kLanes * groups(count); ++i)
  {
    const std::array<double, 25>& m = maps[std::min(i, count - 1)].matrix();
    for (std::size_t e = 0; e < kEntries; ++e)
    {
      this->Entries[entryIndex(i, e)] = m[e];
    }
  }
}

PointMaps::PointMaps(const Even* versors, std::size_t count)
  : Count(count)
  , Entries(kGroupEntries * groups(count))
  , Finite(count)
{
  for (std::size_t first = 0; first < count; first += kLanes)
  {
    groupImages(versors + first, count - first, this->Entries.data() + entryIndex(first, 0),
      this->Finite.data() + first);
  }
}

PointMap PointMaps::map(std::size_t i) const
{
  PointMap m;
  for (std::size_t e = 0; e < kEntries; ++e)
  {
    m.Matrix[e] = this->Entries[entryIndex(i, e)];
  }
  return m;
}

// PointMap::apply(p, out)'s operations in its order, on eight maps at a time (ConformalLanes.h).
BOOSTED_LANE_CLONES
void PointMaps::apply(Vec3 p, Vec3* out, bool* mapped) const
{
  using detail::Eight;
  const ConformalVector x = ConformalVector::point(p);
  for (std::size_t first = 0; first < this->Count; first += kLanes)
  {
    const double* entries = this->Entries.data() + entryIndex(first, 0);
    auto entry = [entries](int i, int j) {
      Eight m;
      std::memcpy(&m, entries + kLanes * (i * ConformalVector::Count + j), sizeof m);
      return m;
    };
    Eight r[ConformalVector::Count];
    detail::conformalProduct(entry, x.c.data(), r);
    Eight image[3];
    const auto ok = detail::normalizedLanes(r, image);
    const int lanes = static_cast<int>(std::min(kLanes, this->Count - first));
    for (int l = 0; l < lanes; ++l)
    {
      const std::size_t i = first + static_cast<std::size_t>(l);
      mapped[i] = ok[l] != 0;
      if (mapped[i])
      {
        out[i] = { image[0][l], image[1][l], image[2][l] };
      }
    }
  }
}

std::array<double, 25> commutatorMatrix(const Bivector& b)
{
  // B X - X B = -2 X.B, and X.(a^b) = (X.a) b - (X.b) a. The two vectors (a, b) of each bivector
  // component, in ConformalVector order (no, e1, e2, e3, ni), and the null basis metric:
  // e_i.e_i = 1, no.ni = -1, no.no = ni.ni = 0.
  constexpr int NO = ConformalVector::NO, NI = ConformalVector::NI;
  constexpr int E1 = ConformalVector::E1, E2 = ConformalVector::E2, E3 = ConformalVector::E3;
  constexpr int pairs[Bivector::Count][2] = { { E1, E2 }, { E1, E3 }, { E2, E3 }, { E1, NO },
    { E2, NO }, { E3, NO }, { E1, NI }, { E2, NI }, { E3, NI }, { NO, NI } };
  auto metric = [](int i, int j) -> double {
    if (i == j)
    {
      return (i == NO || i == NI) ? 0.0 : 1.0;
    }
    return ((i == NO && j == NI) || (i == NI && j == NO)) ? -1.0 : 0.0;
  };
  std::array<double, 25> matrix{};
  constexpr int n = ConformalVector::Count;
  for (int k = 0; k < n; ++k) // the image of basis vector k is column k
  {
    for (int p = 0; p < Bivector::Count; ++p)
    {
      const int a = pairs[p][0], c = pairs[p][1];
      matrix[c * n + k] -= 2.0 * b[p] * metric(k, a);
      matrix[a * n + k] += 2.0 * b[p] * metric(k, c);
    }
  }
  return matrix;
}

bool PointMap::apply(Vec3 p, Vec3& out) const
{
  return normalizePoint(this->apply(ConformalVector::point(p)), out);
}
} // namespace cga
