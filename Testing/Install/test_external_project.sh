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
