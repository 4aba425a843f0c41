# Shared by tools/demo and tools/test: install what is missing, then configure and build.
# Sourced, not run. Respects BUILD_DIR (default: <repo>/build), BUILD_TYPE (default: Release) and
# JOBS (default: nproc).
set -euo pipefail

REPO_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
BUILD_DIR="${BUILD_DIR:-$REPO_DIR/build}"
JOBS="${JOBS:-$(nproc)}"

# Debian 12 packages: ParaView 5.11 with its own VTK 9.2, MPI, the test and benchmark
# libraries, Xvfb for headless rendering, and the dev packages ParaView's CMake config looks for;
# Qt's help tools for the plugin's help pages; for the plugin's GUI side, the packages that
# ParaView's pqComponents and its VTK modules need from CMake (Qt5 OpenGL, HDF5, NetCDF, libxml2,
# Boost); SLEEF for the kernel, mpmath for the accuracy test, file, which CPack's Debian
# generator runs on every packaged file, and Ceres Solver for the fit filter.
DEBIAN_PACKAGES=(
  build-essential cmake git
  paraview paraview-dev python3-paraview python3-dev
  mpi-default-bin mpi-default-dev
  libgtest-dev libbenchmark-dev libeigen3-dev nlohmann-json3-dev
  xvfb xauth libgl1-mesa-dri
  libutfcpp-dev libavformat-dev libavcodec-dev libavutil-dev libswscale-dev libswresample-dev
  libexpat1-dev liblzma-dev liblz4-dev libdouble-conversion-dev zlib1g-dev libpng-dev
  libjpeg-dev libtiff-dev libfreetype-dev libx11-dev libxt-dev libglew-dev libgl-dev
  libopengl-dev libglx-dev
  qtbase5-dev qttools5-dev qtxmlpatterns5-dev-tools
  libqt5opengl5-dev libhdf5-dev libnetcdf-dev libxml2-dev libboost-dev
  python3-mpmath libsleef-dev file
  libceres-dev
)

log() { printf '\033[1m==> %s\033[0m\n' "$*"; }

install_packages() {
  local missing=()
  local package
  for package in "${DEBIAN_PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$package")
    fi
  done
  if [ ${#missing[@]} -eq 0 ]; then
    log "All ${#DEBIAN_PACKAGES[@]} Debian packages are present"
    return
  fi
  local sudo=()
  if [ "$(id -u)" -ne 0 ]; then
    if ! command -v sudo >/dev/null; then
      echo "Missing packages (${missing[*]}) and neither root nor sudo is available." >&2
      exit 1
    fi
    sudo=(sudo)
  fi
  log "Installing ${#missing[@]} Debian packages: ${missing[*]}"
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get update -qq
  "${sudo[@]}" env DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends \
    "${missing[@]}"
}

configure_and_build() {
  local build_type="${BUILD_TYPE:-Release}"
  log "Configuring ($build_type) in $BUILD_DIR"
  mkdir -p "$BUILD_DIR"
  cmake -S "$REPO_DIR" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE="$build_type" \
    -DPython3_EXECUTABLE=/usr/bin/python3 "$@" >"$BUILD_DIR/configure.log" 2>&1 || {
    cat "$BUILD_DIR/configure.log" >&2
    exit 1
  }
  log "Building with $JOBS jobs"
  cmake --build "$BUILD_DIR" -j "$JOBS"
}

# Runs a command with an X server: rendering in Debian's VTK and ParaView needs one (no EGL/OSMesa).
with_x() {
  if [ -n "${DISPLAY:-}" ] && [ -z "${CI:-}" ]; then
    "$@"
  else
    # -noreset: by default Xvfb resets when its last client leaves, and a render window opening
    # during that reset fails ("bad X server connection"); the serialized rendering tests hit it.
    xvfb-run -a -s "-screen 0 1280x1024x24 -noreset" "$@"
  fi
}

python_path() {
  local version
  version="$(/usr/bin/python3 -c 'import sys; print("%d.%d" % sys.version_info[:2])')"
  echo "$BUILD_DIR/lib/python$version/site-packages"
}
