#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# Builds the core, the CLI, the tests and the libFuzzer targets with clang, AddressSanitizer and
# UndefinedBehaviorSanitizer into ./build-asan (no studio: Qt and VTK are not instrumented; no
# Python module: an ASan-instrumented extension cannot be loaded by a plain interpreter).
# NDEBUG as in Release: the sanitizers check the code that ships. Extra CMake arguments are
# passed through.
set -euo pipefail
cd "$(dirname "$0")/.."
CC=clang CXX=clang++ cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Sanitize \
  -DCMAKE_CXX_FLAGS_SANITIZE="-O1 -g -DNDEBUG" -DCMAKE_C_FLAGS_SANITIZE="-O1 -g -DNDEBUG" \
  -DLAYERMOD_SANITIZE=ON -DLAYERMOD_BUILD_FUZZERS=ON -DLAYERMOD_BUILD_GUI=OFF \
  -DLAYERMOD_BUILD_BENCHMARKS=OFF -DLAYERMOD_BUILD_PYTHON=OFF -DLAYERMOD_WARNINGS_AS_ERRORS=ON "$@"
cmake --build build-asan -j "$(nproc)"
