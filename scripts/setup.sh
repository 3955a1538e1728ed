#!/usr/bin/env bash
# Installs what the build needs (only what is missing) and builds what is
# stale. Safe to run any number of times; the second run is a no-op build.
#
#   scripts/setup.sh            # install + configure + build into build/
#   BUILD_DIR=build-debug BUILD_TYPE=Debug scripts/setup.sh
set -euo pipefail
cd "$(dirname "$0")/.."

BUILD_DIR=${BUILD_DIR:-build}
BUILD_TYPE=${BUILD_TYPE:-Release}

# Debian 12 packages. libopencv-dev is here only because OIIO's CMake config
# names OpenCV's include directory (see ../shared/debian-notes.md).
packages=(
  build-essential cmake ninja-build pkg-config
  libembree-dev libtbb-dev
  libopenimageio-dev openimageio-tools libopencv-dev
  libopencolorio-dev
  libtomlplusplus-dev libeigen3-dev libcli11-dev
  libvtk9-dev
  libmedc-dev libgmsh-dev libxml2-dev libhdf5-dev
  libpango1.0-dev libcairo2-dev poppler-utils
  libssl-dev
  googletest libgtest-dev
  fonts-dejavu-core
  python3
)

source scripts/lib/packages.sh
install_missing "${packages[@]}"

if [[ ! -f "$BUILD_DIR/build.ninja" ]]; then
  cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE="$BUILD_TYPE"
fi
cmake --build "$BUILD_DIR" -j "${JOBS:-2}"
