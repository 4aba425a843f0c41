#!/usr/bin/env bash
# The VTK modules and the Python package build against VTK alone, with ParaView hidden from CMake
# (so no ParaView header or target can sneak into them), and the result imports and runs. GoogleTest
# is hidden too, with BUILD_TESTING left on (its default): the configure must say which tests it
# skips and still build the library and the Python package. (The benchmarks are not built: they
# are not what this test is about, and they would only make it slower.)
# Usage: test_standalone_vtk_build.sh <source dir> <VTK_DIR> <python>
set -euo pipefail
source_dir="$1"
vtk_dir="$2"
python="$3"
build="$(mktemp -d)"
trap 'rm -rf "$build"' EXIT

cmake -S "$source_dir" -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_DISABLE_FIND_PACKAGE_ParaView=ON -DCMAKE_DISABLE_FIND_PACKAGE_GTest=ON \
  -DVTK_DIR="$vtk_dir" -DPython3_EXECUTABLE="$python" -DBOOSTEDSURFACES_BUILD_BENCHMARKS=OFF \
  >"$build/configure.log" 2>&1 || { cat "$build/configure.log"; exit 1; }
grep -q "ParaView not found" "$build/configure.log"
for skipped in "the kernel's GoogleTest suite" "the Sources.\\* tests of TestBoostedSurfaceSource" \
               "the Filters.\\* tests of TestPointPairDeformationFilter"; do
  grep -q "GTest not found, skipping $skipped" "$build/configure.log" ||
    { echo "the configure did not report skipping: $skipped" >&2; cat "$build/configure.log"; exit 1; }
done
cmake --build "$build" -j 2 >"$build/build.log" 2>&1 || { tail -50 "$build/build.log"; exit 1; }
# The tests that need no GTest are still there.
(cd "$build" && ctest -N) | grep "Image.TestBoostedSurfaceSourceImage" >/dev/null ||
  { echo "the image tests are missing without GTest" >&2; exit 1; }
if find "$build" -name 'BoostedSurfaces.so' -path '*plugins*' | grep -q .; then
  echo "the plugin was built although ParaView was hidden" >&2
  exit 1
fi
site_packages="$(find "$build" -type d -name site-packages | head -n 1)"
PYTHONPATH="$site_packages" "$python" -c "
from boostedsurfaces import vtkBoostedSurfaceSource
s = vtkBoostedSurfaceSource(); s.Update()
assert s.GetOutput().GetNumberOfCells() == 64 * 64
from boostedsurfaces import vtkPointPairDeformationFilter
d = vtkPointPairDeformationFilter(); d.SetInputConnection(s.GetOutputPort()); d.Update()
assert d.GetOutput().GetNumberOfCells() == 64 * 64
print('standalone VTK build OK')"
