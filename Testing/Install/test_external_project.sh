#!/usr/bin/env bash
# An external CMake project builds against `cmake --install`'s tree with find_package(BoostedSurfaces)
# alone (no VTK_DIR, no source tree), links a VTK source and the core, and runs.
# Usage: test_external_project.sh <build dir> <project dir>
set -euo pipefail
build_dir="$1"
project_dir="$2"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null

# The core is one shared library: its kernel (and the kernel's instruction-set choice) is defined
# there and in no other installed library (the VTK modules, the Python modules, the plugin).
# (grep reads all of nm's output, so that pipefail cannot see nm die of a closed pipe)
kernel_symbol='cga::kernel::activeMapBlock'
defines_kernel() { nm -DC --defined-only "$1" | grep -F "$kernel_symbol" >/dev/null; }
defines_kernel "$work/prefix/lib/libBoostedSurfacesCGA.so" ||
  { echo "libBoostedSurfacesCGA.so does not define $kernel_symbol" >&2; exit 1; }
checked=0
while IFS= read -r library; do
  if defines_kernel "$library"; then
    echo "$library holds its own copy of the kernel ($kernel_symbol)" >&2
    exit 1
  fi
  checked=$((checked + 1))
done < <(find "$work/prefix" -name '*.so' ! -name 'libBoostedSurfacesCGA.so*')
test "$checked" -ge 3
echo "the kernel is defined once, in libBoostedSurfacesCGA.so ($checked other libraries checked)"
cmake -S "$project_dir" -B "$work/build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$work/prefix" >"$work/configure.log" 2>&1 || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" -j 2 >"$work/build.log" 2>&1 || { tail -50 "$work/build.log"; exit 1; }
# The executable finds the installed libraries, not the build tree's.
if ldd "$work/build/UseBoostedSurfaces" | grep -F "$build_dir/"; then
  echo "the external project links the build tree's libraries" >&2
  exit 1
fi
"$work/build/UseBoostedSurfaces"
echo "external project OK"
