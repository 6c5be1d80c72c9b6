#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Installs every Debian 12 package LayerMOD needs to build, test and package.
# Idempotent: the single source of truth for CI, the README and developers.
set -euo pipefail

BUILD_PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev libopencv-dev libopencv-contrib-dev libassimp-dev libopenmesh-dev
  nlohmann-json3-dev libcli11-dev libtbb-dev libzip-dev libdeflate-dev zlib1g-dev
  libgtest-dev libgmock-dev googletest libbenchmark-dev
)
PYTHON_PACKAGES=(
  python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest
)
GUI_PACKAGES=(
  qtbase5-dev libqt5opengl5-dev libvtk9-dev libvtk9-qt-dev
  xvfb xauth libgl1-mesa-dri
)
TOOL_PACKAGES=(
  clang clang-format clang-tidy libclang-rt-14-dev dpkg-dev file
)

missing=()
for pkg in "${BUILD_PACKAGES[@]}" "${PYTHON_PACKAGES[@]}" "${GUI_PACKAGES[@]}" "${TOOL_PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null | grep -q 'install ok installed' || missing+=("$pkg")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
# Recommends stay on: Debian's libvtk9-dev CMake config needs packages it only recommends.
$SUDO apt-get install -y -q "${missing[@]}"
echo "install-deps: installed ${#missing[@]} package(s)"
