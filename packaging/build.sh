#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Configures and builds LayerMOD (Release, warnings as errors) into ./build.
# Extra CMake arguments are passed through, e.g. -DLAYERMOD_BUILD_GUI=OFF.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DLAYERMOD_WARNINGS_AS_ERRORS=ON "$@"
cmake --build build -j "$(nproc)"
