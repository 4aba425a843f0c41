// The one builder of the classes' "Generators" output port (vtkPointPairDeformationFilter,
// vtkPointPairFitFilter, vtkDipoleFieldSource, vtkCurvaturePatchSource, vtkHopfFibrationSource,
// vtkConformalOrbitSource), each writing it through its own cache (Write(output, cache)): a
// vtkPolyData of one vertex per generator, control point, corner or base point, at its location,
// with the point arrays a glyph filter (vtkGlyph3D, vtkGlyph3DMapper, ParaView's 3D Glyphs
// representation) reads: "Direction" (3 components, as given: its length is part of the generator;
// the active vectors) and "Weight" (the active scalars), and where the class has them "Kind" (int,
// cga::GeneratorKind's values), "Pitch", "Curvature" (2 components: kappa_u, kappa_v) and
// "KindIdentified" (int, 1 or 0: the fit filter's search told the kind apart). A generator with a
// non-finite value is left out (the classes that accept one ignore it too), so the port holds
// finite values only.
#ifndef vtkBoostedGeneratorGlyphs_h
#define vtkBoostedGeneratorGlyphs_h

#include "BoostedSurfacesCommonModule.h" // for export macro
#include "cga/PointPairField.h"
#include "vtkSmartPointer.h" // for the cache

#include <vector>

class vtkInformation;
class vtkInformationVector;
class vtkPolyData;

class BOOSTEDSURFACESCOMMON_EXPORT vtkBoostedGeneratorGlyphs
{
public:
  /// The optional arrays, or-ed: Kind and Pitch (generator rows), Curvature (control points),
  /// KindIdentified (the fit filter's FitKinds).
  enum Columns
  {
    NoColumns = 0,
    KindAndPitch = 1,
    Curvature = 2,
    KindIdentified = 4
  };
  explicit vtkBoostedGeneratorGlyphs(int columns)
    : Columns(columns)
  {
  }

  /// One point; kind, pitch, the curvatures and identified are written only when the columns
  /// have them.
  void Add(const cga::Vec3& location, const cga::Vec3& direction, double weight,
    int kind = 0, double pitch = 0.0, double kappaU = 0.0, double kappaV = 0.0,
    bool identified = false);
  /// A generator row as the core reads it (location, direction, weight, kind, pitch), and
  /// whether its kind was identified.
  void Add(const cga::GeneratorParameters& generator, bool identified = false);
  /// Each of `generators`.
  void Add(const std::vector<cga::GeneratorParameters>& generators);

  /// Replaces `output` by the points added so far (double points, one vertex each).
  void Write(vtkPolyData* output) const;
  /// The same through `cache`, the polydata of the last such Write (null at first): written
  /// anew only when it does not hold these points and columns, bit for bit; `output` then shares
  /// its arrays (ShallowCopy). An update whose generators did not change writes nothing
  /// (building the arrays cost about a sixth of the deformation filter's serial instructions per
  /// update, README Performance, Threads).
  void Write(vtkPolyData* output, vtkSmartPointer<vtkPolyData>& cache) const;

  /// The information of a "Generators" output port: vtkPolyData.
  static void FillOutputPortInformation(vtkInformation* info);
  /// True when every output port of this update asks for piece 0: the generators come once
  /// under MPI (a consumer of any port on another rank asks for its own piece).
  static bool OnFirstPiece(vtkInformationVector* outputVector);

private:
  /// True when `data` holds exactly what Write would write.
  bool IsWrittenIn(vtkPolyData* data) const;

  struct Point
  {
    cga::Vec3 location, direction;
    double weight, pitch, kappaU, kappaV;
    int kind, identified;
  };
  int Columns;
  std::vector<Point> Points;
};

#endif
