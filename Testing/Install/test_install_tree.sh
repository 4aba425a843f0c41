#!/usr/bin/env bash
# `cmake --install` gives a tree that Python and ParaView use without the build tree.
# Usage: test_install_tree.sh <build dir> <python> [pvpython]
set -euo pipefail
build_dir="$1"
python="$2"
pvpython="${3:-}"
prefix="$(mktemp -d)"
trap 'rm -rf "$prefix"' EXIT

cmake --install "$build_dir" --prefix "$prefix" >/dev/null
site_packages="$(find "$prefix" -type d -name site-packages | head -n 1)"
test -n "$site_packages"

# Run from an unrelated directory so that nothing of the build tree is picked up.
cd "$prefix"
PYTHONPATH="$site_packages" "$python" - <<'PY'
from boostedsurfaces import vtkBoostedSurfaceSource
source = vtkBoostedSurfaceSource()
source.Update()
count = source.GetOutput().GetNumberOfPoints()
assert count == 65 * 65, count
print("installed Python package: %d points" % count)
from boostedsurfaces import vtkPointPairDeformationFilter
deformation = vtkPointPairDeformationFilter()
deformation.SetInputConnection(source.GetOutputPort())
deformation.AddGenerator(0, 0, 0, 1, 0, 0, 0.5)
deformation.Update()
assert deformation.GetOutput().GetNumberOfPoints() == count
print("installed Python package: the deformation filter runs")
PY

if [ -n "$pvpython" ]; then
  plugin="$(find "$prefix" -name BoostedSurfaces.so -path '*plugins*' | head -n 1)"
  test -n "$plugin"
  cat >"$prefix/load_plugin.py" <<PY
from paraview import simple
simple.LoadPlugin("$plugin", remote=False, ns=globals())
surface = BoostedSurface()
surface.UpdatePipeline()
count = surface.GetDataInformation().GetNumberOfPoints()
assert count == 65 * 65, count
print("installed plugin: %d points" % count)
deformation = PointPairDeformation(Input=surface)
deformation.UpdatePipeline()
assert deformation.GetDataInformation().GetNumberOfPoints() == count
print("installed plugin: the deformation filter runs")
PY
  "$pvpython" "$prefix/load_plugin.py"
fi
echo "install tree OK"
